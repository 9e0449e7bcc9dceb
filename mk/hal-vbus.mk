# SPDX-License-Identifier: MIT
# The in-memory HAL backend (virtual clock and buses, hal/vbus/) as one
# static library per build variant: build/<variant>/libhal_vbus.a. A program
# links it INSTEAD of libhal_linux.a (both define every hal.h function):
# squeal-replay, the unit tests (with tests/support/test_hal.o on top) and
# the conformance suite's vbus run.
HAL_VBUS_SRCS := $(sort $(wildcard hal/vbus/*.c)) $(HAL_CONTRACT_HOST)

define hal_vbus_rules
build/$(1)/libhal_vbus.a: $$(patsubst %.c,build/$(1)/app/%.o,$$(HAL_VBUS_SRCS))
	@rm -f $$@
	ar rcs $$@ $$^
endef
$(foreach v,$(VARIANTS),$(eval $(call hal_vbus_rules,$(v))))
