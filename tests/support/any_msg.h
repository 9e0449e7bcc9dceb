/* SPDX-License-Identifier: MIT */
/*
 * One value of any of the six messages of squeal_msgs.h, and pack/unpack
 * chosen by CAN id, for the test programs that walk msg_table (the frame
 * emitter, the message fuzzer).
 */
#ifndef ANY_MSG_H
#define ANY_MSG_H

#include <stdint.h>

#include "squeal_msgs.h"

typedef union {
	msg_disc_speed_t ds;
	msg_pad_force_t pf;
	msg_squeal_status_t st;
	msg_squeal_detail_t dt;
	msg_squeal_detail2_t d2;
	msg_squeal_diag_t dg;
} any_msg_t;

/* The message's own unpack/pack; SQ_EINVAL for an id that is none of the six. */
int any_msg_unpack(uint16_t id, const uint8_t *d, uint8_t dlc, any_msg_t *m);
int any_msg_pack(uint16_t id, const any_msg_t *m, uint8_t d[8], uint8_t *dlc);

#endif
