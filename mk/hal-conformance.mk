# SPDX-License-Identifier: MIT
# The HAL conformance suite (tests/hal/conformance.c): ONE source, linked
# with each backend's harness (tests/hal/conformance_backend.h) and the
# suite's contract handler (tests/hal/conf_contract.c), ASan+UBSan:
#   build/test/tests/hal/vbus/conf_hal_vbus_can       the in-memory bus (make test)
#   build/test/tests/hal/linux/conf_hal_linux_can  hal/linux on vcan0 + vcan1, run in
#                                         the QEMU guest by
#                                         tests/system/vcan/run-conformance.sh
# Another backend: $(eval $(call hal_conformance_prog,NAME,HARNESS+BACKEND
# objects and libraries)) gives build/test/NAME (NAME: tests/hal/DIR/conf_MODULE); add it to
# TEST_PROGS.
HAL_CONF_OBJS := build/test/app/tests/hal/conformance.o build/test/app/tests/hal/conf_contract.o

define hal_conformance_prog
build/test/$(1): $$(HAL_CONF_OBJS) $(2)
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_test) -o $$@ $$^
endef
$(eval $(call hal_conformance_prog,tests/hal/vbus/conf_hal_vbus_can,build/test/app/tests/hal/vbus/conf_hal_vbus_can.o build/test/libhal_vbus.a))
$(eval $(call hal_conformance_prog,tests/hal/linux/conf_hal_linux_can,build/test/app/tests/hal/linux/conf_hal_linux_can.o build/test/libhal_linux.a))

TEST_PROGS += build/test/tests/hal/vbus/conf_hal_vbus_can tests/system/vcan/run-conformance.sh
tests/system/vcan/run-conformance.sh: build/test/tests/hal/linux/conf_hal_linux_can
