# SPDX-License-Identifier: MIT
# The STM32G474 chip part on the host against its real chip.h with the
# peripherals in arrays (tests/support/regsim/g4); iwdg.c for the reset
# cause decode with the G4's RCC_CSR. No PIE: the calibration slots are
# absolute linker symbols inside the test's flash array.
REGSIM_G4_DEPS := tests/support/regsim/g4/chip.h hal/stm32g4/stm32g474/chip.h hal/stm32f4/cortex_m.h
build/test/tests/hal/stm32g4/test_chip_g4: tests/hal/stm32g4/test_chip_g4.c hal/stm32g4/chip_g4.c hal/stm32f4/iwdg.c \
		$(REGSIM_G4_DEPS)
	@mkdir -p $(@D)
	$(CC) $(WARN) -O1 -g $(SAN) -fno-pie -no-pie $(FW_INC) -Ihal/stm32f4 -Itests/support/regsim/g4 -o $@ \
		tests/hal/stm32g4/test_chip_g4.c hal/stm32g4/chip_g4.c hal/stm32f4/iwdg.c -lcmocka \
		-Wl,--defsym,__calib_start=regsim_flash_mem,--defsym,__calib_slot_size=4096
TEST_PROGS += build/test/tests/hal/stm32g4/test_chip_g4
