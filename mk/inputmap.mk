# SPDX-License-Identifier: MIT
# Input map: E2E P02, counter check, unit conversion (the
# signal descriptors: mk/protocol.mk, test_can_signal); cmocka, both
# numeric builds, ASan+UBSan.
#   build/<v>/tests/firmware/monitor/test_input_conv
INPUTMAP_TEST_VARIANTS := test test-fixed
define inputmap_test_rules
build/$(1)/tests/firmware/monitor/test_input_conv: build/$(1)/app/tests/firmware/monitor/test_input_conv.o build/$(1)/app/tests/support/test_contract.o build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(INPUTMAP_TEST_VARIANTS),$(eval $(call inputmap_test_rules,$(v))))
TEST_PROGS += $(foreach v,$(INPUTMAP_TEST_VARIANTS),build/$(v)/tests/firmware/monitor/test_input_conv)

# The fixture vehicle layouts (tests/firmware/monitor/fixtures/*.cal) through the calibration
# text parser and the monitor's input path, both numeric builds.
#   build/<v>/tests/firmware/monitor/test_input_rx
define vehicle_inputs_rules
build/$(1)/tests/firmware/monitor/test_input_rx: build/$(1)/app/tests/firmware/monitor/test_input_rx.o build/$(1)/app/tests/support/map_fixture.o build/$(1)/app/tests/support/test_contract.o build/$(1)/app/host-sim/calib_text.o build/$(1)/app/host-sim/calib_sections.o build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(INPUTMAP_TEST_VARIANTS),$(eval $(call vehicle_inputs_rules,$(v))))
TEST_PROGS += $(foreach v,$(INPUTMAP_TEST_VARIANTS),build/$(v)/tests/firmware/monitor/test_input_rx)

# A braking drive in each fixture layout: plant --calib -> replay --calib,
# operating points and states against values derived in Python.
tests/firmware/monitor/test_input_rx_drive.py: build/host/squeal-sim
TEST_PROGS += tests/firmware/monitor/test_input_rx_drive.py

# squeal-sim calib-check and the --calib commands (ecu, plant, classify)
# refusing a calibration that does not set up, both builds.
tests/host-sim/test_cmd_calib_check.py: build/host/squeal-sim build/host-fixed/squeal-sim
TEST_PROGS += tests/host-sim/test_cmd_calib_check.py
