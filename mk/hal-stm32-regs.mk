# SPDX-License-Identifier: MIT
# Issue 14 register-level fixes, on the host: the chip files built against
# their real chip.h with the peripherals moved into arrays (tests/target/regsim).
REGSIM_CFLAGS := $(WARN) -O1 -g $(SAN) $(FW_INC) -Ihal/stm32f4

build/test/target/test_regsim_f4: tests/target/test_regsim_f4.c hal/stm32f4/clock.c hal/stm32f4/iwdg.c hal/stm32f4/chip_common.c \
		tests/target/regsim/f4/chip.h hal/stm32f4/stm32f405/chip.h
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -Itests/target/regsim/f4 -o $@ tests/target/test_regsim_f4.c \
		hal/stm32f4/clock.c hal/stm32f4/iwdg.c hal/stm32f4/chip_common.c -lcmocka
TEST_PROGS += build/test/target/test_regsim_f4

# -DBXCAN_SIM: bxcan.c's register accessors go to the test (bus 1 must
# answer SQ_ENODEV without touching one)
build/test/target/test_regsim_f103: tests/target/test_regsim_f103.c hal/stm32f103/chip_f1.c hal/stm32f4/iwdg.c hal/stm32f4/chip_common.c \
		hal/stm32f4/bxcan.c hal/stm32f4/bxcan_timing.c hal/common/hal_can_common.c \
		tests/target/regsim/f103/chip.h hal/stm32f103/stm32f103xb/chip.h
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -DBXCAN_SIM -Itests/target/regsim/f103 -o $@ tests/target/test_regsim_f103.c \
		hal/stm32f103/chip_f1.c hal/stm32f4/iwdg.c hal/stm32f4/chip_common.c hal/stm32f4/bxcan.c hal/stm32f4/bxcan_timing.c \
		hal/common/hal_can_common.c -lcmocka
TEST_PROGS += build/test/target/test_regsim_f103
