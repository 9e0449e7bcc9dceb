/* SPDX-License-Identifier: MIT */
/*
 * candump_log: see candump_log.h for the grammar. The parser is a cursor
 * over the caller's bytes, which it neither copies nor reads beyond
 * line[len - 1]: single bytes are read through byte_at() (peek(),
 * peek_at()), which answers 0 at and past the line's end (as if NUL bytes
 * followed it), and the wider reads (eight bytes at once) are taken only
 * where the line has those eight bytes left.
 *
 * Each field has its general rule, byte by byte. The usual form of a
 * field (what candump writes: the timestamp with ten and six digits, a
 * short interface name, a three-digit identifier, data without '.') is
 * recognised first with a few word operations and gives what the general
 * rule would give; anything else takes the general rule from where the
 * cursor stands. The hot functions are inlined and the cursor's address
 * is not passed to any other, so the compiler keeps it in registers.
 *
 * A NUL byte inside the line makes it malformed (CANDUMP_ERR_NUL at the
 * first one) whatever else is wrong with it, yet lines are not scanned for
 * one before parsing: a NUL reads as 0, like the line's end, and no rule
 * that leads to a frame or a blank line accepts a 0 byte before the end
 * (each byte of those lines is matched against blanks, digits, hex digits,
 * the interface name's characters or a punctuation mark, and the end is
 * tested by position). So a line with a NUL cannot come out as a frame or
 * blank, and only the other outcomes (comment, DROPCOUNT, malformed) look
 * for one before they are returned, as if it had been looked for first.
 */
#include "candump_log.h"

#include <stdarg.h>
#include <string.h>

typedef struct {
	const char *s; /* the caller's bytes: only s[0 .. len - 1] are read */
	size_t len;
	size_t i;      /* never beyond len */
} cursor_t;

/* s[i] of a line of len bytes, 0 at and past its end */
static inline int byte_at(const char *s, size_t len, size_t i)
{
	return (i < len) ? (unsigned char)s[i] : 0;
}

static inline int peek_at(const cursor_t *c, size_t off)
{
	return byte_at(c->s, c->len, c->i + off);
}

static inline int peek(const cursor_t *c)
{
	return peek_at(c, 0U);
}

static inline bool at_end(const cursor_t *c)
{
	return c->i >= c->len;
}

/* ' ' or '\t': one compare and a bit test */
static inline bool is_blank(int ch)
{
	return ((unsigned)ch <= (unsigned)' ') && ((((1ULL << ' ') | (1ULL << '\t')) >> (unsigned)ch) & 1U) != 0U;
}

static inline bool is_digit(int ch)
{
	return (ch >= '0') && (ch <= '9');
}

/* 0..15 for a hex digit, -1 otherwise (a table: the hot path of every
 * identifier and data byte) */
#define HEX_ROW_NONE -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1
static const signed char hex_table[256] = {
	HEX_ROW_NONE, HEX_ROW_NONE,
	-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
	0, 1, 2, 3, 4, 5, 6, 7, 8, 9, -1, -1, -1, -1, -1, -1, /* '0'..'9' */
	-1, 10, 11, 12, 13, 14, 15, -1, -1, -1, -1, -1, -1, -1, -1, -1, /* '@' 'A'..'F' */
	-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
	-1, 10, 11, 12, 13, 14, 15, -1, -1, -1, -1, -1, -1, -1, -1, -1, /* '`' 'a'..'f' */
	HEX_ROW_NONE, HEX_ROW_NONE, HEX_ROW_NONE, HEX_ROW_NONE, HEX_ROW_NONE, HEX_ROW_NONE,
	HEX_ROW_NONE, HEX_ROW_NONE, HEX_ROW_NONE
};
_Static_assert(sizeof(hex_table) == 256U, "one entry per byte");

static inline int hex_val(int ch)
{
	return hex_table[(unsigned char)ch];
}

static inline void skip_blanks(cursor_t *c)
{
	while (!at_end(c) && is_blank(peek(c))) {
		c->i++;
	}
}

static const char *const err_text[CANDUMP_ERR_COUNT] = {
	[CANDUMP_OK] = "ok",
	[CANDUMP_ERR_NUL] = "NUL byte in the line",
	[CANDUMP_ERR_TOO_LONG] = "line too long",
	[CANDUMP_ERR_NOT_A_FRAME] = "not a candump -L line (does not start with '(')",
	[CANDUMP_ERR_TIMESTAMP] = "bad timestamp (want (SECONDS.FRACTION) with 6 or 9 fraction digits)",
	[CANDUMP_ERR_TIME_RANGE] = "timestamp out of range",
	[CANDUMP_ERR_IFACE] = "missing or too long interface name",
	[CANDUMP_ERR_NO_FRAME] = "no frame after the interface name",
	[CANDUMP_ERR_NO_HASH] = "no '#' after the identifier",
	[CANDUMP_ERR_ID_DIGITS] = "identifier must have 3 or 8 hex digits",
	[CANDUMP_ERR_ID_HEX] = "bad hex digit in the identifier",
	[CANDUMP_ERR_ID_RANGE] = "identifier too large",
	[CANDUMP_ERR_DATA_HEX] = "bad hex digit in the data",
	[CANDUMP_ERR_DATA_ODD] = "odd number of data digits",
	[CANDUMP_ERR_DATA_LEN] = "too many data bytes",
	[CANDUMP_ERR_FD_LEN] = "not a valid CAN FD length",
	[CANDUMP_ERR_FD_FLAGS] = "missing or bad CAN FD flags digit",
	[CANDUMP_ERR_DLC_CODE] = "bad _X DLC code (only after 8 bytes, X = 9..F)",
	[CANDUMP_ERR_RTR_LEN] = "bad remote frame length (0..8)",
	[CANDUMP_ERR_ERROR_FRAME] = "error frame in remote or FD form",
	[CANDUMP_ERR_XL] = "malformed CAN XL frame",
	[CANDUMP_ERR_TRAILING] = "unexpected characters after the frame",
};

