/* SPDX-License-Identifier: MIT */
/* Pieces shared by the float and fixed implementations of squeal_model.h. */
#ifndef SQUEAL_MODEL_INTERNAL_H
#define SQUEAL_MODEL_INTERNAL_H

#include "squeal_model.h"

/* A result with this state, no flags and every value 0. */
void squeal_model_result_clear(squeal_result_t *out, squeal_state_t state);

#endif /* SQUEAL_MODEL_INTERNAL_H */
