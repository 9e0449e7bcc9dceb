# SPDX-License-Identifier: MIT
# Tests on real SocketCAN: hal/linux's self-test in the QEMU guest of
# tests/system/vcan/guest.sh, and hal/linux's host test (no CAN needed).
VCAN_SELFTEST := build/test/tests/system/vcan/selftest_hal_linux
VCAN_HOSTTEST := build/test/tests/hal/linux/test_hal_linux

$(VCAN_SELFTEST): build/test/app/tests/system/vcan/selftest_hal_linux.o build/test/libhal_linux.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^

$(VCAN_HOSTTEST): build/test/app/tests/hal/linux/test_hal_linux.o build/test/app/tests/support/test_contract.o build/test/libhal_linux.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka

# The guest wrapper builds its binary itself too; prebuilding keeps make -j.
test: $(VCAN_SELFTEST)
TEST_PROGS += $(VCAN_HOSTTEST) tests/system/vcan/run-selftest.sh
