/* SPDX-License-Identifier: MIT */
/*
 * calib_text: calibration text files <-> calib_t. See calib_text.h for the
 * format. This file is the file: it reads the lines (comments, `[section]`
 * headers, `key = value`), names FILE:LINE in every message, and writes a
 * calibration back as a file; what a key means is calib_sections.c's (the
 * flat keys' table and the sections), which this file calls and which calls
 * nothing here.
 */
#include "calib_text.h"

#include <ctype.h>
#include <errno.h>
#include <inttypes.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "calib_map.h"
#include "input_conv.h"
#include "sq_status.h"
#include "text_errf.h"

#define LINE_MAX_LEN 512

size_t calib_text_key_count(void)
{
	return calib_key_count();
}

const char *calib_text_key_name(size_t i)
{
	return calib_key_name(i);
}

int calib_text_brake(const calib_t *cal, const char *pos_name, calib_corner_t *brake,
		     char *msg, size_t msglen)
{
	int pos;
	uint32_t k;

	if (pos_name == NULL) {
		calib_corner_defaults(cal, 0U, brake);
		return 0;
	}
	pos = calib_corner_pos(pos_name);
	if (pos < 0) {
		text_errf(msg, msglen, "unknown corner '%s' (FL, FR, RL or RR)", pos_name);
		return -1;
	}
	for (k = 0U; k < cal->n_corners; k++) {
		if (cal->corners[k].pos == (uint8_t)pos) {
			*brake = cal->corners[k];
			return 0;
		}
	}
	if ((cal->n_corners == 0U) && (pos == 0)) {
		calib_corner_defaults(cal, 0U, brake); /* the legacy form's one corner */
		return 0;
	}
	text_errf(msg, msglen, "the calibration has no [corner %s]", calib_corner_pos_name((unsigned int)pos));
	return -1;
}


static char *trim(char *s)
{
	char *e;

	while (isspace((unsigned char)*s)) {
		s++;
	}
	e = s + strlen(s);
	while ((e > s) && isspace((unsigned char)e[-1])) {
		e--;
	}
	*e = '\0';
	return s;
}

int calib_text_parse(FILE *f, const char *name, calib_t *out, char *err,
		     size_t errlen)
{
	return calib_text_parse_map(f, name, out, NULL, err, errlen);
}

