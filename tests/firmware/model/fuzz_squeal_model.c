/* SPDX-License-Identifier: MIT */
/*
 * fuzz_model: squeal_model_classify() with arbitrary bit patterns in every
 * field of squeal_params_t and squeal_point_t (float build: any float incl.
 * NaN, infinities, subnormals, -0; fixed build: any int32) and any criterion
 * value. Built twice (fuzz_model_float, fuzz_model_fixed).
 *
 * Input: 8 little-endian 32-bit words (mass, omega0, damping, mu_inf,
 * delta_mu, slope, v0, force) then one byte for the criterion.
 *
 * Properties (squeal_model.h):
 *   - the return code is SQ_OK or SQ_EINVAL, and SQ_OK iff state != INVALID;
 *   - the state is one of the five documented values;
 *   - INVALID: no flags, every value 0; INVALID iff params or point is
 *     outside the domain or the criterion unknown (params_check agrees);
 *   - only known flag bits; every SAT bit comes with its HAS bit; a field
 *     whose HAS bit is clear is 0; every float field is finite;
 *   - basin ratio < 1 exactly when bistable (BISTABLE always has a basin);
 *   - UNSTABLE: ln Q <= ln 1/2 (lq2 <= 0), no cycle; BISTABLE/STABLE with a
 *     cycle: Q > 1/2;
 *   - pure: a second call gives the same bytes; NULL pointers give SQ_EINVAL
 *     without touching the output.
 */
#include "fuzz_common.h"

#include "squeal_model.h"

#if defined(SQUEAL_NUMERIC_FIXED)
#define RATIO_ONE ((squeal_num_t)1 << SQUEAL_Q_RATIO)
#define IS_FINITE(x) ((void)(x), 1)
#else
#define RATIO_ONE 1.0f
#define IS_FINITE(x) (((x) == (x)) && ((x) - (x) == 0.0f))
#endif

static squeal_num_t num_from(fuzz_in_t *in)
{
	const uint32_t bits = fuzz_u32(in);
	squeal_num_t v;

	_Static_assert(sizeof(v) == sizeof(bits), "32-bit numbers");
	memcpy(&v, &bits, sizeof(v));
	return v;
}

#define KNOWN_FLAGS (SQUEAL_HAS_LNQ | SQUEAL_HAS_HOPF_V0 | SQUEAL_HAS_HOPF_FORCE | \
		     SQUEAL_HAS_CYCLE | SQUEAL_HAS_BASIN | SQUEAL_SAT_HOPF_V0 |     \
		     SQUEAL_SAT_HOPF_FORCE | SQUEAL_SAT_CYCLE_X |                   \
		     SQUEAL_SAT_AMPLITUDE | SQUEAL_SAT_TRIGGER | SQUEAL_SAT_BASIN)