const char *candump_strerror(candump_err_t err)
{
	if (((unsigned)err < (unsigned)CANDUMP_ERR_COUNT) && (err_text[err] != NULL)) {
		return err_text[err];
	}
	return "unknown error";
}

/* ---- eight characters at once ------------------------------------------------
 * A word read from the line holds its characters first-in-lowest-byte (a
 * little-endian host). The tests below mark failing bytes in their bit 7;
 * a byte below the first failing one never carries or borrows into it, so
 * the lowest mark is exact (marks above it may be wrong, and are not used). */
_Static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "words of characters are little-endian");

#define BYTES(b) (0x0101010101010101ULL * (uint64_t)(b)) /* b in every byte */

static inline uint64_t load8(const char *p)
{
	uint64_t w;

	memcpy(&w, p, sizeof(w));
	return w;
}

/* The index (0..7) of the lowest marked byte of m, 8 if there is none. */
static inline unsigned first_marked(uint64_t m)
{
	return (m == 0U) ? 8U : ((unsigned)__builtin_ctzll(m) >> 3);
}

/* t: a word less '0' in every byte. Marks the bytes that were no decimal
 * digit: above 9, or borrowed (a byte below '0': bit 7 set). */
static inline uint64_t non_digits(uint64_t t)
{
	return ((t + BYTES(0x76)) | t) & BYTES(0x80);
}

/* The value of eight digits, t their word less '0' in every byte: pairs,
 * fours, then all eight combined by multiplications. */
static inline uint64_t digits8(uint64_t t)
{
	t = ((t * 2561U) >> 8) & 0x00FF00FF00FF00FFULL;           /* 10 a + b  */
	t = ((t * 6553601U) >> 16) & 0x0000FFFF0000FFFFULL;       /* 100 p + q */
	return ((t * 42949672960001ULL) >> 32) & 0xFFFFFFFFULL;   /* 10^4 f + g */
}

/* Eight decimal digits at p (eight bytes of the line): true and their
 * value in *v, else false (*v untouched). */
static inline bool eight_digits(const char *p, uint64_t *v)
{
	const uint64_t t = load8(p) - BYTES('0');

	if (non_digits(t) != 0U) {
		return false;
	}
	*v = digits8(t);
	return true;
}

/* The usual timestamp after '(': ten digits of Unix seconds, '.', six of
 * microseconds, ')', in three words (the first two overlap); subtracting
 * ".000000)" leaves the fraction's digit values and 0 for '.' and ')',
 * which then count as digits of value 0 in the limits test and in
 * digits8(): ten times the microseconds. True and *t_ns set for exactly
 * that form (what the general rule in parse_time() makes of it: no range
 * error is possible), false for anything else. */
#define USUAL_TIME_LEN 18U
#define USUAL_FRACTION  0x293030303030302EULL /* ".000000)" */
#define USUAL_FRAC_LIMS 0x7F7676767676767FULL /* '.', ')' exact; digits <= 9 */
static inline bool usual_time(const char *p, size_t left, uint64_t *t_ns)
{
	uint64_t t0;
	uint64_t t1;
	uint64_t f;

	if (left < USUAL_TIME_LEN) {
		return false;
	}
	t0 = load8(p) - BYTES('0');          /* seconds' digits 1..8  */
	t1 = load8(p + 2) - BYTES('0');      /* seconds' digits 3..10 */
	f = load8(p + 10) - USUAL_FRACTION;  /* ".DDDDDD)"            */
	if (((non_digits(t0) | non_digits(t1)) != 0U) ||
	    ((((f + USUAL_FRAC_LIMS) | f) & BYTES(0x80)) != 0U)) {
		return false;
	}
	*t_ns = (digits8(t0) * 100U + ((t1 >> 48) & 0xFFU) * 10U + (t1 >> 56)) * 1000000000ULL +
		digits8(f) * 100U;
	return true;
}

/* Marks the bytes of w below b (b <= 0x80; a borrow runs upward only). */
static inline uint64_t bytes_below(uint64_t w, unsigned b)
{
	return (w - BYTES(b)) & ~w & BYTES(0x80);
}

/* Marks the bytes of w that are no hex digit: no decimal digit (see
 * non_digits()), and with bit 5 set (lowercase) not 0x61..0x66, which
 * adding 0x1F makes 0x80..0x85 (bit 7 set, and the rest below 6). */
static inline uint64_t non_hex(uint64_t w)
{
	const uint64_t d = w - BYTES('0');
	const uint64_t l = (w | BYTES(0x20)) + BYTES(0x1F);

	return ((d + BYTES(0x76)) | d) & (~l | ((l & BYTES(0x7F)) + BYTES(0x7A))) & BYTES(0x80);
}

/* Eight hex digits as their four bytes, the first in the lowest: each
 * digit's value (letters have bit 6 set: + 9), then each pair into the low
 * byte of its 16 bits, then those four bytes together. */
static inline uint32_t hex_bytes(uint64_t w)
{
	uint64_t v = (w & BYTES(0x0F)) + (((w >> 6) & BYTES(1)) * 9U);

	v = ((v << 4) | (v >> 8)) & 0x00FF00FF00FF00FFULL;
	v = (v | (v >> 8)) & 0x0000FFFF0000FFFFULL;
	return (uint32_t)(v | (v >> 16));
}

/* ---- the line -------------------------------------------------------------------- */

