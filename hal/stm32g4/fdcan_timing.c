/* SPDX-License-Identifier: MIT */
/*
 * FDCAN bit timing (RM0440 chapter 44; registers FDCAN_NBTP, FDCAN_DBTP,
 * FDCAN_TDCR in section 44.4), pure arithmetic so the host tests
 * can check it. A bit is 1 + TSEG1 + TSEG2 time quanta of BRP kernel clocks
 * (FDCAN_CKDIV left at /1). Each phase separately: the smallest prescaler
 * (finest quantum, as CiA 601-3 recommends) that makes the rate exactly (no
 * rounding: the oscillator tolerance of CAN FD is spent on the clock, not on
 * the timing) with the sample point within the fields' ranges; the sample
 * point the quantum nearest 87.5 % (nominal, CiA 301's value) or 75 % (data:
 * a short bit needs room after the sample point for the transceiver's loop
 * delay asymmetry); on a tie the later quantum. SJW = TSEG2 (the largest
 * resynchronisation the phase allows).
 *
 * Transmitter delay compensation (DBTP.TDC): in the data phase the
 * transmitter samples its own bit at a secondary sample point, the measured
 * TX->RX loop delay plus TDCR.TDCO; TDCO = the data sample point in kernel
 * clocks (DBRP x (1 + DTSEG1)), which must fit TDCO's 7 bits. TDCF = 0 (no
 * filter window).
 */
#include <stddef.h>

#include "fdcan.h"
#include "sq_status.h"

/* Field positions (fdcan_regs.h repeats them for the driver; this file also
 * builds on the host without the register header). */
#define NBTP_NTSEG2_SHIFT 0U
#define NBTP_NTSEG1_SHIFT 8U
#define NBTP_NBRP_SHIFT 16U
#define NBTP_NSJW_SHIFT 25U
#define DBTP_DSJW_SHIFT 0U
#define DBTP_DTSEG2_SHIFT 4U
#define DBTP_DTSEG1_SHIFT 8U
#define DBTP_DBRP_SHIFT 16U
#define DBTP_TDC (1U << 23)
#define TDCR_TDCO_SHIFT 8U
#define TDCO_MAX 127U

#define NOMINAL_MAX_BPS 1000000UL
#define DATA_MAX_BPS 8000000UL

typedef struct {
	uint32_t brp_max;
	uint32_t tq_min;
	uint32_t tq_max;
	uint32_t tseg1_min;
	uint32_t tseg1_max;
	uint32_t tseg2_min;
	uint32_t tseg2_max;
	uint32_t sample_permille;
} phase_limits_t;

typedef struct {
	uint32_t brp;
	uint32_t tq;
	uint32_t tseg1;
	uint32_t tseg2;
} phase_t;

/* Field widths of RM0440's FDCAN_NBTP and FDCAN_DBTP (value - 1 stored). */
static const phase_limits_t nominal_limits = { 512U, 8U, 385U, 2U, 256U, 2U, 128U, 875U };
static const phase_limits_t data_limits = { 32U, 5U, 49U, 2U, 32U, 1U, 16U, 750U };

static int phase_timing(uint32_t kernel_hz, uint32_t bps, const phase_limits_t *lim, phase_t *out)
{
	uint32_t clocks_per_bit;
	uint32_t brp;

	if ((kernel_hz % bps) != 0U) {
		return SQ_EINVAL; /* no exact rate with any prescaler */
	}
	clocks_per_bit = kernel_hz / bps;
	for (brp = 1U; brp <= lim->brp_max; brp++) {
		uint32_t tq;
		uint32_t sp_tq;

		if ((clocks_per_bit % brp) != 0U) {
			continue;
		}
		tq = clocks_per_bit / brp;
		if ((tq < lim->tq_min) || (tq > lim->tq_max)) {
			continue;
		}
		/* the nearest quantum, a tie to the later one */
		sp_tq = (lim->sample_permille * tq + 500U) / 1000U;
		if ((sp_tq < 1U + lim->tseg1_min) || (sp_tq > 1U + lim->tseg1_max) ||
		    ((tq - sp_tq) < lim->tseg2_min) || ((tq - sp_tq) > lim->tseg2_max)) {
			continue;
		}
		out->brp = brp;
		out->tq = tq;
		out->tseg1 = sp_tq - 1U;
		out->tseg2 = tq - sp_tq;
		return SQ_OK;
	}
	return SQ_EINVAL;
}

int fdcan_bit_timing(uint32_t kernel_hz, uint32_t nominal_bps, uint32_t data_bps, fdcan_timing_t *t)
{
	phase_t n;
	phase_t d;
	uint32_t tdco;

	if ((t == NULL) || (kernel_hz == 0U) || (nominal_bps == 0U) || (nominal_bps > NOMINAL_MAX_BPS) ||
	    (data_bps < nominal_bps) || (data_bps > DATA_MAX_BPS)) {
		return SQ_EINVAL;
	}
	if ((phase_timing(kernel_hz, nominal_bps, &nominal_limits, &n) != SQ_OK) ||
	    (phase_timing(kernel_hz, data_bps, &data_limits, &d) != SQ_OK)) {
		return SQ_EINVAL;
	}
	tdco = d.brp * (1U + d.tseg1);
	if (tdco > TDCO_MAX) {
		return SQ_EINVAL;
	}
	t->nbtp = ((n.tseg2 - 1U) << NBTP_NSJW_SHIFT) | ((n.brp - 1U) << NBTP_NBRP_SHIFT) |
		  ((n.tseg1 - 1U) << NBTP_NTSEG1_SHIFT) | ((n.tseg2 - 1U) << NBTP_NTSEG2_SHIFT);
	t->dbtp = DBTP_TDC | ((d.brp - 1U) << DBTP_DBRP_SHIFT) | ((d.tseg1 - 1U) << DBTP_DTSEG1_SHIFT) |
		  ((d.tseg2 - 1U) << DBTP_DTSEG2_SHIFT) | ((d.tseg2 - 1U) << DBTP_DSJW_SHIFT);
	t->tdcr = tdco << TDCR_TDCO_SHIFT;
	t->nominal_tq = n.tq;
	t->data_tq = d.tq;
	t->tdco_mtq = tdco;
	return SQ_OK;
}
