# SPDX-License-Identifier: MIT
# squeal-sim ecu/plant, the calibration text format, and the integration
# tests on real vcan (tests/system/integration/, in the QEMU guest of
# tests/system/vcan/guest.sh):
#   build/test/tests/host-sim/test_calib_text        cmocka, ASan+UBSan: calibration text files
#   tests/host-sim/test_cmd_plant_log.py  plant --log (E2E, timing, scenarios,
#                                     faults, seeds) and ecu error paths, no CAN
#   tests/system/integration/run-vcan.sh     plant/ecu/candump/canplayer on vcan0 in
#                                     the QEMU guest, checked by check_vcan.py
#   tests/system/integration/bench-live.sh   (make bench) live latency and rates

CALIB_TEXT_TEST := build/test/tests/host-sim/test_calib_text

$(CALIB_TEXT_TEST): build/test/app/tests/host-sim/test_calib_text.o build/test/app/host-sim/calib_text.o build/test/app/host-sim/calib_sections.o build/test/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm

TEST_PROGS += $(CALIB_TEXT_TEST)

# plant --log and ecu's error paths on any machine (no CAN needed), through
# the ASan+UBSan build of squeal-sim
tests/host-sim/test_cmd_plant_log.py: build/test/squeal-sim
TEST_PROGS += tests/host-sim/test_cmd_plant_log.py

# plant -> ecu -> candump on vcan0 in the QEMU guest, checked on the host
# (tests/support/check_vcan.py): about 60-90 s with the guest's boot.
tests/system/integration/run-vcan.sh: build/host/squeal-sim
TEST_PROGS += tests/system/integration/run-vcan.sh

# make bench: live latency and highest zero-loss input rate in the guest
tests/system/integration/bench-live.sh: build/host/squeal-sim
BENCH_PROGS += tests/system/integration/bench-live.sh

# ecu on two buses (vcan0 listen-only inputs, vcan1 outputs) in the guest
tests/system/integration/run-two-bus.sh: build/host/squeal-sim
TEST_PROGS += tests/system/integration/run-two-bus.sh
