# SPDX-License-Identifier: MIT
# The in-memory backend's own promises (hal/vbus/hal_vbus.h: the mode and
# the backend's counts survive an injected status) and the rules every
# backend shares (hal/hal_can_common.h), both numeric builds, ASan+UBSan:
#   build/<v>/tests/hal/vbus/test_hal_vbus_can        the buses
#   build/<v>/tests/hal/vbus/test_hal_vbus_sys        clock, idle, storage, watchdog, platform
#   build/<v>/tests/hal/common/test_hal_can_common_states  the shared rules, through this backend
HAL_VBUS_TEST_VARIANTS := test test-fixed
HAL_VBUS_TESTS := tests/hal/vbus/test_hal_vbus_can tests/hal/vbus/test_hal_vbus_sys tests/hal/common/test_hal_can_common_states
define hal_vbus_test_rules
build/$(1)/$(2): build/$(1)/app/$(2).o build/$(1)/app/tests/support/test_contract.o build/$(1)/libhal_vbus.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka
endef
$(foreach v,$(HAL_VBUS_TEST_VARIANTS),$(foreach t,$(HAL_VBUS_TESTS),$(eval $(call hal_vbus_test_rules,$(v),$(t)))))
TEST_PROGS += $(foreach v,$(HAL_VBUS_TEST_VARIANTS),$(foreach t,$(HAL_VBUS_TESTS),build/$(v)/$(t)))
