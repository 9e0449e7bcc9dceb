/* SPDX-License-Identifier: MIT */
/*
 * host-sim/decode_inputs.c on the fixture layout tests/host-sim/two_corners.cal
 * (run from the top of the checkout, as make test does): each input of a
 * frame in text and CSV, the corner's view of it, a short frame, and the
 * frames this build cannot hold, against lines written out by hand:
 *   WS_FL 3600 * 0.01 = 36 km/h = 10 m/s vehicle, v0 = 10 * 0.15 / 0.3 = 5;
 *   WS_FR 6000 * 0.1 = 600 rpm = 20 pi rad/s, v0 = 0.15 * 20 pi = 9.424778;
 *   P_FL 1000 * 0.1 - 10 = 90 bar on 2000 mm^2 at eta 0.8 = 14400 N;
 *   T_FR 500 Nm, half of it on FR: 250 / (2 faces * mu * 0.15 m) with
 *   mu = 0.3 + 0.2 exp(-9.424778) (FR's last v0) = 2777.628 N.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "decode_inputs.h"
#include "sq_cmocka.h"

#define FIXTURE "tests/host-sim/two_corners.cal"

static decode_inputs_t d; /* large: not on the stack */

static void feed(const char *line, bool csv, char *out, size_t size)
{
	candump_frame_t f;
	FILE *mem;

	memset(out, 0, size); /* fmemopen leaves the buffer as it was when nothing is written */
	mem = fmemopen(out, size, "w");
	assert_non_null(mem);
	assert_int_equal(candump_parse_line(line, strlen(line), &f, NULL, NULL), CANDUMP_LINE_FRAME);
	decode_inputs_frame(&d, &f, csv, mem);
	assert_int_equal(fclose(mem), 0);
}

static void test_load(void **state)
{
	(void)state;
	assert_int_equal(decode_inputs_load(&d, FIXTURE), 0);
	assert_int_equal(d.n_inputs, 4);
	assert_int_equal(d.n_corners, 2);
	assert_string_equal(d.names.input[0], "WS_FL");
	assert_string_equal(d.names.input[3], "T_FR");
	assert_int_equal(decode_inputs_load(&d, "/nonexistent/x.cal"), -1);
}

static void test_text_lines(void **state)
{
	char out[512];
	double force_n = 0.0;
	const double mu = 0.3 + 0.2 * exp(-0.15 * 20.0 * M_PI);

	(void)state;
	assert_int_equal(decode_inputs_load(&d, FIXTURE), 0);
	feed("(1.000000) can0 120#100E7017", false, out, sizeof(out));
	assert_string_equal(out,
			    "  WS_FL raw=3600 phys=36 km/h valid=1 reason=ok FL:v0_mps=5.000000\n"
			    "  WS_FR raw=6000 phys=600 rpm valid=1 reason=ok FR:v0_mps=9.424778\n");
	feed("(1.010000) can0 130#E803", false, out, sizeof(out));
	assert_string_equal(out, "  P_FL raw=1000 phys=90 bar valid=1 reason=ok FL:force_N=14400.000\n");
	feed("(1.010000) can0 00000140#00F401", false, out, sizeof(out));
	assert_int_equal(strncmp(out, "  T_FR raw=500 phys=500 Nm valid=1 reason=ok FR:force_N=", 56), 0);
	force_n = strtod(out + 56, NULL);
	/* the firmware's fixed-point conversion: within 5 mN */
	assert_true(fabs(force_n - 250.0 / (2.0 * mu * 0.15)) <= 0.005);
	/* a frame of an identifier no input uses: nothing */
	feed("(1.020000) can0 123#00", false, out, sizeof(out));
	assert_string_equal(out, "");
	/* an extended frame on a standard input's identifier: not that input */
	feed("(1.020000) can0 00000130#E803", false, out, sizeof(out));
	assert_string_equal(out, "");
	/* one byte where P_FL needs two: no value, reason dlc */
	feed("(1.020000) can0 130#E8", false, out, sizeof(out));
	assert_string_equal(out, "  P_FL valid=0 reason=dlc\n");
}

static void test_csv_rows(void **state)
{
	char out[512];

	(void)state;
	assert_int_equal(decode_inputs_load(&d, FIXTURE), 0);
	{
		FILE *mem = fmemopen(out, sizeof(out), "w");

		assert_non_null(mem);
		decode_inputs_csv_header(mem);
		assert_int_equal(fclose(mem), 0);
		assert_string_equal(out, "t_s,iface,id,input,raw,physical,unit,valid,reason\n");
	}
	feed("(12.345678) can1 120#100E7017", true, out, sizeof(out));
	assert_string_equal(out, "12.345678,can1,120,WS_FL,3600,36,km/h,1,ok\n"
				 "12.345678,can1,120,WS_FR,6000,600,rpm,1,ok\n");
	feed("(12.355678) can1 00000140#00F401", true, out, sizeof(out));
	assert_string_equal(out, "12.355678,can1,00000140,T_FR,500,500,Nm,1,ok\n");
	feed("(12.365678) can1 130#E8", true, out, sizeof(out));
	assert_string_equal(out, "12.365678,can1,130,P_FL,,,bar,0,dlc\n");
}

static void test_frames_this_build_cannot_hold(void **state)
{
	char out[512];
	char want[200];
	FILE *mem;

	(void)state;
	assert_int_equal(decode_inputs_load(&d, FIXTURE), 0);
	memset(out, 0, sizeof(out));
	mem = fmemopen(out, sizeof(out), "w");
	assert_non_null(mem);
	decode_inputs_summary(&d, mem); /* none yet: nothing said */
	assert_int_equal(fclose(mem), 0);
	assert_string_equal(out, "");
	feed("(1.000000) can0 45120#81:00:12345678#00112233", false, out, sizeof(out));
	assert_string_equal(out, "");
	assert_int_equal(d.skipped_xl, 1);
	assert_int_equal(d.skipped_fd, 0);
	mem = fmemopen(out, sizeof(out), "w");
	assert_non_null(mem);
	decode_inputs_summary(&d, mem);
	assert_int_equal(fclose(mem), 0);
	snprintf(want, sizeof(want),
		 "squeal-sim decode: 1 frames not decoded as inputs (CAN XL 1, CAN FD longer than "
		 "this build's %u-byte frames 0)\n", (unsigned)HAL_CAN_MAX_DLEN);
	assert_string_equal(out, want);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_load),
	cmocka_unit_test(test_text_lines),
	cmocka_unit_test(test_csv_rows),
	cmocka_unit_test(test_frames_this_build_cannot_hold))
