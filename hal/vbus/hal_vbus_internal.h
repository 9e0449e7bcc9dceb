/* SPDX-License-Identifier: MIT */
/* hal_vbus_internal.h: what hal_vbus_can.c and hal_vbus_sys.c share. */
#ifndef HAL_VBUS_INTERNAL_H
#define HAL_VBUS_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>

void hal_vbus_can_reset(void);
void hal_vbus_sys_reset(void);

/* The earliest arrival time of a queued frame on any bus, if there is one. */
bool hal_vbus_next_arrival_us(uint64_t *t_us);

#endif /* HAL_VBUS_INTERNAL_H */