/* (SECONDS.FRACTION): the usual form at once, else digit by digit. The
 * loops work on local copies of the cursor: a store through a char pointer
 * may alias it, which would make the compiler reload it after every
 * character. */
static inline candump_err_t parse_time(cursor_t *c, uint64_t *t_ns)
{
	const uint64_t max_s = UINT64_MAX / 1000000000ULL;
	const char *const s = c->s;
	const size_t len = c->len;
	size_t i = c->i + 1U; /* after '(' */
	uint64_t sec = 0U;
	uint64_t frac = 0U;
	unsigned nd = 0U;
	unsigned nf = 0U;
	candump_err_t e = CANDUMP_OK;
	uint64_t eight;

	if (usual_time(&s[i], len - i, t_ns)) {
		c->i = i + USUAL_TIME_LEN;
		return CANDUMP_OK;
	}
	/* the first eight digits at once (a Unix time has ten) */
	if ((len - i >= 8U) && eight_digits(&s[i], &eight)) {
		sec = eight;
		nd = 8U;
		i += 8U;
	}
	while (is_digit(byte_at(s, len, i))) {
		/* 19 digits cannot overflow: the test only from the 20th */
		if ((nd >= 19U) && ((nd >= 20U) || (sec > (UINT64_MAX - 9U) / 10U))) {
			c->i = i;
			return CANDUMP_ERR_TIME_RANGE;
		}
		sec = sec * 10U + (uint64_t)(s[i] - '0');
		nd++;
		i++;
	}
	if ((nd == 0U) || (byte_at(s, len, i) != '.')) {
		c->i = i;
		return CANDUMP_ERR_TIMESTAMP;
	}
	i++;
	while (is_digit(byte_at(s, len, i)) && (nf < 9U)) {
		frac = frac * 10U + (uint64_t)(s[i] - '0');
		nf++;
		i++;
	}
	if (is_digit(byte_at(s, len, i)) || ((nf != 6U) && (nf != 9U)) || (byte_at(s, len, i) != ')')) {
		e = CANDUMP_ERR_TIMESTAMP;
	} else {
		i++;
		if (nf == 6U) {
			frac *= 1000U;
		}
		if ((sec > max_s) || ((sec == max_s) && (frac > UINT64_MAX - max_s * 1000000000ULL))) {
			e = CANDUMP_ERR_TIME_RANGE;
		} else {
			*t_ns = sec * 1000000000ULL + frac;
		}
	}
	c->i = i;
	return e;
}

/* The interface name at the cursor into out->iface (zeroed before), or
 * CANDUMP_ERR_IFACE; it ends at a blank or the line's end (or a NUL: see
 * the top of the file). The usual short name is found in one word: it
 * ends at its first byte below '!' when that is a blank or a NUL; any
 * other name takes the loop. */
static inline candump_err_t parse_iface(cursor_t *c, candump_frame_t *out)
{
	const char *const p = c->s + c->i;
	size_t k;

	if (c->i + 8U <= c->len) {
		const uint64_t w = load8(p);

		k = first_marked(bytes_below(w, '!'));
		if ((k > 0U) && (k < 8U) && (is_blank((unsigned char)p[k]) || (p[k] == '\0'))) {
			const uint64_t name = w & ((1ULL << (8U * k)) - 1U); /* the rest stays 0 */

			memcpy(out->iface, &name, sizeof(name));
			c->i += k;
			return CANDUMP_OK;
		}
	}
	for (k = 0U; (k <= CANDUMP_IFACE_MAX) && (peek_at(c, k) != 0) && !is_blank(peek_at(c, k)); k++) {
	}
	if (k > CANDUMP_IFACE_MAX) {
		c->i += CANDUMP_IFACE_MAX; /* where the name became too long */
		return CANDUMP_ERR_IFACE;
	}
	if (k == 0U) {
		return CANDUMP_ERR_IFACE;
	}
	memcpy(out->iface, p, k);
	c->i += k;
	return CANDUMP_OK;
}

/* Where the data ends: the line's end, a blank, "_X", a CR or LF. */
static inline bool data_end(const char *s, size_t len, size_t i)
{
	const int ch = byte_at(s, len, i);

	return (i >= len) || is_blank(ch) || (ch == '_') || (ch == '\r') || (ch == '\n');
}

/* Hex bytes with optional '.' before each, up to max (stored if data),
 * from s[*pos] (of len bytes) one at a time, after the *n_io bytes taken
 * before: the general rule. *pos ends where parsing stopped, *n_io is the
 * number of bytes (of use when no error). */
static candump_err_t data_bytes(const char *s, size_t len, size_t *pos, uint8_t *data,
				size_t max, size_t *n_io)
{
	size_t i = *pos;
	size_t n = *n_io;
	candump_err_t e = CANDUMP_OK;

	for (;;) {
		int hi;
		int lo;

		if (byte_at(s, len, i) == '.') {
			i++;
		}
		hi = hex_val(byte_at(s, len, i));
		if (hi < 0) {
			e = data_end(s, len, i) ? CANDUMP_OK : CANDUMP_ERR_DATA_HEX;
			break;
		}
		lo = hex_val(byte_at(s, len, i + 1U));
		if (lo < 0) {
			i++;
			e = (data_end(s, len, i) || (byte_at(s, len, i) == '.')) ? CANDUMP_ERR_DATA_ODD :
				CANDUMP_ERR_DATA_HEX;
			break;
		}
		if (n >= max) {
			e = CANDUMP_ERR_DATA_LEN;
			break;
		}
		if (data != NULL) {
			data[n] = (uint8_t)((hi << 4) | lo);
		}
		n++;
		i += 2U;
	}
	*pos = i;
	*n_io = n;
	return e;
}

