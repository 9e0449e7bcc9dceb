/* SPDX-License-Identifier: MIT */
/*
 * hal_vbus_sys.c: the in-memory backend's clock, idle, calibration storage,
 * watchdog, reset reason and platform faults (see hal_vbus.h).
 */
#include <string.h>

#include "hal_vbus.h"
#include "hal_vbus_internal.h"

static struct {
	uint64_t now_us;
	uint32_t cycles_per_call;
	uint32_t cycles_extra;

	uint8_t calib[HAL_CALIB_MAX_LEN];
	uint32_t calib_len;
	bool calib_present;
	bool calib_unreadable;

	uint32_t wd_kicks;
	uint32_t wd_timeout_ms;
	uint32_t platform_faults;
	hal_reset_reason_t reset_reason;
	bool has_selftest;
	hal_selftest_t selftest;
} sys;

void hal_vbus_sys_reset(void)
{
	(void)memset(&sys, 0, sizeof(sys));
	sys.reset_reason = HAL_RESET_POWER_ON;
}

void hal_vbus_reset(void)
{
	hal_vbus_sys_reset();
	hal_vbus_can_reset();
}

/* ---- clock ---------------------------------------------------------------- */

void hal_vbus_set_time_us(uint64_t t_us)
{
	if (t_us > sys.now_us) {
		sys.now_us = t_us; /* monotonic, as hal.h promises */
	}
}

void hal_vbus_set_cycles_per_call(uint32_t cycles)
{
	sys.cycles_per_call = cycles;
}

uint64_t hal_time_us(void)
{
	return sys.now_us;
}

void hal_idle_until(uint64_t deadline_us)
{
	uint64_t t = deadline_us;
	uint64_t arrival_us;

	if (hal_vbus_next_arrival_us(&arrival_us) && (arrival_us < t)) {
		t = arrival_us;
	}
	hal_vbus_set_time_us(t);
}

uint32_t hal_cycles(void)
{
	sys.cycles_extra += sys.cycles_per_call;
	return (uint32_t)(sys.now_us * HAL_VBUS_CYCLES_PER_US) + sys.cycles_extra;
}

uint32_t hal_cycles_per_us(void)
{
	return HAL_VBUS_CYCLES_PER_US;
}

/* ---- calibration storage -------------------------------------------------- */

int hal_vbus_calib_store(const uint8_t *block, uint32_t len)
{
	if ((len > HAL_CALIB_MAX_LEN) || ((block == NULL) && (len > 0U))) {
		return SQ_EINVAL;
	}
	(void)memset(sys.calib, 0xFF, sizeof(sys.calib)); /* erased flash */
	if (len > 0U) {
		(void)memcpy(sys.calib, block, len);
	}
	sys.calib_len = len;
	sys.calib_present = true;
	return SQ_OK;
}

void hal_vbus_calib_erase(void)
{
	sys.calib_present = false;
	sys.calib_len = 0U;
}

void hal_vbus_calib_set_unreadable(bool unreadable)
{
	sys.calib_unreadable = unreadable;
}

uint32_t hal_vbus_calib_stored(uint8_t *buf, uint32_t max)
{
	if (!sys.calib_present) {
		return 0U;
	}
	if (buf != NULL) {
		(void)memcpy(buf, sys.calib, (sys.calib_len < max) ? sys.calib_len : max);
	}
	return sys.calib_len;
}

int hal_calib_read(uint8_t *buf, uint32_t len)
{
	if ((buf == NULL) || (len > HAL_CALIB_MAX_LEN)) {
		return SQ_EINVAL;
	}
	if (sys.calib_unreadable) {
		return SQ_EIO;
	}
	if (!sys.calib_present) {
		return SQ_ENOENT;
	}
	/* like flash: the bytes beyond what was written read as erased */
	(void)memcpy(buf, sys.calib, len);
	return SQ_OK;
}

int hal_calib_write(const uint8_t *buf, uint32_t len)
{
	if (buf == NULL) {
		return SQ_EINVAL;
	}
	return hal_vbus_calib_store(buf, len);
}

/* ---- watchdog, reset, platform -------------------------------------------- */

int hal_watchdog_start(uint32_t timeout_ms)
{
	if (timeout_ms == 0U) {
		return SQ_EINVAL;
	}
	sys.wd_timeout_ms = timeout_ms;
	return SQ_OK;
}

void hal_watchdog_kick(void)
{
	sys.wd_kicks++;
}

uint32_t hal_vbus_watchdog_kicks(void)
{
	return sys.wd_kicks;
}

uint32_t hal_vbus_watchdog_timeout_ms(void)
{
	return sys.wd_timeout_ms;
}

hal_reset_reason_t hal_reset_reason(void)
{
	return sys.reset_reason;
}

void hal_vbus_set_reset_reason(hal_reset_reason_t why)
{
	sys.reset_reason = why;
}

uint32_t hal_platform_faults(void)
{
	return sys.platform_faults;
}

void hal_vbus_set_platform_faults(uint32_t bits)
{
	sys.platform_faults = bits;
}

/* A virtual board has no self-test of its own; a test may give it one. */
int hal_selftest(hal_selftest_t *result)
{
	HAL_REQUIRE(result != NULL);
	if (!sys.has_selftest) {
		return SQ_ENOTSUP;
	}
	*result = sys.selftest;
	return SQ_OK;
}

void hal_vbus_set_selftest(const hal_selftest_t *result)
{
	sys.has_selftest = result != NULL;
	if (result != NULL) {
		sys.selftest = *result;
	}
}
