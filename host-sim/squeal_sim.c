/* SPDX-License-Identifier: MIT */
/*
 * squeal-sim: the Linux programs around the brake-squeal monitor firmware,
 * one binary with subcommands (docs/commands.md).
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "squeal_model.h"
#include "sim_commands.h"
#include "sim_version.h"
#include "oscsim/oscsim_cmd.h"

/*
 * replay runs the firmware on the in-memory HAL, linked into its own
 * program (a backend is chosen at link time): squeal-replay, next to this
 * executable, takes over this process with the same arguments.
 */
static int cmd_replay_exec(int argc, char **argv)
{
	char path[PATH_MAX];
	ssize_t n = readlink("/proc/self/exe", path, sizeof(path) - 1U);
	char *slash;

	(void)argc;
	if (n <= 0) {
		fprintf(stderr, "squeal-sim replay: cannot find this program: %s\n", strerror(errno));
		return 1;
	}
	path[n] = '\0';
	slash = strrchr(path, '/');
	if ((slash == NULL) ||
	    ((size_t)(slash - path) + sizeof("/squeal-replay") > sizeof(path))) {
		fprintf(stderr, "squeal-sim replay: path too long: %s\n", path);
		return 1;
	}
	memcpy(slash, "/squeal-replay", sizeof("/squeal-replay"));
	(void)execv(path, argv);
	fprintf(stderr, "squeal-sim replay: cannot run %s: %s (make builds it)\n", path,
		strerror(errno));
	return 1;
}

typedef struct {
	const char *name;
	int (*run)(int argc, char **argv);
	const char *summary;
} command_t;

static const command_t commands[] = {
	{ "classify", cmd_classify, "classify one operating point (model only)" },
	{ "sweep", cmd_sweep, "classify a table of operating points (demo)" },
	{ "ecu", cmd_ecu, "the monitor firmware on a SocketCAN interface" },
	{ "plant", cmd_plant, "send DiscSpeed/PadForce from a scenario (or write a log)" },
	{ "replay", cmd_replay_exec, "feed a candump log through the firmware in virtual time" },
	{ "decode", cmd_decode, "print CAN frames as physical values (log or interface)" },
	{ "calib-check", cmd_calib_check, "does a calibration file load and set up exactly?" },
	{ "map", oscsim_cmd_map, "stability map: model vs simulation (CSV)" },
	{ "simulate", oscsim_cmd_simulate, "simulate the stick-slip oscillator at one point" },
};

static void usage(FILE *f)
{
	size_t i;

	fprintf(f, "usage: squeal-sim COMMAND [OPTIONS]   (numeric build: %s)\n\n",
		SQUEAL_NUMERIC_NAME);
	fprintf(f, "commands:\n");
	for (i = 0; i < sizeof(commands) / sizeof(commands[0]); i++) {
		fprintf(f, "  %-11s %s\n", commands[i].name, commands[i].summary);
	}
	fprintf(f, "\n'squeal-sim COMMAND --help' describes each command;\n"
		"'squeal-sim --version' prints the version and the numeric build.\n");
}

int main(int argc, char **argv)
{
	size_t i;

	if (argc < 2) {
		usage(stderr);
		return 2;
	}
	if ((strcmp(argv[1], "--help") == 0) || (strcmp(argv[1], "-h") == 0)) {
		usage(stdout);
		return 0;
	}
	if (strcmp(argv[1], "--version") == 0) {
		printf("squeal-sim %s (numeric build: %s)\n", SQUEAL_SIM_VERSION, SQUEAL_NUMERIC_NAME);
		return 0;
	}
	for (i = 0; i < sizeof(commands) / sizeof(commands[0]); i++) {
		if (strcmp(argv[1], commands[i].name) == 0) {
			return commands[i].run(argc - 1, argv + 1);
		}
	}
	fprintf(stderr, "squeal-sim: unknown command '%s'\n", argv[1]);
	usage(stderr);
	return 2;
}