/* data_bytes() for a frame's data (into data, *n_out bytes), with the
 * usual data taken here first: hex digits without '.' up to the line's
 * end, four bytes and then one byte at a time (as data_bytes() would take
 * them); anything else goes on there. (Not the cursor but its parts: a
 * pointer to it passed to a function that is not inlined, as data_bytes()
 * is not, would keep it in memory throughout.) */
static inline candump_err_t parse_data(const char *s, size_t len, size_t *pos, uint8_t *data,
				       size_t max, size_t *n_out)
{
	size_t i = *pos;
	size_t n = 0U;

	while ((i + 8U <= len) && (n + 4U <= max)) {
		const uint64_t w = load8(&s[i]);
		uint32_t b;

		if (non_hex(w) != 0U) {
			break;
		}
		b = hex_bytes(w);
		memcpy(&data[n], &b, sizeof(b));
		n += 4U;
		i += 8U;
	}
	while ((len - i >= 2U) && (n < max)) {
		const int hi = hex_val(s[i]);
		const int lo = hex_val(s[i + 1U]);

		if ((hi | lo) < 0) {
			break;
		}
		data[n] = (uint8_t)((hi << 4) | lo);
		n++;
		i += 2U;
	}
	*pos = i;
	*n_out = n;
	return (i == len) ? CANDUMP_OK : data_bytes(s, len, pos, data, max, n_out);
}

/* parse_data() at the cursor */
static inline candump_err_t cursor_data(cursor_t *c, uint8_t *data, size_t max, size_t *n_out)
{
	size_t pos = c->i;
	const candump_err_t e = parse_data(c->s, c->len, &pos, data, max, n_out);

	c->i = pos;
	return e;
}

/* optional _X after 8 bytes (classic data or RTR of length 8) */
static inline candump_err_t parse_dlc_code(cursor_t *c, candump_frame_t *out)
{
	int x;

	if (peek(c) != '_') {
		return CANDUMP_OK;
	}
	x = hex_val(peek_at(c, 1U));
	if ((out->len != 8U) || (x < 9)) {
		return CANDUMP_ERR_DLC_CODE;
	}
	out->len8_dlc = (uint8_t)x;
	c->i += 2U;
	return CANDUMP_OK;
}

static inline bool fd_len_valid(size_t n)
{
	return (n <= 8U) || (n == 12U) || (n == 16U) || (n == 20U) || (n == 24U) ||
	       (n == 32U) || (n == 48U) || (n == 64U);
}

/* VVPPP#FF:SS:AAAAAAAA#data; the cursor is on the first id digit. */
static candump_err_t parse_xl(cursor_t *c, candump_frame_t *out)
{
	static const char shape[] = "HH:HH:HHHHHHHH#";
	uint32_t prio = 0U;
	size_t n = 0U;
	size_t k;
	candump_err_t e;

	for (k = 0U; k < 5U; k++) {
		const int v = hex_val(peek(c));

		if (v < 0) {
			return CANDUMP_ERR_XL;
		}
		if (k >= 2U) {
			prio = (prio << 4) | (uint32_t)v;
		}
		c->i++;
	}
	c->i++; /* '#' */
	for (k = 0U; shape[k] != '\0'; k++) {
		const int ch = peek(c);

		if ((shape[k] == 'H') ? (hex_val(ch) < 0) : (ch != shape[k])) {
			return CANDUMP_ERR_XL;
		}
		c->i++;
	}
	{
		size_t pos = c->i;

		e = data_bytes(c->s, c->len, &pos, NULL, CANDUMP_XL_DATA_MAX, &n); /* rare: no fast path */
		c->i = pos;
	}
	if (e != CANDUMP_OK) {
		return e;
	}
	if ((n == 0U) || (prio > CANDUMP_SFF_MAX)) {
		return CANDUMP_ERR_XL;
	}
	out->kind = CANDUMP_KIND_XL;
	out->id = prio;
	out->xl_len = (uint16_t)n;
	return CANDUMP_OK;
}

