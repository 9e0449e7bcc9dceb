/* SPDX-License-Identifier: MIT */
/*
 * calib_sections: see calib_sections.h. The meaning of a finished input or
 * corner is checked by the firmware's own calib_map.c, so the text front
 * end and the stored block cannot disagree about what is valid.
 */
#include "calib_sections.h"

#include <ctype.h>
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "calib_map.h"
#include "num_text.h"
#include "text_errf.h"
#include "input_conv.h"
#include "sq_contract.h"
#include "sq_status.h"
#include "squeal_model.h"

static const char *const pos_names[CALIB_MAX_CORNERS] = { "FL", "FR", "RL", "RR" };
static const char *const prot_names[CALIB_PROT_COUNT] = { "none", "p01", "p02", "counter", "p05" };

void calib_sections_init(calib_sections_t *s)
{
	memset(s, 0, sizeof(*s));
}

bool calib_sections_open(const calib_sections_t *s)
{
	return s->count > 0U;
}

/* The words of a yes/no and of a byte order value (any case). */
typedef struct {
	const char *name;
	uint8_t value;
} choice_t;

static const choice_t bool_choices[] = {
	{ "1", 1U }, { "yes", 1U }, { "true", 1U }, { "on", 1U },
	{ "0", 0U }, { "no", 0U }, { "false", 0U }, { "off", 0U }, { NULL, 0U }
};
static const choice_t order_choices[] = {
	{ "intel", (uint8_t)CAN_SIGNAL_INTEL }, { "motorola", (uint8_t)CAN_SIGNAL_MOTOROLA },
	{ NULL, 0U }
};

static bool parse_choice(const choice_t *choices, const char *t, uint8_t *out)
{
	size_t i;

	for (i = 0U; choices[i].name != NULL; i++) {
		if (strcasecmp(t, choices[i].name) == 0) {
			*out = choices[i].value;
			return true;
		}
	}
	return false;
}

/* ---- the flat keys ------------------------------------------------------------ */

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

/* the standard deviation of a model parameter: key KEY_sd, a Q-format field */
#define K_SD(param, field, scale, unit) \
	K(param "_sd", field, KIND_Q, scale, unit, "standard deviation of " param)

#define Q16 65536.0
#define Q12 4096.0
#define Q15 32768.0
#define Q24 16777216.0
#define Q30 1073741824.0

static const key_desc_t key_table[] = {
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
	/* uncertainty (docs/uncertainty.md): 0 <= sd <= |param|
	 * (mu_inf's <= 1.5), |corr| <= 1; all 0: crisp classes as before */
	K_SD("mass_kg", sd.mass_sd_q16, Q16, "kg"),
	K_SD("omega0_radps", sd.omega0_sd_q12, Q12, "rad/s"),
	K_SD("damping", sd.damping_sd_q30, Q30, "-"),
	K("mu_inf_sd", sd.mu_inf_sd_q30, KIND_Q, Q30, "-",
	  "standard deviation of mu_inf (carried; enters no border)"),
	K_SD("delta_mu", sd.delta_mu_sd_q30, Q30, "-"),
	K_SD("slope_spm", sd.slope_sd_q24, Q24, "s/m"),
	K("slope_delta_mu_corr", sd.slope_delta_mu_corr_q30, KIND_Q, Q30, "-",
	  "correlation of slope_spm and delta_mu estimates"),
	K("uncertain_k_sigma", uncertain_k_q16, KIND_Q, Q16, "sigma",
	  "within k sigma of a border: the more severe neighbouring level (0 = off)"),
};

#define KEY_COUNT (sizeof(key_table) / sizeof(key_table[0]))
_Static_assert(KEY_COUNT == CALIB_KEY_COUNT, "one key per calib_t field");

size_t calib_key_count(void)
{
	return KEY_COUNT;
}

const char *calib_key_name(size_t i)
{
	return (i < KEY_COUNT) ? key_table[i].key : NULL;
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

static const key_desc_t *find_key(const char *name)
{
	size_t i;

	for (i = 0; i < KEY_COUNT; i++) {
		if (strcmp(key_table[i].key, name) == 0) {
			return &key_table[i];
		}
	}
	return NULL;
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
	uint8_t b = 0U;
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
			text_errf(err, errlen, "%s must be 'exact' or 'cubic', got '%s'",
				k->key, text);
			return -1;
		}
		return 0;
	case KIND_BOOL:
		if (parse_choice(bool_choices, text, &b)) {
			*raw = b;
		} else {
			text_errf(err, errlen, "%s must be yes/no (or 1/0), got '%s'",
				k->key, text);
			return -1;
		}
		return 0;
	case KIND_INT:
	case KIND_HEX:
		if (!num_text_int(text, &iv)) {
			text_errf(err, errlen, "%s needs an integer (decimal or 0x hex), got '%s'",
				k->key, text);
			return -1;
		}
		break;
	default:
		if (!num_text_real(text, &v)) {
			text_errf(err, errlen, "%s needs a number, got '%s'", k->key, text);
			return -1;
		}
		v *= k->scale;
		if (!(v >= (double)min - 0.5) || !(v <= (double)max + 0.5)) {
			text_errf(err, errlen, "%s = %s is out of range (%s)", k->key,
				text, range);
			return -1;
		}
		iv = (int64_t)llround(v);
		if ((k->kind == KIND_SCALED) &&
		    (fabs(v - (double)iv) > 1e-6 * fmax(1.0, fabs(v)))) {
			char step[40];

			format_value(k, 1, step, sizeof(step));
			text_errf(err, errlen, "%s = %s is not a whole multiple of its resolution %s%s%s",
				k->key, text, step,
				strcmp(k->unit, "-") != 0 ? " " : "",
				strcmp(k->unit, "-") != 0 ? k->unit : "");
			return -1;
		}
		break;
	}
	if ((iv < min) || (iv > max)) {
		text_errf(err, errlen, "%s = %s is out of range (%s)", k->key, text, range);
		return -1;
	}
	*raw = iv;
	return 0;
}

