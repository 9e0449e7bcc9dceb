# SPDX-License-Identifier: MIT
# The Linux HAL (SocketCAN, clock, signals, calibration file) as one static
# library per build variant: build/<variant>/libhal_linux.a.
HAL_LINUX_SRCS := $(sort $(wildcard hal/linux/*.c)) $(HAL_CONTRACT_HOST)

define hal_linux_rules
build/$(1)/libhal_linux.a: $$(patsubst %.c,build/$(1)/app/%.o,$$(HAL_LINUX_SRCS))
	@rm -f $$@
	ar rcs $$@ $$^
endef
$(foreach v,$(VARIANTS),$(eval $(call hal_linux_rules,$(v))))

ALL_TARGETS += build/host/libhal_linux.a build/host-fixed/libhal_linux.a
