/* SPDX-License-Identifier: MIT */
#include "any_msg.h"

#include "sq_status.h"

/* One row per message: its CAN id, its functions' prefix, its member. */
#define ANY_MSG_ROWS(X)                                  \
	X(MSG_DISC_SPEED_ID, msg_disc_speed, ds)         \
	X(MSG_PAD_FORCE_ID, msg_pad_force, pf)           \
	X(MSG_SQUEAL_STATUS_ID, msg_squeal_status, st)   \
	X(MSG_SQUEAL_DETAIL_ID, msg_squeal_detail, dt)   \
	X(MSG_SQUEAL_DETAIL2_ID, msg_squeal_detail2, d2) \
	X(MSG_SQUEAL_DIAG_ID, msg_squeal_diag, dg)

int any_msg_unpack(uint16_t id, const uint8_t *d, uint8_t dlc, any_msg_t *m)
{
#define UNPACK_CASE(ID, FN, MEMBER) \
	case ID:                    \
		return FN##_unpack(d, dlc, &m->MEMBER);
	switch (id) {
		ANY_MSG_ROWS(UNPACK_CASE)
	default:
		return SQ_EINVAL;
	}
#undef UNPACK_CASE
}

int any_msg_pack(uint16_t id, const any_msg_t *m, uint8_t d[8], uint8_t *dlc)
{
#define PACK_CASE(ID, FN, MEMBER) \
	case ID:                  \
		return FN##_pack(&m->MEMBER, d, dlc);
	switch (id) {
		ANY_MSG_ROWS(PACK_CASE)
	default:
		return SQ_EINVAL;
	}
#undef PACK_CASE
}
