/* SPDX-License-Identifier: MIT */
/*
 * candump_log: read and write the log format of `candump -L` (can-utils),
 * one line at a time, with fixed buffers and no heap.
 *
 * Grammar of one frame line (what candump writes, and what its readers such
 * as canplayer accept; the candump -L format of can-utils):
 *
 *   (SECONDS.FRACTION) IFACE FRAME [T|R]
 *
 *   SECONDS   1..20 decimal digits; FRACTION exactly 6 (us) or 9 (ns) digits
 *   IFACE     1..15 characters, no blank (IFNAMSIZ - 1)
 *   FRAME     classic  III#DD..      3 hex digits: standard id <= 0x7FF
 *                      IIIIIIII#DD.. 8 hex digits: extended id <= 0x1FFFFFFF
 *                      0..8 bytes, hex pairs in either case, each pair may
 *                      be preceded by one '.'; with 8 bytes an optional _X
 *                      (X = 9..F: the raw DLC code of a "len8_dlc" frame)
 *             RTR      III#R, III#R5, III#R8_C  (optional length 0..8, _X)
 *             CAN FD   III##F DD..  F = flags nibble 0..F (BRS 1, ESI 2,
 *                      FDF 4), then 0..64 bytes, a valid FD length
 *                      (0..8, 12, 16, 20, 24, 32, 48, 64)
 *             error    8 digits with the error flag 0x20000000 set (first
 *                      digit 2 or 3): the id is the error class, 0..8 bytes
 *             CAN XL   VVPPP#FF:SS:AAAAAAAA#DD..  recognised, not decoded
 *   T|R       candump -x: sent/received by this host (kept, not needed)
 *   Fields are separated by blanks (spaces or tabs); trailing blanks and a
 *   CR are ignored.
 *
 * Other lines: empty or blank lines, comments (first non-blank character
 * '#' or ';'), and "DROPCOUNT: dropped N CAN frame(s) ..." are reported as
 * such. Any other line is malformed, with a reason (candump_err_t), the
 * column where parsing stopped, and nothing else changed: the parser reads
 * exactly len bytes (embedded NUL bytes are an error, not an end) and never
 * reads or writes beyond its arguments.
 *
 * Example lines:
 *   (1700000000.123456) can0 110#5A03E803
 *   (0000000012.340000) vcan0 18FEF100#0102030405060708_C
 *   (1700000000.123456789) can0 123#R8
 *   (1700000000.123456) can0 123##5112233
 *   (1700000000.123456) can0 20000004#0004000000000000
 */
#ifndef CANDUMP_LOG_H
#define CANDUMP_LOG_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define CANDUMP_IFACE_MAX   15U   /* characters, IFNAMSIZ - 1            */
#define CANDUMP_DATA_MAX    64U   /* CAN FD                              */
#define CANDUMP_XL_DATA_MAX 2048U /* CAN XL (length checked, not stored) */
/* Longest line accepted: a CAN XL frame with 2048 bytes and '.' between
 * every byte fits (20 + 1 + 15 + 1 + 21 + 6144 + 2 < 6400). */
#define CANDUMP_LINE_MAX    6400U

#define CANDUMP_ERR_FLAG    0x20000000U /* CAN_ERR_FLAG of linux/can.h   */
#define CANDUMP_ERR_MASK    0x1FFFFFFFU
#define CANDUMP_SFF_MAX     0x7FFU
#define CANDUMP_EFF_MAX     0x1FFFFFFFU

/* What one line is. */
typedef enum {
	CANDUMP_LINE_FRAME = 0,   /* a frame: see candump_frame_t.kind     */
	CANDUMP_LINE_BLANK,       /* empty or only blanks                  */
	CANDUMP_LINE_COMMENT,     /* '#' or ';' comment                    */
	CANDUMP_LINE_DROPCOUNT,   /* candump's drop report (.dropped)      */
	CANDUMP_LINE_MALFORMED    /* see the candump_err_t                 */
} candump_line_t;

