/* SPDX-License-Identifier: MIT */
/*
 * Test images only (-DSQ_TARGET_TEST): the event sink the drivers report
 * to (stm32_test.h). It prints through semihosting and counts watchdog
 * kicks; it knows no driver, so any driver may call it.
 */
#include <stddef.h>

#include "stm32_test.h"
#include "stm32_time.h"

/* Linked only into the test images (mk/target.mk); empty elsewhere. */
#if defined(SQ_TARGET_TEST)

static uint32_t kicks_seen;
static uint32_t last_kick_ms;

static bool is_kick(const char *w)
{
	return (w[0] == 'w') && (w[1] == 'd') && (w[2] == 'g') && (w[3] == '_') && (w[4] == 'k');
}

void stm32_test_note(const char *what, uint32_t value)
{
	if (is_kick(what)) {
		kicks_seen = value;
		last_kick_ms = stm32_uptime_ms();
		if (value == 1U) {
			semihost_write0("EVT wdg_kick first\n");
		}
		return;
	}
	semihost_write0("EVT ");
	semihost_write0(what);
	semihost_print_u32(" value=", value, "\n");
}

uint32_t stm32_test_kicks(uint32_t *last_ms)
{
	if (last_ms != NULL) {
		*last_ms = last_kick_ms;
	}
	return kicks_seen;
}

#endif /* SQ_TARGET_TEST */
