# SPDX-License-Identifier: MIT
# Offline replay of candump logs and the decoder:
#   host-sim/candump_log.c   candump -L parser/writer and streaming reader
#   host-sim/cmd_replay.c    squeal-sim replay LOG|-   (virtual time, hal/vbus;
#                            program build/<v>/squeal-replay)
#   host-sim/cmd_decode.c    squeal-sim decode [LOG|-|--iface IF] [--csv]
#   build/test/tests/host-sim/test_candump_log     cmocka, ASan+UBSan
#   tests/host-sim/test_cmd_replay.py     replay/decode end to end (python-can,
#                                   canmatrix, the reference model)
#   tests/host-sim/test_cmd_replay_order.py  out-of-order blocks, restarts, gaps,
#                                   two interfaces, names and reasons
#   tests/host-sim/bench_cmd_replay.sh    make bench: replay vs python-can+canmatrix,
#                                   with and without frame output
#   host-sim/replay_summary.c, json_writer.c   replay --summary-json
#   build/test/tests/host-sim/test_json_writer     cmocka: the JSON writer's output and misuse
#   tests/host-sim/test_replay_summary.py  the JSON vs Python's json + canmatrix
REPLAY_SIM_SRCS := host-sim/candump_log.c host-sim/cmd_decode.c host-sim/decode_inputs.c
SIM_SRCS += $(REPLAY_SIM_SRCS)

# host.mk's rule expands its prerequisites when it is read (before this
# file): name ours explicitly so they are built.
$(foreach v,$(VARIANTS),$(eval build/$(v)/squeal-sim: $(patsubst %.c,build/$(v)/app/%.o,$(REPLAY_SIM_SRCS))))

# replay runs the firmware on the in-memory HAL: its own program,
# build/<v>/squeal-replay (libhal_vbus.a instead of libhal_linux.a), which
# `squeal-sim replay` execs from its own directory, so it is built with it.
REPLAY_SRCS := host-sim/squeal_replay.c host-sim/cmd_replay.c host-sim/candump_log.c \
	host-sim/calib_text.c host-sim/calib_sections.c host-sim/replay_summary.c host-sim/json_writer.c
define replay_program
build/$(1)/squeal-replay: $$(patsubst %.c,build/$(1)/app/%.o,$$(REPLAY_SRCS)) build/$(1)/libfirmware.a build/$(1)/libhal_vbus.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lm
build/$(1)/squeal-sim: build/$(1)/squeal-replay
endef
$(foreach v,$(VARIANTS),$(eval $(call replay_program,$(v))))
ALL_TARGETS += build/host/squeal-replay build/host-fixed/squeal-replay

build/test/tests/host-sim/test_candump_log: build/test/app/tests/host-sim/test_candump_log.o build/test/app/host-sim/candump_log.o
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka

# The end-to-end test runs the sanitizer builds of squeal-sim (float, fixed)
# and the release build for the long determinism run.
tests/host-sim/test_cmd_replay.py: build/test/squeal-sim build/test-fixed/squeal-sim build/host/squeal-sim

TEST_PROGS += build/test/tests/host-sim/test_candump_log tests/host-sim/test_cmd_replay.py

# Time order, restarts, gaps, interfaces and the summary in the vehicle's
# words, on logs generated here (both numeric builds).
tests/host-sim/test_cmd_replay_order.py: build/test/squeal-sim build/test-fixed/squeal-sim
TEST_PROGS += tests/host-sim/test_cmd_replay_order.py

# make bench: replay/decode throughput vs python-can + canmatrix, peak RSS
tests/host-sim/bench_cmd_replay.sh: build/host/squeal-sim
BENCH_PROGS += tests/host-sim/bench_cmd_replay.sh

# replay --summary-json: the summary module alone on four-corner
# frame streams (summary_driver), and the JSON of real replays, both checked
# with Python's json module and an independent recomputation from the frames
# decoded by canmatrix.
build/test/tests/host-sim/summary_driver: build/test/app/tests/host-sim/summary_driver.o build/test/app/host-sim/replay_summary.o build/test/app/host-sim/json_writer.o build/test/app/host-sim/candump_log.o build/test/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^
tests/host-sim/test_replay_summary.py: build/test/tests/host-sim/summary_driver build/test/squeal-sim build/test-fixed/squeal-sim
build/test/tests/host-sim/test_json_writer: build/test/app/tests/host-sim/test_json_writer.o build/test/app/host-sim/json_writer.o
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka
TEST_PROGS += tests/host-sim/test_replay_summary.py build/test/tests/host-sim/test_json_writer

# Replay skips the ticks that change nothing (squeal_app_next_event_us()):
# the same bytes as 1 ms stepping (--step-every-ms) on every scenario, the
# sender's faults, holes, gaps, off-grid times and vehicle layouts, both
# numeric builds.
tests/host-sim/test_replay_skip.py: build/host/squeal-sim build/host-fixed/squeal-sim
TEST_PROGS += tests/host-sim/test_replay_skip.py

# replay --each LOG...: every log as a run of its own (documents, stderr,
# exit status), broken logs between, both builds and their sanitizer builds.
tests/host-sim/test_cmd_replay_each.py: build/host/squeal-sim build/host-fixed/squeal-sim \
		build/test/squeal-sim build/test-fixed/squeal-sim
TEST_PROGS += tests/host-sim/test_cmd_replay_each.py

# squeal_app_next_event_us(): the deadlines by hand, and every tick before
# the reported time changes nothing (cmocka, both numeric builds, ASan+UBSan)
$(foreach v,$(MONITOR_TEST_VARIANTS),$(eval $(call monitor_test_rules,$(v),tests/firmware/app/test_squeal_app_next_event)))
TEST_PROGS += $(foreach v,$(MONITOR_TEST_VARIANTS),build/$(v)/tests/firmware/app/test_squeal_app_next_event)

# make bench: replay against can-utils log2asc and python-can + canmatrix on
# the project's, a vehicle layout's, a vehicle bus's and CAN FD traffic
# (10^6 frames each), as CPU-time ratios from one run
tests/host-sim/bench_replay_vs.py: build/host/squeal-sim
BENCH_PROGS += tests/host-sim/bench_replay_vs.py
