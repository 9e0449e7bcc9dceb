/* SPDX-License-Identifier: MIT */
/*
 * The class of an operating point: the one definition of its values. The
 * model returns them (squeal_model.h) and the CAN signal SquealState carries
 * them unchanged (squeal_msgs.h derives its MSG_SQUEAL_STATE_* from these),
 * so INVALID is the bus's FAULT value.
 */
#ifndef SQUEAL_STATE_H
#define SQUEAL_STATE_H

typedef enum {
	SQUEAL_STATE_STABLE = 0,      /* no sliding cycle below the stick line  */
	SQUEAL_STATE_BISTABLE = 1,    /* stable, inside an unstable cycle        */
	SQUEAL_STATE_UNSTABLE = 2,    /* steady sliding unstable (Q <= 1/2)      */
	SQUEAL_STATE_NOT_SLIDING = 3, /* v0 == 0 or no pad force                 */
	SQUEAL_STATE_INVALID = 15     /* input outside the documented domain; on
				       * the bus: FAULT                         */
} squeal_state_t;

/* States 0 .. SQUEAL_STATE_NAMED - 1 are the model's classes, each with a
 * name of its own (squeal_model_state_name); INVALID is the only other. */
#define SQUEAL_STATE_NAMED ((unsigned int)SQUEAL_STATE_NOT_SLIDING + 1U)

#endif /* SQUEAL_STATE_H */
