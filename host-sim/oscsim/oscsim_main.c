/* SPDX-License-Identifier: MIT */
/*
 * oscsim: a stand-alone driver for the simulator's subcommands (the same
 * functions squeal-sim dispatches to as 'map' and 'simulate').
 */
#include <stdio.h>
#include <string.h>

#include "oscsim_cmd.h"

int main(int argc, char **argv)
{
	if (argc >= 2 && strcmp(argv[1], "map") == 0) {
		return oscsim_cmd_map(argc - 1, argv + 1);
	}
	if (argc >= 2 && strcmp(argv[1], "simulate") == 0) {
		return oscsim_cmd_simulate(argc - 1, argv + 1);
	}
	fprintf(stderr, "usage: oscsim map|simulate [OPTIONS]   ('oscsim map --help')\n");
	return 2;
}
