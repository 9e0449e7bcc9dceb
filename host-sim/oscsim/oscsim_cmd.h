/* SPDX-License-Identifier: MIT */
/*
 * The simulator's subcommands for squeal-sim (wired in by its dispatcher):
 *   squeal-sim map       sweep (a, v0), simulation vs the firmware model
 *   squeal-sim simulate  one point of the full oscillator, CSV trajectory
 * Each takes argv with argv[0] the subcommand name and returns the process
 * exit code (0 ok, 1 a check failed or the run failed, 2 usage).
 */
#ifndef OSCSIM_CMD_H
#define OSCSIM_CMD_H

int oscsim_cmd_map(int argc, char **argv);
int oscsim_cmd_simulate(int argc, char **argv);

#endif /* OSCSIM_CMD_H */
