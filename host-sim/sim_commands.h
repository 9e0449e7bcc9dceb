/* SPDX-License-Identifier: MIT */
/* The subcommands of squeal-sim. Each returns the process exit code. */
#ifndef SIM_COMMANDS_H
#define SIM_COMMANDS_H

int cmd_classify(int argc, char **argv);
int cmd_sweep(int argc, char **argv);
int cmd_ecu(int argc, char **argv);
int cmd_plant(int argc, char **argv);
int cmd_replay(int argc, char **argv);
int cmd_decode(int argc, char **argv);
int cmd_calib_check(int argc, char **argv);

#endif /* SIM_COMMANDS_H */
