/* SPDX-License-Identifier: MIT */
/* candump_hal: see candump_hal.h. */
#include "candump_hal.h"

#include <stddef.h>
#include <string.h>

int candump_to_hal(const candump_frame_t *f, hal_can_frame_t *hf)
{
	memset(hf, 0, sizeof(*hf));
	if ((f->kind == CANDUMP_KIND_XL) ||
	    ((f->kind == CANDUMP_KIND_FD) && (f->len > HAL_CAN_MAX_DLEN))) {
		return SQ_ENOTSUP;
	}
	hf->id = f->id;
	hf->dlc = (f->len > HAL_CAN_MAX_DLEN) ? (uint8_t)HAL_CAN_MAX_DLEN : f->len;
	switch (f->kind) {
	case CANDUMP_KIND_RTR:
		hf->flags = HAL_CAN_FLAG_RTR;
		break;
	case CANDUMP_KIND_ERROR:
		hf->flags = HAL_CAN_FLAG_ERR;
		break;
	case CANDUMP_KIND_FD:
		hf->flags = (uint8_t)(HAL_CAN_FLAG_FDF |
				      (((f->fd_flags & CANDUMP_FD_BRS) != 0U) ? HAL_CAN_FLAG_BRS : 0U) |
				      (((f->fd_flags & CANDUMP_FD_ESI) != 0U) ? HAL_CAN_FLAG_ESI : 0U));
		break;
	default:
		break;
	}
	if (f->ext && (f->kind != CANDUMP_KIND_ERROR)) {
		hf->flags |= HAL_CAN_FLAG_EXT;
	}
	if (f->kind != CANDUMP_KIND_RTR) {
		memcpy(hf->data, f->data, hf->dlc);
	}
	return SQ_OK;
}

void candump_from_hal(const hal_can_frame_t *hf, uint64_t t_ns, const char *iface,
		      candump_frame_t *f)
{
	const size_t n = strnlen(iface, CANDUMP_IFACE_MAX);
	const size_t len = (hf->dlc > HAL_CAN_MAX_DLEN) ? HAL_CAN_MAX_DLEN : hf->dlc;

	/* the fields, not the 64 data bytes: only len of them are written
	 * below (a frame per output line: this is the replay's hot path) */
	memset(f, 0, offsetof(candump_frame_t, data));
	f->t_ns = t_ns;
	memcpy(f->iface, iface, n);
	f->id = hf->id;
	f->ext = (hf->flags & HAL_CAN_FLAG_EXT) != 0U;
	f->len = (uint8_t)len;
	f->kind = CANDUMP_KIND_CLASSIC;
	if ((hf->flags & HAL_CAN_FLAG_ERR) != 0U) {
		f->kind = CANDUMP_KIND_ERROR;
		f->id &= CANDUMP_ERR_MASK;
		f->ext = true;
	} else if ((hf->flags & HAL_CAN_FLAG_FDF) != 0U) {
		f->kind = CANDUMP_KIND_FD;
		f->fd_flags = (uint8_t)(CANDUMP_FD_FDF |
					(((hf->flags & HAL_CAN_FLAG_BRS) != 0U) ? CANDUMP_FD_BRS : 0U) |
					(((hf->flags & HAL_CAN_FLAG_ESI) != 0U) ? CANDUMP_FD_ESI : 0U));
	} else if ((hf->flags & HAL_CAN_FLAG_RTR) != 0U) {
		f->kind = CANDUMP_KIND_RTR;
	} else {
		/* classic data */
	}
	if (f->kind != CANDUMP_KIND_RTR) {
		memcpy(f->data, hf->data, len);
	}
}
