/* SPDX-License-Identifier: MIT */
/*
 * gen_seeds: writes the seed corpora of the fuzz targets into
 * DIR/<target>/seed-NNN (run by gen-seeds.sh; the result is committed).
 * Seeds are well-formed inputs made with the firmware's own encoders, so
 * the fuzzer starts from the interesting paths (valid E2E, valid blocks,
 * every model state) and mutates from there.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "calib.h"
#include "calib_text.h"
#include "candump_log.h"
#include "e2e_p01.h"
#include "sq_status.h"
#include "squeal_msgs.h"

static const char *out_dir;

static void write_seed(const char *target, unsigned int n, const uint8_t *p, size_t len)
{
	char path[512];
	FILE *f;

	(void)snprintf(path, sizeof(path), "%s/%s/seed-%03u", out_dir, target, n);
	f = fopen(path, "wb");
	if ((f == NULL) || (fwrite(p, 1U, len, f) != len) || (fclose(f) != 0)) {
		(void)fprintf(stderr, "gen_seeds: cannot write %s\n", path);
		exit(1);
	}
}

/* ---- buffer helper ------------------------------------------------------ */
typedef struct {
	uint8_t b[4096];
	size_t n;
} buf_t;

static void put8(buf_t *b, uint32_t v)
{
	if (b->n < sizeof(b->b)) {
		b->b[b->n++] = (uint8_t)v;
	}
}

static void put16(buf_t *b, uint32_t v)
{
	put8(b, v & 0xFFU);
	put8(b, (v >> 8) & 0xFFU);
}

static void put32(buf_t *b, uint32_t v)
{
	put16(b, v & 0xFFFFU);
	put16(b, v >> 16);
}

/* ---- model -------------------------------------------------------------- */
typedef struct {
	double m, w0, d, mu_inf, dmu, a, v0, n;
	uint8_t crit;
} model_case_t;

static const model_case_t model_cases[] = {
	/* the paper's brake (docs/model.md section 8) at several points */
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 2.0, 0.0, 0.0, 0 },      /* not sliding */
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 2.0, 10.0, 0.0, 0 },     /* no force */
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 2.0, 0.5, 4000.0, 0 },   /* unstable */
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 2.0, 2.0, 3000.0, 0 },   /* bistable */
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 2.0, 2.0, 3000.0, 1 },   /* cubic */
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 2.0, 8.0, 2000.0, 0 },   /* stable */
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 2.0, 8.0, 2000.0, 1 },
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 0.0, 8.0, 2000.0, 0 },   /* slope 0 */
	{ 1.0, 5000.0, 0.023, 0.25, -0.15, 2.0, 8.0, 2000.0, 0 },  /* rising mu */
	{ 10000.0, 500000.0, 1.0, 1.5, 1.5, 20.0, 100.0, 500000.0, 0 }, /* maxima */
	{ 1e-4, 1e-3, 1e-6, 0.0, 1e-6, 1e-6, 1e-6, 1e-3, 0 },     /* tiny */
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 2.0, 100.0, 1.0, 1 },    /* huge Q */
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 2.0, 101.0, 2000.0, 0 }, /* v0 out */
	{ 1.0, 5000.0, 0.023, 0.25, 0.15, 2.0, 2.0, 3000.0, 2 },   /* bad crit */
};

#define N_MODEL (sizeof(model_cases) / sizeof(model_cases[0]))

static uint32_t float_bits(double v)
{
	const float f = (float)v;
	uint32_t u;

	memcpy(&u, &f, sizeof(u));
	return u;
}

static uint32_t q_bits(double v, int q)
{
	const double s = v * (double)(1LL << q);
	const double lim = 2147483647.0;

	return (uint32_t)(int32_t)((s > lim) ? lim : ((s < -lim) ? -lim : s));
}

static void seeds_model(void)
{
	unsigned int i;

	for (i = 0U; i < N_MODEL; i++) {
		const model_case_t *c = &model_cases[i];
		buf_t fb = { { 0 }, 0U };
		buf_t xb = { { 0 }, 0U };

		put32(&fb, float_bits(c->m));
		put32(&fb, float_bits(c->w0));
		put32(&fb, float_bits(c->d));
		put32(&fb, float_bits(c->mu_inf));
		put32(&fb, float_bits(c->dmu));
		put32(&fb, float_bits(c->a));
		put32(&fb, float_bits(c->v0));
		put32(&fb, float_bits(c->n));
		put8(&fb, c->crit);
		write_seed("fuzz_model_float", i, fb.b, fb.n);

		put32(&xb, q_bits(c->m, 16));
		put32(&xb, q_bits(c->w0, 12));
		put32(&xb, q_bits(c->d, 30));
		put32(&xb, q_bits(c->mu_inf, 30));
		put32(&xb, q_bits(c->dmu, 30));
		put32(&xb, q_bits(c->a, 24));
		put32(&xb, q_bits(c->v0, 20));
		put32(&xb, q_bits(c->n, 12));
		put8(&xb, c->crit);
		write_seed("fuzz_model_fixed", i, xb.b, xb.n);
	}
	/* NaN and infinities in the float build */
	{
		buf_t b = { { 0 }, 0U };
		uint32_t k;

		for (k = 0U; k < 8U; k++) {
			put32(&b, (k & 1U) ? 0x7FC00000U : 0x7F800000U);
		}
		put8(&b, 0U);
		write_seed("fuzz_model_float", (unsigned int)N_MODEL, b.b, b.n);
	}
}

