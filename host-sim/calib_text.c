/* SPDX-License-Identifier: MIT */
/*
 * calib_text: calibration text files <-> calib_t. See calib_text.h for the
 * format. One table row per key: where the field lives, how the physical
 * value maps to the stored one, and the stored range. The ranges repeat
 * calib.c's (which are private to the firmware); a unit test walks every
 * row and proves that its ends are accepted by calib_validate() and one
 * step beyond is refused, so the two tables cannot drift apart unnoticed.
 */
#include "calib_text.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "calib_map.h"
#include "sq_status.h"
#include "squeal_model.h"

typedef enum {
	KIND_Q,       /* value * scale, rounded to nearest (Q-format fields)   */
	KIND_SCALED,  /* value * scale must be a whole number                  */
	KIND_INT,     /* integer, decimal or 0x hex                            */
	KIND_HEX,     /* integer, written as hex (CAN identifiers)             */
	KIND_CRITERION, /* exact | cubic                                       */
	KIND_BOOL     /* 0/1, no/yes, false/true, off/on                       */
} key_kind_t;

typedef struct {
	const char *key;
	uint16_t offset;
	uint8_t size;      /* bytes in calib_t: 1, 2, 4 */
	uint8_t is_signed; /* the int32_t Q-format model fields */
	key_kind_t kind;
	double scale;      /* stored = physical * scale (KIND_Q, KIND_SCALED) */
	const char *unit;
	const char *what;
} key_desc_t;

/* The valid range of each key is calib.c's (calib_field_range()). */
#define K(key, field, kind, scale, unit, what) \
	{ key, (uint16_t)offsetof(calib_t, field), \
	  (uint8_t)sizeof(((calib_t *)0)->field), \
	  (uint8_t)(((kind) == KIND_Q) && (sizeof(((calib_t *)0)->field) == 4U)), \
	  kind, scale, unit, what }

#define Q16 65536.0
#define Q12 4096.0
#define Q15 32768.0
#define Q24 16777216.0
#define Q30 1073741824.0

