# SPDX-License-Identifier: MIT
# The STM32G474 chip part on the host against its real chip.h with the
# peripherals in arrays (tests/support/regsim/g4); iwdg.c for the reset
# cause decode with the G4's RCC_CSR; calib_flash.c on its double words
# (power cut, ECC double error). No PIE: the calibration slots are
# absolute linker symbols inside the test's flash array.
REGSIM_G4_DEPS := tests/support/regsim/g4/chip.h tests/support/regsim/calib_pattern.h hal/stm32g4/stm32g474/chip.h hal/stm32f4/cortex_m.h
G4_CHIP_SRCS := hal/stm32g4/chip_g4.c hal/stm32f4/iwdg.c hal/stm32f4/chip_common.c hal/stm32f4/hse_meter.c \
	hal/stm32f4/calib_flash.c
build/test/tests/hal/stm32g4/test_chip_g4: tests/hal/stm32g4/test_chip_g4.c $(G4_CHIP_SRCS) \
		$(REGSIM_G4_DEPS)
	@mkdir -p $(@D)
	$(CC) $(WARN) -O1 -g $(SAN) -fno-pie -no-pie $(FW_INC) -Ihal/stm32f4 -Itests/support/regsim/g4 -Itests/support -o $@ \
		tests/hal/stm32g4/test_chip_g4.c $(G4_CHIP_SRCS) -lcmocka \
		-Wl,--defsym,__calib_start=regsim_flash_mem,--defsym,__calib_slot_size=4096,--defsym,__calib_slot_count=2
TEST_PROGS += build/test/tests/hal/stm32g4/test_chip_g4
