/* SPDX-License-Identifier: MIT */
/*
 * The model over the golden vectors, identical code on the target and on
 * the host: one digest over every output bit, so "same digest" means the
 * two builds gave the same results bit for bit. Freestanding (no printf):
 * the target prints through semihosting.
 */
#include <stddef.h>
#include <stdint.h>

#include "squeal_model.h"
#include "tv_vectors.h"

#define TV_CHUNK 512U

static void fnv_word(uint32_t *h, uint32_t w)
{
	uint32_t i;

	for (i = 0; i < 4U; i++) {
		*h ^= (w >> (8U * i)) & 0xFFU;
		*h *= 16777619UL;
	}
}

static uint32_t raw_bits(squeal_num_t v)
{
	uint32_t w;
	const unsigned char *src = (const unsigned char *)&v;
	unsigned char *dst = (unsigned char *)&w;
	size_t i;

	_Static_assert(sizeof(squeal_num_t) == sizeof(uint32_t), "32-bit numbers");
	for (i = 0; i < sizeof(w); i++) {
		dst[i] = src[i];
	}
	return w;
}

static squeal_num_t from_bits(uint32_t w)
{
	squeal_num_t v;
	const unsigned char *src = (const unsigned char *)&w;
	unsigned char *dst = (unsigned char *)&v;
	size_t i;

	for (i = 0; i < sizeof(v); i++) {
		dst[i] = src[i];
	}
	return v;
}

/* "<key><decimal or hex>" appended to buf at *pos (buf is 96 bytes). */
static void put_str(char *buf, uint32_t *pos, const char *s)
{
	while (*s != '\0' && *pos < 94U) {
		buf[(*pos)++] = *s++;
	}
	buf[*pos] = '\0';
}

static void put_u32(char *buf, uint32_t *pos, uint32_t v)
{
	char tmp[11];
	uint32_t n = 0;

	do {
		tmp[n++] = (char)('0' + (char)(v % 10U));
		v /= 10U;
	} while (v != 0U && n < sizeof(tmp));
	while (n > 0U && *pos < 94U) {
		buf[(*pos)++] = tmp[--n];
	}
	buf[*pos] = '\0';
}

static void put_hex(char *buf, uint32_t *pos, uint32_t v)
{
	static const char digits[] = "0123456789abcdef";
	uint32_t i;

	for (i = 0; i < 8U && *pos < 94U; i++) {
		buf[(*pos)++] = digits[(v >> (28U - 4U * i)) & 0xFU];
	}
	buf[*pos] = '\0';
}

uint32_t tv_run(void (*out)(const char *line), uint32_t (*cycles)(void),
		uint64_t *total_cycles, uint32_t *max_cycles)
{
	uint32_t digest = 2166136261UL;
	uint32_t chunk = 2166136261UL;
	uint32_t states[5] = { 0U, 0U, 0U, 0U, 0U };
	uint32_t n = 0U;
	uint32_t p;
	uint64_t total = 0U;
	uint32_t worst = 0U;
	char line[96];
	uint32_t pos;

	for (p = 0; p < tv_point_count; p++) {
		const tv_point_t *tp = &tv_points[p];
		squeal_params_t prm;
		squeal_point_t pt;
		uint32_t c;

		pt.v0_mps = from_bits(tp->in[0]);
		pt.force_n = from_bits(tp->in[1]);
		prm.slope_spm = from_bits(tp->in[2]);
		prm.damping = from_bits(tp->in[3]);
		prm.omega0_radps = from_bits(tp->in[4]);
		prm.mass_kg = from_bits(tp->in[5]);
		prm.mu_inf = from_bits(tp->in[6]);
		prm.delta_mu = from_bits(tp->in[7]);
		for (c = 0; c < 2U; c++) {
			squeal_result_t r;
			uint32_t t0 = 0U;
			int rc;
			uint32_t word[11];
			uint32_t k;

			if ((tp->criteria & (1U << c)) == 0U) {
				continue;
			}
			if (cycles != NULL) {
				t0 = cycles();
			}
			rc = squeal_model_classify(&prm, &pt, c == 0U ? SQUEAL_CRITERION_EXACT
								  : SQUEAL_CRITERION_CUBIC, &r);
			if (cycles != NULL) {
				uint32_t dt = cycles() - t0;

				total += dt;
				if (dt > worst) {
					worst = dt;
				}
			}
			word[0] = (uint32_t)rc;
			word[1] = (uint32_t)r.state;
			word[2] = r.flags;
			word[3] = raw_bits(r.ln_q);
			word[4] = raw_bits(r.hopf_v0_mps);
			word[5] = raw_bits(r.hopf_margin_mps);
			word[6] = raw_bits(r.hopf_force_n);
			word[7] = raw_bits(r.cycle_x);
			word[8] = raw_bits(r.lc_amplitude_um);
			word[9] = raw_bits(r.trigger_velocity_mps);
			word[10] = raw_bits(r.basin_ratio);
			for (k = 0; k < 11U; k++) {
				fnv_word(&digest, word[k]);
				fnv_word(&chunk, word[k]);
			}
			states[r.state <= SQUEAL_STATE_NOT_SLIDING ? (uint32_t)r.state : 4U]++;
			n++;
			if (n % TV_CHUNK == 0U) {
				pos = 0U;
				put_str(line, &pos, "CHUNK ");
				put_u32(line, &pos, n / TV_CHUNK - 1U);
				put_str(line, &pos, " ");
				put_hex(line, &pos, chunk);
				put_str(line, &pos, "\n");
				out(line);
				chunk = 2166136261UL;
			}
		}
	}
	pos = 0U;
	put_str(line, &pos, "DIGEST numeric=");
	put_str(line, &pos, tv_numeric);
	put_str(line, &pos, " n=");
	put_u32(line, &pos, n);
	put_str(line, &pos, " fnv=");
	put_hex(line, &pos, digest);
	put_str(line, &pos, " states=");
	for (p = 0; p < 5U; p++) {
		put_u32(line, &pos, states[p]);
		put_str(line, &pos, p < 4U ? "," : "\n");
	}
	out(line);
	if (total_cycles != NULL) {
		*total_cycles = total;
	}
	if (max_cycles != NULL) {
		*max_cycles = worst;
	}
	return n;
}
