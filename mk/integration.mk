# SPDX-License-Identifier: MIT
# squeal-sim ecu/plant, the calibration text format, and the integration
# tests on real vcan (tests/integration/, in the QEMU guest of
# tests/vcan/guest.sh):
#   build/test/test_calib_text        cmocka, ASan+UBSan: calibration text files

CALIB_TEXT_TEST := build/test/test_calib_text

$(CALIB_TEXT_TEST): build/test/app/tests/unit/test_calib_text.o build/test/app/host-sim/calib_text.o build/test/libfirmware.a
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm

TEST_PROGS += $(CALIB_TEXT_TEST)

# plant -> ecu -> candump on vcan0 in the QEMU guest, checked on the host
# (tests/integration/check_vcan.py): about 60-90 s with the guest's boot.
tests/integration/run-vcan.sh: build/host/squeal-sim
TEST_PROGS += tests/integration/run-vcan.sh

# make bench: live latency and highest zero-loss input rate in the guest
tests/integration/bench-live.sh: build/host/squeal-sim
BENCH_PROGS += tests/integration/bench-live.sh
