# SPDX-License-Identifier: MIT
# The CAN FD rules every HAL backend shares (hal/common/hal_can_common.c),
# ASan+UBSan, built as the host builds are (64-byte frames) and as the ECU
# images are (-DHAL_CAN_CLASSIC_ONLY, 8-byte frames):
#   build/test/tests/hal/common/test_hal_can_common
#   build/test/tests/hal/common/test_hal_can_common-classic
HAL_CAN_COMMON_TEST_SRCS := tests/hal/common/test_hal_can_common.c hal/common/hal_can_common.c \
	tests/support/test_contract.c
HAL_CAN_COMMON_TEST_DEPS := $(HAL_CAN_COMMON_TEST_SRCS) hal/hal.h hal/hal_can_common.h hal/sq_status.h \
	hal/sq_contract.h

build/test/tests/hal/common/test_hal_can_common: $(HAL_CAN_COMMON_TEST_DEPS)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(OPT_test) $(FW_INC) -DHAL_CAN_COMMON_TEST_NAME='"hal_can_common"' -o $@ \
		$(HAL_CAN_COMMON_TEST_SRCS) -lcmocka
build/test/tests/hal/common/test_hal_can_common-classic: $(HAL_CAN_COMMON_TEST_DEPS)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(OPT_test) $(FW_INC) -DHAL_CAN_CLASSIC_ONLY \
		-DHAL_CAN_COMMON_TEST_NAME='"hal_can_common classic-only"' -o $@ \
		$(HAL_CAN_COMMON_TEST_SRCS) -lcmocka
TEST_PROGS += build/test/tests/hal/common/test_hal_can_common \
	build/test/tests/hal/common/test_hal_can_common-classic

# The scheduler hands FD frames of up to 64 bytes to the monitors
# (firmware/app/squeal_app.c), both numeric builds, on the in-memory bus:
#   build/<v>/tests/firmware/app/test_squeal_app_fd
FD_APP_TEST_VARIANTS := test test-fixed
define fd_app_test_rules
build/$(1)/tests/firmware/app/test_squeal_app_fd: build/$(1)/app/tests/firmware/app/test_squeal_app_fd.o \
		build/$(1)/app/tests/support/test_hal.o build/$(1)/app/tests/support/test_contract.o \
		build/$(1)/libfirmware.a build/$(1)/libhal_vbus.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(FD_APP_TEST_VARIANTS),$(eval $(call fd_app_test_rules,$(v))))
TEST_PROGS += $(foreach v,$(FD_APP_TEST_VARIANTS),build/$(v)/tests/firmware/app/test_squeal_app_fd)
