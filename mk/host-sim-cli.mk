# SPDX-License-Identifier: MIT
# host-sim's command line: host-sim/cli_args.c (the option tables of every
# squeal-sim subcommand) in each program that parses one, and its tests.
#   squeal-sim       (SIM_SRCS, linked in the top-level Makefile)
#   squeal-replay    (mk/replay.mk's rule links $^)
#   liboscsim.a      (map, simulate; the archive is made of $^)
CLI_ARGS_SRC := host-sim/cli_args.c
SIM_SRCS += $(CLI_ARGS_SRC)
$(foreach v,$(VARIANTS),$(eval build/$(v)/squeal-replay: build/$(v)/app/$(CLI_ARGS_SRC:.c=.o)))
$(foreach v,$(VARIANTS),$(eval build/$(v)/liboscsim.a: build/$(v)/app/$(CLI_ARGS_SRC:.c=.o)))