/* ---- messages ----------------------------------------------------------- */
/* A protected frame of message k: one fuzz_msgs record [mode, dlc, 8 bytes]. */
static void msg_record(buf_t *b, uint32_t k, const uint8_t *packed, e2e_p01_tx_t *tx)
{
	const msg_desc_t *d = &msg_table[k];
	const e2e_p01_config_t cfg = { d->data_id, d->dlc, 1U };
	uint8_t f[8];
	uint32_t i;

	memcpy(f, packed, 8U);
	if (e2e_p01_protect(&cfg, tx, f, d->dlc) != SQ_OK) {
		exit(1);
	}
	put8(b, 0x20U | k); /* own DLC, CRC as it is */
	put8(b, d->dlc);
	for (i = 0U; i < 8U; i++) {
		put8(b, f[i]);
	}
}

static void packed_msg(uint32_t k, uint32_t v, uint8_t out[8])
{
	uint8_t dlc = 0U;
	int rc;

	memset(out, 0, 8U);
	switch (msg_table[k].id) {
	case MSG_DISC_SPEED_ID: {
		const msg_disc_speed_t m = { 0U, 0U, (uint16_t)v };

		rc = msg_disc_speed_pack(&m, out, &dlc);
		break;
	}
	case MSG_PAD_FORCE_ID: {
		const msg_pad_force_t m = { 0U, 0U, (uint16_t)v };

		rc = msg_pad_force_pack(&m, out, &dlc);
		break;
	}
	case MSG_SQUEAL_STATUS_ID: {
		const msg_squeal_status_t m = { 0U, 0U, (uint8_t)(v % 4U), (uint8_t)(v % 4U),
						(uint16_t)(v % 10001U), (int16_t)(v % 1000U),
						(uint8_t)(v % 256U) };

		rc = msg_squeal_status_pack(&m, out, &dlc);
		break;
	}
	case MSG_SQUEAL_DETAIL_ID: {
		const msg_squeal_detail_t m = { 0U, 0U, (uint16_t)(v % 16000U), 500U, 100U, 200U };

		rc = msg_squeal_detail_pack(&m, out, &dlc);
		break;
	}
	case MSG_SQUEAL_DETAIL2_ID: {
		const msg_squeal_detail2_t m = { 0U, 0U, (uint16_t)v, 3000U, 12U };

		rc = msg_squeal_detail2_pack(&m, out, &dlc);
		break;
	}
	default: {
		msg_squeal_diag_t m;

		memset(&m, 0, sizeof(m));
		m.page = (uint8_t)(v % MSG_DIAG_PAGE_COUNT);
		m.fault_bits = (uint16_t)(v & MSG_FAULT_ALL);
		m.uptime_s = v;
		m.bus_off_count = 1U;
		m.worst_task_time_us = 120U;
		m.e2e_error_count_force = 3U;
		m.rx_bad_frame_count = 7U;
		rc = msg_squeal_diag_pack(&m, out, &dlc);
		break;
	}
	}
	if (rc != SQ_OK) {
		(void)fprintf(stderr, "gen_seeds: pack of message %u failed\n", k);
		exit(1);
	}
}

static void seeds_msgs(void)
{
	unsigned int s;

	for (s = 0U; s < 12U; s++) {
		buf_t b = { { 0 }, 0U };
		e2e_p01_tx_t tx[MSG_COUNT];
		uint32_t k;
		uint32_t i;

		for (k = 0U; k < MSG_COUNT; k++) {
			e2e_p01_tx_init(&tx[k]);
		}
		put8(&b, 1U + s % 14U); /* MaxDeltaCounterInit */
		for (i = 0U; i < 8U + s; i++) {
			uint8_t f[8];

			k = (s < MSG_COUNT) ? s : (i % MSG_COUNT);
			packed_msg(k, 1000U * i + 37U * s, f);
			if ((s >= 8U) && (i % 3U == 2U)) {
				/* a lost frame: the counter jumps */
				tx[k].counter = (uint8_t)((tx[k].counter + 1U + s % 4U) % 15U);
			}
			msg_record(&b, k, f, &tx[k]);
		}
		if (s == 11U) {
			/* a "no frame" cycle and a wrong DLC */
			put8(&b, 0x08U);
			put8(&b, 4U);
			for (i = 0U; i < 8U; i++) {
				put8(&b, 0U);
			}
			put8(&b, 0x00U);
			put8(&b, 3U);
			for (i = 0U; i < 8U; i++) {
				put8(&b, 0xFFU);
			}
		}
		write_seed("fuzz_msgs", s, b.b, b.n);
	}
}