int calib_text_parse_map(FILE *f, const char *name, calib_t *out, calib_names_t *names,
			 char *err, size_t errlen)
{
	char line[LINE_MAX_LEN];
	unsigned int seen_line[CALIB_KEY_COUNT];
	char msg[200];
	calib_t cal;
	unsigned int lineno = 0;
	static calib_sections_t sections; /* large: not on the stack */
	unsigned int legacy_line = 0;
	const char *legacy_key = "";
	unsigned int iface_line = 0;
	char iface[CALIB_IFACE_LEN] = "";

	if ((f == NULL) || (out == NULL)) {
		text_errf(err, errlen, "calib_text_parse: NULL argument");
		return SQ_EINVAL;
	}
	if (name == NULL) {
		name = "<calibration>";
	}
	memset(seen_line, 0, sizeof(seen_line));
	calib_sections_init(&sections);
	if (names != NULL) {
		memset(names, 0, sizeof(*names));
	}
	calib_default(&cal);
	while (fgets(line, sizeof(line), f) != NULL) {
		int k;
		char *hash;
		char *eq;
		char *key;
		char *value;
		size_t idx;

		lineno++;
		if ((strchr(line, '\n') == NULL) && !feof(f)) {
			text_errf(err, errlen, "%s:%u: line longer than %d characters",
				name, lineno, LINE_MAX_LEN - 2);
			return SQ_EBADMSG;
		}
		hash = strchr(line, '#');
		if (hash != NULL) {
			*hash = '\0';
		}
		key = trim(line);
		if (*key == '\0') {
			continue;
		}
		if (*key == '[') {
			if (calib_sections_header(&sections, key, lineno, msg, sizeof(msg)) != 0) {
				text_errf(err, errlen, "%s:%u: %s", name, lineno, msg);
				return SQ_EBADMSG;
			}
			continue;
		}
		eq = strchr(key, '=');
		if (eq == NULL) {
			text_errf(err, errlen, "%s:%u: expected 'key = value', got '%s'",
				name, lineno, key);
			return SQ_EBADMSG;
		}
		*eq = '\0';
		value = trim(eq + 1);
		key = trim(key);
		if (*key == '\0') {
			text_errf(err, errlen, "%s:%u: missing key before '='", name, lineno);
			return SQ_EBADMSG;
		}
		if (calib_sections_open(&sections)) {
			/* a key of the current [input]/[corner] section */
			if (*value == '\0') {
				text_errf(err, errlen, "%s:%u: %s has no value", name, lineno, key);
				return SQ_EBADMSG;
			}
			if (calib_sections_key(&sections, key, value, lineno, msg, sizeof(msg)) != 0) {
				text_errf(err, errlen, "%s:%u: %s", name, lineno, msg);
				return SQ_EBADMSG;
			}
			continue;
		}
		if (strcmp(key, "input_iface") == 0) {
			/* host only: where the inputs come from (not in the block) */
			if (iface_line != 0U) {
				text_errf(err, errlen, "%s:%u: duplicate key 'input_iface' (first set on line %u)",
					name, lineno, iface_line);
				return SQ_EBADMSG;
			}
			iface_line = lineno;
			if (!calib_iface_name_valid(value)) {
				text_errf(err, errlen, "%s:%u: input_iface = '%s': 1..15 of A-Z a-z 0-9 _ . -",
					name, lineno, value);
				return SQ_EBADMSG;
			}
			snprintf(iface, sizeof(iface), "%s", value);
			continue;
		}
		k = calib_key_find(key);
		if (k < 0) {
			text_errf(err, errlen, "%s:%u: unknown key '%s' (docs/calib-example.txt lists them)",
				name, lineno, key);
			return SQ_EBADMSG;
		}
		idx = (size_t)k;
		if (seen_line[idx] != 0U) {
			text_errf(err, errlen, "%s:%u: duplicate key '%s' (first set on line %u)",
				name, lineno, key, seen_line[idx]);
			return SQ_EBADMSG;
		}
		seen_line[idx] = lineno;
		if ((legacy_line == 0U) && calib_key_legacy_input(idx)) {
			legacy_line = lineno;
			legacy_key = calib_key_name(idx);
		}
		if (*value == '\0') {
			text_errf(err, errlen, "%s:%u: %s has no value", name, lineno, key);
			return SQ_EBADMSG;
		}
		if (strpbrk(value, " \t") != NULL) {
			text_errf(err, errlen, "%s:%u: %s: one value expected, got '%s'",
				name, lineno, key, value);
			return SQ_EBADMSG;
		}
		if (calib_key_set(idx, value, &cal, msg, sizeof(msg)) != 0) {
			text_errf(err, errlen, "%s:%u: %s", name, lineno, msg);
			return SQ_EBADMSG;
		}
	}
	if (ferror(f)) {
		text_errf(err, errlen, "%s: read error", name);
		return SQ_EIO;
	}
	if (calib_sections_finish(&sections, name, legacy_line, legacy_key, &cal, names, err,
				  errlen) != 0) {
		return SQ_EBADMSG;
	}
	if (calib_validate(&cal) != SQ_OK) {
		calib_map_error_t me = { -1, -1, NULL };
		const int bk = calib_key_find("bitrate_kbps");
		const int dk = calib_key_find("delta_mu");

		if ((int64_t)cal.mu_inf_q30 + cal.delta_mu_q30 < 0) {
			const unsigned int dl = seen_line[(size_t)dk];

			if (dl != 0U) {
				text_errf(err, errlen, "%s:%u: mu_inf + delta_mu must not be negative (mu_0 >= 0)",
					name, dl);
			} else {
				text_errf(err, errlen, "%s: mu_inf + delta_mu must not be negative (mu_0 >= 0)",
					name);
			}
		} else if (calib_sd_validate(&cal) != SQ_OK) {
			text_errf(err, errlen, "%s: a standard deviation must be in 0 .. |its parameter| (mu_inf_sd <= 1.5), a brake's own or a corner's",
				name);
		} else if (calib_check(&cal) == CALIB_ERR_BITRATE) {
			text_errf(err, errlen, "%s:%u: %s", name, seen_line[(size_t)bk],
				calib_error_name(CALIB_ERR_BITRATE));
		} else if (calib_map_check(&cal, &me) != SQ_OK) {
			text_errf(err, errlen, "%s: the inputs do not set up: %s", name,
				(me.why != NULL) ? me.why : "invalid input map");
		} else {
			text_errf(err, errlen, "%s: the six CAN identifiers (disc_speed_id, pad_force_id, status_id, detail_id, diag_id, detail2_id) must all differ",
				name);
		}
		return SQ_EBADMSG;
	}
	if (names != NULL) {
		snprintf(names->input_iface, sizeof(names->input_iface), "%s", iface);
	}
	*out = cal;
	return SQ_OK;
}

