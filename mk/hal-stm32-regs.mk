# SPDX-License-Identifier: MIT
# The chip files on the host, built against their real chip.h with the
# peripherals moved into arrays (tests/support/regsim).
REGSIM_CFLAGS := $(WARN) -O1 -g $(SAN) $(FW_INC) -Ihal/stm32f4 -Itests/support

# One STM32F4 file per program, on tests/support/regsim/f4 (the register
# arrays are regsim_f4.c's; each test defines the functions of the other
# files the one under test calls; $(2): more sources, e.g. the contract
# catcher):
# build/test/tests/hal/stm32f4/test_MODULE
REGSIM_F4_DEPS := tests/support/regsim/f4/chip.h tests/support/regsim/f4/regsim_f4.c hal/stm32f4/stm32f405/chip.h \
	hal/stm32f4/cortex_m.h tests/support/sq_cmocka.h
define regsim_f4_test
build/test/tests/hal/stm32f4/test_$(1): tests/hal/stm32f4/test_$(1).c hal/stm32f4/$(1).c $(2) $$(REGSIM_F4_DEPS)
	@mkdir -p $$(@D)
	$$(CC) $$(REGSIM_CFLAGS) -Itests/support/regsim/f4 -o $$@ tests/hal/stm32f4/test_$(1).c hal/stm32f4/$(1).c \
		tests/support/regsim/f4/regsim_f4.c $(2) -lcmocka
endef
REGSIM_F4_MODULES := clock iwdg can_pins platform_faults selftest systick
$(foreach m,$(filter-out selftest clock systick,$(REGSIM_F4_MODULES)),$(eval $(call regsim_f4_test,$(m))))
$(eval $(call regsim_f4_test,selftest,tests/support/test_contract.c))
# the clock rates it sets live in the F4/F103 common part
$(eval $(call regsim_f4_test,clock,hal/stm32f4/chip_common.c hal/stm32f4/hse_meter.c))

# systick.c included by its test, which sets the millisecond count near
# its 32-bit wrap
build/test/tests/hal/stm32f4/test_systick: tests/hal/stm32f4/test_systick.c hal/stm32f4/systick.c $(REGSIM_F4_DEPS)
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -Itests/support/regsim/f4 -o $@ tests/hal/stm32f4/test_systick.c \
		tests/support/regsim/f4/regsim_f4.c -lcmocka

# the HSE meter alone on a timer in an array (the test's crystal answers
# the capture waits)
build/test/tests/hal/stm32f4/test_hse_meter: tests/hal/stm32f4/test_hse_meter.c hal/stm32f4/hse_meter.c \
		hal/stm32f4/stm32_hse_meter.h hal/stm32f4/cortex_m.h
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -o $@ tests/hal/stm32f4/test_hse_meter.c hal/stm32f4/hse_meter.c -lcmocka
TEST_PROGS += build/test/tests/hal/stm32f4/test_hse_meter

# board.c's main() built as board_main(): the test has its own
build/test/regsim/hal/stm32f4/board.o: hal/stm32f4/board.c $(REGSIM_F4_DEPS)
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -Itests/support/regsim/f4 -Dmain=board_main -c $< -o $@
build/test/tests/hal/stm32f4/test_board: tests/hal/stm32f4/test_board.c build/test/regsim/hal/stm32f4/board.o
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -Itests/support/regsim/f4 -o $@ $^ -lcmocka
TEST_PROGS += build/test/tests/hal/stm32f4/test_board
TEST_PROGS += $(foreach m,$(REGSIM_F4_MODULES),build/test/tests/hal/stm32f4/test_$(m))

# flash.c: its registers behind the hook of the regsim header, the slots'
# first sector from the link as on the target (linker/stm32f405xg.ld), no
# PIE so that the simulated flash array has a 32-bit address
# (flash.c's 0xFFUL masks are 64 bits wide on the host only: -Wno-conversion
# for that one file here; on the target unsigned long is 32 bits)
build/test/regsim/hal/stm32f4/flash.o: hal/stm32f4/flash.c hal/stm32f4/chip_api.h $(REGSIM_F4_DEPS)
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -Wno-conversion -DREGSIM_F4_FLASH_HOOK -Itests/support/regsim/f4 -fno-pie -c $< -o $@
# the flash unlock and wait flash.c calls live in the F4/F103 common part
build/test/regsim/hal/stm32f4/chip_common.o: hal/stm32f4/chip_common.c hal/stm32f4/chip_api.h $(REGSIM_F4_DEPS)
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -DREGSIM_F4_FLASH_HOOK -Itests/support/regsim/f4 -fno-pie -c $< -o $@
build/test/tests/hal/stm32f4/test_flash: tests/hal/stm32f4/test_flash.c build/test/regsim/hal/stm32f4/flash.o \
		build/test/regsim/hal/stm32f4/chip_common.o $(REGSIM_F4_DEPS)
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -DREGSIM_F4_FLASH_HOOK -Itests/support/regsim/f4 -fno-pie -no-pie -o $@ \
		tests/hal/stm32f4/test_flash.c build/test/regsim/hal/stm32f4/flash.o build/test/regsim/hal/stm32f4/chip_common.o \
		tests/support/regsim/f4/regsim_f4.c -lcmocka -Wl,--defsym,__calib_first_sector=1
TEST_PROGS += build/test/tests/hal/stm32f4/test_flash

# -DBXCAN_SIM: bxcan.c's register accessors go to the test (bus 1 must
# answer SQ_ENODEV without touching one); the calibration slots from the
# link as on the target (linker/stm32f103xb.ld: two slots of 2 KiB) in the
# test's flash array, no PIE so that their addresses fit in 32 bits
build/test/tests/hal/stm32f103/test_chip_f1: tests/hal/stm32f103/test_chip_f1.c hal/stm32f103/chip_f1.c hal/stm32f4/iwdg.c hal/stm32f4/chip_common.c \
		hal/stm32f4/bxcan.c hal/stm32f4/bxcan_timing.c hal/common/hal_can_common.c hal/stm32f4/can_queue.c \
		tests/support/regsim/f103/chip.h hal/stm32f103/stm32f103xb/chip.h
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -DBXCAN_SIM -Itests/support/regsim/f103 -fno-pie -no-pie -o $@ tests/hal/stm32f103/test_chip_f1.c \
		hal/stm32f103/chip_f1.c hal/stm32f4/iwdg.c hal/stm32f4/chip_common.c hal/stm32f4/bxcan.c \
		hal/stm32f4/bxcan_timing.c hal/common/hal_can_common.c hal/stm32f4/can_queue.c -lcmocka \
		-Wl,--defsym,__calib_start=regsim_f1_flash_mem,--defsym,__calib_slot_size=2048
TEST_PROGS += build/test/tests/hal/stm32f103/test_chip_f1
