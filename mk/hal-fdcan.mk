# SPDX-License-Identifier: MIT
# The STM32G474 FDCAN driver (hal/stm32g4/fdcan.c) on the host, on simulated
# registers and message RAM (tests/hal/stm32g4/fdcan_sim.c, -DFDCAN_SIM),
# ASan+UBSan: its own cmocka test, the HAL conformance suite
# (tests/hal/conformance.c) with the fdcan harness, and the bit timing:
#   build/test/tests/hal/stm32g4/test_fdcan
#   build/test/tests/hal/stm32g4/conf_fdcan
#   build/test/tests/hal/stm32g4/test_fdcan_timing
FDCAN_SIM_SRCS := tests/hal/stm32g4/fdcan_sim.c tests/hal/cortex_sim.c tests/hal/wire_sim.c hal/stm32g4/fdcan.c hal/stm32g4/fdcan_timing.c \
	hal/common/hal_can_common.c hal/stm32f4/can_queue.c
FDCAN_SIM_DEPS := $(FDCAN_SIM_SRCS) tests/hal/stm32g4/fdcan_sim.h tests/hal/cortex_sim.h tests/hal/wire_sim.h tests/hal/can_sim.h tests/hal/stm32g4/sim/chip.h \
	hal/stm32g4/fdcan.h hal/stm32g4/fdcan_regs.h hal/stm32f4/cortex_m.h hal/stm32f4/can_queue.h hal/stm32f4/chip_api.h \
	hal/hal.h hal/hal_can_common.h
# tests/hal/stm32g4/sim first: its chip.h puts the instances on the simulation
FDCAN_SIM_CFLAGS := $(WARN) -O1 -g $(SAN) -DFDCAN_SIM $(FW_INC) -Itests/hal/stm32g4/sim -Itests/hal \
	-Itests/hal/stm32g4 -Ihal/stm32g4 -Ihal/stm32f4

build/test/tests/hal/stm32g4/test_fdcan: tests/hal/stm32g4/test_fdcan.c $(FDCAN_SIM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(FDCAN_SIM_CFLAGS) -o $@ tests/hal/stm32g4/test_fdcan.c $(FDCAN_SIM_SRCS) -lcmocka

build/test/tests/hal/stm32g4/conf_fdcan: tests/hal/conformance.c tests/hal/stm32g4/conf_fdcan.c \
		tests/hal/conf_contract.c tests/hal/conf_can_sim.c tests/hal/conformance_backend.h \
		tests/hal/conformance_contract.h $(FDCAN_SIM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(FDCAN_SIM_CFLAGS) -o $@ tests/hal/conformance.c tests/hal/stm32g4/conf_fdcan.c \
		tests/hal/conf_contract.c tests/hal/conf_can_sim.c $(FDCAN_SIM_SRCS)

# pure arithmetic: no simulation
build/test/tests/hal/stm32g4/test_fdcan_timing: tests/hal/stm32g4/test_fdcan_timing.c \
		hal/stm32g4/fdcan_timing.c hal/stm32g4/fdcan.h
	@mkdir -p $(@D)
	$(CC) $(WARN) -O1 -g $(SAN) $(FW_INC) -Ihal/stm32g4 -Ihal/stm32f4 -o $@ tests/hal/stm32g4/test_fdcan_timing.c \
		hal/stm32g4/fdcan_timing.c -lcmocka

TEST_PROGS += build/test/tests/hal/stm32g4/test_fdcan build/test/tests/hal/stm32g4/conf_fdcan \
	build/test/tests/hal/stm32g4/test_fdcan_timing
