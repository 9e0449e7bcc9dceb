/* SPDX-License-Identifier: MIT */
/* cli_args: see cli_args.h. */
#include "cli_args.h"

#include <math.h>
#include <stdarg.h>
#include <string.h>

#include "num_text.h"
#include "squeal_model.h"

/* An option's name column in the help: "--name META", at most this wide
 * before the description moves to the next line. */
#define HELP_COLUMN_MAX 24U

cli_result_t cli_error(const cli_spec_t *spec, const char *opt, const char *fmt, ...)
{
	va_list ap;

	fprintf(stderr, "squeal-sim %s: ", spec->cmd);
	if (opt != NULL) {
		fprintf(stderr, "--%s: ", opt);
	}
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
	return CLI_USAGE;
}

int cli_exit_status(cli_result_t r)
{
	return (r == CLI_HELP) ? 0 : 2;
}

/* A whole number lo..hi (decimal; hex too, as the calibration file). */
static cli_result_t set_whole(const cli_spec_t *spec, const cli_opt_t *o, const char *text,
			      uint64_t *out)
{
	int64_t v = 0;

	if (!num_text_int(text, &v) || ((double)v < o->lo) || ((double)v > o->hi)) {
		return cli_error(spec, o->name, "needs a whole number in %.0f..%.0f, got '%s'", o->lo, o->hi,
				 text);
	}
	*out = (uint64_t)v;
	return CLI_OK;
}

static cli_result_t set_real(const cli_spec_t *spec, const cli_opt_t *o, const char *text)
{
	double v = 0.0;
	const bool lo_open = (o->flags & CLI_LO_OPEN) != 0U;

	if (!num_text_real(text, &v)) {
		return cli_error(spec, o->name, "needs a number, got '%s'", text);
	}
	if ((v < o->lo) || (v > o->hi) || (lo_open && (v <= o->lo))) {
		return cli_error(spec, o->name, "needs a number in %s%g, %g], got '%s'", lo_open ? "(" : "[",
				 o->lo, o->hi, text);
	}
	*(double *)o->dest = v;
	return CLI_OK;
}

static cli_result_t set_choice(const cli_spec_t *spec, const cli_opt_t *o, const char *text)
{
	char list[128] = "";
	size_t len = 0U;
	int i;

	for (i = 0; o->choices[i] != NULL; i++) {
		if (strcmp(text, o->choices[i]) == 0) {
			*(int *)o->dest = i;
			return CLI_OK;
		}
		len += (size_t)snprintf(list + len, sizeof(list) - len, "%s%s", (i == 0) ? "" : " or ",
					o->choices[i]);
		if (len >= sizeof(list)) {
			len = sizeof(list) - 1U;
		}
	}
	return cli_error(spec, o->name, "is %s, got '%s'", list, text);
}

/* Store one option's value (text is NULL for a flag). */
static cli_result_t set_value(const cli_spec_t *spec, const cli_opt_t *o, const char *text)
{
	uint64_t whole = 0U;
	cli_result_t r = CLI_OK;

	switch (o->kind) {
	case CLI_FLAG:
		*(bool *)o->dest = true;
		break;
	case CLI_TEXT:
		*(const char **)o->dest = text;
		break;
	case CLI_NAME:
		if ((text[0] == '\0') || ((double)strlen(text) > o->hi) ||
		    (strpbrk(text, " \t\n") != NULL)) {
			return cli_error(spec, o->name, "needs 1..%.0f characters without blanks, got '%s'",
					 o->hi, text);
		}
		*(const char **)o->dest = text;
		break;
	case CLI_REAL:
		r = set_real(spec, o, text);
		break;
	case CLI_U64:
		r = set_whole(spec, o, text, &whole);
		if (r == CLI_OK) {
			*(uint64_t *)o->dest = whole * ((o->scale != 0U) ? o->scale : 1U);
		}
		break;
	case CLI_U32:
		r = set_whole(spec, o, text, &whole);
		if (r == CLI_OK) {
			*(uint32_t *)o->dest = (uint32_t)whole; /* hi of a U32 row fits */
		}
		break;
	default:
		r = set_choice(spec, o, text);
		break;
	}
	if ((r == CLI_OK) && (o->given != NULL)) {
		*o->given = true;
	}
	return r;
}

/* The option a word names: exact, else the one it is a prefix of. */
static const cli_opt_t *find_opt(const cli_spec_t *spec, const char *word, size_t len,
				 bool *ambiguous)
{
	const cli_opt_t *found = NULL;
	size_t i;

	*ambiguous = false;
	for (i = 0U; i < spec->n_opts; i++) {
		const char *n = spec->opts[i].name;

		if ((strncmp(n, word, len) == 0) && (n[len] == '\0')) {
			return &spec->opts[i];
		}
	}
	for (i = 0U; i < spec->n_opts; i++) {
		if (strncmp(spec->opts[i].name, word, len) == 0) {
			*ambiguous = *ambiguous || (found != NULL);
			found = &spec->opts[i];
		}
	}
	return *ambiguous ? NULL : found;
}