static void check_result(int rc, const squeal_result_t *r, int params_ok,
			 int criterion_ok)
{
	const uint32_t f = r->flags;

	FUZZ_REQUIRE((rc == SQ_OK) || (rc == SQ_EINVAL));
	FUZZ_REQUIRE((r->state == SQUEAL_STATE_STABLE) ||
		     (r->state == SQUEAL_STATE_BISTABLE) ||
		     (r->state == SQUEAL_STATE_UNSTABLE) ||
		     (r->state == SQUEAL_STATE_NOT_SLIDING) ||
		     (r->state == SQUEAL_STATE_INVALID));
	FUZZ_REQUIRE((rc == SQ_OK) == (r->state != SQUEAL_STATE_INVALID));
	if (!params_ok || !criterion_ok) {
		FUZZ_REQUIRE(r->state == SQUEAL_STATE_INVALID);
	}
	FUZZ_REQUIRE((f & ~(uint32_t)KNOWN_FLAGS) == 0U);
	if ((r->state == SQUEAL_STATE_INVALID) || (r->state == SQUEAL_STATE_NOT_SLIDING)) {
		FUZZ_REQUIRE(f == 0U);
	}
	/* SAT implies HAS */
	if ((f & SQUEAL_SAT_HOPF_V0) != 0U) {
		FUZZ_REQUIRE((f & SQUEAL_HAS_HOPF_V0) != 0U);
	}
	if ((f & SQUEAL_SAT_HOPF_FORCE) != 0U) {
		FUZZ_REQUIRE((f & SQUEAL_HAS_HOPF_FORCE) != 0U);
	}
	if ((f & (SQUEAL_SAT_CYCLE_X | SQUEAL_SAT_AMPLITUDE | SQUEAL_SAT_TRIGGER)) != 0U) {
		FUZZ_REQUIRE((f & SQUEAL_HAS_CYCLE) != 0U);
	}
	if ((f & SQUEAL_SAT_BASIN) != 0U) {
		FUZZ_REQUIRE((f & SQUEAL_HAS_BASIN) != 0U);
	}
	/* no HAS: the field is 0 */
	if ((f & SQUEAL_HAS_LNQ) == 0U) {
		FUZZ_REQUIRE(r->ln_q == 0);
	}
	if ((f & SQUEAL_HAS_HOPF_V0) == 0U) {
		FUZZ_REQUIRE((r->hopf_v0_mps == 0) && (r->hopf_margin_mps == 0));
	}
	if ((f & SQUEAL_HAS_HOPF_FORCE) == 0U) {
		FUZZ_REQUIRE(r->hopf_force_n == 0);
	}
	if ((f & SQUEAL_HAS_CYCLE) == 0U) {
		FUZZ_REQUIRE((r->cycle_x == 0) && (r->lc_amplitude_um == 0) &&
			     (r->trigger_velocity_mps == 0));
	}
	if ((f & SQUEAL_HAS_BASIN) == 0U) {
		FUZZ_REQUIRE(r->basin_ratio == 0);
	}
	FUZZ_REQUIRE(IS_FINITE(r->ln_q) && IS_FINITE(r->hopf_v0_mps) &&
		     IS_FINITE(r->hopf_margin_mps) && IS_FINITE(r->hopf_force_n) &&
		     IS_FINITE(r->cycle_x) && IS_FINITE(r->lc_amplitude_um) &&
		     IS_FINITE(r->trigger_velocity_mps) && IS_FINITE(r->basin_ratio));
	/* the basin ratio decides bistable vs stable */
	if (r->state == SQUEAL_STATE_BISTABLE) {
		FUZZ_REQUIRE((f & SQUEAL_HAS_BASIN) != 0U);
		FUZZ_REQUIRE(r->basin_ratio < RATIO_ONE);
		FUZZ_REQUIRE(r->basin_ratio > 0);
	} else if ((f & SQUEAL_HAS_BASIN) != 0U) {
		FUZZ_REQUIRE(r->state == SQUEAL_STATE_STABLE);
		FUZZ_REQUIRE(r->basin_ratio >= RATIO_ONE);
	}
	/* a cycle exists exactly for Q > 1/2 with falling friction; the
	 * unstable state has none */
	if (r->state == SQUEAL_STATE_UNSTABLE) {
		FUZZ_REQUIRE((f & (SQUEAL_HAS_CYCLE | SQUEAL_HAS_BASIN)) == 0U);
		FUZZ_REQUIRE((f & SQUEAL_HAS_LNQ) != 0U);
	}
	if ((f & SQUEAL_HAS_CYCLE) != 0U) {
		FUZZ_REQUIRE((f & SQUEAL_HAS_BASIN) != 0U);
		/* >= 0, not > 0: in the fixed build x = 4 sqrt(Q - 1/2) rounds
		 * to 0 in Q20 when Q is within ~1e-12 of 1/2 */
		FUZZ_REQUIRE(r->cycle_x >= 0);
	}
	if ((f & SQUEAL_HAS_HOPF_V0) != 0U) {
		/* >= 0: a border below one LSB (2^-20 m/s in the fixed build)
		 * rounds to 0 */
		FUZZ_REQUIRE(r->hopf_v0_mps >= 0);
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	fuzz_in_t in = { data, size };
	squeal_params_t p;
	squeal_point_t pt;
	squeal_criterion_t crit;
	squeal_result_t r1;
	squeal_result_t r2;
	int rc1;
	int rc2;
	int params_ok;
	int crit_ok;

	p.mass_kg = num_from(&in);
	p.omega0_radps = num_from(&in);
	p.damping = num_from(&in);
	p.mu_inf = num_from(&in);
	p.delta_mu = num_from(&in);
	p.slope_spm = num_from(&in);
	pt.v0_mps = num_from(&in);
	pt.force_n = num_from(&in);
	/* 0 exact, 1 cubic, anything else must be refused; values beyond the
	 * enumerators are still values of its (int-compatible) type */
	crit = (squeal_criterion_t)(fuzz_u8(&in) % 4U);

	params_ok = (squeal_model_params_check(&p) == SQ_OK);
	crit_ok = (crit == SQUEAL_CRITERION_EXACT) || (crit == SQUEAL_CRITERION_CUBIC);

	memset(&r1, 0xA5, sizeof(r1));
	memset(&r2, 0x5A, sizeof(r2));
	rc1 = squeal_model_classify(&p, &pt, crit, &r1);
	rc2 = squeal_model_classify(&p, &pt, crit, &r2);
	check_result(rc1, &r1, params_ok, crit_ok);
	/* pure and fully written: the same output whatever was there before */
	FUZZ_REQUIRE(rc1 == rc2);
	FUZZ_REQUIRE(memcmp(&r1, &r2, sizeof(r1)) == 0);

	/* (NULL pointers are programming errors: the contract handler, checked
	 * in tests/firmware/model/test_squeal_model.c) */
	return 0;
}
