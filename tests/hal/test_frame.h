/* SPDX-License-Identifier: MIT */
/*
 * The HAL tests' frame builder: a frame with this id, flags and length whose
 * data bytes are seed, seed + step, seed + 2 step, ... (mod 256), so that a
 * byte lost, moved or kept from another frame shows. A remote frame carries
 * no data: its dlc is the length it asks for.
 */
#ifndef TEST_FRAME_H
#define TEST_FRAME_H

#include <stdint.h>
#include <string.h>

#include "hal.h"

static inline hal_can_frame_t test_frame(uint32_t id, uint8_t flags, uint8_t dlc, uint8_t seed, uint8_t step)
{
	hal_can_frame_t f;
	uint8_t i;

	memset(&f, 0, sizeof(f));
	f.id = id;
	f.flags = flags;
	f.dlc = dlc;
	for (i = 0U; ((flags & HAL_CAN_FLAG_RTR) == 0U) && (i < dlc) && (i < HAL_CAN_MAX_DLEN); i++) {
		f.data[i] = (uint8_t)(seed + step * i);
	}
	return f;
}

#endif /* TEST_FRAME_H */
