/* SPDX-License-Identifier: MIT */
/*
 * Bring-up self-test at every start (selftest.c): what the board measured
 * about itself before the firmware runs. See README.md, "Bring-up".
 */
#ifndef STM32_SELFTEST_H
#define STM32_SELFTEST_H

#include <stdint.h>

#include "hal.h"

/* Loopback result per bus (stm32_selftest_t.loopback; SquealDiag values) */
#define STM32_LOOPBACK_PASS        0U /* frame came back unchanged          */
#define STM32_LOOPBACK_FAIL        1U /* controller answered, frame did not */
#define STM32_LOOPBACK_UNAVAILABLE 2U /* no controller / no clock (QEMU)    */
#define STM32_LOOPBACK_NO_BUS      3U /* the chip has no such controller    */

typedef struct {
	uint32_t hse_hz;          /* measured crystal, 0 none, 0xFFFFFFFF n/a */
	uint32_t reset_reason;    /* hal_reset_reason_t                        */
	uint32_t bor_level;       /* 3..0, 0xFF: the chip has none             */
	uint32_t loopback[HAL_CAN_BUSES]; /* STM32_LOOPBACK_* per bus          */
	uint32_t stack_hwm_prev;  /* bytes, 0xFFFFFFFF unknown (power-on)      */
	uint32_t faults;          /* STM32_SELFTEST_* bits that failed         */
} stm32_selftest_t;

/* Which checks failed (stm32_selftest_t.faults). */
#define STM32_SELFTEST_CRYSTAL   (1U << 0) /* no crystal, or not CHIP_HSE_HZ */
#define STM32_SELFTEST_BOR       (1U << 1) /* BOR below level 3             */
#define STM32_SELFTEST_LOOPBACK  (1U << 2) /* a controller failed loopback  */
#define STM32_SELFTEST_STACK     (1U << 3) /* previous run used > 7/8 stack */

/* Run once, after the clocks and before CAN joins the bus. A failure
 * raises its HAL fault bit (CLOCK_FALLBACK, CAN_INIT) or
 * STM32_FAULT_SELFTEST; the ECU runs on with what works. */
const stm32_selftest_t *stm32_selftest_run(uint32_t stack_reserve_bytes);
const stm32_selftest_t *stm32_selftest(void);

/* Platform fault bit for self-test failures (BOR level, stack). */
#define STM32_FAULT_SELFTEST HAL_FAULT_SELFTEST

#endif /* STM32_SELFTEST_H */
