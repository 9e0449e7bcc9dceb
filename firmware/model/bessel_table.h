/* SPDX-License-Identifier: MIT */
/* Tabulated H(s) = ln(2 I1(s)/s) - s for the fixed-point build (Q28). */
#ifndef BESSEL_TABLE_H
#define BESSEL_TABLE_H

#include <stdint.h>

#define SQ_BESSEL_STEP_LOG2 4   /* nodes every 1/16 */
#define SQ_BESSEL_S_MAX 32      /* table covers s in [0, 32] */
#define SQ_BESSEL_TABLE_LEN ((SQ_BESSEL_S_MAX << SQ_BESSEL_STEP_LOG2) + 1)
#define SQ_BESSEL_Q 28

extern const int32_t sq_bessel_h_q28[SQ_BESSEL_TABLE_LEN];
extern const int32_t sq_bessel_dh_q28[SQ_BESSEL_TABLE_LEN];

#endif /* BESSEL_TABLE_H */