int calib_text_load(const char *path, calib_t *out, char *err, size_t errlen)
{
	return calib_text_load_map(path, out, NULL, err, errlen);
}

int calib_text_load_map(const char *path, calib_t *out, calib_names_t *names, char *err,
			size_t errlen)
{
	FILE *f;
	int rc;

	if ((path == NULL) || (out == NULL)) {
		text_errf(err, errlen, "calib_text_load: NULL argument");
		return SQ_EINVAL;
	}
	f = fopen(path, "r");
	if (f == NULL) {
		text_errf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
		return SQ_ENOENT;
	}
	rc = calib_text_parse_map(f, path, out, names, err, errlen);
	fclose(f);
	return rc;
}

static void put_dec(FILE *f, const char *key, calib_dec_t d)
{
	char b[64];

	calib_dec_format(d, b, sizeof(b));
	fprintf(f, "%s = %s\n", key, b);
}

static void put_sig(FILE *f, const char *prefix, const can_signal_t *s)
{
	fprintf(f, "%sstart_bit = %u\n%slength = %u\n%sbyte_order = %s\n", prefix, s->start_bit,
		prefix, s->length, prefix, s->byte_order != 0U ? "motorola" : "intel");
}

/* The input and corner sections of cal (nothing for the legacy form); the
 * inputs are named in0..in7 unless names gives their names (and their
 * `signal` lines). */
static int write_sections(FILE *f, const calib_t *cal, const calib_names_t *names)
{
	unsigned int i;
	char nm[CALIB_MAX_INPUTS][CALIB_SECTION_NAME_LEN];

	if (cal->n_corners == 0U) {
		return SQ_OK;
	}
	for (i = 0; i < cal->n_inputs; i++) {
		const calib_input_t *in = &cal->inputs[i];
		unsigned int j;

		if (names != NULL) {
			snprintf(nm[i], sizeof(nm[i]), "%s", names->input[i]);
		} else {
			snprintf(nm[i], sizeof(nm[i]), "in%u", i);
		}
		fprintf(f, "\n[input %s]\nid = 0x%" PRIX32 "\n", nm[i], in->id);
		if ((in->flags & CALIB_IN_EXTENDED) != 0U) {
			fprintf(f, "extended = yes\n");
		}
		if (in->fd != 0U) {
			fprintf(f, "fd = yes\n");
		}
		fprintf(f, "min_dlc = %u\n", in->min_dlc);
		if ((in->flags & CALIB_IN_DLC_EXACT) != 0U) {
			fprintf(f, "exact_dlc = yes\n");
		}
		put_sig(f, "", &in->sig);
		fprintf(f, "signed = %s\n", in->sig.is_signed != 0U ? "yes" : "no");
		put_dec(f, "factor", in->factor);
		put_dec(f, "offset", in->offset);
		fprintf(f, "unit = %s\n", input_unit_name((input_unit_t)in->unit));
		if ((names != NULL) && (names->signal[i][0] != '\0')) {
			fprintf(f, "signal = %s\n", names->signal[i]);
		}
		if ((in->flags & CALIB_IN_MUX) != 0U) {
			put_sig(f, "mux_", &in->mux);
			fprintf(f, "mux_value = %" PRIu32 "\n", in->mux_value);
			if (in->mux_value_max != in->mux_value) {
				fprintf(f, "mux_value_max = %" PRIu32 "\n", in->mux_value_max);
			}
		}
		if ((in->flags & CALIB_IN_MUX2) != 0U) {
			put_sig(f, "mux2_", &in->mux2);
			fprintf(f, "mux2_value = %" PRIu32 "\n", in->mux2_value);
			if (in->mux2_value_max != in->mux2_value) {
				fprintf(f, "mux2_value_max = %" PRIu32 "\n", in->mux2_value_max);
			}
		}
		if ((in->flags & CALIB_IN_NA) != 0U) {
			fprintf(f, "na_raw = 0x%" PRIX32 "\n", in->na_raw);
		}
		if ((in->flags & CALIB_IN_NA2) != 0U) {
			fprintf(f, "na_raw2 = 0x%" PRIX32 "\n", in->na_raw2);
		}
		if ((in->flags & CALIB_IN_QUALIFIER) != 0U) {
			fprintf(f, "qualifier_bit = %u\nqualifier_invalid = %u\n", in->qualifier_bit,
				in->qualifier_invalid);
		}
		fprintf(f, "protection = %s\n", calib_prot_name(in->protection));
		if ((in->protection == (uint8_t)CALIB_PROT_P01) ||
		    (in->protection == (uint8_t)CALIB_PROT_P05)) {
			fprintf(f, "data_id = 0x%04X\n", in->data_id);
		}
		if ((in->protection == (uint8_t)CALIB_PROT_P05) && (in->e2e_offset_byte != 0U)) {
			fprintf(f, "e2e_offset_byte = %u\n", in->e2e_offset_byte);
		}
		if (in->protection == (uint8_t)CALIB_PROT_P02) {
			fprintf(f, "data_id_list =");
			for (j = 0; j < CALIB_DATA_ID_LIST_LEN; j++) {
				fprintf(f, " 0x%02X", in->data_id_list[j]);
			}
			fprintf(f, "\n");
		}
		if (in->protection == (uint8_t)CALIB_PROT_COUNTER) {
			put_sig(f, "counter_", &in->counter);
			fprintf(f, "counter_modulus = %u\n", in->counter_modulus);
		}
		if (in->protection != (uint8_t)CALIB_PROT_NONE) {
			fprintf(f, "max_delta_counter = %u\n", in->max_delta_counter);
		}
		fprintf(f, "period_ms = %u\nstale_cycles = %u\n", in->period_ms, in->stale_cycles);
		put_dec(f, "max", in->max);
		put_dec(f, "min", in->min);
		put_dec(f, "step_max", in->step_max);
	}
	for (i = 0; i < cal->n_corners; i++) {
		const calib_corner_t *c = &cal->corners[i];
		calib_t tmp = *cal;
		size_t k;

		calib_flat_from_corner(c, &tmp);
		fprintf(f, "\n[corner %s]\nspeed = %s\nforce = %s\n", calib_corner_pos_name(c->pos),
			nm[c->speed_input], nm[c->force_input]);
		if (c->piston_area_cmm2 != 0U) {
			fprintf(f, "piston_area_mm2 = %u.%02u\n", c->piston_area_cmm2 / 100U,
				c->piston_area_cmm2 % 100U);
		}
		if (c->torque_share_ppm != 1000000U) {
			fprintf(f, "torque_share = %u.%06u\n", c->torque_share_ppm / 1000000U,
				c->torque_share_ppm % 1000000U);
		}
		fprintf(f, "efficiency = %u.%06u\naxle_factor = %u.%06u\nfriction_faces = %u\n",
			c->efficiency_ppm / 1000000U, c->efficiency_ppm % 1000000U,
			c->axle_factor_ppm / 1000000U, c->axle_factor_ppm % 1000000U,
			c->friction_faces);
		for (k = 0; calib_corner_flat_keys[k] != NULL; k++) {
			char b[48];

			calib_key_format((size_t)calib_key_find(calib_corner_flat_keys[k]), &tmp, b,
					 sizeof(b));
			fprintf(f, "%s = %s\n", calib_corner_flat_keys[k], b);
		}
	}
	return ferror(f) ? SQ_EIO : SQ_OK;
}

