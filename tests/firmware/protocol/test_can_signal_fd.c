/* SPDX-License-Identifier: MIT */
/*
 * can_signal on CAN FD frames (firmware/protocol/can_signal.c): signals at
 * high start bits of 24-, 48- and 64-byte frames, Intel and Motorola,
 * signed and unsigned, up to 32 bits and up to the frame's last bit.
 *
 * Every expected raw value, sign-extended value and encoded frame comes
 * from canmatrix reading tests/firmware/protocol/fixtures/fd_signals.dbc
 * (gen_can_signal_fd.py -> can_signal_fd_ref.h at build time); the
 * descriptor lengths and overlaps below are derived by hand from the DBC
 * bit numbering (bit j of byte i is 8 i + j).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "can_signal.h"
#include "can_signal_fd_ref.h"

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))

static can_signal_t desc_of(const fd_sig_ref_t *r)
{
	return (can_signal_t){ r->start_bit, r->length,
			       r->motorola ? (uint8_t)CAN_SIGNAL_MOTOROLA : (uint8_t)CAN_SIGNAL_INTEL,
			       r->is_signed };
}

static can_signal_t sig(uint16_t start, uint8_t len, uint8_t order)
{
	return (can_signal_t){ start, len, order, 0U };
}

/* Every fixture signal is a valid descriptor within its frame's length. */
static void test_fixture_descriptors_valid(void **state)
{
	size_t i;

	(void)state;
	assert_true(N_OF(fd_sigs) >= 12U);
	for (i = 0; i < N_OF(fd_sigs); i++) {
		const can_signal_t s = desc_of(&fd_sigs[i]);

		if (!can_signal_valid(&s) || (can_signal_min_dlc(&s) > fd_sigs[i].frame_len)) {
			fail_msg("%s: min_dlc %u, frame %u", fd_sigs[i].name, can_signal_min_dlc(&s),
				 fd_sigs[i].frame_len);
		}
	}
}

/* min_dlc by hand: the byte of the last bit (Intel MSB, Motorola LSB) + 1. */
static void test_min_dlc_by_hand(void **state)
{
	const can_signal_t wheel = sig(64, 14, CAN_SIGNAL_INTEL);      /* 64..77: byte 9 */
	const can_signal_t moto = sig(335, 16, CAN_SIGNAL_MOTOROLA);   /* 335..328, 343..336 */
	const can_signal_t top = sig(511, 1, CAN_SIGNAL_INTEL);        /* byte 63 */
	const can_signal_t moto_end = sig(498, 11, CAN_SIGNAL_MOTOROLA); /* 498..496, 511..504 */
	const can_signal_t intel32 = sig(480, 32, CAN_SIGNAL_INTEL);   /* 480..511 */

	(void)state;
	assert_int_equal(can_signal_min_dlc(&wheel), 10);
	assert_int_equal(can_signal_min_dlc(&moto), 43);
	assert_int_equal(can_signal_min_dlc(&top), 64);
	assert_int_equal(can_signal_min_dlc(&moto_end), 64);
	assert_int_equal(can_signal_min_dlc(&intel32), 64);
}

/* Beyond bit 511: refused, never read. */
static void test_beyond_the_fd_frame(void **state)
{
	const can_signal_t start512 = sig(512, 1, CAN_SIGNAL_INTEL);
	const can_signal_t intel_out = sig(481, 32, CAN_SIGNAL_INTEL);     /* ends at 512 */
	const can_signal_t moto_out = sig(499, 13, CAN_SIGNAL_MOTOROLA);   /* 499..496, 511..504, then byte 64 */
	const can_signal_t moto_in = sig(499, 12, CAN_SIGNAL_MOTOROLA);    /* ends at bit 504 */
	const can_signal_t huge = sig(0xFFFF, 8, CAN_SIGNAL_INTEL);

	(void)state;
	assert_false(can_signal_valid(&start512));
	assert_false(can_signal_valid(&intel_out));
	assert_false(can_signal_valid(&moto_out));
	assert_false(can_signal_valid(&huge));
	assert_int_equal(can_signal_min_dlc(&moto_in), 64);
}

