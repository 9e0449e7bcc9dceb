/* SPDX-License-Identifier: MIT */
/*
 * The four string.h functions GCC may call on its own (structure copies and
 * clears) even in freestanding code. The image links no C library: newlib's
 * start-up and heap are not wanted, and this is all it would bring.
 * The loops are byte-wise and kept from being turned back into calls to
 * themselves.
 */
#include <stddef.h>
#include <stdint.h>

void *memcpy(void *restrict dst, const void *restrict src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
int memcmp(const void *a, const void *b, size_t n);

#if defined(__clang__)
#define NO_LOOP_CALLS __attribute__((no_builtin))
#else
#define NO_LOOP_CALLS __attribute__((optimize("no-tree-loop-distribute-patterns")))
#endif

NO_LOOP_CALLS void *memcpy(void *restrict dst, const void *restrict src, size_t n)
{
	uint8_t *d = dst;
	const uint8_t *s = src;
	size_t i;

	for (i = 0; i < n; i++) {
		d[i] = s[i];
	}
	return dst;
}

NO_LOOP_CALLS void *memmove(void *dst, const void *src, size_t n)
{
	uint8_t *d = dst;
	const uint8_t *s = src;
	size_t i;

	if ((uintptr_t)d < (uintptr_t)s) {
		for (i = 0; i < n; i++) {
			d[i] = s[i];
		}
	} else {
		for (i = n; i > 0U; i--) {
			d[i - 1U] = s[i - 1U];
		}
	}
	return dst;
}

NO_LOOP_CALLS void *memset(void *dst, int c, size_t n)
{
	uint8_t *d = dst;
	size_t i;

	for (i = 0; i < n; i++) {
		d[i] = (uint8_t)c;
	}
	return dst;
}

NO_LOOP_CALLS int memcmp(const void *a, const void *b, size_t n)
{
	const uint8_t *p = a;
	const uint8_t *q = b;
	size_t i;

	for (i = 0; i < n; i++) {
		if (p[i] != q[i]) {
			return (int)p[i] - (int)q[i];
		}
	}
	return 0;
}
