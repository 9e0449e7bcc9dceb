# SPDX-License-Identifier: MIT
# Tests on real SocketCAN: hal/linux's self-test in the QEMU guest of
# tests/system/vcan/guest.sh, and hal/linux's host tests (no CAN needed),
# one per file: test_hal_linux (no CAN), _time, _idle, _calib.
VCAN_SELFTEST := build/test/tests/system/vcan/selftest_hal_linux
VCAN_HOSTTEST := build/test/tests/hal/linux/test_hal_linux

$(VCAN_SELFTEST): build/test/app/tests/system/vcan/selftest_hal_linux.o build/test/libhal_linux.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^

VCAN_HOSTTESTS := $(VCAN_HOSTTEST) $(addprefix build/test/tests/hal/linux/test_hal_linux_,time idle calib)
$(VCAN_HOSTTESTS): build/test/tests/%: build/test/app/tests/%.o build/test/app/tests/support/test_contract.o build/test/libhal_linux.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka

# The guest wrapper builds its binary itself too; prebuilding keeps make -j.
test: $(VCAN_SELFTEST)
TEST_PROGS += $(VCAN_HOSTTESTS) tests/system/vcan/run-selftest.sh