typedef enum {
	CANDUMP_KIND_CLASSIC = 0, /* classic data frame                    */
	CANDUMP_KIND_RTR,         /* classic remote frame (len = requested) */
	CANDUMP_KIND_FD,          /* CAN FD data frame                     */
	CANDUMP_KIND_ERROR,       /* error frame: id = error class         */
	CANDUMP_KIND_XL           /* CAN XL frame: not decoded (no data)   */
} candump_kind_t;

/* Why a line is malformed. */
typedef enum {
	CANDUMP_OK = 0,
	CANDUMP_ERR_NUL,            /* a NUL byte inside the line                */
	CANDUMP_ERR_TOO_LONG,       /* longer than CANDUMP_LINE_MAX              */
	CANDUMP_ERR_NOT_A_FRAME,    /* does not start with '(' (and not a comment) */
	CANDUMP_ERR_TIMESTAMP,      /* not (digits.6 or 9 digits)                */
	CANDUMP_ERR_TIME_RANGE,     /* seconds too large for a 64-bit ns count   */
	CANDUMP_ERR_IFACE,          /* missing, or longer than 15 characters     */
	CANDUMP_ERR_NO_FRAME,       /* nothing after the interface               */
	CANDUMP_ERR_NO_HASH,        /* no '#' after the identifier               */
	CANDUMP_ERR_ID_DIGITS,      /* identifier not 3 or 8 hex digits          */
	CANDUMP_ERR_ID_HEX,         /* a non-hex character in the identifier     */
	CANDUMP_ERR_ID_RANGE,       /* 3 digits > 0x7FF, 8 digits > 0x3FFFFFFF   */
	CANDUMP_ERR_DATA_HEX,       /* a non-hex character in the data           */
	CANDUMP_ERR_DATA_ODD,       /* an odd number of data digits              */
	CANDUMP_ERR_DATA_LEN,       /* more bytes than the frame type allows     */
	CANDUMP_ERR_FD_LEN,         /* not a valid CAN FD length                 */
	CANDUMP_ERR_FD_FLAGS,       /* missing or non-hex FD flags digit         */
	CANDUMP_ERR_DLC_CODE,       /* _X not after 8 bytes, or X not 9..F       */
	CANDUMP_ERR_RTR_LEN,        /* RTR length not 0..8                       */
	CANDUMP_ERR_ERROR_FRAME,    /* an error frame in RTR or FD form          */
	CANDUMP_ERR_XL,             /* a malformed CAN XL frame                  */
	CANDUMP_ERR_TRAILING,       /* characters after the frame                */
	CANDUMP_ERR_COUNT
} candump_err_t;

typedef struct {
	uint64_t t_ns;                    /* timestamp in nanoseconds         */
	char iface[CANDUMP_IFACE_MAX + 1U]; /* NUL-terminated                 */
	candump_kind_t kind;
	uint32_t id;         /* 11/29-bit id; error class (no flag); XL priority */
	bool ext;            /* 8-digit identifier (extended; error frames too) */
	uint8_t len;         /* data bytes (RTR: the requested length)          */
	uint8_t len8_dlc;    /* 9..15 from _X, else 0                           */
	uint8_t fd_flags;    /* CAN FD flags nibble                             */
	char dir;            /* 'T', 'R' or 0 (candump -x)                      */
	uint16_t xl_len;     /* CAN XL data bytes (not stored)                  */
	uint32_t dropped;    /* CANDUMP_LINE_DROPCOUNT: frames dropped (0 if unreadable) */
	uint8_t data[CANDUMP_DATA_MAX];
} candump_frame_t;

/*
 * Parse one line of len bytes (without or with its '\n'; a trailing "\n",
 * "\r\n" is ignored). Never reads beyond line[len - 1]. Returns what the
 * line is; *out is filled for FRAME (and .dropped for DROPCOUNT), left in an
 * unspecified but valid state otherwise. *err (may be NULL) is CANDUMP_OK
 * unless MALFORMED; *col (may be NULL) is the 0-based byte where parsing
 * stopped for MALFORMED, else 0. out must not be NULL (MALFORMED with
 * CANDUMP_ERR_NOT_A_FRAME if it is, or if line is NULL with len > 0).
 */
