# SPDX-License-Identifier: MIT
# Input map (issue 11): signal descriptors, E2E P02, counter check, unit
# conversion; cmocka, both numeric builds, ASan+UBSan.
#   build/<v>/test_inputmap
INPUTMAP_TEST_VARIANTS := test test-fixed
define inputmap_test_rules
build/$(1)/test_inputmap: build/$(1)/app/tests/unit/test_inputmap.o build/$(1)/app/tests/support/test_contract.o build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(INPUTMAP_TEST_VARIANTS),$(eval $(call inputmap_test_rules,$(v))))
TEST_PROGS += $(foreach v,$(INPUTMAP_TEST_VARIANTS),build/$(v)/test_inputmap)

# The fixture vehicle layouts (tests/inputmap/*.cal) through the calibration
# text parser and the monitor's input path, both numeric builds.
#   build/<v>/test_vehicle_inputs
define vehicle_inputs_rules
build/$(1)/test_vehicle_inputs: build/$(1)/app/tests/unit/test_vehicle_inputs.o build/$(1)/app/tests/support/test_contract.o build/$(1)/app/host-sim/calib_text.o build/$(1)/app/host-sim/calib_sections.o build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(INPUTMAP_TEST_VARIANTS),$(eval $(call vehicle_inputs_rules,$(v))))
TEST_PROGS += $(foreach v,$(INPUTMAP_TEST_VARIANTS),build/$(v)/test_vehicle_inputs)

# A braking drive in each fixture layout: plant --calib -> replay --calib,
# operating points and states against values derived in Python.
tests/inputmap/test_vehicle_drive.py: build/host/squeal-sim
TEST_PROGS += tests/inputmap/test_vehicle_drive.py

# squeal-sim calib-check and the --calib commands (ecu, plant, classify)
# refusing a calibration that does not set up, both builds.
tests/cli/test_calib_check.py: build/host/squeal-sim build/host-fixed/squeal-sim
TEST_PROGS += tests/cli/test_calib_check.py