static const key_desc_t keys[] = {
	K("mass_kg", mass_q16, KIND_Q, Q16, "kg",
	  "moving mass of pad and caliper m"),
	K("omega0_radps", omega0_q12, KIND_Q, Q12, "rad/s",
	  "natural angular frequency w0"),
	K("damping", damping_q30, KIND_Q, Q30, "-",
	  "damping ratio D"),
	K("mu_inf", mu_inf_q30, KIND_Q, Q30, "-",
	  "friction coefficient at high sliding speed"),
	K("delta_mu", delta_mu_q30, KIND_Q, Q30, "-",
	  "mu_0 - mu_inf (mu_inf + delta_mu >= 0)"),
	K("slope_spm", slope_q24, KIND_Q, Q24, "s/m",
	  "friction slope a"),
	K("criterion", criterion, KIND_CRITERION, 1.0, "",
	  "exact (I1(s)/s, default) or cubic (the paper's)"),
	K("pad_radius_m", pad_radius_um, KIND_SCALED, 1e6, "m",
	  "effective pad radius r_p (resolution 1 um)"),
	K("wheel_radius_m", wheel_radius_um, KIND_SCALED, 1e6, "m",
	  "rolling radius r_w (resolution 1 um)"),
	K("bitrate_kbps", bitrate_kbps, KIND_INT, 1.0, "kbit/s",
	  "CAN bit rate (the ECU's controller; SocketCAN ignores it)"),
	K("disc_speed_id", disc_speed_id, KIND_HEX, 1.0, "",
	  "DiscSpeed identifier (11 bit)"),
	K("pad_force_id", pad_force_id, KIND_HEX, 1.0, "",
	  "PadForce identifier"),
	K("status_id", status_id, KIND_HEX, 1.0, "",
	  "SquealStatus identifier"),
	K("detail_id", detail_id, KIND_HEX, 1.0, "",
	  "SquealDetail identifier"),
	K("diag_id", diag_id, KIND_HEX, 1.0, "",
	  "SquealDiag identifier"),
	K("detail2_id", detail2_id, KIND_HEX, 1.0, "",
	  "SquealDetail2 identifier"),
	K("e2e_check_inputs", e2e_check_inputs, KIND_BOOL, 1.0, "",
	  "check the inputs' E2E CRC and counter (yes/no)"),
	K("e2e_max_delta_counter", e2e_max_delta_counter, KIND_INT, 1.0, "",
	  "E2E P01 MaxDeltaCounterInit"),
	K("input_period_ms", input_period_ms, KIND_INT, 1.0, "ms",
	  "expected input period"),
	K("status_period_ms", status_period_ms, KIND_INT, 1.0, "ms",
	  "SquealStatus period"),
	K("detail_period_ms", detail_period_ms, KIND_INT, 1.0, "ms",
	  "SquealDetail/SquealDetail2 period"),
	K("diag_period_ms", diag_period_ms, KIND_INT, 1.0, "ms",
	  "SquealDiag period"),
	K("stale_cycles", stale_cycles, KIND_INT, 1.0, "periods",
	  "missed input periods before an input is stale"),
	K("speed_max_radps", speed_max_raw, KIND_SCALED, 100.0, "rad/s",
	  "plausible disc speed maximum (resolution 0.01 rad/s)"),
	K("speed_step_max_radps", speed_step_max_raw, KIND_SCALED, 100.0,
	  "rad/s", "plausible disc speed change between frames"),
	K("force_max_n", force_max_raw, KIND_SCALED, 2.0, "N",
	  "plausible pad force maximum (resolution 0.5 N)"),
	K("force_step_max_n", force_step_max_raw, KIND_SCALED, 2.0, "N",
	  "plausible pad force change between frames"),
	K("lowpass_alpha", lowpass_alpha_q15, KIND_Q, Q15, "-",
	  "first-order input filter weight of a new value (1 = off)"),
	K("v0_min_mps", v0_min_umps, KIND_SCALED, 1e6, "m/s",
	  "not sliding below this disc surface speed (resolution 1 um/s)"),
	K("force_min_n", force_min_mn, KIND_SCALED, 1e3, "N",
	  "not sliding below this pad force (resolution 1 mN)"),
	K("debounce_count", debounce_count, KIND_INT, 1.0, "",
	  "agreeing classifications before a state change"),
	K("hyst_lnq", hyst_lnq_micro, KIND_SCALED, 1e6, "-",
	  "Hopf hysteresis band in |ln 2Q| (resolution 1e-6)"),
	K("hyst_rho", hyst_rho_ppm, KIND_SCALED, 1e6, "-",
	  "stable-border hysteresis band in |rho - 1| (resolution 1e-6)"),
	K("rho_warn", rho_warn_ppm, KIND_SCALED, 1e6, "-",
	  "bistable with basin ratio below this -> warning level 2"),
	K("watchdog_ms", watchdog_ms, KIND_INT, 1.0, "ms",
	  "watchdog timeout"),
	K("input_bus", input_bus, KIND_INT, 1.0, "",
	  "bus the inputs come from (0 = CAN1 / --iface, 1 = CAN2 / --out-iface)"),
	K("output_bus", output_bus, KIND_INT, 1.0, "",
	  "bus the Squeal* frames go out on"),
	K("input_listen_only", input_listen_only, KIND_BOOL, 1.0, "",
	  "input bus listen-only: nothing sent on it, no ACK (yes/no)"),
	/* uncertainty (issue 12, docs/uncertainty.md): 0 <= sd <= |param|
	 * (mu_inf's <= 1.5), |corr| <= 1; all 0: crisp classes as before */
	K("mass_kg_sd", sd.mass_sd_q16, KIND_Q, Q16, "kg",
	  "standard deviation of mass_kg"),
	K("omega0_radps_sd", sd.omega0_sd_q12, KIND_Q, Q12, "rad/s",
	  "standard deviation of omega0_radps"),
	K("damping_sd", sd.damping_sd_q30, KIND_Q, Q30, "-",
	  "standard deviation of damping"),
	K("mu_inf_sd", sd.mu_inf_sd_q30, KIND_Q, Q30, "-",
	  "standard deviation of mu_inf (carried; enters no border)"),
	K("delta_mu_sd", sd.delta_mu_sd_q30, KIND_Q, Q30, "-",
	  "standard deviation of delta_mu"),
	K("slope_spm_sd", sd.slope_sd_q24, KIND_Q, Q24, "s/m",
	  "standard deviation of slope_spm"),
	K("slope_delta_mu_corr", sd.slope_delta_mu_corr_q30, KIND_Q, Q30, "-",
	  "correlation of slope_spm and delta_mu estimates"),
	K("uncertain_k_sigma", uncertain_k_q16, KIND_Q, Q16, "sigma",
	  "within k sigma of a border: the more severe neighbouring level (0 = off)"),
};

