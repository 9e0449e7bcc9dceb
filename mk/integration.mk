# SPDX-License-Identifier: MIT
# squeal-sim ecu/plant, the calibration text format, and the integration
# tests on real vcan (tests/integration/, in the QEMU guest of
# tests/vcan/guest.sh):
#   build/test/test_calib_text        cmocka, ASan+UBSan: calibration text files
#   tests/integration/test_plant_log.py  plant --log (E2E, timing, scenarios,
#                                     faults, seeds) and ecu error paths, no CAN
#   tests/integration/run-vcan.sh     plant/ecu/candump/canplayer on vcan0 in
#                                     the QEMU guest, checked by check_vcan.py
#   tests/integration/bench-live.sh   (make bench) live latency and rates

CALIB_TEXT_TEST := build/test/test_calib_text

$(CALIB_TEXT_TEST): build/test/app/tests/unit/test_calib_text.o build/test/app/host-sim/calib_text.o build/test/app/host-sim/calib_sections.o build/test/libfirmware.a
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm

TEST_PROGS += $(CALIB_TEXT_TEST)

# plant --log and ecu's error paths on any machine (no CAN needed), through
# the ASan+UBSan build of squeal-sim
tests/integration/test_plant_log.py: build/test/squeal-sim
TEST_PROGS += tests/integration/test_plant_log.py

# plant -> ecu -> candump on vcan0 in the QEMU guest, checked on the host
# (tests/integration/check_vcan.py): about 60-90 s with the guest's boot.
tests/integration/run-vcan.sh: build/host/squeal-sim
TEST_PROGS += tests/integration/run-vcan.sh

# make bench: live latency and highest zero-loss input rate in the guest
tests/integration/bench-live.sh: build/host/squeal-sim
BENCH_PROGS += tests/integration/bench-live.sh

# ecu on two buses (vcan0 listen-only inputs, vcan1 outputs) in the guest
tests/integration/run-two-bus.sh: build/host/squeal-sim
TEST_PROGS += tests/integration/run-two-bus.sh