static inline candump_err_t parse_frame(cursor_t *c, candump_frame_t *out)
{
	uint32_t id = 0U;
	size_t nd;
	size_t n = 0U;
	size_t max = 8U;
	candump_err_t e;

	/* the usual standard identifier "HHH#" at once; else the
	 * identifier's digits one by one (a ninth is already too many) and,
	 * in the same pass, their value (used for 3 or 8 digits only) */
	if ((c->i + 4U <= c->len) && (c->s[c->i + 3U] == '#') &&
	    ((hex_val(c->s[c->i]) | hex_val(c->s[c->i + 1U]) | hex_val(c->s[c->i + 2U])) >= 0)) {
		nd = 3U;
		id = ((uint32_t)hex_val(c->s[c->i]) << 8) | ((uint32_t)hex_val(c->s[c->i + 1U]) << 4) |
		     (uint32_t)hex_val(c->s[c->i + 2U]);
	} else {
		for (nd = 0U; nd < 9U; nd++) {
			const int v = hex_val(peek_at(c, nd));

			if (v < 0) {
				break;
			}
			id = (id << 4) | (uint32_t)v;
		}
	}
	if ((nd == 5U) && (peek_at(c, 5U) == '#') && (peek_at(c, 8U) == ':')) {
		return parse_xl(c, out);
	}
	c->i += nd;
	if ((nd != 3U) && (nd != 8U)) {
		if ((nd > 8U) || (peek(c) == '#')) {
			return CANDUMP_ERR_ID_DIGITS;
		}
		return (at_end(c) || is_blank(peek(c))) ? CANDUMP_ERR_NO_HASH :
			CANDUMP_ERR_ID_HEX;
	}
	out->ext = (nd == 8U);
	if (peek(c) != '#') {
		return (at_end(c) || is_blank(peek(c))) ? CANDUMP_ERR_NO_HASH :
			CANDUMP_ERR_ID_HEX;
	}
	c->i++; /* '#' */
	out->kind = CANDUMP_KIND_CLASSIC;
	if (out->ext) {
		if (id > 0x3FFFFFFFU) {
			return CANDUMP_ERR_ID_RANGE;
		}
		if ((id & CANDUMP_ERR_FLAG) != 0U) {
			out->kind = CANDUMP_KIND_ERROR;
			id &= CANDUMP_ERR_MASK;
		}
	} else if (id > CANDUMP_SFF_MAX) {
		c->i -= 4U;
		return CANDUMP_ERR_ID_RANGE;
	}
	out->id = id;

	if ((peek(c) == 'R') || (peek(c) == 'r')) { /* remote frame */
		if (out->kind == CANDUMP_KIND_ERROR) {
			return CANDUMP_ERR_ERROR_FRAME;
		}
		c->i++;
		out->kind = CANDUMP_KIND_RTR;
		if (is_digit(peek(c))) {
			if (peek(c) > '8') {
				return CANDUMP_ERR_RTR_LEN;
			}
			out->len = (uint8_t)(peek(c) - '0');
			c->i++;
		} else if (hex_val(peek(c)) >= 0) {
			return CANDUMP_ERR_RTR_LEN;
		}
		return parse_dlc_code(c, out);
	}
	if (peek(c) == '#') { /* CAN FD */
		int flags;

		c->i++;
		if (out->kind == CANDUMP_KIND_ERROR) {
			return CANDUMP_ERR_ERROR_FRAME;
		}
		flags = hex_val(peek(c));
		if (flags < 0) {
			return CANDUMP_ERR_FD_FLAGS;
		}
		c->i++;
		out->kind = CANDUMP_KIND_FD;
		out->fd_flags = (uint8_t)flags;
		max = CANDUMP_DATA_MAX;
	}
	/* classic or FD data: one call (a copy less to inline) */
	e = cursor_data(c, out->data, max, &n);
	if (e != CANDUMP_OK) {
		return e;
	}
	if (out->kind == CANDUMP_KIND_FD) {
		if (!fd_len_valid(n)) {
			return CANDUMP_ERR_FD_LEN;
		}
		out->len = (uint8_t)n;
		return (peek(c) == '_') ? CANDUMP_ERR_DLC_CODE : CANDUMP_OK;
	}
	out->len = (uint8_t)n;
	return parse_dlc_code(c, out);
}

/* "DROPCOUNT: dropped N CAN frame(s) on 'IF' socket (total drops M)" */
static uint32_t parse_dropped(const cursor_t *line)
{
	static const char key[] = "DROPCOUNT: dropped ";
	cursor_t c = *line;
	uint64_t n = 0U;
	size_t k;

	for (k = 0U; key[k] != '\0'; k++) {
		if (peek(&c) != (unsigned char)key[k]) {
			return 0U;
		}
		c.i++;
	}
	while (is_digit(peek(&c)) && (n <= UINT32_MAX)) {
		n = n * 10U + (uint64_t)(peek(&c) - '0');
		c.i++;
	}
	return (n > UINT32_MAX) ? UINT32_MAX : (uint32_t)n;
}

candump_line_t candump_parse_line(const char *line, size_t len,
				  candump_frame_t *out, candump_err_t *err,
				  size_t *col)
{
	cursor_t c = { line, len, 0U };
	candump_err_t e = CANDUMP_OK;
	candump_line_t kind = CANDUMP_LINE_MALFORMED;

	if (err != NULL) {
		*err = CANDUMP_OK;
	}
	if (col != NULL) {
		*col = 0U;
	}
	if ((out == NULL) || ((line == NULL) && (len > 0U))) {
		if (err != NULL) {
			*err = CANDUMP_ERR_NOT_A_FRAME;
		}
		return CANDUMP_LINE_MALFORMED;
	}
	/* the line ends before its "\n" or "\r\n" */
	if ((c.len > 0U) && (c.s[c.len - 1U] == '\n')) {
		c.len--;
	}
	if ((c.len > 0U) && (c.s[c.len - 1U] == '\r')) {
		c.len--;
	}
	/* in two parts: one memset of the whole struct becomes a "rep stos",
	 * slow to start, these become a few vector stores */
	memset(out, 0, offsetof(candump_frame_t, data));
	memset(out->data, 0, sizeof(out->data));
	if (c.len > CANDUMP_LINE_MAX) {
		c.i = CANDUMP_LINE_MAX;
		e = CANDUMP_ERR_TOO_LONG;
		goto done; /* before a NUL, as the whole line is not looked at */
	}
	if (peek(&c) != '(') { /* not at once a frame's */
		skip_blanks(&c);
		if (at_end(&c)) {
			kind = CANDUMP_LINE_BLANK;
			goto done;
		}
		if ((peek(&c) == '#') || (peek(&c) == ';')) {
			kind = CANDUMP_LINE_COMMENT;
			goto done;
		}
		if ((c.len - c.i >= 10U) && (memcmp(c.s + c.i, "DROPCOUNT:", 10U) == 0)) {
			out->dropped = parse_dropped(&c);
			kind = CANDUMP_LINE_DROPCOUNT;
			goto done;
		}
		if (peek(&c) != '(') {
			e = CANDUMP_ERR_NOT_A_FRAME;
			goto done;
		}
	}
	e = parse_time(&c, &out->t_ns);
	if (e != CANDUMP_OK) {
		goto done;
	}
	if (!is_blank(peek(&c))) {
		e = CANDUMP_ERR_IFACE;
		goto done;
	}
	c.i++;
	skip_blanks(&c);
	e = parse_iface(&c, out);
	if (e != CANDUMP_OK) {
		goto done;
	}
	skip_blanks(&c);
	if (at_end(&c)) {
		e = CANDUMP_ERR_NO_FRAME;
		goto done;
	}
	e = parse_frame(&c, out);
	if (e != CANDUMP_OK) {
		goto done;
	}
	/* optional direction of candump -x, then nothing */
	if (is_blank(peek(&c))) {
		skip_blanks(&c);
		if (((peek(&c) == 'T') || (peek(&c) == 'R')) &&
		    ((c.i + 1U >= c.len) || is_blank(peek_at(&c, 1U)))) {
			out->dir = (char)peek(&c);
			c.i++;
			skip_blanks(&c);
		}
	}
	if (!at_end(&c)) {
		e = CANDUMP_ERR_TRAILING;
		goto done;
	}
	kind = CANDUMP_LINE_FRAME;
done:
	if ((kind != CANDUMP_LINE_FRAME) && (kind != CANDUMP_LINE_BLANK) &&
	    (e != CANDUMP_ERR_TOO_LONG) && (c.len > 0U)) {
		/* a NUL anywhere comes first (see the top of the file) */
		const char *const nul = memchr(c.s, '\0', c.len);

		if (nul != NULL) {
			kind = CANDUMP_LINE_MALFORMED;
			e = CANDUMP_ERR_NUL;
			c.i = (size_t)(nul - c.s);
		}
	}
	if (e != CANDUMP_OK) {
		kind = CANDUMP_LINE_MALFORMED;
		if (err != NULL) {
			*err = e;
		}
		if (col != NULL) {
			*col = c.i;
		}
	}
	return kind;
}