#define KEY_COUNT (sizeof(keys) / sizeof(keys[0]))
#define LINE_MAX_LEN 512

_Static_assert(KEY_COUNT == 46U, "one key per calib_t field");

size_t calib_text_key_count(void)
{
	return KEY_COUNT;
}

const char *calib_text_key_name(size_t i)
{
	return (i < KEY_COUNT) ? keys[i].key : NULL;
}

static int64_t field_get(const calib_t *cal, const key_desc_t *k)
{
	const uint8_t *p = (const uint8_t *)cal + k->offset;
	uint8_t u8;
	uint16_t u16;
	uint32_t u32;
	int32_t i32;

	switch (k->size) {
	case 1U:
		memcpy(&u8, p, 1U);
		return u8;
	case 2U:
		memcpy(&u16, p, 2U);
		return u16;
	default:
		if (k->is_signed != 0U) {
			memcpy(&i32, p, 4U);
			return i32;
		}
		memcpy(&u32, p, 4U);
		return u32;
	}
}

/* v is within the key's range, which fits the field */
static void field_set(calib_t *cal, const key_desc_t *k, int64_t v)
{
	uint8_t *p = (uint8_t *)cal + k->offset;
	uint8_t u8 = (uint8_t)v;
	uint16_t u16 = (uint16_t)v;
	uint32_t u32 = (uint32_t)v;
	int32_t i32 = (int32_t)v;

	switch (k->size) {
	case 1U:
		memcpy(p, &u8, 1U);
		break;
	case 2U:
		memcpy(p, &u16, 2U);
		break;
	default:
		if (k->is_signed != 0U) {
			memcpy(p, &i32, 4U);
		} else {
			memcpy(p, &u32, 4U);
		}
		break;
	}
}

static double physical(const key_desc_t *k, int64_t raw)
{
	return (double)raw / k->scale;
}

/* Does text parse back (as convert_value does) to exactly raw? */
static bool reads_back(const key_desc_t *k, const char *text, int64_t raw)
{
	const double v = strtod(text, NULL) * k->scale;
	const int64_t iv = (int64_t)llround(v);

	if (iv != raw) {
		return false;
	}
	return (k->kind != KIND_SCALED) ||
	       (fabs(v - (double)iv) <= 1e-6 * fmax(1.0, fabs(v)));
}