int calib_text_write(FILE *f, const calib_t *cal)
{
	return calib_text_write_map(f, cal, NULL);
}

int calib_text_write_map(FILE *f, const calib_t *cal, const calib_names_t *names)
{
	calib_t def;
	size_t i;

	if ((f == NULL) || (cal == NULL) || (calib_validate(cal) != SQ_OK)) {
		return SQ_EINVAL;
	}
	calib_default(&def);
	fprintf(f, "# squeal-sim calibration (squeal-sim ecu --calib FILE)\n"
		"# key = value; '#' starts a comment; keys left out keep their default.\n");
	for (i = 0; i < calib_key_count(); i++) {
		char val[48];
		char comment[200];
		char line[128];

		if ((cal->n_corners != 0U) && calib_key_legacy_input(i)) {
			continue; /* the [input] sections configure the inputs */
		}
		calib_key_format(i, cal, val, sizeof(val));
		calib_key_comment(i, &def, comment, sizeof(comment));
		snprintf(line, sizeof(line), "%s = %s", calib_key_name(i), val);
		fprintf(f, "%-34s # %s\n", line, comment);
	}
	if ((names != NULL) && (names->input_iface[0] != '\0')) {
		char line[64];

		snprintf(line, sizeof(line), "input_iface = %s", names->input_iface);
		fprintf(f, "%-34s # the log/SocketCAN interface of the inputs (host only)\n", line);
	}
	if (write_sections(f, cal, names) != SQ_OK) {
		return SQ_EIO;
	}
	fflush(f);
	return ferror(f) ? SQ_EIO : SQ_OK;
}
