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