/* Shortest %g text of a stored value that parses back to the same value. */
static void format_value(const key_desc_t *k, int64_t raw, char *buf, size_t len)
{
	int prec;

	switch (k->kind) {
	case KIND_CRITERION:
		snprintf(buf, len, "%s", raw == (int64_t)SQUEAL_CRITERION_CUBIC ?
			 "cubic" : "exact");
		return;
	case KIND_BOOL:
		snprintf(buf, len, "%s", raw != 0 ? "yes" : "no");
		return;
	case KIND_HEX:
		snprintf(buf, len, "0x%03llX", (unsigned long long)raw);
		return;
	case KIND_INT:
		snprintf(buf, len, "%lld", (long long)raw);
		return;
	default:
		break;
	}
	/* plain decimals first (5000, 0.023), exponent form for the tiny */
	for (prec = 0; prec <= 9; prec++) {
		snprintf(buf, len, "%.*f", prec, physical(k, raw));
		if (reads_back(k, buf, raw)) {
			return;
		}
	}
	for (prec = 1; prec <= 17; prec++) {
		snprintf(buf, len, "%.*g", prec, physical(k, raw));
		if (reads_back(k, buf, raw)) {
			return;
		}
	}
	snprintf(buf, len, "%.17g", physical(k, raw));
}

void calib_text_errf(char *err, size_t errlen, const char *fmt, ...)
{
	va_list ap;

	if ((err == NULL) || (errlen == 0U)) {
		return;
	}
	va_start(ap, fmt);
	vsnprintf(err, errlen, fmt, ap);
	va_end(ap);
}

static const key_desc_t *find_key(const char *name)
{
	size_t i;

	for (i = 0; i < KEY_COUNT; i++) {
		if (strcmp(keys[i].key, name) == 0) {
			return &keys[i];
		}
	}
	return NULL;
}

/* Integer: decimal with optional sign, or 0x hex. */
bool calib_text_parse_int(const char *text, int64_t *out)
{
	char *end = NULL;
	long long v;

	errno = 0;
	if ((text[0] == '0') && ((text[1] == 'x') || (text[1] == 'X'))) {
		if (!isxdigit((unsigned char)text[2])) {
			return false;
		}
		v = strtoll(text + 2, &end, 16);
	} else {
		if (!isdigit((unsigned char)text[0]) &&
		    !(((text[0] == '-') || (text[0] == '+')) &&
		      isdigit((unsigned char)text[1]))) {
			return false;
		}
		v = strtoll(text, &end, 10);
	}
	if ((errno != 0) || (end == NULL) || (*end != '\0')) {
		return false;
	}
	*out = v;
	return true;
}

/* Decimal number (no hex floats, no inf/nan). */
static bool parse_real(const char *text, double *out)
{
	const char *p;
	char *end = NULL;
	double v;

	for (p = text; *p != '\0'; p++) {
		if (!isdigit((unsigned char)*p) && (strchr("+-.eE", *p) == NULL)) {
			return false;
		}
	}
	errno = 0;
	v = strtod(text, &end);
	if ((end == text) || (*end != '\0') || (errno == ERANGE) || !isfinite(v)) {
		return false;
	}
	*out = v;
	return true;
}

/* The stored range of a key: calib.c's table is the one source. A key
 * whose field calib.c does not know is a programming error: empty range. */
static void key_range(const key_desc_t *k, int64_t *min, int64_t *max)
{
	if (calib_field_range(k->offset, min, max) != SQ_OK) {
		*min = 1;
		*max = 0;
	}
}

static void range_text(const key_desc_t *k, char *buf, size_t len)
{
	char lo[40];
	char hi[40];

	int64_t min;
	int64_t max;

	key_range(k, &min, &max);
	format_value(k, min, lo, sizeof(lo));
	format_value(k, max, hi, sizeof(hi));
	snprintf(buf, len, "%s .. %s%s%s", lo, hi,
		 (k->unit[0] != '\0' && strcmp(k->unit, "-") != 0) ? " " : "",
		 strcmp(k->unit, "-") != 0 ? k->unit : "");
}

