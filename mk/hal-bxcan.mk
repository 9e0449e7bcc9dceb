# SPDX-License-Identifier: MIT
# The bxCAN driver (hal/stm32f4/bxcan.c) on the host, on simulated registers
# (tests/hal/stm32f4/bxcan_sim.c, -DBXCAN_SIM): its own cmocka test, and the HAL
# conformance suite (tests/hal/conformance.c) with the bxcan-sim harness.
BXCAN_SIM_SRCS := tests/hal/stm32f4/bxcan_sim.c tests/hal/cortex_sim.c tests/hal/wire_sim.c hal/stm32f4/bxcan.c hal/stm32f4/bxcan_timing.c hal/stm32f4/can_pins.c \
	hal/common/hal_can_common.c hal/stm32f4/can_queue.c
BXCAN_SIM_DEPS := $(BXCAN_SIM_SRCS) tests/hal/stm32f4/bxcan_sim.h tests/hal/cortex_sim.h tests/hal/wire_sim.h tests/hal/can_sim.h tests/hal/stm32f4/sim/chip.h hal/stm32f4/bxcan.h \
	hal/stm32f4/bxcan_regs.h hal/stm32f4/cortex_m.h hal/stm32f4/can_queue.h hal/stm32f4/stm32f405/chip.h hal/hal.h hal/hal_can_common.h
# tests/hal/stm32f4/sim first: its chip.h puts the peripherals on the simulation
BXCAN_SIM_CFLAGS := $(WARN) -O1 -g $(SAN) -DBXCAN_SIM $(FW_INC) -Itests/hal/stm32f4/sim -Itests/hal -Itests/hal/stm32f4 -Ihal/stm32f4 -Itests/support

build/test/tests/hal/stm32f4/test_bxcan: tests/hal/stm32f4/test_bxcan.c $(BXCAN_SIM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(BXCAN_SIM_CFLAGS) -o $@ tests/hal/stm32f4/test_bxcan.c $(BXCAN_SIM_SRCS) -lcmocka
TEST_PROGS += build/test/tests/hal/stm32f4/test_bxcan

# the one conformance suite (tests/hal/conformance.c, mk/hal-conformance.mk)
# on the simulated bxCAN pair; its own contract handler catches the suite's
# deliberate programming errors
build/test/tests/hal/stm32f4/conf_bxcan: tests/hal/conformance.c tests/hal/stm32f4/conf_bxcan.c \
		tests/hal/conf_contract.c tests/hal/conf_can_sim.c tests/hal/conformance_backend.h \
		tests/hal/conformance_contract.h $(BXCAN_SIM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(BXCAN_SIM_CFLAGS) -o $@ tests/hal/conformance.c tests/hal/stm32f4/conf_bxcan.c \
		tests/hal/conf_contract.c tests/hal/conf_can_sim.c $(BXCAN_SIM_SRCS)
TEST_PROGS += build/test/tests/hal/stm32f4/conf_bxcan

# the drivers' shared RX ring and TX queue, alone (no simulation)
build/test/tests/hal/stm32f4/test_can_queue: tests/hal/stm32f4/test_can_queue.c hal/stm32f4/can_queue.c \
		hal/stm32f4/can_queue.h hal/stm32f4/cortex_m.h hal/hal.h
	@mkdir -p $(@D)
	$(CC) $(WARN) -O1 -g $(SAN) $(FW_INC) -Ihal/stm32f4 -o $@ tests/hal/stm32f4/test_can_queue.c \
		hal/stm32f4/can_queue.c -lcmocka
TEST_PROGS += build/test/tests/hal/stm32f4/test_can_queue
