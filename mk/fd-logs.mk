# SPDX-License-Identifier: MIT
# CAN FD in logs, replay, decode and the plant's log:
#   host-sim/candump_hal.c   the one candump frame <-> HAL frame conversion
#                            (FD flags both ways), used by replay, decode, plant
#   build/test/tests/host-sim/test_candump_hal   cmocka, ASan+UBSan: FD lines
#                            of every length and flags, both flag conventions,
#                            non-DLC lengths, the HAL conversion, and the writer
#                            against can-utils' log2long/log2asc/asc2log
SIM_SRCS += host-sim/candump_hal.c
# squeal-replay's link rule (mk/replay.mk) takes every prerequisite ($^)
$(foreach v,$(VARIANTS),$(eval build/$(v)/squeal-replay: build/$(v)/app/host-sim/candump_hal.o))

define fd_logs_unit
build/$(1)/tests/host-sim/test_candump_hal: build/$(1)/app/tests/host-sim/test_candump_hal.o build/$(1)/app/host-sim/candump_log.o build/$(1)/app/host-sim/candump_hal.o
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka
endef
$(foreach v,test test-fixed,$(eval $(call fd_logs_unit,$(v))))
TEST_PROGS += build/test/tests/host-sim/test_candump_hal

# replay and decode --inputs-csv of FD logs written by the test (P05 of its
# own, states from the reference model), both numeric builds
tests/host-sim/test_cmd_replay_fd.py: build/test/squeal-sim build/test-fixed/squeal-sim
TEST_PROGS += tests/host-sim/test_cmd_replay_fd.py

# CAN FD on a real vcan0 (MTU 72) in the QEMU guest: canplayer/candump of an
# FD log give the same lines; plant --iface -> ecu of the FD layout live
tests/system/integration/run-fd-log.sh: build/host/squeal-sim
TEST_PROGS += tests/system/integration/run-fd-log.sh

# make bench: replay frames/s of FD traffic beside classic traffic
tests/host-sim/bench_cmd_replay_fd.sh: build/host/squeal-sim
BENCH_PROGS += tests/host-sim/bench_cmd_replay_fd.sh