candump_line_t candump_parse_line(const char *line, size_t len,
				  candump_frame_t *out, candump_err_t *err,
				  size_t *col);

/* A short English description of an error ("bad hex digit in data"). */
const char *candump_strerror(candump_err_t err);

/* Longest line candump_format_frame() writes (classic / RTR / error /
 * FD; XL frames are not written), without the NUL:
 * "(" 20 "." 6 ") " iface 15 " " id 8 "##" 1 + 128 data + " T" */
#define CANDUMP_FORMAT_MAX (1U + 20U + 1U + 6U + 2U + CANDUMP_IFACE_MAX + 1U + \
			    8U + 2U + 1U + 2U * CANDUMP_DATA_MAX + 3U + 2U)

/*
 * Write one frame as candump -L does: "(%010llu.%06llu) IFACE FRAME"
 * (microseconds, truncated from t_ns), uppercase hex, a '\n' at the end when
 * newline is true, NUL-terminated. XL frames are refused. Returns the number
 * of characters written (without the NUL), or -1 when the frame cannot be
 * written (bad kind/len/id/iface) or size is too small (buf then holds "").
 */
int candump_format_frame(const candump_frame_t *f, bool newline, char *buf,
			 size_t size);

/*
 * Line reader over a FILE with a fixed buffer (streaming; memory does not
 * grow with the log). A line longer than CANDUMP_LINE_MAX is returned
 * truncated with *too_long set, and the rest of it is skipped.
 */
typedef struct {
	FILE *f;
	size_t pos;
	size_t end;
	bool eof;
	bool error;
	uint64_t line_no;                 /* number of the last line returned */
	char buf[1U << 18];               /* large reads; lines are taken in place */
	char line[CANDUMP_LINE_MAX + 1U];
} candump_reader_t;

void candump_reader_init(candump_reader_t *r, FILE *f);

/*
 * Next line (without its newline; may contain NUL bytes) into *line and *len.
 * Returns 1 for a line, 0 at the end, -1 on a read error.
 */
int candump_reader_next(candump_reader_t *r, const char **line, size_t *len,
			bool *too_long);

/*
 * Messages about malformed lines are held back until the log's first frame:
 * a file without a single CAN frame is one error ("FILE: no CAN frame in N
 * lines"),
 * not a message per line of some other text. The first
 * CANDUMP_PENDING_MAX messages are kept and written when the first frame
 * arrives (the others are counted in one line); after it, each message is
 * written at once.
 */
#define CANDUMP_PENDING_MAX 16U
#define CANDUMP_PENDING_LEN 160U

typedef struct {
	FILE *out;
	const char *log_name;
	bool frames_seen;
	uint32_t n;
	uint64_t more;      /* messages beyond CANDUMP_PENDING_MAX */
	char msg[CANDUMP_PENDING_MAX][CANDUMP_PENDING_LEN];
} candump_pending_t;

void candump_pending_init(candump_pending_t *p, FILE *out, const char *log_name);
/* One message (printf format, a newline is added). */
void candump_pending_report(candump_pending_t *p, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* A frame was read: write what was held back (once). */
void candump_pending_frame(candump_pending_t *p);
/* After the log of `lines` lines: the one line for a log without a frame
 * ("LOG: no CAN frame in N lines"); true then. */
bool candump_pending_no_frames(candump_pending_t *p, uint64_t lines);
/* That line's text (without the newline), cut to len - 1 bytes; a log
 * name of a path's length (4096) fits CANDUMP_NO_FRAMES_TEXT_MAX. */
#define CANDUMP_NO_FRAMES_TEXT_MAX 4160U
void candump_no_frames_text(char *buf, size_t len, const char *log_name, uint64_t lines);

#endif /* CANDUMP_LOG_H */
