/* SPDX-License-Identifier: MIT */
/*
 * calib_sections: what the keys of a calibration text file mean, below the
 * file reading of calib_text.c (which calls this module; nothing here calls
 * back up):
 *
 *   calib_key_*()            the flat `key = value` keys, one table row per
 *                            calib_t field: conversion, range, formatting
 *   calib_sections_header()  a `[...]` line starts an `[input NAME]` or
 *                            `[corner POS]` section (the input map,
 *                            docs/calib-input-map.md)
 *   calib_sections_key()     a `key = value` line inside a section
 *   calib_sections_finish()  after the last line: defaults, names resolved,
 *                            every input and corner checked (calib_map.c),
 *                            cal->inputs / corners written
 * Messages come without FILE:LINE (calib_text adds the line it read), except
 * calib_sections_finish's, which name the line of the key responsible.
 */
#ifndef CALIB_SECTIONS_H
#define CALIB_SECTIONS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "calib.h"

#define CALIB_SECTION_NAME_LEN 16U
#define CALIB_SECTIONS_MAX (CALIB_MAX_INPUTS + CALIB_MAX_CORNERS)
#define CALIB_SECTION_KEYS_MAX 40U
#define CALIB_SECTION_VALUE_LEN 160U

typedef struct {
	char key[32];
	char value[CALIB_SECTION_VALUE_LEN];
	unsigned int line;
} calib_section_kv_t;

typedef struct {
	bool is_corner;
	char name[CALIB_SECTION_NAME_LEN]; /* input NAME, or FL/FR/RL/RR */
	unsigned int line;
	unsigned int nkv;
	calib_section_kv_t kv[CALIB_SECTION_KEYS_MAX];
} calib_section_t;

typedef struct {
	unsigned int count;
	unsigned int inputs;
	unsigned int corners;
	calib_section_t sec[CALIB_SECTIONS_MAX];
} calib_sections_t;

#define CALIB_IFACE_LEN 16U
#define CALIB_SIGNAL_NAME_LEN 64U

/* The host-only names of a parsed calibration (never in the ECU block):
 * the `[input NAME]` names and their `signal = MSG.SIG` DBC names, by
 * index in calib_t.inputs, and the top-level `input_iface` ("" when not
 * given). */
typedef struct {
	char input[CALIB_MAX_INPUTS][CALIB_SECTION_NAME_LEN];
	char signal[CALIB_MAX_INPUTS][CALIB_SIGNAL_NAME_LEN];
	char input_iface[CALIB_IFACE_LEN];
} calib_names_t;

/* ---- the flat keys: index 0 .. CALIB_KEY_COUNT - 1 (one per calib_t field) ---- */
#define CALIB_KEY_COUNT 46U
size_t calib_key_count(void);
const char *calib_key_name(size_t i);   /* NULL past the end */
int calib_key_find(const char *name);   /* its index, or -1: no such key */
/* a key of the legacy DiscSpeed/PadForce inputs (refused with [corner]s) */
bool calib_key_legacy_input(size_t i);
/* Convert value with key i's rules into cal: 0, or -1 with msg. */
int calib_key_set(size_t i, const char *value, calib_t *cal, char *msg, size_t msglen);
/* Key i's value in cal: the shortest text that reads back exactly. */
void calib_key_format(size_t i, const calib_t *cal, char *buf, size_t len);
/* "what it is; default X; range A .. B unit" (def: the defaults). */
void calib_key_comment(size_t i, const calib_t *def, char *buf, size_t len);

/* A corner position by name ("FL".."RR", any case): 0..3, or -1. */
int calib_corner_pos(const char *name);
const char *calib_corner_pos_name(unsigned int pos);

/* `input_iface` values: 1..15 of A-Z a-z 0-9 _ . - */
bool calib_iface_name_valid(const char *name);

void calib_sections_init(calib_sections_t *s);

/* Is the state inside a section (keys belong to it)? */
bool calib_sections_open(const calib_sections_t *s);

/* 0, or -1 with msg (no FILE:LINE) */
int calib_sections_header(calib_sections_t *s, const char *text, unsigned int line,
			  char *msg, size_t msglen);
int calib_sections_key(calib_sections_t *s, const char *key, const char *value,
		       unsigned int line, char *msg, size_t msglen);

/*
 * After the file: when there are sections, build the map into *cal (whose
 * flat keys are final) and fill names (may be NULL). legacy_line is the line
 * of a legacy input key in the file (0 if none): refused with corners.
 * 0, or -1 with err = "FILE:LINE: message".
 */
int calib_sections_finish(const calib_sections_t *s, const char *file,
			  unsigned int legacy_line, const char *legacy_key,
			  calib_t *cal, calib_names_t *names, char *err, size_t errlen);

/* The flat keys a [corner] may give (its own brake, geometry and output
 * identifiers), NULL-terminated; a protection's name (none, p01, ...). */
extern const char *const calib_corner_flat_keys[];
const char *calib_prot_name(unsigned int prot);

/* decimal text <-> calib_dec_t, exactly: up to 17 significant digits,
 * plain or exponent notation as Python's repr(float) writes them
 * ("0.0009765625", "1e-07", "0.33333333333333331"); more digits only
 * when they are zeros. calib_dec_format writes the shortest exact text
 * (plain, or mantissa `e` exponent when that is shorter); len >= 32. */
bool calib_dec_parse(const char *text, calib_dec_t *out);
void calib_dec_format(calib_dec_t d, char *buf, size_t len);
double calib_dec_value(calib_dec_t d);

#endif /* CALIB_SECTIONS_H */