/* ---- calibration block -------------------------------------------------- */
static void seeds_calib(void)
{
	uint8_t blk[CALIB_BLOCK_LEN + 8U];
	calib_t cal;
	unsigned int n = 0U;
	unsigned int v;

	for (v = 0U; v < 8U; v++) {
		calib_default(&cal);
		switch (v) {
		case 1U: cal.criterion = 1U; break;
		case 2U: cal.e2e_check_inputs = 0U; break;
		case 3U: cal.delta_mu_q30 = -(1 << 28); break;
		case 4U: cal.lowpass_alpha_q15 = 1U; cal.debounce_count = 50U; break;
		case 5U: cal.disc_speed_id = 0x7FFU; cal.pad_force_id = 0U; break;
		case 6U: cal.mass_q16 = 1; cal.omega0_q12 = 1; cal.slope_q24 = 0; break;
		case 7U: cal.watchdog_ms = 10000U; cal.diag_period_ms = 100U; break;
		default: break;
		}
		memset(blk, 0, sizeof(blk));
		if (calib_encode(&cal, blk, sizeof(blk)) != SQ_OK) {
			(void)fprintf(stderr, "gen_seeds: calib variant %u invalid\n", v);
			exit(1);
		}
		write_seed("fuzz_calib_block", n++, blk, CALIB_BLOCK_LEN);
	}
	calib_default(&cal);
	(void)calib_encode(&cal, blk, sizeof(blk));
	write_seed("fuzz_calib_block", n++, blk, CALIB_BLOCK_LEN + 8U); /* trailing bytes */
	write_seed("fuzz_calib_block", n++, blk, CALIB_BLOCK_LEN - 1U); /* truncated */
	blk[20] ^= 0x01U;
	write_seed("fuzz_calib_block", n++, blk, CALIB_BLOCK_LEN);      /* bad CRC */
	memset(blk, 0xFF, sizeof(blk));
	write_seed("fuzz_calib_block", n++, blk, CALIB_BLOCK_LEN);      /* erased flash */
}

/* ---- monitor ------------------------------------------------------------ */
/* op 7: one 10 ms input cycle (speed raw 0.01 rad/s, force raw 0.5 N) */
static void mon_cycle(buf_t *b, uint32_t speed, uint32_t force)
{
	put8(b, 0x07U);
	put16(b, speed);
	put16(b, force);
}

static void mon_drain(buf_t *b)
{
	put8(b, 0x04U | (8U << 3));
	put8(b, 0U);
}

static void seeds_monitor(void)
{
	unsigned int s;

	for (s = 0U; s < 12U; s++) {
		buf_t b = { { 0 }, 0U };
		uint32_t i;

		put8(&b, s % 4U); /* calibration variant */
		/* a braking manoeuvre: speed falls, force rises */
		for (i = 0U; i < 40U; i++) {
			const uint32_t speed = 20000U - i * (300U + 50U * s);
			const uint32_t force = 2000U + i * (100U + 40U * s);

			mon_cycle(&b, speed, force);
			if ((i % 4U) == 3U) {
				mon_drain(&b);
			}
			if ((s == 5U) && (i == 20U)) {
				put8(&b, 0x03U | 0x08U); /* 200 ms without input */
				put16(&b, 200U);
			}
			if ((s == 6U) && (i == 10U)) {
				put8(&b, 0x05U);         /* bus-off reported */
				put8(&b, 3U);
				put8(&b, 255U);
				put8(&b, 0U);
				put32(&b, 1U);
				put32(&b, 0U);
				put32(&b, 0U);
				put32(&b, 0U);
			}
			if ((s == 7U) && (i % 5U == 0U)) {
				put8(&b, 0x00U);         /* a foreign frame */
				put8(&b, 0x80U);
				put8(&b, 0x00U);
				put16(&b, 0x7DFU);
				put8(&b, 8U);
				put32(&b, 0x2E020103U);
				put32(&b, 0xFFFFFFFFU);
				put8(&b, 1U);
				put16(&b, 0U);
			}
			if ((s == 8U) && (i == 15U)) {
				put8(&b, 0x02U | (5U << 4)); /* counter jump */
				put16(&b, speed);
			}
		}
		write_seed("fuzz_monitor", s, b.b, b.n);
	}
}

