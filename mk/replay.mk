# SPDX-License-Identifier: MIT
# Offline replay of candump logs and the decoder (issue 4):
#   host-sim/candump_log.c   candump -L parser/writer and streaming reader
#   host-sim/cmd_replay.c    squeal-sim replay LOG|-   (virtual time, hal_vbus)
#   host-sim/cmd_decode.c    squeal-sim decode [LOG|-|--iface IF] [--csv]
#   build/test/test_candump_log     cmocka, ASan+UBSan
#   tests/replay/test_replay.py     replay/decode end to end (python-can,
#                                   canmatrix, the reference model)
#   tests/replay/bench-replay.sh    make bench: replay vs python-can+canmatrix
REPLAY_SIM_SRCS := host-sim/candump_log.c host-sim/cmd_replay.c host-sim/cmd_decode.c host-sim/decode_inputs.c
SIM_SRCS += $(REPLAY_SIM_SRCS)

# host.mk's rule expands its prerequisites when it is read (before this
# file): name ours explicitly so they are built.
$(foreach v,$(VARIANTS),$(eval build/$(v)/squeal-sim: $(patsubst %.c,build/$(v)/app/%.o,$(REPLAY_SIM_SRCS))))

build/test/test_candump_log: build/test/app/tests/unit/test_candump_log.o build/test/app/host-sim/candump_log.o
	$(CC) $(OPT_test) -o $@ $^ -lcmocka

# The end-to-end test runs the sanitizer builds of squeal-sim (float, fixed)
# and the release build for the long determinism run.
tests/replay/test_replay.py: build/test/squeal-sim build/test-fixed/squeal-sim build/host/squeal-sim

TEST_PROGS += build/test/test_candump_log tests/replay/test_replay.py

# make bench: replay/decode throughput vs python-can + canmatrix, peak RSS
tests/replay/bench-replay.sh: build/host/squeal-sim
BENCH_PROGS += tests/replay/bench-replay.sh
