/* SPDX-License-Identifier: MIT */
/*
 * candump_hal: the one conversion between a candump -L frame (candump_log.h)
 * and a HAL frame (hal.h), used by replay, decode and the plant's log.
 *
 * CAN FD flags: a `##F` line is an FD frame whatever its flags digit says
 * (can-utils on kernels before CAN XL write BRS 1 | ESI 2 only, on newer
 * ones the kernel adds FDF 4), so the HAL frame gets HAL_CAN_FLAG_FDF
 * always, plus BRS and ESI from the digit. Written back, the digit is
 * FDF | BRS | ESI: what candump of Debian 12 (can-utils 2020.11, kernel
 * 6.1.0-57) writes for a received FD frame, measured on vcan0 in the QEMU
 * guest (tests/system/run-fd-log.sh), so a log we write and one candump
 * wrote of the same traffic are the same bytes.
 */
#ifndef CANDUMP_HAL_H
#define CANDUMP_HAL_H

#include <stdint.h>

#include "candump_log.h"
#include "hal.h"

#define CANDUMP_FD_BRS 0x1U /* CANFD_BRS of linux/can.h */
#define CANDUMP_FD_ESI 0x2U /* CANFD_ESI                */
#define CANDUMP_FD_FDF 0x4U /* CANFD_FDF (set by newer kernels on every FD frame) */

/*
 * The HAL frame of a log frame (timestamp_us 0: the caller sets when it
 * arrives). Classic data, remote (dlc = the requested length) and error
 * frames (HAL_CAN_FLAG_ERR, id = the error class) always convert; a _X raw
 * DLC code is not carried. SQ_OK, or SQ_ENOTSUP for a frame this build's HAL
 * cannot hold: CAN XL, and CAN FD longer than HAL_CAN_MAX_DLEN (a classic-only
 * build); *hf is then zeroed.
 */
int candump_to_hal(const candump_frame_t *f, hal_can_frame_t *hf);

/*
 * The log frame of a HAL frame at t_ns on interface iface (cut to
 * CANDUMP_IFACE_MAX characters). An error frame's id keeps only the class.
 * Only the frame's len data bytes are written (the others are left as they
 * were: nothing reads beyond len).
 */
void candump_from_hal(const hal_can_frame_t *hf, uint64_t t_ns, const char *iface,
		      candump_frame_t *f);

#endif /* CANDUMP_HAL_H */
