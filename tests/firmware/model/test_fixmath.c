/* SPDX-License-Identifier: MIT */
/*
 * firmware/model/fixmath.c (fixed build only) against the C library's long
 * double log/exp/expm1, an independent implementation, at the accuracy
 * fixmath.h documents. The model's golden-vector tests allow 1e-3 relative
 * error and cannot see a fixmath change that costs a few digits (make mutate
 * found two: the ln range reduction and the exp underflow threshold).
 *   - fx_ln_u64: absolute error <= 1e-8 over random 64-bit arguments and
 *     several Q formats (fixmath.h says ~1e-9; measured up to 3.7e-9; a
 *     wrong range reduction costs 1e-7);
 *   - fx_exp_q32_to_i64 / _i32: within 0.5 LSB plus 1e-6 relative (measured
 *     4.9e-7 for large results), down to results of 0..3 LSB where the
 *     rounding, not the series, decides; saturation and underflow. Results
 *     of 2^62 and more are left out: the function saturates from 2^62 on
 *     (shift >= 32), one bit before INT64_MAX (conservative; reported);
 *   - fx_expm1_small_q30 on [0, 1): within 4 LSB of Q30.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <math.h>
#include <stdlib.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "fixmath.h"

static uint64_t rng_state = 0x9E3779B97F4A7C15ULL;

static uint64_t rng(void) /* xorshift64* */
{
	rng_state ^= rng_state >> 12;
	rng_state ^= rng_state << 25;
	rng_state ^= rng_state >> 27;
	return rng_state * 0x2545F4914F6CDD1DULL;
}

static void check_ln(uint64_t x, int32_t frac_bits)
{
	const long double want = logl((long double)x) - (long double)frac_bits * logl(2.0L);
	const long double got = (long double)fx_ln_u64(x, frac_bits) / 4294967296.0L;

	if (fabsl(got - want) > 1e-8L) {
		fail_msg("ln(%llu / 2^%d): %.12Lf, libm %.12Lf", (unsigned long long)x, frac_bits,
			 got, want);
	}
}

static void test_ln_against_libm(void **state)
{
	static const int32_t qs[] = { 0, 16, 30, 32, 62 };

	(void)state;
	for (size_t q = 0; q < sizeof(qs) / sizeof(qs[0]); q++) {
		for (uint32_t n = 0U; n < 64U; n++) {
			const uint64_t p = (uint64_t)1 << n;

			check_ln(p, qs[q]);
			check_ln(p + (p >> 1), qs[q]);      /* 1.5: near the sqrt2 split */
			check_ln(p + (p >> 2) + (p >> 3), qs[q]); /* 1.375 */
			if (n > 0U) {
				check_ln(p - 1U, qs[q]);
			}
		}
		for (uint32_t i = 0U; i < 20000U; i++) {
			const uint64_t x = rng() >> (rng() % 64U);

			if (x != 0U) {
				check_ln(x, qs[q]);
			}
		}
	}
	assert_true(fx_ln_u64(0U, 0) == INT64_MIN / 2);
}

static void check_exp(int64_t y_q32, int32_t q_out)
{
	bool sat = true;
	const long double want = expl((long double)y_q32 / 4294967296.0L) * ldexpl(1.0L, q_out);
	const int64_t got = fx_exp_q32_to_i64(y_q32, q_out, &sat);

	if (want >= 4.6e18L) {
		return; /* 2^62 and more: saturation, tested separately */
	}
	assert_false(sat);
	if (fabsl((long double)got - want) > 0.5L + 1e-6L * want) {
		fail_msg("e^(%lld/2^32) in Q%d: %lld, libm %.3Lf", (long long)y_q32, q_out,
			 (long long)got, want);
	}
}

static void test_exp_against_libm(void **state)
{
	static const int32_t qs[] = { 0, 16, 30, 32, 48 };

	(void)state;
	for (size_t q = 0; q < sizeof(qs) / sizeof(qs[0]); q++) {
		/* results of about 0.3 .. 3 LSB: y = ln(t / 2^q) */
		for (uint32_t t = 1U; t <= 30U; t++) {
			const long double y = logl((long double)t / 10.0L) - (long double)qs[q] * logl(2.0L);

			check_exp((int64_t)llroundl(y * 4294967296.0L), qs[q]);
		}
		for (uint32_t i = 0U; i < 20000U; i++) {
			/* y in [-60, 40) */
			const int64_t y = (int64_t)(rng() % (100ULL << 32)) - (60LL << 32);

			check_exp(y, qs[q]);
		}
	}
}

static void test_exp_saturation_and_underflow(void **state)
{
	bool sat = false;

	(void)state;
	assert_int_equal(fx_exp_q32_to_i64(50LL << 32, 0, &sat), INT64_MAX); /* e^50 > 2^63 */
	assert_true(sat);
	sat = false;
	assert_int_equal(fx_exp_q32_to_i32(22LL << 32, 0, &sat), INT32_MAX); /* e^22 > 2^31 */
	assert_true(sat);
	sat = true;
	/* e^21 = 1318815734.48 */
	assert_true(labs((long)fx_exp_q32_to_i32(21LL << 32, 0, &sat) - 1318815734L) <= 2L);
	assert_false(sat);
	sat = true;
	assert_int_equal(fx_exp_q32_to_i64(-50LL * 4294967296LL, 0, &sat), 0); /* underflow, no sat */
	assert_false(sat);
}

static void test_expm1_small(void **state)
{
	(void)state;
	for (uint32_t i = 0U; i <= 4096U; i++) {
		const int64_t y = (int64_t)(((uint64_t)i << 32) / 4096U) - (i == 4096U ? 1 : 0);
		const long double want = expm1l((long double)y / 4294967296.0L) * 1073741824.0L;
		const uint32_t got = fx_expm1_small_q30(y);

		if (fabsl((long double)got - want) > 4.0L) {
			fail_msg("expm1(%lld/2^32) in Q30: %u, libm %.2Lf", (long long)y, got, want);
		}
	}
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_ln_against_libm),
	cmocka_unit_test(test_exp_against_libm),
	cmocka_unit_test(test_exp_saturation_and_underflow),
	cmocka_unit_test(test_expm1_small))