/* ---- writer ---------------------------------------------------------------- */

static const char hex_upper[] = "0123456789ABCDEF";

/* "00" .. "99" */
static const char dec_pairs[] =
	"00010203040506070809101112131415161718192021222324252627282930313233343536373839"
	"40414243444546474849505152535455565758596061626364656667686970717273747576777879"
	"8081828384858687888990919293949596979899";

/* v < 10^8 as eight decimal digits (leading zeros), the first in the
 * lowest byte: split into 4 + 4 digits in the two halves of a word, each
 * half into 2 + 2 (/ 100 as * 10486 >> 20, exact below 10^4), each of
 * those into 1 + 1 (/ 10 as * 103 >> 10, exact below 100). A split of
 * lanes x into quotients q and remainders r at 2^k above them is
 * (x << k) + q * (1 - d * 2^k): no lane overflows into the next. */
static inline uint64_t dec8(uint32_t v)
{
	uint64_t x = ((uint64_t)v << 32) + (uint64_t)(v / 10000U) * (1U - (10000ULL << 32));
	uint64_t q = ((x * 10486U) >> 20) & 0x0000007F0000007FULL;

	x = (x << 16) + q * (1U - (100ULL << 16));
	q = ((x * 103U) >> 10) & 0x000F000F000F000FULL;
	x = (x << 8) + q * (1U - (10ULL << 8));
	return x | BYTES('0');
}

/* "(SECONDS.MICROSECONDS) " as %010llu.%06llu: at least ten digits of
 * seconds, the microseconds truncated. Ten digits (before the year 2286)
 * and six are the sixteen of the time in microseconds: its two halves of
 * eight digits. */
static char *put_time(char *p, uint64_t t_ns)
{
	const uint64_t t_us = t_ns / 1000U;
	uint64_t w;

	*p++ = '(';
	if (t_us < 10000000000000000ULL) {
		const uint64_t hi = t_us / 100000000U;

		w = dec8((uint32_t)hi);
		memcpy(p, &w, sizeof(w));
		w = dec8((uint32_t)(t_us - hi * 100000000U));
		memcpy(p + 8, &w, 2U);
		p[10] = '.';
		w >>= 16;
		memcpy(p + 11, &w, 6U);
	} else {
		/* eleven digits of seconds (t_ns < 2^64): one, then ten */
		const uint64_t sec = t_us / 1000000U;
		const uint64_t lo = sec % 10000000000ULL;

		*p++ = (char)('0' + sec / 10000000000ULL);
		memcpy(p, &dec_pairs[2U * (lo / 100000000U)], 2U);
		w = dec8((uint32_t)(lo % 100000000U));
		memcpy(p + 2, &w, sizeof(w));
		p[10] = '.';
		w = dec8((uint32_t)(t_us % 1000000U)) >> 16;
		memcpy(p + 11, &w, 6U);
	}
	p[17] = ')';
	p[18] = ' ';
	return p + 19;
}

/* "00" .. "FF": a byte's two hex digits in one copy */
static const char hex_pairs[] =
	"000102030405060708090A0B0C0D0E0F101112131415161718191A1B1C1D1E1F"
	"202122232425262728292A2B2C2D2E2F303132333435363738393A3B3C3D3E3F"
	"404142434445464748494A4B4C4D4E4F505152535455565758595A5B5C5D5E5F"
	"606162636465666768696A6B6C6D6E6F707172737475767778797A7B7C7D7E7F"
	"808182838485868788898A8B8C8D8E8F909192939495969798999A9B9C9D9E9F"
	"A0A1A2A3A4A5A6A7A8A9AAABACADAEAFB0B1B2B3B4B5B6B7B8B9BABBBCBDBEBF"
	"C0C1C2C3C4C5C6C7C8C9CACBCCCDCECFD0D1D2D3D4D5D6D7D8D9DADBDCDDDEDF"
	"E0E1E2E3E4E5E6E7E8E9EAEBECEDEEEFF0F1F2F3F4F5F6F7F8F9FAFBFCFDFEFF";

