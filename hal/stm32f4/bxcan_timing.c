/* SPDX-License-Identifier: MIT */
/*
 * bxCAN bit timing (RM0090 section 32.7.7), pure arithmetic so the host
 * tests can check it: a bit is 1 + BS1 + BS2 time quanta of (BRP+1) APB
 * clocks. We look for an exact bit rate (no rounding: CAN tolerates about
 * 0.5 % between nodes and the clock error comes on top) with 8..25 quanta,
 * and of those take the sample point nearest 87.5 % (CiA 301's value for
 * 500 kbit/s and below), preferring more quanta on a tie (finer resync).
 * SJW is 1 quantum.
 */
#include <stddef.h>

#include "bxcan.h"
#include "sq_status.h"

/* BTR field positions (bxcan_regs.h repeats them for the driver; this file
 * also builds on the host, without the register header). */
#define CAN_BTR_BRP_SHIFT 0U
#define CAN_BTR_TS1_SHIFT 16U
#define CAN_BTR_TS2_SHIFT 20U
#define CAN_BTR_SJW_SHIFT 24U

#define TQ_MIN 8U
#define TQ_MAX 25U
#define BS1_MAX 16U
#define BS2_MAX 8U
#define BRP_MAX 1024U
#define SAMPLE_TARGET_PERMILLE 875U

int bxcan_bit_timing(uint32_t apb_hz, uint32_t bitrate_bps, uint32_t *btr)
{
	uint32_t best_err = 0xFFFFFFFFUL;
	uint32_t best = 0U;
	uint32_t ntq;

	if (btr == NULL || bitrate_bps == 0U || apb_hz == 0U || bitrate_bps > 1000000UL) {
		return SQ_EINVAL;
	}
	for (ntq = TQ_MAX; ntq >= TQ_MIN; ntq--) {
		uint32_t clocks_per_bit;
		uint32_t brp;
		uint32_t bs2;

		if (apb_hz % bitrate_bps != 0U) {
			break; /* no exact rate at any ntq */
		}
		clocks_per_bit = apb_hz / bitrate_bps;
		if (clocks_per_bit % ntq != 0U) {
			continue;
		}
		brp = clocks_per_bit / ntq;
		if (brp < 1U || brp > BRP_MAX) {
			continue;
		}
		for (bs2 = 1U; bs2 <= BS2_MAX; bs2++) {
			uint32_t bs1 = ntq - 1U - bs2;
			uint32_t sp;
			uint32_t err;

			if (bs1 < 1U || bs1 > BS1_MAX) {
				continue;
			}
			sp = (1U + bs1) * 1000U / ntq;
			err = sp > SAMPLE_TARGET_PERMILLE ? sp - SAMPLE_TARGET_PERMILLE
							  : SAMPLE_TARGET_PERMILLE - sp;
			if (err < best_err) {
				best_err = err;
				best = ((brp - 1U) << CAN_BTR_BRP_SHIFT) |
				       ((bs1 - 1U) << CAN_BTR_TS1_SHIFT) |
				       ((bs2 - 1U) << CAN_BTR_TS2_SHIFT) |
				       (0UL << CAN_BTR_SJW_SHIFT);
			}
		}
	}
	if (best_err == 0xFFFFFFFFUL) {
		return SQ_EINVAL;
	}
	*btr = best;
	return SQ_OK;
}
