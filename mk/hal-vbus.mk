# SPDX-License-Identifier: MIT
# The in-memory backend's own promises (hal/vbus/hal_vbus.h: the mode and
# the backend's counts survive an injected status) and the rules every
# backend shares (hal/hal_can_common.h), both numeric builds, ASan+UBSan:
#   build/<v>/tests/hal/vbus/test_hal_vbus_can
HAL_VBUS_TEST_VARIANTS := test test-fixed
define hal_vbus_test_rules
build/$(1)/tests/hal/vbus/test_hal_vbus_can: build/$(1)/app/tests/hal/vbus/test_hal_vbus_can.o build/$(1)/app/tests/support/test_contract.o \
		build/$(1)/libhal_vbus.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka
endef
$(foreach v,$(HAL_VBUS_TEST_VARIANTS),$(eval $(call hal_vbus_test_rules,$(v))))
TEST_PROGS += $(foreach v,$(HAL_VBUS_TEST_VARIANTS),build/$(v)/tests/hal/vbus/test_hal_vbus_can)