/* A flat key by name (the corner sections read theirs with the flat rules). */
static int flat_key_set(const char *key, const char *value, calib_t *cal, char *msg,
			size_t msglen)
{
	const key_desc_t *k = find_key(key);
	int64_t raw = 0;

	if (k == NULL) {
		text_errf(msg, msglen, "unknown key '%s'", key);
		return -1;
	}
	if (convert_value(k, value, &raw, msg, msglen) != 0) {
		return -1;
	}
	field_set(cal, k, raw);
	return 0;
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
int calib_key_find(const char *name)
{
	const key_desc_t *k = find_key(name);

	return (k != NULL) ? (int)(k - key_table) : -1;
}

bool calib_key_legacy_input(size_t i)
{
	return (i < KEY_COUNT) && legacy_input_key(key_table[i].key);
}

int calib_key_set(size_t i, const char *value, calib_t *cal, char *msg, size_t msglen)
{
	int64_t raw = 0;

	HAL_REQUIRE(i < KEY_COUNT);
	if (convert_value(&key_table[i], value, &raw, msg, msglen) != 0) {
		return -1;
	}
	field_set(cal, &key_table[i], raw);
	return 0;
}

void calib_key_format(size_t i, const calib_t *cal, char *buf, size_t len)
{
	HAL_REQUIRE(i < KEY_COUNT);
	format_value(&key_table[i], field_get(cal, &key_table[i]), buf, len);
}

void calib_key_comment(size_t i, const calib_t *def, char *buf, size_t len)
{
	char dval[48];
	char range[100];

	HAL_REQUIRE(i < KEY_COUNT);
	format_value(&key_table[i], field_get(def, &key_table[i]), dval, sizeof(dval));
	range_text(&key_table[i], range, sizeof(range));
	snprintf(buf, len, "%s; default %s; range %s", key_table[i].what, dval, range);
}

/* ---- numbers ---------------------------------------------------------------- */

bool calib_dec_parse(const char *text, calib_dec_t *out)
{
	const char *p = text;
	bool neg = false;
	int64_t mant = 0;
	int32_t exp = 0;
	int digits = 0;
	bool dot = false;
	calib_dec_t d;

	if ((*p == '+') || (*p == '-')) {
		neg = (*p == '-');
		p++;
	}
	if (!isdigit((unsigned char)*p) && !((*p == '.') && isdigit((unsigned char)p[1]))) {
		return false;
	}
	for (; (*p != '\0') && (*p != 'e') && (*p != 'E'); p++) {
		if (*p == '.') {
			if (dot) {
				return false;
			}
			dot = true;
			continue;
		}
		if (!isdigit((unsigned char)*p)) {
			return false;
		}
		if ((mant == 0) && (*p == '0')) {
			if (dot) {
				exp--;
			}
			continue;
		}
		if (digits >= 17) {
			/* beyond 17 significant digits only zeros are exact */
			if (*p != '0') {
				return false;
			}
			if (!dot) {
				exp++;
			}
			continue;
		}
		mant = mant * 10 + (*p - '0');
		digits++;
		if (dot) {
			exp--;
		}
	}
	if ((*p == 'e') || (*p == 'E')) {
		char *end = NULL;
		long e;

		if (!isdigit((unsigned char)p[1]) &&
		    !(((p[1] == '-') || (p[1] == '+')) && isdigit((unsigned char)p[2]))) {
			return false;
		}
		errno = 0;
		e = strtol(p + 1, &end, 10);
		if ((errno != 0) || (*end != '\0') || (e < -400) || (e > 400)) {
			return false;
		}
		exp += (int32_t)e;
	}
	while ((mant != 0) && ((mant % 10) == 0)) {
		mant /= 10;
		exp++;
	}
	if (mant == 0) {
		exp = 0;
	}
	/* a large exponent may move into the mantissa (1e31 = 10e30) */
	while ((exp > INPUT_DEC_EXP_MAX) && (mant != 0) && (mant <= INPUT_DEC_MANT_MAX / 10)) {
		mant *= 10;
		exp--;
	}
	d.mant = neg ? -mant : mant;
	d.exp = (int8_t)((exp < -128) ? -128 : ((exp > 127) ? 127 : exp));
	if ((exp < INPUT_DEC_EXP_MIN) || (exp > INPUT_DEC_EXP_MAX) || !input_dec_valid(d)) {
		return false;
	}
	*out = d;
	return true;
}

void calib_dec_format(calib_dec_t d, char *buf, size_t len)
{
	char digits[24];
	char plain[64];
	char expo[40];
	const bool neg = d.mant < 0;
	const unsigned long long m = neg ? (unsigned long long)(-d.mant) : (unsigned long long)d.mant;
	const int n = snprintf(digits, sizeof(digits), "%llu", m);
	const int e = d.exp;

	if (e >= 0) {
		snprintf(plain, sizeof(plain), "%s%s%.*s", neg ? "-" : "", digits, e,
			 "000000000000000000000000000000");
	} else if (n > -e) {
		snprintf(plain, sizeof(plain), "%s%.*s.%s", neg ? "-" : "", n + e, digits,
			 digits + n + e);
	} else {
		snprintf(plain, sizeof(plain), "%s0.%.*s%s", neg ? "-" : "", -e - n,
			 "000000000000000000000000000000", digits);
	}
	snprintf(expo, sizeof(expo), "%s%se%d", neg ? "-" : "", digits, e);
	snprintf(buf, len, "%s", ((e != 0) && (strlen(expo) < strlen(plain))) ? expo : plain);
}

double calib_dec_value(calib_dec_t d)
{
	return (double)d.mant * pow(10.0, d.exp);
}

/* ---- lines --------------------------------------------------------------------- */

bool calib_iface_name_valid(const char *n)
{
	size_t i;
	const size_t len = strlen(n);

	if ((len == 0U) || (len >= CALIB_IFACE_LEN)) {
		return false;
	}
	for (i = 0; i < len; i++) {
		if (!isalnum((unsigned char)n[i]) && (strchr("_.-", n[i]) == NULL)) {
			return false;
		}
	}
	return true;
}

static bool valid_name(const char *n)
{
	size_t i;
	const size_t len = strlen(n);

	if ((len == 0U) || (len >= CALIB_SECTION_NAME_LEN)) {
		return false;
	}
	for (i = 0; i < len; i++) {
		if (!isalnum((unsigned char)n[i]) && (n[i] != '_')) {
			return false;
		}
	}
	return true;
}

int calib_corner_pos(const char *n)
{
	int i;

	for (i = 0; i < (int)CALIB_MAX_CORNERS; i++) {
		if (strcasecmp(n, pos_names[i]) == 0) {
			return i;
		}
	}
	return -1;
}

int calib_sections_header(calib_sections_t *s, const char *text, unsigned int line,
			  char *msg, size_t msglen)
{
	char kind[16];
	char name[64];
	char extra[8];
	calib_section_t *sec;
	unsigned int i;
	int n;

	n = sscanf(text, "[%15s %63[^] \t] ]%7s", kind, name, extra);
	if ((n != 2) || (text[strlen(text) - 1U] != ']')) {
		text_errf(msg, msglen, "expected '[input NAME]' or '[corner POS]', got '%s'", text);
		return -1;
	}
	if ((strcmp(kind, "input") != 0) && (strcmp(kind, "corner") != 0)) {
		text_errf(msg, msglen, "unknown section '%s' (input or corner)", kind);
		return -1;
	}
	if (s->count >= CALIB_SECTIONS_MAX) {
		text_errf(msg, msglen, "too many sections");
		return -1;
	}
	if (strcmp(kind, "input") == 0) {
		if (!valid_name(name)) {
			text_errf(msg, msglen, "input name '%s': 1..15 of A-Z a-z 0-9 _", name);
			return -1;
		}
		if (s->inputs >= CALIB_MAX_INPUTS) {
			text_errf(msg, msglen, "more than %u inputs", CALIB_MAX_INPUTS);
			return -1;
		}
	} else {
		if (calib_corner_pos(name) < 0) {
			text_errf(msg, msglen, "corner '%s': FL, FR, RL or RR", name);
			return -1;
		}
	}
	for (i = 0; i < s->count; i++) {
		const calib_section_t *o = &s->sec[i];

		if ((o->is_corner == (strcmp(kind, "corner") == 0)) &&
		    (strcasecmp(o->name, name) == 0)) {
			text_errf(msg, msglen, "duplicate %s '%s' (first on line %u)", kind, name, o->line);
			return -1;
		}
	}
	sec = &s->sec[s->count];
	memset(sec, 0, sizeof(*sec));
	sec->is_corner = strcmp(kind, "corner") == 0;
	{
		/* valid_name()/calib_corner_pos() bounded the length */
		const size_t len = strnlen(name, sizeof(sec->name) - 1U);

		memcpy(sec->name, name, len);
		sec->name[len] = '\0';
	}
	sec->line = line;
	s->count++;
	if (sec->is_corner) {
		s->corners++;
	} else {
		s->inputs++;
	}
	return 0;
}

int calib_sections_key(calib_sections_t *s, const char *key, const char *value,
		       unsigned int line, char *msg, size_t msglen)
{
	calib_section_t *sec = &s->sec[s->count - 1U];
	unsigned int i;

	for (i = 0; i < sec->nkv; i++) {
		if (strcmp(sec->kv[i].key, key) == 0) {
			text_errf(msg, msglen, "duplicate key '%s' (first set on line %u)", key,
			     sec->kv[i].line);
			return -1;
		}
	}
	if ((sec->nkv >= CALIB_SECTION_KEYS_MAX) || (strlen(key) >= sizeof(sec->kv[0].key)) ||
	    (strlen(value) >= sizeof(sec->kv[0].value))) {
		text_errf(msg, msglen, "key or value too long, or too many keys in the section");
		return -1;
	}
	snprintf(sec->kv[sec->nkv].key, sizeof(sec->kv[0].key), "%s", key);
	snprintf(sec->kv[sec->nkv].value, sizeof(sec->kv[0].value), "%s", value);
	sec->kv[sec->nkv].line = line;
	sec->nkv++;
	return 0;
}

/* ---- inputs ---------------------------------------------------------------------- */

typedef struct {
	const calib_section_t *sec;
	const char *file;
	char *err;
	size_t errlen;
} ctx_t;

static const calib_section_kv_t *kv_of(const calib_section_t *sec, const char *key)
{
	unsigned int i;

	for (i = 0; i < sec->nkv; i++) {
		if (strcmp(sec->kv[i].key, key) == 0) {
			return &sec->kv[i];
		}
	}
	return NULL;
}

static int kv_err(const ctx_t *c, const calib_section_kv_t *kv, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

static int kv_err(const ctx_t *c, const calib_section_kv_t *kv, const char *fmt, ...)
{
	char m[200];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(m, sizeof(m), fmt, ap);
	va_end(ap);
	text_errf(c->err, c->errlen, "%s:%u: [%s %s] %s", c->file, kv != NULL ? kv->line : c->sec->line,
	     c->sec->is_corner ? "corner" : "input", c->sec->name, m);
	return -1;
}

/* An integer key in [lo, hi]; *present says whether it was given. */
static int get_int(const ctx_t *c, const char *key, int64_t lo, int64_t hi, bool required,
		   int64_t *out, bool *present)
{
	const calib_section_kv_t *kv = kv_of(c->sec, key);

	if (present != NULL) {
		*present = kv != NULL;
	}
	if (kv == NULL) {
		return required ? kv_err(c, NULL, "%s is required", key) : 0;
	}
	if (!num_text_int(kv->value, out)) {
		return kv_err(c, kv, "%s needs an integer (decimal or 0x hex), got '%s'", key,
			      kv->value);
	}
	if ((*out < lo) || (*out > hi)) {
		return kv_err(c, kv, "%s = %s is out of range (%" PRId64 " .. %" PRId64 ")", key,
			      kv->value, lo, hi);
	}
	return 0;
}

static int get_u8(const ctx_t *c, const char *key, int64_t lo, int64_t hi, bool required,
		  uint8_t *out)
{
	int64_t v = *out;
	bool present = false;

	if (get_int(c, key, lo, hi, required, &v, &present) != 0) {
		return -1;
	}
	*out = (uint8_t)v;
	return 0;
}

/* A key whose value is one of choices (what: them in words, for the messages). */
static int get_choice(const ctx_t *c, const char *key, const choice_t *choices, const char *what,
		      bool required, uint8_t *out, bool *present)
{
	const calib_section_kv_t *kv = kv_of(c->sec, key);

	*present = kv != NULL;
	if (kv == NULL) {
		return required ? kv_err(c, NULL, "%s is required (%s)", key, what) : 0;
	}
	if (!parse_choice(choices, kv->value, out)) {
		return kv_err(c, kv, "%s must be %s, got '%s'", key, what, kv->value);
	}
	return 0;
}

static int get_bool(const ctx_t *c, const char *key, uint8_t *out, bool *present)
{
	return get_choice(c, key, bool_choices, "yes or no", false, out, present);
}

static int get_dec(const ctx_t *c, const char *key, bool required, calib_dec_t *out)
{
	const calib_section_kv_t *kv = kv_of(c->sec, key);

	if (kv == NULL) {
		return required ? kv_err(c, NULL, "%s is required", key) : 0;
	}
	if (!calib_dec_parse(kv->value, out)) {
		return kv_err(c, kv, "%s needs a decimal number (at most 17 significant digits, 1e-30 .. 1e30 steps), got '%s'",
			      key, kv->value);
	}
	return 0;
}

static int get_signal(const ctx_t *c, const char *prefix, bool required, can_signal_t *sig,
		      bool *present)
{
	char k1[32];
	char k2[32];
	char k3[32];
	int64_t v = 0;
	bool p1 = false;
	bool p2 = false;
	bool p3 = false;

	snprintf(k1, sizeof(k1), "%sstart_bit", prefix);
	snprintf(k2, sizeof(k2), "%slength", prefix);
	snprintf(k3, sizeof(k3), "%sbyte_order", prefix);
	if (get_int(c, k1, 0, (int64_t)CAN_SIGNAL_MAX_BITS - 1, required, &v, &p1) != 0) {
		return -1;
	}
	sig->start_bit = (uint16_t)v;
	if (get_int(c, k2, 0, 255, required, &v, &p2) != 0) {
		return -1;
	}
	sig->length = (uint8_t)v;
	if ((p2) && ((v == 0) || (v > 32))) {
		return kv_err(c, kv_of(c->sec, k2), "%s = %" PRId64 ": zero length or over 32 bits",
			      k2, v);
	}
	if (get_choice(c, k3, order_choices, "intel or motorola", required, &sig->byte_order, &p3) != 0) {
		return -1;
	}
	*present = p1 || p2 || p3;
	if (*present && !(p1 && p2 && p3)) {
		return kv_err(c, NULL, "%sstart_bit, %slength and %sbyte_order go together",
			      prefix, prefix, prefix);
	}
	if (*present && !can_signal_valid(sig)) {
		return kv_err(c, kv_of(c->sec, k1), "%s signal runs beyond the 512 bits of an FD frame",
			      prefix[0] != '\0' ? prefix : "value");
	}
	return 0;
}

/* A "not available" code of the value signal (key na_raw or na_raw2, its
 * flag set when given): a signed signal's code may be written as a number
 * (-32768, as a VAL_ table writes it) or as its raw bits (0x8000). */
static int get_na(const ctx_t *c, const char *key, uint8_t flag, calib_input_t *in, uint32_t *raw)
{
	int64_t v = 0;
	bool present = false;

	if (get_int(c, key, INT32_MIN, UINT32_MAX, false, &v, &present) != 0) {
		return -1;
	}
	if (!present) {
		return 0;
	}
	if ((v < 0) && ((in->sig.is_signed == 0U) ||
			(v < -((int64_t)1 << (in->sig.length - 1U))))) {
		return kv_err(c, kv_of(c->sec, key),
			      "%s = %" PRId64 " is not a value of this %s %u-bit signal", key, v,
			      (in->sig.is_signed != 0U) ? "signed" : "unsigned", (unsigned)in->sig.length);
	}
	in->flags |= flag;
	*raw = (v < 0) ? can_signal_raw_of(&in->sig, v) : (uint32_t)v;
	return 0;
}

/* A selector (prefix "mux_" or "mux2_"): its signal and value, all four or
 * none, and the inclusive end of its range (default: the value). value_sig:
 * the value signal the selector must not overlap (NULL: not checked here). */
static int get_selector(const ctx_t *c, const char *prefix, const can_signal_t *value_sig,
			can_signal_t *sig, uint8_t flag, uint8_t *flags, uint32_t *value,
			uint32_t *value_max)
{
	char key[32];
	char key_max[32];
	bool present = false;
	int64_t v = 0;

	(void)snprintf(key, sizeof(key), "%svalue", prefix);
	(void)snprintf(key_max, sizeof(key_max), "%svalue_max", prefix);
	if (get_signal(c, prefix, false, sig, &present) != 0) {
		return -1;
	}
	if (present != (kv_of(c->sec, key) != NULL)) {
		return kv_err(c, NULL, "%sstart_bit, %slength, %sbyte_order and %svalue: all four or none",
			      prefix, prefix, prefix, prefix);
	}
	if (present) {
		*flags |= flag;
		if (get_int(c, key, 0, UINT32_MAX, true, &v, NULL) != 0) {
			return -1;
		}
		*value = (uint32_t)v;
		*value_max = (uint32_t)v;
		if ((value_sig != NULL) && can_signal_overlap(sig, value_sig)) {
			return kv_err(c, kv_of(c->sec, "mux_start_bit"),
				      "the mux selector overlaps the value signal");
		}
	}
	if (get_int(c, key_max, 0, UINT32_MAX, false, &v, &present) != 0) {
		return -1;
	}
	if (present) {
		if ((*flags & flag) == 0U) {
			return kv_err(c, kv_of(c->sec, key_max), "%s without the %s* selector", key_max,
				      prefix);
		}
		*value_max = (uint32_t)v;
	}
	return 0;
}

static int get_dil(const ctx_t *c, calib_input_t *in)
{
	const calib_section_kv_t *kv = kv_of(c->sec, "data_id_list");
	char buf[CALIB_SECTION_VALUE_LEN];
	char *save = NULL;
	char *tok;
	unsigned int n = 0;

	if (kv == NULL) {
		return kv_err(c, NULL, "data_id_list is required for p02 (16 bytes)");
	}
	snprintf(buf, sizeof(buf), "%s", kv->value);
	for (tok = strtok_r(buf, " \t,", &save); tok != NULL; tok = strtok_r(NULL, " \t,", &save)) {
		int64_t v;

		if ((n >= CALIB_DATA_ID_LIST_LEN) || !num_text_int(tok, &v) || (v < 0) || (v > 255)) {
			return kv_err(c, kv, "data_id_list: 16 byte values 0..255 separated by blanks or commas");
		}
		in->data_id_list[n] = (uint8_t)v;
		n++;
	}
	if (n != CALIB_DATA_ID_LIST_LEN) {
		return kv_err(c, kv, "data_id_list: 16 byte values 0..255 separated by blanks or commas");
	}
	return 0;
}

static const char *const input_keys[] = {
	"id", "extended", "min_dlc", "exact_dlc", "start_bit", "length", "byte_order", "signed",
	"factor", "offset", "unit", "signal", "mux_start_bit", "mux_length", "mux_byte_order",
	"mux_value", "mux_value_max", "mux2_start_bit", "mux2_length", "mux2_byte_order",
	"mux2_value", "mux2_value_max", "na_raw", "na_raw2", "qualifier_bit", "qualifier_invalid", "protection",
	"data_id", "data_id_list", "counter_start_bit", "counter_length",
	"counter_byte_order", "counter_modulus", "max_delta_counter", "period_ms",
	"stale_cycles", "max", "min", "step_max", "fd", "e2e_offset_byte", NULL
};

/* the brake's standard deviations: flat keys a corner may override */
#define SD_KEYS "mass_kg_sd", "omega0_radps_sd", "damping_sd", "mu_inf_sd", "delta_mu_sd", \
	"slope_spm_sd", "slope_delta_mu_corr"

static const char *const corner_keys[] = {
	"speed", "force", "piston_area_mm2", "efficiency", "axle_factor", "friction_faces",
	"torque_share",
	"mass_kg", "omega0_radps", "damping", "mu_inf", "delta_mu", "slope_spm", "criterion",
	"pad_radius_m", "wheel_radius_m", "status_id", "detail_id", "detail2_id", "diag_id",
	SD_KEYS, NULL
};

/* The flat keys a corner section may give (its own brake, geometry and
 * output identifiers), each read and written with the flat key's rules. */
const char *const calib_corner_flat_keys[] = { "mass_kg", "omega0_radps", "damping", "mu_inf",
	"delta_mu", "slope_spm", "criterion", "pad_radius_m", "wheel_radius_m",
	"status_id", "detail_id", "detail2_id", "diag_id", SD_KEYS, NULL };

static int unknown_keys(const ctx_t *c, const char *const *known)
{
	unsigned int i;

	for (i = 0; i < c->sec->nkv; i++) {
		size_t j;
		bool ok = false;

		for (j = 0; known[j] != NULL; j++) {
			ok = ok || (strcmp(known[j], c->sec->kv[i].key) == 0);
		}
		if (!ok) {
			return kv_err(c, &c->sec->kv[i], "unknown key '%s' (docs/calib-input-map.md)",
				      c->sec->kv[i].key);
		}
	}
	return 0;
}

/* The key a message starts with ("max is below min", "mux_value_max
 * below ..."), when the section gives it. */
static const calib_section_kv_t *lead_key(const calib_section_t *sec, const char *why)
{
	char key[32];
	size_t n = strcspn(why, " :");

	if ((n == 0U) || (n >= sizeof(key))) {
		return NULL;
	}
	memcpy(key, why, n);
	key[n] = '\0';
	return kv_of(sec, key);
}

/* The line of the key a calib_input_check() message is about. */
static const calib_section_kv_t *blame(const ctx_t *c, const char *why)
{
	if (lead_key(c->sec, why) != NULL) {
		return lead_key(c->sec, why);
	}
	static const char *const keys[] = { "min_dlc", "e2e_offset_byte", "max_delta_counter", "counter_modulus",
		"mux_value", "qualifier", "na_raw", "step_max", "period_ms", "factor",
		"length", "id", NULL };
	size_t i;

	for (i = 0; keys[i] != NULL; i++) {
		if (strstr(why, keys[i]) != NULL) {
			const calib_section_kv_t *kv = kv_of(c->sec, keys[i]);

			if ((kv == NULL) && (strcmp(keys[i], "qualifier") == 0)) {
				kv = kv_of(c->sec, "qualifier_bit");
			}
			return kv;
		}
	}
	return NULL;
}

static int build_input(const ctx_t *c, calib_input_t *in)
{
	int64_t v = 0;
	bool present = false;
	uint8_t b = 0U;
	const calib_section_kv_t *kv;
	input_unit_t unit;
	const char *why = NULL;
	uint8_t need;

	memset(in, 0, sizeof(*in));
	in->max_delta_counter = 2U;
	in->stale_cycles = 3U;
	in->qualifier_invalid = 1U;
	if (unknown_keys(c, input_keys) != 0) {
		return -1;
	}
	if (get_int(c, "id", 0, 0x1FFFFFFF, true, &v, NULL) != 0) {
		return -1;
	}
	in->id = (uint32_t)v;
	if (get_bool(c, "extended", &b, &present) != 0) {
		return -1;
	}
	if (present && (b != 0U)) {
		in->flags |= CALIB_IN_EXTENDED;
	}
	if ((in->id > 0x7FFU) && ((in->flags & CALIB_IN_EXTENDED) == 0U)) {
		return kv_err(c, kv_of(c->sec, "id"), "id 0x%" PRIX32 " is above 0x7FF: needs extended = yes",
			      in->id);
	}
	if (get_bool(c, "fd", &in->fd, &present) != 0) {
		return -1;
	}
	if (get_bool(c, "exact_dlc", &b, &present) != 0) {
		return -1;
	}
	if (present && (b != 0U)) {
		in->flags |= CALIB_IN_DLC_EXACT;
	}
	if (get_signal(c, "", true, &in->sig, &present) != 0) {
		return -1;
	}
	if (get_bool(c, "signed", &in->sig.is_signed, &present) != 0) {
		return -1;
	}
	if (get_dec(c, "factor", true, &in->factor) != 0) {
		return -1;
	}
	if (in->factor.mant == 0) {
		return kv_err(c, kv_of(c->sec, "factor"), "factor 0");
	}
	if (get_dec(c, "offset", false, &in->offset) != 0) {
		return -1;
	}
	kv = kv_of(c->sec, "unit");
	if (kv == NULL) {
		return kv_err(c, NULL, "unit is required (km/h kph m/s mph rad/s rpm 1/min N kN bar kPa MPa psi Nm)");
	}
	if (input_unit_parse(kv->value, &unit) != SQ_OK) {
		return kv_err(c, kv, "unknown unit '%s' (km/h kph m/s mph rad/s rpm 1/min N kN bar kPa MPa psi Nm)",
			      kv->value);
	}
	in->unit = (uint8_t)unit;
	/* multiplexer, and a second selector condition */
	if ((get_selector(c, "mux_", &in->sig, &in->mux, CALIB_IN_MUX, &in->flags, &in->mux_value,
			  &in->mux_value_max) != 0) ||
	    (get_selector(c, "mux2_", NULL, &in->mux2, CALIB_IN_MUX2, &in->flags, &in->mux2_value,
			  &in->mux2_value_max) != 0)) {
		return -1;
	}
	kv = kv_of(c->sec, "signal");
	if (kv != NULL) {
		size_t j;
		const size_t len = strlen(kv->value);
		bool ok = (len >= 1U) && (len < CALIB_SIGNAL_NAME_LEN);

		for (j = 0; ok && (j < len); j++) {
			ok = isgraph((unsigned char)kv->value[j]) != 0;
		}
		if (!ok) {
			return kv_err(c, kv, "signal: the DBC name MSG.SIG, 1..%u printable characters without blanks",
				      CALIB_SIGNAL_NAME_LEN - 1U);
		}
	}
	if ((get_na(c, "na_raw", CALIB_IN_NA, in, &in->na_raw) != 0) ||
	    (get_na(c, "na_raw2", CALIB_IN_NA2, in, &in->na_raw2) != 0)) {
		return -1;
	}
	if (get_int(c, "qualifier_bit", 0, (int64_t)CAN_SIGNAL_MAX_BITS - 1, false, &v, &present) != 0) {
		return -1;
	}
	if (present) {
		in->flags |= CALIB_IN_QUALIFIER;
		in->qualifier_bit = (uint16_t)v;
	}
	if (get_u8(c, "qualifier_invalid", 0, 1, false, &in->qualifier_invalid) != 0) {
		return -1;
	}
	kv = kv_of(c->sec, "protection");
	if (kv != NULL) {
		unsigned int p;

		for (p = 0; p < (unsigned int)CALIB_PROT_COUNT; p++) {
			if (strcasecmp(kv->value, prot_names[p]) == 0) {
				break;
			}
		}
		if (p == (unsigned int)CALIB_PROT_COUNT) {
			return kv_err(c, kv, "protection must be none, p01, p02, p05 or counter, got '%s'",
				      kv->value);
		}
		in->protection = (uint8_t)p;
	}
	if ((in->protection == (uint8_t)CALIB_PROT_P01) ||
	    (in->protection == (uint8_t)CALIB_PROT_P05)) {
		if (get_int(c, "data_id", 0, 0xFFFF, true, &v, NULL) != 0) {
			return -1;
		}
		in->data_id = (uint16_t)v;
	}
	if (get_u8(c, "e2e_offset_byte", 0, (int64_t)CAN_SIGNAL_MAX_BYTES - 3, false,
		   &in->e2e_offset_byte) != 0) {
		return -1;
	}
	if ((kv_of(c->sec, "e2e_offset_byte") != NULL) &&
	    (in->protection != (uint8_t)CALIB_PROT_P05)) {
		return kv_err(c, kv_of(c->sec, "e2e_offset_byte"), "e2e_offset_byte is for protection = p05");
	}
	if ((in->protection == (uint8_t)CALIB_PROT_P02) && (get_dil(c, in) != 0)) {
		return -1;
	}
	if (in->protection == (uint8_t)CALIB_PROT_COUNTER) {
		if (get_signal(c, "counter_", true, &in->counter, &present) != 0) {
			return -1;
		}
		in->counter_modulus = (uint8_t)((in->counter.length <= 4U) ?
						(1U << in->counter.length) : 16U);
		if (get_u8(c, "counter_modulus", 2, 16, false, &in->counter_modulus) != 0) {
			return -1;
		}
	}
	if (get_u8(c, "max_delta_counter", 1, 255, false, &in->max_delta_counter) != 0) {
		return -1;
	}
	if (get_int(c, "period_ms", 1, 1000, true, &v, NULL) != 0) {
		return -1;
	}
	in->period_ms = (uint16_t)v;
	if (get_u8(c, "stale_cycles", 1, 100, false, &in->stale_cycles) != 0) {
		return -1;
	}
	if ((get_dec(c, "max", true, &in->max) != 0) || (get_dec(c, "min", false, &in->min) != 0) ||
	    (get_dec(c, "step_max", true, &in->step_max) != 0)) {
		return -1;
	}
	need = calib_input_needed_dlc(in);
	in->min_dlc = calib_input_frame_len(in); /* fd: the next FD length */
	if (get_int(c, "min_dlc", 0, (int64_t)CAN_SIGNAL_MAX_BYTES, false, &v, &present) != 0) {
		return -1;
	}
	if (present) {
		if (v < need) {
			return kv_err(c, kv_of(c->sec, "min_dlc"),
				      "a signal beyond min_dlc %" PRId64 " (its bits need %u bytes)", v, need);
		}
		in->min_dlc = (uint8_t)v;
	}
	if (calib_input_check(in, &why) != SQ_OK) {
		return kv_err(c, blame(c, why), "%s", why);
	}
	return 0;
}

/* ---- corners --------------------------------------------------------------------- */

static int input_index(const calib_sections_t *s, const char *name)
{
	unsigned int i;
	int idx = 0;

	for (i = 0; i < s->count; i++) {
		if (!s->sec[i].is_corner) {
			if (strcmp(s->sec[i].name, name) == 0) {
				return idx;
			}
			idx++;
		}
	}
	return -1;
}

static int ppm_key(const ctx_t *c, const char *key, uint32_t max_ppm, uint32_t *out)
{
	const calib_section_kv_t *kv = kv_of(c->sec, key);
	calib_dec_t d;
	double v;

	if (kv == NULL) {
		return 0;
	}
	if (!calib_dec_parse(kv->value, &d)) {
		return kv_err(c, kv, "%s needs a number, got '%s'", key, kv->value);
	}
	v = calib_dec_value(d) * 1e6;
	if (!(v > 0.0) || (v > (double)max_ppm) || (fabs(v - nearbyint(v)) > 1e-6)) {
		return kv_err(c, kv, "%s = %s must be in (0, %g] with at most 6 decimals", key,
			      kv->value, (double)max_ppm / 1e6);
	}
	*out = (uint32_t)nearbyint(v);
	return 0;
}

static int build_corner(const ctx_t *c, const calib_sections_t *s, const calib_t *flat,
			calib_corner_t *corner)
{
	const calib_section_kv_t *kv;
	calib_t tmp = *flat;
	char msg[200];
	size_t i;
	int idx;
	const int pos = calib_corner_pos(c->sec->name);

	if (unknown_keys(c, corner_keys) != 0) {
		return -1;
	}
	/* the corner's defaults (outputs: the flat ones + 0x10 pos), then its
	 * keys, each read with the flat key's own rules */
	calib_corner_defaults(flat, (uint8_t)pos, corner);
	calib_flat_from_corner(corner, &tmp);
	for (i = 0; calib_corner_flat_keys[i] != NULL; i++) {
		kv = kv_of(c->sec, calib_corner_flat_keys[i]);
		if ((kv != NULL) && (flat_key_set(kv->key, kv->value, &tmp, msg, sizeof(msg)) != 0)) {
			return kv_err(c, kv, "%s", msg);
		}
	}
	calib_corner_from_flat(&tmp, corner);
	for (i = 0; i < 2U; i++) {
		const char *key = (i == 0U) ? "speed" : "force";

		kv = kv_of(c->sec, key);
		if (kv == NULL) {
			return kv_err(c, NULL, "%s is required (the name of an [input])", key);
		}
		idx = input_index(s, kv->value);
		if (idx < 0) {
			return kv_err(c, kv, "%s names an unknown input '%s'", key, kv->value);
		}
		if (i == 0U) {
			corner->speed_input = (uint8_t)idx;
		} else {
			corner->force_input = (uint8_t)idx;
		}
	}
	kv = kv_of(c->sec, "piston_area_mm2");
	if (kv != NULL) {
		calib_dec_t d;
		double v;

		if (!calib_dec_parse(kv->value, &d)) {
			return kv_err(c, kv, "piston_area_mm2 needs a number, got '%s'", kv->value);
		}
		v = calib_dec_value(d) * 100.0;
		if (!(v >= 1.0) || (v > 1e8) || (fabs(v - nearbyint(v)) > 1e-6)) {
			return kv_err(c, kv, "piston_area_mm2 = %s: 0.01 .. 1e6 mm^2 in steps of 0.01",
				      kv->value);
		}
		corner->piston_area_cmm2 = (uint32_t)nearbyint(v);
	}
	if ((ppm_key(c, "torque_share", 1000000U, &corner->torque_share_ppm) != 0) ||
	    (ppm_key(c, "efficiency", 1000000U, &corner->efficiency_ppm) != 0) ||
	    (ppm_key(c, "axle_factor", 4000000U, &corner->axle_factor_ppm) != 0) ||
	    (get_u8(c, "friction_faces", 1, 4, false, &corner->friction_faces) != 0)) {
		return -1;
	}
	return 0;
}

static int corner_blame(const ctx_t *c, const char *why)
{
	const char *key = NULL;

	if (strncmp(why, "torque_share", 12U) == 0) {
		key = "torque_share";
	} else if (strstr(why, "speed") != NULL) {
		key = "speed";
	} else if ((strstr(why, "force") != NULL) || (strstr(why, "pressure") != NULL)) {
		key = (strstr(why, "piston") != NULL) ? NULL : "force";
	} else {
		key = NULL;
	}
	return kv_err(c, (key != NULL) ? kv_of(c->sec, key) : NULL, "%s", why);
}

int calib_sections_finish(const calib_sections_t *s, const char *file,
			  unsigned int legacy_line, const char *legacy_key,
			  calib_t *cal, calib_names_t *names, char *err, size_t errlen)
{
	calib_t out = *cal;
	calib_map_error_t me;
	unsigned int i;
	unsigned int ni = 0;
	unsigned int nc = 0;
	ctx_t c = { NULL, file, err, errlen };

	if (s->count == 0U) {
		return 0;
	}
	for (i = 0; i < s->count; i++) {
		c.sec = &s->sec[i];
		if (!c.sec->is_corner) {
			if (build_input(&c, &out.inputs[ni]) != 0) {
				return -1;
			}
			if (names != NULL) {
				const calib_section_kv_t *sig = kv_of(c.sec, "signal");

				snprintf(names->input[ni], sizeof(names->input[ni]), "%s", c.sec->name);
				snprintf(names->signal[ni], sizeof(names->signal[ni]), "%.63s",
					 (sig != NULL) ? sig->value : "");
			}
			ni++;
		}
	}
	out.n_inputs = (uint8_t)ni;
	if (s->corners == 0U) {
		text_errf(err, errlen, "%s:%u: [input] sections but no [corner] uses them", file,
		     s->sec[0].line);
		return -1;
	}
	if (legacy_line != 0U) {
		text_errf(err, errlen, "%s:%u: legacy input key '%s' in a file with [corner] sections",
		     file, legacy_line, legacy_key);
		return -1;
	}
	for (i = 0; i < s->count; i++) {
		c.sec = &s->sec[i];
		if (c.sec->is_corner) {
			if (build_corner(&c, s, cal, &out.corners[nc]) != 0) {
				return -1;
			}
			nc++;
		}
	}
	out.n_corners = (uint8_t)nc;
	if (calib_map_check(&out, &me) != SQ_OK) {
		/* find the section it concerns */
		unsigned int want = (me.corner >= 0) ? (unsigned int)me.corner : 0U;
		unsigned int k = 0;

		for (i = 0; i < s->count; i++) {
			if (s->sec[i].is_corner == (me.corner >= 0)) {
				if (k == ((me.corner >= 0) ? want : (unsigned int)(me.input >= 0 ? me.input : 0))) {
					c.sec = &s->sec[i];
					break;
				}
				k++;
			}
		}
		if ((me.corner >= 0) && (me.input >= 0) && (me.why != NULL)) {
			/* an input that cannot be set up with this corner's
			 * geometry: the input's key, when the message names one */
			unsigned int n = 0;

			for (i = 0; i < s->count; i++) {
				if (!s->sec[i].is_corner) {
					if ((n == (unsigned int)me.input) && (lead_key(&s->sec[i], me.why) != NULL)) {
						ctx_t ci = { &s->sec[i], file, err, errlen };

						return kv_err(&ci, lead_key(&s->sec[i], me.why), "%s (with [corner %s])",
							      me.why, c.sec->name);
					}
					n++;
				}
			}
		}
		return corner_blame(&c, me.why != NULL ? me.why : "invalid input map");
	}
	*cal = out;
	return 0;
}

const char *calib_corner_pos_name(unsigned int pos)
{
	return (pos < CALIB_MAX_CORNERS) ? pos_names[pos] : "?";
}

const char *calib_prot_name(unsigned int prot)
{
	return (prot < CALIB_PROT_COUNT) ? prot_names[prot] : "?";
}