/* ---- candump lines -------------------------------------------------------- */
static const char *const candump_lines[] = {
	"(1700000000.123456) can0 110#5A03E803",
	"(0000000012.340000) vcan0 18FEF100#0102030405060708_C",
	"(1700000000.123456789) can0 123#R8",
	"(1700000000.123456) can0 123#R",
	"(1700000000.123456) can0 123#R8_C",
	"(1700000000.123456) can0 123##5112233",
	"(1700000000.123456) can0 123##4",
	"(1700000000.123456) can0 20000004#0004000000000000",
	"(1700000000.123456) can0 00000123#",
	"(1700000000.123456) can0 123#11.22.33.44 R",
	"(1700000000.123456) can0 300#a1b2c3d4e5f60708 T",
	"(1700000000.123456) can0 3AB12#C0:00:00000000#1122334455",
	"# a comment",
	"; another",
	"DROPCOUNT: dropped 3 CAN frame on 'can0' socket (total drops 3)",
	"   ",
	"(1.000000) can0 7FF#0011223344556677\r",
	"(1700000000.123456) can0 800#00",
	"(1700000000.123456) can0 12#00",
	"(1700000000.12345) can0 123#00",
};

static void seeds_candump(void)
{
	char text[65536];
	size_t n = 0U;
	unsigned int i;

	for (i = 0U; i < sizeof(candump_lines) / sizeof(candump_lines[0]); i++) {
		write_seed("fuzz_candump", i, (const uint8_t *)candump_lines[i],
			   strlen(candump_lines[i]));
	}
	/* a whole log: DiscSpeed/PadForce frames as the plant sends them */
	for (i = 0U; i < 40U; i++) {
		candump_frame_t f;
		int len;

		memset(&f, 0, sizeof(f));
		f.t_ns = 1700000000000000000ULL + 10000000ULL * i;
		(void)snprintf(f.iface, sizeof(f.iface), "vcan0");
		f.kind = CANDUMP_KIND_CLASSIC;
		f.id = (i & 1U) ? 0x111U : 0x110U;
		f.len = 4U;
		f.data[0] = (uint8_t)(i * 37U);
		f.data[1] = (uint8_t)(i % 15U);
		f.data[2] = (uint8_t)i;
		f.data[3] = 0x10U;
		len = candump_format_frame(&f, true, &text[n], sizeof(text) - n);
		if (len < 0) {
			(void)fprintf(stderr, "gen_seeds: candump_format_frame failed\n");
			exit(1);
		}
		n += (size_t)len;
	}
	write_seed("fuzz_candump", i, (const uint8_t *)text, n);
}

/* ---- calibration text files ----------------------------------------------- */
static void seeds_calib_text(void)
{
	unsigned int v;

	for (v = 0U; v < 4U; v++) {
		calib_t cal;
		char *text = NULL;
		size_t len = 0U;
		FILE *f;

		calib_default(&cal);
		if (v == 1U) {
			cal.criterion = 1U;
			cal.disc_speed_id = 0x7F0U;
		} else if (v == 2U) {
			cal.e2e_check_inputs = 0U;
			cal.delta_mu_q30 = -(1 << 27);
		} else if (v == 3U) {
			cal.lowpass_alpha_q15 = 1000U;
			cal.pad_radius_um = 10000U;
		}
		f = open_memstream(&text, &len);
		if ((f == NULL) || (calib_text_write(f, &cal) != 0) || (fclose(f) != 0)) {
			(void)fprintf(stderr, "gen_seeds: calib_text_write failed\n");
			exit(1);
		}
		write_seed("fuzz_calib_text", v, (const uint8_t *)text, len);
		free(text);
	}
	{
		static const char small[] = "mass_kg = 1.5\ncriterion = cubic # c\n"
					    "disc_speed_id = 0x120\n\n  pad_radius_m=0.1\n";
		static const char bad[] = "mass_kg = 1.5\nmass_kg = 2\nnope = 3\n";

		write_seed("fuzz_calib_text", 4U, (const uint8_t *)small, sizeof(small) - 1U);
		write_seed("fuzz_calib_text", 5U, (const uint8_t *)bad, sizeof(bad) - 1U);
	}
}

int main(int argc, char **argv)
{
	if (argc != 2) {
		(void)fprintf(stderr, "usage: gen_seeds DIR\n");
		return 2;
	}
	out_dir = argv[1];
	seeds_model();
	seeds_msgs();
	seeds_calib();
	seeds_monitor();
	seeds_candump();
	seeds_calib_text();
	return 0;
}
