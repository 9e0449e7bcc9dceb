/* SPDX-License-Identifier: MIT */
/*
 * ARM semihosting for test builds (-DSQ_TARGET_TEST) under QEMU or a
 * debugger: "bkpt 0xAB" with the operation in r0 and the argument in r1.
 * Never linked into the ECU image: without a debugger, bkpt faults.
 */
#include <stddef.h>

#include "stm32_test.h"

#if defined(SQ_TARGET_TEST)

#define SYS_WRITE0        0x04U
#define SYS_EXIT_EXTENDED 0x20U
#define ADP_STOPPED_APPLICATION_EXIT 0x20026UL

static uint32_t semihost_call(uint32_t op, const void *arg)
{
	register uint32_t r0 __asm__("r0") = op;
	register const void *r1 __asm__("r1") = arg;

	__asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
	return r0;
}

void semihost_write0(const char *s)
{
	(void)semihost_call(SYS_WRITE0, s);
}

void semihost_exit(uint32_t code)
{
	const uint32_t block[2] = { ADP_STOPPED_APPLICATION_EXIT, code };

	(void)semihost_call(SYS_EXIT_EXTENDED, block);
	for (;;) {
		/* not reached under QEMU; a debugger may resume: stay put */
	}
}

static void print3(const char *prefix, const char *mid, const char *suffix)
{
	if (prefix != NULL) {
		semihost_write0(prefix);
	}
	semihost_write0(mid);
	if (suffix != NULL) {
		semihost_write0(suffix);
	}
}

void semihost_print_u32(const char *prefix, uint32_t value, const char *suffix)
{
	char buf[11];
	uint32_t i = sizeof(buf) - 1U;

	buf[i] = '\0';
	do {
		i--;
		buf[i] = (char)('0' + (char)(value % 10U));
		value /= 10U;
	} while (value != 0U && i > 0U);
	print3(prefix, &buf[i], suffix);
}

void semihost_print_hex(const char *prefix, uint32_t value, const char *suffix)
{
	static const char digits[] = "0123456789abcdef";
	char buf[9];
	uint32_t i;

	for (i = 0; i < 8U; i++) {
		buf[i] = digits[(value >> (28U - 4U * i)) & 0xFU];
	}
	buf[8] = '\0';
	print3(prefix, buf, suffix);
}

#endif /* SQ_TARGET_TEST */
