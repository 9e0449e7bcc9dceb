# SPDX-License-Identifier: MIT
# Tests named after modules that had none (tests/README.md: the tree
# mirrors the source).
#   hal/stm32f4/chip_common.c      tests/hal/stm32f4/test_chip_common.c
#   tools/dbc_tolerant.py          tests/tools/test_dbc_tolerant.py
#   tools/gen_fleet_logs.py        tests/tools/test_gen_fleet_logs.py
#   tools/plots/plot_*.py          tests/tools/plots/test_plot_*.py

# chip_common.c alone on the F4 register simulation, its flash registers
# behind the hook (the test plays RM0090's key sequence and write-1-to-clear)
build/test/tests/hal/stm32f4/test_chip_common: tests/hal/stm32f4/test_chip_common.c hal/stm32f4/chip_common.c \
		hal/stm32f4/chip_api.h tests/support/regsim/f4/flash_rm0090.h $(REGSIM_F4_DEPS)
	@mkdir -p $(@D)
	$(CC) $(REGSIM_CFLAGS) -DREGSIM_F4_FLASH_HOOK -Itests/support/regsim/f4 -o $@ \
		tests/hal/stm32f4/test_chip_common.c hal/stm32f4/chip_common.c tests/support/regsim/f4/regsim_f4.c -lcmocka
TEST_PROGS += build/test/tests/hal/stm32f4/test_chip_common
# test_flash.c plays the same key sequence
build/test/tests/hal/stm32f4/test_flash: tests/support/regsim/f4/flash_rm0090.h

TEST_PROGS += tests/tools/test_dbc_tolerant.py
tests/tools/test_gen_fleet_logs.py: build/host/squeal-sim
TEST_PROGS += tests/tools/test_gen_fleet_logs.py
TEST_PROGS += tests/tools/plots/test_plot_map.py
TEST_PROGS += tests/tools/plots/test_plot_drive.py
TEST_PROGS += tests/tools/plots/test_plot_calib_bands.py
tests/tools/plots/test_plot_phase.py: build/host/oscsim
TEST_PROGS += tests/tools/plots/test_plot_phase.py