/* Overlaps at the end of the frame, derived from the bit numbers. */
static void test_overlap_high_bits(void **state)
{
	const can_signal_t moto_byte63 = sig(511, 8, CAN_SIGNAL_MOTOROLA); /* 511..504 */
	const can_signal_t intel_504 = sig(504, 1, CAN_SIGNAL_INTEL);
	const can_signal_t intel_500 = sig(500, 4, CAN_SIGNAL_INTEL);      /* 500..503 */
	const can_signal_t moto_cross = sig(496, 9, CAN_SIGNAL_MOTOROLA);  /* 496, then 511..504 */
	const can_signal_t intel_497 = sig(497, 7, CAN_SIGNAL_INTEL);      /* 497..503 */

	(void)state;
	assert_true(can_signal_overlap(&moto_byte63, &intel_504));
	assert_true(can_signal_overlap(&intel_504, &moto_byte63));
	assert_false(can_signal_overlap(&moto_byte63, &intel_500));
	assert_true(can_signal_overlap(&moto_cross, &moto_byte63));
	assert_false(can_signal_overlap(&moto_cross, &intel_497));
	assert_false(can_signal_overlap(&intel_497, &moto_cross));
}

/* No two signals of one fixture message share a bit (the DBC's layout). */
static void test_fixture_signals_disjoint(void **state)
{
	size_t i;
	size_t j;

	(void)state;
	for (i = 0; i < N_OF(fd_sigs); i++) {
		for (j = 0; j < N_OF(fd_sigs); j++) {
			const can_signal_t a = desc_of(&fd_sigs[i]);
			const can_signal_t b = desc_of(&fd_sigs[j]);

			if ((i != j) && (fd_sigs[i].frame_len == fd_sigs[j].frame_len) &&
			    can_signal_overlap(&a, &b)) {
				fail_msg("%s overlaps %s", fd_sigs[i].name, fd_sigs[j].name);
			}
		}
	}
}

/* Every signal of every random frame: canmatrix's raw and value. */
static void test_get_equals_canmatrix(void **state)
{
	size_t i;

	(void)state;
	assert_true(N_OF(fd_decoded) >= 500U);
	for (i = 0; i < N_OF(fd_decoded); i++) {
		const fd_dec_ref_t *d = &fd_decoded[i];
		const can_signal_t s = desc_of(&fd_sigs[d->sig]);
		const uint32_t raw = can_signal_get(&s, fd_frames[d->frame]);

		if ((raw != d->raw) || (can_signal_value(&s, raw) != d->value)) {
			fail_msg("frame %u %s: raw 0x%X value %lld, canmatrix 0x%X %lld", d->frame,
				 fd_sigs[d->sig].name, raw, (long long)can_signal_value(&s, raw), d->raw,
				 (long long)d->value);
		}
	}
}

/* put into a zero frame: canmatrix's encoding, byte for byte, all 64. */
static void test_put_equals_canmatrix(void **state)
{
	size_t i;

	(void)state;
	for (i = 0; i < N_OF(fd_puts); i++) {
		const fd_put_ref_t *p = &fd_puts[i];
		const can_signal_t s = desc_of(&fd_sigs[p->sig]);
		uint8_t data[CAN_SIGNAL_MAX_BYTES] = { 0 };

		can_signal_put(&s, data, p->raw);
		if (memcmp(data, p->data, sizeof(data)) != 0) {
			fail_msg("%s = 0x%X: encoded differently from canmatrix", fd_sigs[p->sig].name,
				 p->raw);
		}
		assert_int_equal(can_signal_get(&s, data), p->raw);
	}
}

/* put keeps every other bit: writing one signal of a random frame leaves
 * canmatrix's values of the others. */
static void test_put_keeps_other_signals(void **state)
{
	size_t i;
	size_t j;

	(void)state;
	for (i = 0; i < N_OF(fd_decoded); i++) {
		const fd_dec_ref_t *d = &fd_decoded[i];
		const can_signal_t s = desc_of(&fd_sigs[d->sig]);
		uint8_t data[CAN_SIGNAL_MAX_BYTES];

		memcpy(data, fd_frames[d->frame], sizeof(data));
		can_signal_put(&s, data, ~d->raw);
		for (j = 0; j < N_OF(fd_decoded); j++) {
			const fd_dec_ref_t *o = &fd_decoded[j];
			const can_signal_t t = desc_of(&fd_sigs[o->sig]);

			if ((o->frame == d->frame) && (o->sig != d->sig)) {
				assert_int_equal(can_signal_get(&t, data), o->raw);
			}
		}
	}
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_fixture_descriptors_valid),
	cmocka_unit_test(test_min_dlc_by_hand),
	cmocka_unit_test(test_beyond_the_fd_frame),
	cmocka_unit_test(test_overlap_high_bits),
	cmocka_unit_test(test_fixture_signals_disjoint),
	cmocka_unit_test(test_get_equals_canmatrix),
	cmocka_unit_test(test_put_equals_canmatrix),
	cmocka_unit_test(test_put_keeps_other_signals))