/* A byte's two hex digits from hex_pairs, the first in the low byte. */
static inline uint64_t hex_pair(uint8_t b)
{
	uint16_t w;

	memcpy(&w, &hex_pairs[2U * b], sizeof(w));
	return w;
}

/* A byte as its two uppercase hex digits at p. */
static inline char *put_pair(char *p, uint8_t b)
{
	memcpy(p, &hex_pairs[2U * b], 2U);
	return p + 2;
}

/* The bytes as uppercase hex pairs: four pairs in one store, then one by
 * one. */
static char *put_bytes(char *p, const uint8_t *data, size_t n)
{
	size_t k = 0U;

	for (; k + 4U <= n; k += 4U) {
		const uint64_t w = hex_pair(data[k]) | (hex_pair(data[k + 1U]) << 16) |
				   (hex_pair(data[k + 2U]) << 32) | (hex_pair(data[k + 3U]) << 48);

		memcpy(p, &w, sizeof(w));
		p += 8;
	}
	for (; k < n; k++) {
		p = put_pair(p, data[k]);
	}
	return p;
}

/* An identifier of 3 (v <= 0xFFF) or 8 hex digits. */
static inline char *put_id(char *p, uint32_t v, bool eight)
{
	if (eight) {
		p = put_pair(p, (uint8_t)(v >> 24));
		p = put_pair(p, (uint8_t)(v >> 16));
		p = put_pair(p, (uint8_t)(v >> 8));
	} else {
		*p++ = hex_upper[(v >> 8) & 0xFU];
	}
	return put_pair(p, (uint8_t)v);
}

/* n (1..15) bytes of a name from its 16-byte field: two copies of 8 or
 * of 4 that overlap (fixed sizes: no call; no byte written beyond n) */
static inline char *put_name(char *p, const char *name, size_t n)
{
	size_t k;

	if (n >= 8U) {
		memcpy(p, name, 8U);
		memcpy(p + n - 8U, name + n - 8U, 8U);
	} else if (n >= 4U) {
		memcpy(p, name, 4U);
		memcpy(p + n - 4U, name + n - 4U, 4U);
	} else {
		for (k = 0U; k < n; k++) {
			p[k] = name[k];
		}
	}
	return p + n;
}

/* The length of the NUL-terminated name in the 16 bytes of an iface
 * field, 16 if it has no NUL (two words: no call to strnlen()). */
static size_t iface_len(const char *iface)
{
	const uint64_t z = bytes_below(load8(iface), 1U);

	return (z != 0U) ? first_marked(z) : (8U + first_marked(bytes_below(load8(iface + 8), 1U)));
}

int candump_format_frame(const candump_frame_t *f, bool newline, char *buf,
			 size_t size)
{
	char tmp[CANDUMP_FORMAT_MAX + 2U];
	char *p;
	char *first;
	size_t ifl;
	size_t n;

	_Static_assert(sizeof(f->iface) == 16U, "the name's field is two words");
	if ((buf == NULL) || (size == 0U)) {
		return -1;
	}
	buf[0] = '\0';
	if (f == NULL) {
		return -1;
	}
	/* straight into buf when the longest line fits, else through tmp */
	first = (size >= sizeof(tmp)) ? buf : tmp;
	p = first;
	ifl = iface_len(f->iface);
	if ((ifl == 0U) || (ifl > CANDUMP_IFACE_MAX)) {
		goto bad;
	}
	p = put_time(p, f->t_ns);
	p = put_name(p, f->iface, ifl);
	*p++ = ' ';
	switch (f->kind) {
	case CANDUMP_KIND_CLASSIC:
	case CANDUMP_KIND_RTR:
		if ((f->len > 8U) || ((f->len8_dlc != 0U) &&
				      ((f->len != 8U) || (f->len8_dlc < 9U) || (f->len8_dlc > 15U)))) {
			goto bad;
		}
		if (f->id > (f->ext ? CANDUMP_EFF_MAX : CANDUMP_SFF_MAX)) {
			goto bad;
		}
		p = put_id(p, f->id, f->ext);
		*p++ = '#';
		if (f->kind == CANDUMP_KIND_RTR) {
			*p++ = 'R';
			if (f->len > 0U) {
				*p++ = (char)('0' + f->len);
			}
		} else {
			p = put_bytes(p, f->data, f->len);
		}
		if (f->len8_dlc != 0U) {
			*p++ = '_';
			*p++ = hex_upper[f->len8_dlc];
		}
		break;
	case CANDUMP_KIND_FD:
		if (!fd_len_valid(f->len) || (f->fd_flags > 0xFU) ||
		    (f->id > (f->ext ? CANDUMP_EFF_MAX : CANDUMP_SFF_MAX))) {
			goto bad;
		}
		p = put_id(p, f->id, f->ext);
		*p++ = '#';
		*p++ = '#';
		*p++ = hex_upper[f->fd_flags];
		p = put_bytes(p, f->data, f->len);
		break;
	case CANDUMP_KIND_ERROR:
		if ((f->id > CANDUMP_ERR_MASK) || (f->len > 8U) ||
		    ((f->len8_dlc != 0U) &&
		     ((f->len != 8U) || (f->len8_dlc < 9U) || (f->len8_dlc > 15U)))) {
			goto bad;
		}
		p = put_id(p, f->id | CANDUMP_ERR_FLAG, true);
		*p++ = '#';
		p = put_bytes(p, f->data, f->len);
		/* an error frame is a classic frame: its DLC code too (as the
		 * parser accepts it, so a round trip keeps it) */
		if (f->len8_dlc != 0U) {
			*p++ = '_';
			*p++ = hex_upper[f->len8_dlc];
		}
		break;
	default:
		goto bad;
	}
	if ((f->dir == 'T') || (f->dir == 'R')) {
		*p++ = ' ';
		*p++ = f->dir;
	}
	if (newline) {
		*p++ = '\n';
	}
	n = (size_t)(p - first);
	if (n + 1U > size) {
		goto bad;
	}
	if (first == tmp) {
		memcpy(buf, tmp, n);
	}
	buf[n] = '\0';
	return (int)n;
bad:
	buf[0] = '\0'; /* nothing half written */
	return -1;
}

