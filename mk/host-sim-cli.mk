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

# cli_args on a table of its own (cmocka, ASan+UBSan, both numeric builds)
define cli_args_test
build/$(1)/tests/host-sim/test_cli_args: build/$(1)/app/tests/host-sim/test_cli_args.o build/$(1)/app/$(CLI_ARGS_SRC:.c=.o)
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka
TEST_PROGS += build/$(1)/tests/host-sim/test_cli_args
endef
$(foreach v,test test-fixed,$(eval $(call cli_args_test,$(v))))

# every subcommand's --help against its option table, --version; and
# replay --quiet (release builds, both numeric builds)
tests/host-sim/test_cli_help.py tests/host-sim/test_cmd_replay_quiet.py: build/host/squeal-sim build/host-fixed/squeal-sim
TEST_PROGS += tests/host-sim/test_cli_help.py tests/host-sim/test_cmd_replay_quiet.py