/* Convert one value; 0 or -1 with err written (without the FILE:LINE). */
static int convert_value(const key_desc_t *k, const char *text, int64_t *raw,
			 char *err, size_t errlen)
{
	char range[100];
	double v;
	int64_t iv;
	int64_t min;
	int64_t max;

	key_range(k, &min, &max);
	range_text(k, range, sizeof(range));
	switch (k->kind) {
	case KIND_CRITERION:
		if (strcmp(text, "exact") == 0) {
			*raw = (int64_t)SQUEAL_CRITERION_EXACT;
		} else if (strcmp(text, "cubic") == 0) {
			*raw = (int64_t)SQUEAL_CRITERION_CUBIC;
		} else {
			calib_text_errf(err, errlen, "%s must be 'exact' or 'cubic', got '%s'",
				k->key, text);
			return -1;
		}
		return 0;
	case KIND_BOOL:
		if ((strcmp(text, "1") == 0) || (strcasecmp(text, "yes") == 0) ||
		    (strcasecmp(text, "true") == 0) || (strcasecmp(text, "on") == 0)) {
			*raw = 1;
		} else if ((strcmp(text, "0") == 0) || (strcasecmp(text, "no") == 0) ||
			   (strcasecmp(text, "false") == 0) ||
			   (strcasecmp(text, "off") == 0)) {
			*raw = 0;
		} else {
			calib_text_errf(err, errlen, "%s must be yes/no (or 1/0), got '%s'",
				k->key, text);
			return -1;
		}
		return 0;
	case KIND_INT:
	case KIND_HEX:
		if (!calib_text_parse_int(text, &iv)) {
			calib_text_errf(err, errlen, "%s needs an integer (decimal or 0x hex), got '%s'",
				k->key, text);
			return -1;
		}
		break;
	default:
		if (!parse_real(text, &v)) {
			calib_text_errf(err, errlen, "%s needs a number, got '%s'", k->key, text);
			return -1;
		}
		v *= k->scale;
		if (!(v >= (double)min - 0.5) || !(v <= (double)max + 0.5)) {
			calib_text_errf(err, errlen, "%s = %s is out of range (%s)", k->key,
				text, range);
			return -1;
		}
		iv = (int64_t)llround(v);
		if ((k->kind == KIND_SCALED) &&
		    (fabs(v - (double)iv) > 1e-6 * fmax(1.0, fabs(v)))) {
			char step[40];

			format_value(k, 1, step, sizeof(step));
			calib_text_errf(err, errlen, "%s = %s is not a whole multiple of its resolution %s%s%s",
				k->key, text, step,
				strcmp(k->unit, "-") != 0 ? " " : "",
				strcmp(k->unit, "-") != 0 ? k->unit : "");
			return -1;
		}
		break;
	}
	if ((iv < min) || (iv > max)) {
		calib_text_errf(err, errlen, "%s = %s is out of range (%s)", k->key, text, range);
		return -1;
	}
	*raw = iv;
	return 0;
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

int calib_text_flat_key(const char *key, const char *value, calib_t *cal, char *msg,
			size_t msglen)
{
	const key_desc_t *k = find_key(key);
	int64_t raw = 0;

	if (k == NULL) {
		calib_text_errf(msg, msglen, "unknown key '%s'", key);
		return -1;
	}
	if (convert_value(k, value, &raw, msg, msglen) != 0) {
		return -1;
	}
	field_set(cal, k, raw);
	return 0;
}

void calib_text_flat_format(const char *key, const calib_t *cal, char *buf, size_t len)
{
	const key_desc_t *k = find_key(key);

	if (k == NULL) {
		snprintf(buf, len, "?");
		return;
	}
	format_value(k, field_get(cal, k), buf, len);
}

/* The flat keys that describe the legacy DiscSpeed/PadForce inputs: a file
 * with [corner] sections configures its inputs there instead. */
static bool legacy_input_key(const char *key)
{
	static const char *const legacy[] = { "disc_speed_id", "pad_force_id",
		"e2e_check_inputs", "input_period_ms", "speed_max_radps",
		"speed_step_max_radps", "force_max_n", "force_step_max_n" };
	size_t i;

	for (i = 0; i < sizeof(legacy) / sizeof(legacy[0]); i++) {
		if (strcmp(key, legacy[i]) == 0) {
			return true;
		}
	}
	return false;
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
	unsigned int seen_line[KEY_COUNT];
	char msg[200];
	calib_t cal;
	unsigned int lineno = 0;
	static calib_sections_t sections; /* large: not on the stack */
	unsigned int legacy_line = 0;
	const char *legacy_key = "";
	unsigned int iface_line = 0;
	char iface[CALIB_IFACE_LEN] = "";

	if ((f == NULL) || (out == NULL)) {
		calib_text_errf(err, errlen, "calib_text_parse: NULL argument");
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
		const key_desc_t *k;
		char *hash;
		char *eq;
		char *key;
		char *value;
		int64_t raw = 0;
		size_t idx;

		lineno++;
		if ((strchr(line, '\n') == NULL) && !feof(f)) {
			calib_text_errf(err, errlen, "%s:%u: line longer than %d characters",
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
				calib_text_errf(err, errlen, "%s:%u: %s", name, lineno, msg);
				return SQ_EBADMSG;
			}
			continue;
		}
		eq = strchr(key, '=');
		if (eq == NULL) {
			calib_text_errf(err, errlen, "%s:%u: expected 'key = value', got '%s'",
				name, lineno, key);
			return SQ_EBADMSG;
		}
		*eq = '\0';
		value = trim(eq + 1);
		key = trim(key);
		if (*key == '\0') {
			calib_text_errf(err, errlen, "%s:%u: missing key before '='", name, lineno);
			return SQ_EBADMSG;
		}
		if (calib_sections_open(&sections)) {
			/* a key of the current [input]/[corner] section */
			if (*value == '\0') {
				calib_text_errf(err, errlen, "%s:%u: %s has no value", name, lineno, key);
				return SQ_EBADMSG;
			}
			if (calib_sections_key(&sections, key, value, lineno, msg, sizeof(msg)) != 0) {
				calib_text_errf(err, errlen, "%s:%u: %s", name, lineno, msg);
				return SQ_EBADMSG;
			}
			continue;
		}
		if (strcmp(key, "input_iface") == 0) {
			/* host only: where the inputs come from (not in the block) */
			if (iface_line != 0U) {
				calib_text_errf(err, errlen, "%s:%u: duplicate key 'input_iface' (first set on line %u)",
					name, lineno, iface_line);
				return SQ_EBADMSG;
			}
			iface_line = lineno;
			if (!calib_iface_name_valid(value)) {
				calib_text_errf(err, errlen, "%s:%u: input_iface = '%s': 1..15 of A-Z a-z 0-9 _ . -",
					name, lineno, value);
				return SQ_EBADMSG;
			}
			snprintf(iface, sizeof(iface), "%s", value);
			continue;
		}
		k = find_key(key);
		if (k == NULL) {
			calib_text_errf(err, errlen, "%s:%u: unknown key '%s' (docs/calib-example.txt lists them)",
				name, lineno, key);
			return SQ_EBADMSG;
		}
		idx = (size_t)(k - keys);
		if (seen_line[idx] != 0U) {
			calib_text_errf(err, errlen, "%s:%u: duplicate key '%s' (first set on line %u)",
				name, lineno, key, seen_line[idx]);
			return SQ_EBADMSG;
		}
		seen_line[idx] = lineno;
		if ((legacy_line == 0U) && legacy_input_key(key)) {
			legacy_line = lineno;
			legacy_key = k->key;
		}
		if (*value == '\0') {
			calib_text_errf(err, errlen, "%s:%u: %s has no value", name, lineno, key);
			return SQ_EBADMSG;
		}
		if (strpbrk(value, " \t") != NULL) {
			calib_text_errf(err, errlen, "%s:%u: %s: one value expected, got '%s'",
				name, lineno, key, value);
			return SQ_EBADMSG;
		}
		if (convert_value(k, value, &raw, msg, sizeof(msg)) != 0) {
			calib_text_errf(err, errlen, "%s:%u: %s", name, lineno, msg);
			return SQ_EBADMSG;
		}
		field_set(&cal, k, raw);
	}
	if (ferror(f)) {
		calib_text_errf(err, errlen, "%s: read error", name);
		return SQ_EIO;
	}
	if (calib_sections_finish(&sections, name, legacy_line, legacy_key, &cal, names, err,
				  errlen) != 0) {
		return SQ_EBADMSG;
	}
	if (calib_validate(&cal) != SQ_OK) {
		calib_map_error_t me = { -1, -1, NULL };
		const key_desc_t *bk = find_key("bitrate_kbps");
		const key_desc_t *dk = find_key("delta_mu");

		if ((int64_t)cal.mu_inf_q30 + cal.delta_mu_q30 < 0) {
			const unsigned int dl = seen_line[(size_t)(dk - keys)];

			if (dl != 0U) {
				calib_text_errf(err, errlen, "%s:%u: mu_inf + delta_mu must not be negative (mu_0 >= 0)",
					name, dl);
			} else {
				calib_text_errf(err, errlen, "%s: mu_inf + delta_mu must not be negative (mu_0 >= 0)",
					name);
			}
		} else if (calib_sd_validate(&cal) != SQ_OK) {
			calib_text_errf(err, errlen, "%s: a standard deviation must be in 0 .. |its parameter| (mu_inf_sd <= 1.5), a brake's own or a corner's",
				name);
		} else if (calib_check(&cal) == CALIB_ERR_BITRATE) {
			calib_text_errf(err, errlen, "%s:%u: %s", name, seen_line[(size_t)(bk - keys)],
				calib_error_name(CALIB_ERR_BITRATE));
		} else if (calib_map_check(&cal, &me) != SQ_OK) {
			calib_text_errf(err, errlen, "%s: the inputs do not set up: %s", name,
				(me.why != NULL) ? me.why : "invalid input map");
		} else {
			calib_text_errf(err, errlen, "%s: the six CAN identifiers (disc_speed_id, pad_force_id, status_id, detail_id, diag_id, detail2_id) must all differ",
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
		calib_text_errf(err, errlen, "calib_text_load: NULL argument");
		return SQ_EINVAL;
	}
	f = fopen(path, "r");
	if (f == NULL) {
		calib_text_errf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
		return SQ_ENOENT;
	}
	rc = calib_text_parse_map(f, path, out, names, err, errlen);
	fclose(f);
	return rc;
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
	for (i = 0; i < KEY_COUNT; i++) {
		const key_desc_t *k = &keys[i];
		char val[48];
		char dval[48];
		char range[100];
		char line[128];

		format_value(k, field_get(cal, k), val, sizeof(val));
		format_value(k, field_get(&def, k), dval, sizeof(dval));
		range_text(k, range, sizeof(range));
		snprintf(line, sizeof(line), "%s = %s", k->key, val);
		if ((cal->n_corners != 0U) && legacy_input_key(k->key)) {
			continue; /* the [input] sections configure the inputs */
		}
		fprintf(f, "%-34s # %s; default %s; range %s\n", line, k->what, dval,
			range);
	}
	if ((names != NULL) && (names->input_iface[0] != '\0')) {
		char line[64];

		snprintf(line, sizeof(line), "input_iface = %s", names->input_iface);
		fprintf(f, "%-34s # the log/SocketCAN interface of the inputs (host only)\n", line);
	}
	if (calib_sections_write(f, cal, names) != SQ_OK) {
		return SQ_EIO;
	}
	fflush(f);
	return ferror(f) ? SQ_EIO : SQ_OK;
}
