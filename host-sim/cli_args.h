/* SPDX-License-Identifier: MIT */
/*
 * cli_args: the command line of every squeal-sim subcommand, from one table
 * of options per command.
 *
 *   --name VALUE, --name=VALUE, an unambiguous prefix of a name (as
 *   getopt_long), an optional one-letter form (-v), -h/--help, "--" ends the
 *   options; the other words are positional (a lone "-" too).
 *
 * Values are read strictly (num_text.h): a number must be all number, finite
 * and within the option's range; an integer option takes whole numbers only
 * and may be scaled into the stored unit (--tail-ms into microseconds).
 * Every refusal is one line on stderr, "squeal-sim CMD: --opt: reason", and
 * the command exits 2 (bad usage). --help prints the synopsis, the
 * description, one entry per option of the table (so every option the
 * parser accepts is listed) and the closing text, on stdout.
 */
#ifndef CLI_ARGS_H
#define CLI_ARGS_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef enum {
	CLI_FLAG,   /* no value: *(bool *)dest = true                          */
	CLI_TEXT,   /* *(const char **)dest = the value                        */
	CLI_NAME,   /* text of 1..hi characters without blanks                 */
	CLI_REAL,   /* *(double *)dest, finite, lo..hi                         */
	CLI_U64,    /* *(uint64_t *)dest, whole number lo..hi, times scale     */
	CLI_U32,    /* *(uint32_t *)dest, whole number lo..hi                  */
	CLI_CHOICE  /* *(int *)dest = index of the value in choices            */
} cli_kind_t;

/* CLI_REAL: the lower end itself is refused ((lo, hi]) */
#define CLI_LO_OPEN 0x1U

typedef struct {
	const char *name;      /* without the leading "--"                    */
	char letter;           /* short form (-v), or 0                        */
	cli_kind_t kind;
	void *dest;
	bool *given;           /* set when the option is given; may be NULL    */
	double lo;
	double hi;             /* CLI_REAL/CLI_U64/CLI_U32 range; CLI_NAME length */
	uint64_t scale;        /* CLI_U64: stored = value * scale (0 means 1)  */
	unsigned int flags;
	const char *const *choices; /* CLI_CHOICE: NULL-terminated             */
	const char *meta;      /* the value in the help ("MPS"), NULL for none */
	const char *help;      /* description; '\n' continues it on a new line */
} cli_opt_t;

/* Table rows. The option tables are read by tests/host-sim/test_help.py:
 * one row per option, each starting with CLI_<KIND>("name". */
#define CLI_OPT_FLAG(name, letter, dest, help) \
	{ name, letter, CLI_FLAG, dest, NULL, 0.0, 0.0, 0U, 0U, NULL, NULL, help }
#define CLI_OPT_TEXT(name, dest, given, meta, help) \
	{ name, 0, CLI_TEXT, dest, given, 0.0, 0.0, 0U, 0U, NULL, meta, help }
#define CLI_OPT_NAME(name, dest, given, max_len, meta, help) \
	{ name, 0, CLI_NAME, dest, given, 1.0, max_len, 0U, 0U, NULL, meta, help }
#define CLI_OPT_REAL(name, dest, given, lo, hi, flags, meta, help) \
	{ name, 0, CLI_REAL, dest, given, lo, hi, 0U, flags, NULL, meta, help }
/* any finite number: the command checks the domain itself */
#define CLI_OPT_ANY_REAL(name, dest, given, meta, help) \
	CLI_OPT_REAL(name, dest, given, -HUGE_VAL, HUGE_VAL, 0U, meta, help)
#define CLI_OPT_U64(name, dest, given, lo, hi, scale, meta, help) \
	{ name, 0, CLI_U64, dest, given, lo, hi, scale, 0U, NULL, meta, help }
#define CLI_OPT_U32(name, dest, given, lo, hi, meta, help) \
	{ name, 0, CLI_U32, dest, given, lo, hi, 0U, 0U, NULL, meta, help }
#define CLI_OPT_CHOICE(name, dest, given, choices, meta, help) \
	{ name, 0, CLI_CHOICE, dest, given, 0.0, 0.0, 0U, 0U, choices, meta, help }

typedef struct {
	const char *cmd;          /* "classify": messages read "squeal-sim classify: ..." */
	const char *synopsis;     /* the usage lines, from "usage: "           */
	const char *description;  /* what the command does, before the options */
	const char *closing;      /* after the options: exit status, notes; may be NULL */
	const cli_opt_t *opts;
	size_t n_opts;
	size_t min_pos;           /* positional words allowed                  */
	size_t max_pos;
} cli_spec_t;

#define CLI_COUNT(table) (sizeof(table) / sizeof((table)[0]))
/* a spec's option table (a spec without one leaves both out) */
#define CLI_SPEC_OPTS(table) .opts = (table), .n_opts = CLI_COUNT(table)

typedef enum {
	CLI_OK = 0,    /* parsed: run the command                         */
	CLI_HELP = 1,  /* --help printed: exit 0                          */
	CLI_USAGE = 2  /* one error line printed: exit 2                  */
} cli_result_t;

/*
 * Parse argv[1..argc-1] (argv[0] is the command's name) against spec. The
 * positional words go to pos[0..*n_pos-1] (pos may be NULL when max_pos is
 * 0). Options not given leave their destination as it was (the caller's
 * default).
 */
cli_result_t cli_parse(const cli_spec_t *spec, int argc, char **argv, const char **pos,
		       size_t *n_pos);

/* The exit status of a result that is not CLI_OK: 0 for help, 2 for usage. */
int cli_exit_status(cli_result_t r);

/* The help text of spec on f. */
void cli_help(const cli_spec_t *spec, FILE *f);

/* One usage error of a command: "squeal-sim CMD: --opt: message" on stderr
 * (opt NULL: "squeal-sim CMD: message"). Returns CLI_USAGE.
 * cli_usage_error(spec, fmt, ...): for the checks the table cannot express
 * (options that need each other). */
cli_result_t cli_error(const cli_spec_t *spec, const char *opt, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
#define cli_usage_error(spec, ...) cli_error((spec), NULL, __VA_ARGS__)

#endif /* CLI_ARGS_H */
