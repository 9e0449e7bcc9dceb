# SPDX-License-Identifier: MIT
# The host HAL backends as one static library per build variant; a program
# links ONE of them (both define every hal.h function), nothing switches at
# run time:
#   build/<variant>/libhal_linux.a  SocketCAN, clock, signals, calibration
#                                   file (hal/linux/)
#   build/<variant>/libhal_vbus.a   the in-memory backend: virtual clock and
#                                   buses (hal/vbus/): squeal-replay, the unit
#                                   tests (tests/support/test_hal.o on top),
#                                   the conformance suite's vbus run
# Both carry the host's contract handler (hal/host/) and the rules every
# backend shares (hal/common/: the frame and filter checks, the bus-state
# change).
HAL_COMMON_SRCS := $(sort $(wildcard hal/common/*.c))
HAL_LINUX_SRCS := $(sort $(wildcard hal/linux/*.c)) $(HAL_COMMON_SRCS) $(HAL_CONTRACT_HOST)
HAL_VBUS_SRCS := $(sort $(wildcard hal/vbus/*.c)) $(HAL_COMMON_SRCS) $(HAL_CONTRACT_HOST)

# variant, library name, sources
define hal_host_lib
build/$(1)/libhal_$(2).a: $$(patsubst %.c,build/$(1)/app/%.o,$(3))
	@rm -f $$@
	ar rcs $$@ $$^
endef
$(foreach v,$(VARIANTS),$(eval $(call hal_host_lib,$(v),linux,$(HAL_LINUX_SRCS))))
$(foreach v,$(VARIANTS),$(eval $(call hal_host_lib,$(v),vbus,$(HAL_VBUS_SRCS))))

ALL_TARGETS += build/host/libhal_linux.a build/host-fixed/libhal_linux.a

# The host's contract handler alone (print FILE:LINE, abort), its cases in
# child processes: build/test/tests/hal/host/test_hal_contract_abort
build/test/tests/hal/host/test_hal_contract_abort: build/test/app/tests/hal/host/test_hal_contract_abort.o build/test/app/$(HAL_CONTRACT_HOST:.c=.o)
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka
TEST_PROGS += build/test/tests/hal/host/test_hal_contract_abort
