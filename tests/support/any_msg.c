/* SPDX-License-Identifier: MIT */
#include "any_msg.h"

#include "sq_status.h"

int any_msg_unpack(uint16_t id, const uint8_t *d, uint8_t dlc, any_msg_t *m)
{
	switch (id) {
	case MSG_DISC_SPEED_ID:
		return msg_disc_speed_unpack(d, dlc, &m->ds);
	case MSG_PAD_FORCE_ID:
		return msg_pad_force_unpack(d, dlc, &m->pf);
	case MSG_SQUEAL_STATUS_ID:
		return msg_squeal_status_unpack(d, dlc, &m->st);
	case MSG_SQUEAL_DETAIL_ID:
		return msg_squeal_detail_unpack(d, dlc, &m->dt);
	case MSG_SQUEAL_DETAIL2_ID:
		return msg_squeal_detail2_unpack(d, dlc, &m->d2);
	case MSG_SQUEAL_DIAG_ID:
		return msg_squeal_diag_unpack(d, dlc, &m->dg);
	default:
		return SQ_EINVAL;
	}
}

int any_msg_pack(uint16_t id, const any_msg_t *m, uint8_t d[8], uint8_t *dlc)
{
	switch (id) {
	case MSG_DISC_SPEED_ID:
		return msg_disc_speed_pack(&m->ds, d, dlc);
	case MSG_PAD_FORCE_ID:
		return msg_pad_force_pack(&m->pf, d, dlc);
	case MSG_SQUEAL_STATUS_ID:
		return msg_squeal_status_pack(&m->st, d, dlc);
	case MSG_SQUEAL_DETAIL_ID:
		return msg_squeal_detail_pack(&m->dt, d, dlc);
	case MSG_SQUEAL_DETAIL2_ID:
		return msg_squeal_detail2_pack(&m->d2, d, dlc);
	case MSG_SQUEAL_DIAG_ID:
		return msg_squeal_diag_pack(&m->dg, d, dlc);
	default:
		return SQ_EINVAL;
	}
}