static const cli_opt_t *find_letter(const cli_spec_t *spec, char letter)
{
	size_t i;

	for (i = 0U; i < spec->n_opts; i++) {
		if ((spec->opts[i].letter != 0) && (spec->opts[i].letter == letter)) {
			return &spec->opts[i];
		}
	}
	return NULL;
}

static bool is_help(const char *w)
{
	return (strcmp(w, "-h") == 0) || (strcmp(w, "--help") == 0);
}

/* One option word at argv[*i] (and its value after it). */
static cli_result_t take_option(const cli_spec_t *spec, int argc, char **argv, int *i)
{
	const char *w = argv[*i];
	const char *eq = NULL;
	const char *value = NULL;
	const cli_opt_t *o = NULL;
	bool ambiguous = false;

	if (w[1] != '-') {
		o = (w[2] == '\0') ? find_letter(spec, w[1]) : NULL;
	} else {
		eq = strchr(w + 2, '=');
		o = find_opt(spec, w + 2, (eq != NULL) ? (size_t)(eq - (w + 2)) : strlen(w + 2),
			     &ambiguous);
	}
	if (o == NULL) {
		return cli_error(spec, NULL, "%s option '%s' (see --help)",
				       ambiguous ? "ambiguous" : "unknown", w);
	}
	if (o->kind == CLI_FLAG) {
		if (eq != NULL) {
			return cli_error(spec, o->name, "takes no value, got '%s'", w);
		}
		return set_value(spec, o, NULL);
	}
	if (eq != NULL) {
		value = eq + 1;
	} else if (*i + 1 < argc) {
		*i += 1;
		value = argv[*i];
	} else {
		return cli_error(spec, o->name, "needs a value (%s)", (o->meta != NULL) ? o->meta : "see --help");
	}
	return set_value(spec, o, value);
}

cli_result_t cli_parse(const cli_spec_t *spec, int argc, char **argv, const char **pos,
		       size_t *n_pos)
{
	bool options_done = false;
	size_t n = 0U;
	int i;

	for (i = 1; i < argc; i++) {
		const char *w = argv[i];
		cli_result_t r;

		if (!options_done && is_help(w)) {
			cli_help(spec, stdout);
			return CLI_HELP;
		}
		if (!options_done && (strcmp(w, "--") == 0)) {
			options_done = true;
			continue;
		}
		if (options_done || (w[0] != '-') || (w[1] == '\0')) {
			if (n >= spec->max_pos) {
				return cli_error(spec, NULL, "unexpected argument '%s'", w);
			}
			pos[n++] = w;
			continue;
		}
		r = take_option(spec, argc, argv, &i);
		if (r != CLI_OK) {
			return r;
		}
	}
	if (n < spec->min_pos) {
		return cli_error(spec, NULL, "missing argument (see --help)");
	}
	if (n_pos != NULL) {
		*n_pos = n;
	}
	return CLI_OK;
}

/* "--name META" of an option into buf; its length. */
static size_t opt_label(const cli_opt_t *o, char *buf, size_t len)
{
	int n;

	if (o->letter != 0) {
		n = snprintf(buf, len, "-%c, --%s", o->letter, o->name);
	} else {
		n = snprintf(buf, len, "--%s%s%s", o->name, (o->meta != NULL) ? " " : "",
			     (o->meta != NULL) ? o->meta : "");
	}
	return ((n > 0) && ((size_t)n < len)) ? (size_t)n : 0U;
}

/* A description, its continuation lines indented to the column. */
static void put_help(FILE *f, const char *help, size_t column)
{
	const char *p = help;

	for (;;) {
		const char *nl = strchr(p, '\n');

		if (nl == NULL) {
			fprintf(f, "%s\n", p);
			return;
		}
		fprintf(f, "%.*s\n%*s", (int)(nl - p), p, (int)column, "");
		p = nl + 1;
	}
}

void cli_help(const cli_spec_t *spec, FILE *f)
{
	char label[64];
	size_t width = 0U;
	size_t i;

	for (i = 0U; i < spec->n_opts; i++) {
		const size_t l = opt_label(&spec->opts[i], label, sizeof(label));

		if ((l > width) && (l <= HELP_COLUMN_MAX)) {
			width = l;
		}
	}
	fprintf(f, "usage: %s\n\n%s\n\n", spec->synopsis, spec->description);
	for (i = 0U; i < spec->n_opts; i++) {
		const size_t l = opt_label(&spec->opts[i], label, sizeof(label));

		if (l > width) {
			fprintf(f, "  %s\n%*s", label, (int)(width + 4U), "");
		} else {
			fprintf(f, "  %-*s  ", (int)width, label);
		}
		put_help(f, spec->opts[i].help, width + 4U);
	}
	fprintf(f, "  %-*s  this text\n", (int)width, "-h, --help");
	if (spec->closing != NULL) {
		fprintf(f, "\n%s\n", spec->closing);
	}
	fprintf(f, "Numeric build: %s.\n", SQUEAL_NUMERIC_NAME);
}
