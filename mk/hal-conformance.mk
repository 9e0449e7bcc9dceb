# SPDX-License-Identifier: MIT
# The HAL conformance suite (tests/hal/conformance.c): ONE source, linked
# with each backend's harness (tests/hal/conformance_backend.h) and the
# suite's contract handler (tests/hal/conf_contract.c), ASan+UBSan:
#   build/test/hal-conformance-vbus       the in-memory bus (make test)
#   build/test/hal-conformance-socketcan  hal/linux on vcan0 + vcan1, run in
#                                         the QEMU guest by
#                                         tests/vcan/run-conformance.sh
# Another backend: $(eval $(call hal_conformance_prog,NAME,HARNESS+BACKEND
# objects and libraries)) gives build/test/hal-conformance-NAME; add it to
# TEST_PROGS.
HAL_CONF_OBJS := build/test/app/tests/hal/conformance.o build/test/app/tests/hal/conf_contract.o

define hal_conformance_prog
build/test/hal-conformance-$(1): $$(HAL_CONF_OBJS) $(2)
	$$(CC) $$(OPT_test) -o $$@ $$^
endef
$(eval $(call hal_conformance_prog,vbus,build/test/app/tests/hal/conf_vbus.o build/test/libhal_vbus.a))
$(eval $(call hal_conformance_prog,socketcan,build/test/app/tests/hal/conf_socketcan.o build/test/libhal_linux.a))

TEST_PROGS += build/test/hal-conformance-vbus tests/vcan/run-conformance.sh
tests/vcan/run-conformance.sh: build/test/hal-conformance-socketcan