/* ---- reader ---------------------------------------------------------------- */

void candump_reader_init(candump_reader_t *r, FILE *f)
{
	r->f = f;
	r->pos = 0U;
	r->end = 0U;
	r->eof = false;
	r->error = false;
	r->line_no = 0U;
	r->line[0] = '\0';
}

/* Keep the unread bytes, read more behind them (one large read; a byte is
 * kept free for the NUL after a last line without '\n'). false at the end
 * of the file or on an error, with nothing read. */
static bool reader_fill(candump_reader_t *r)
{
	const size_t keep = r->end - r->pos;
	size_t got;

	if (r->eof || r->error) {
		return false;
	}
	if ((keep > 0U) && (r->pos > 0U)) {
		memmove(r->buf, r->buf + r->pos, keep);
	}
	r->pos = 0U;
	r->end = keep;
	got = fread(r->buf + keep, 1U, sizeof(r->buf) - 1U - keep, r->f);
	r->end += got;
	if (got == 0U) {
		if (ferror(r->f)) {
			r->error = true;
		}
		r->eof = true;
		return false;
	}
	return true;
}

/* A line longer than CANDUMP_LINE_MAX: its first CANDUMP_LINE_MAX bytes
 * (in r->line) and the rest skipped up to its '\n'. */
static int reader_long_line(candump_reader_t *r, const char **line, size_t *len)
{
	memcpy(r->line, r->buf + r->pos, CANDUMP_LINE_MAX);
	r->line[CANDUMP_LINE_MAX] = '\0';
	r->pos += CANDUMP_LINE_MAX;
	for (;;) {
		const char *nl = memchr(r->buf + r->pos, '\n', r->end - r->pos);

		if (nl != NULL) {
			r->pos = (size_t)(nl - r->buf) + 1U;
			break;
		}
		r->pos = r->end;
		if (!reader_fill(r)) {
			break;
		}
	}
	if (r->error) {
		return -1;
	}
	*line = r->line;
	*len = CANDUMP_LINE_MAX;
	return 1;
}

/* Lines are handed out where they were read (no copy): the '\n' becomes
 * the NUL; a line cut by the buffer's end is moved to its start first. */
int candump_reader_next(candump_reader_t *r, const char **line, size_t *len,
			bool *too_long)
{
	_Static_assert(sizeof(r->buf) > 2U * (CANDUMP_LINE_MAX + 1U), "a whole line fits the buffer");
	for (;;) {
		char *start = r->buf + r->pos;
		const size_t avail = r->end - r->pos;
		char *nl = (avail > 0U) ? memchr(start, '\n', avail) : NULL;
		size_t n;

		if ((nl == NULL) && (avail > CANDUMP_LINE_MAX)) {
			nl = start + avail; /* too long in any case: no need to look further */
		}
		if ((nl == NULL) && !r->eof && !r->error) {
			(void)reader_fill(r); /* the buffer moved: look again */
			continue;
		}
		if (r->error) {
			return -1;
		}
		if ((nl == NULL) && (avail == 0U)) {
			return 0;
		}
		n = (nl != NULL) ? (size_t)(nl - start) : avail;
		r->line_no++;
		if (too_long != NULL) {
			*too_long = n > CANDUMP_LINE_MAX;
		}
		if (n > CANDUMP_LINE_MAX) {
			return reader_long_line(r, line, len);
		}
		start[n] = '\0'; /* the '\n', or the byte kept free after the last line */
		r->pos += (nl != NULL) ? n + 1U : n;
		*line = start;
		*len = n;
		return 1;
	}
}

/* ---- messages held back until the first frame -------------------------------- */

void candump_pending_init(candump_pending_t *p, FILE *out, const char *log_name)
{
	memset(p, 0, sizeof(*p));
	p->out = out;
	p->log_name = log_name;
}

void candump_pending_report(candump_pending_t *p, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	if (p->frames_seen) {
		(void)vfprintf(p->out, fmt, ap);
		(void)fputc('\n', p->out);
	} else if (p->n < CANDUMP_PENDING_MAX) {
		(void)vsnprintf(p->msg[p->n], sizeof(p->msg[0]), fmt, ap);
		p->n++;
	} else {
		p->more++;
	}
	va_end(ap);
}

void candump_pending_frame(candump_pending_t *p)
{
	uint32_t i;

	if (p->frames_seen) {
		return;
	}
	p->frames_seen = true;
	for (i = 0U; i < p->n; i++) {
		(void)fprintf(p->out, "%s\n", p->msg[i]);
	}
	if (p->more != 0U) {
		(void)fprintf(p->out, "%s: %llu more malformed lines before the first frame\n",
			      p->log_name, (unsigned long long)p->more);
	}
}

void candump_no_frames_text(char *buf, size_t len, const char *log_name, uint64_t lines)
{
	(void)snprintf(buf, len, "%s: no CAN frame in %llu line%s", log_name,
		       (unsigned long long)lines, (lines == 1U) ? "" : "s");
}

bool candump_pending_no_frames(candump_pending_t *p, uint64_t lines)
{
	char text[CANDUMP_NO_FRAMES_TEXT_MAX];

	if (p->frames_seen) {
		return false;
	}
	candump_no_frames_text(text, sizeof(text), p->log_name, lines);
	(void)fprintf(p->out, "%s\n", text);
	return true;
}
