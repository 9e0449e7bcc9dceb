/* SPDX-License-Identifier: MIT */
/* E2E Profile 1 fixtures (p01_frames.h). */
#include "p01_frames.h"

#include "squeal_msgs.h"

uint8_t ref_crc8(const uint8_t *d, size_t n, uint8_t init, uint8_t xorout)
{
	uint8_t c = init;

	for (size_t i = 0; i < n; i++) {
		c ^= d[i];
		for (int k = 0; k < 8; k++) {
			c = (uint8_t)((c & 0x80U) != 0U ? (((unsigned int)c << 1) ^ 0x1DU) : ((unsigned int)c << 1));
		}
	}
	return (uint8_t)(c ^ xorout);
}

const e2e_p01_config_t cfg_ds = { MSG_DISC_SPEED_DATA_ID, MSG_DISC_SPEED_DLC, 1 };
const e2e_p01_config_t cfg_pf = { MSG_PAD_FORCE_DATA_ID, MSG_PAD_FORCE_DLC, 1 };

/* CRC over 51 2C c 39 30 (data ID 0x2C51 low byte first), computed in
 * Python with the bitwise definition above. */
static const uint8_t ds_crc_by_counter[15] = {
	0x1E, 0x91, 0x1D, 0x92, 0x18, 0x97, 0x1B, 0x94,
	0x12, 0x9D, 0x11, 0x9E, 0x14, 0x9B, 0x17,
};

void ds_frame(uint8_t counter, uint8_t f[4])
{
	f[0] = ds_crc_by_counter[counter % 15U];
	f[1] = counter;
	f[2] = 0x39;
	f[3] = 0x30;
}
