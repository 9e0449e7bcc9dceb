# SPDX-License-Identifier: MIT
# Tests named after host-sim modules that had none (C: cmocka, ASan+UBSan;
# Python: the sanitizer builds of the programs):
#   tests/host-sim/test_sim_num.c          double <-> model numbers, both builds
#   tests/host-sim/test_plant_scenario.c   built-in scenarios, scenario files
#   tests/host-sim/test_plant_vehicle.c    a vehicle layout's frames and values
#   tests/host-sim/test_decode_inputs.c    decode --calib's input lines
#                                          (both on tests/host-sim/two_corners.cal,
#                                          both builds)
#   tests/host-sim/test_cmd_decode.py      decode's text/CSV of frames encoded by
#                                          canmatrix, every E2E status, both builds
#   tests/host-sim/oscsim/test_oscsim_cmd.py  oscsim map/simulate vs docs/model.md's
#                                          closed forms (numpy/scipy), both builds
NAMED_HOSTSIM_BOTH := test test-fixed

define named_hostsim_sim_num
build/$(1)/tests/host-sim/test_sim_num: build/$(1)/app/tests/host-sim/test_sim_num.o build/$(1)/app/host-sim/sim_num.o build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
TEST_PROGS += build/$(1)/tests/host-sim/test_sim_num
endef
$(foreach v,$(NAMED_HOSTSIM_BOTH),$(eval $(call named_hostsim_sim_num,$(v))))

# the scenario is doubles on the host: one build
build/test/tests/host-sim/test_plant_scenario: build/test/app/tests/host-sim/test_plant_scenario.o build/test/app/host-sim/plant_scenario.o
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm
TEST_PROGS += build/test/tests/host-sim/test_plant_scenario

tests/host-sim/oscsim/test_oscsim_cmd.py: build/test/oscsim build/test-fixed/oscsim
TEST_PROGS += tests/host-sim/oscsim/test_oscsim_cmd.py

NAMED_HOSTSIM_CALIB := host-sim/calib_text.c host-sim/calib_sections.c
define named_hostsim_map
build/$(1)/tests/host-sim/test_plant_vehicle: build/$(1)/app/tests/host-sim/test_plant_vehicle.o \
		$$(patsubst %.c,build/$(1)/app/%.o,host-sim/plant_vehicle.c $(NAMED_HOSTSIM_CALIB)) build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
build/$(1)/tests/host-sim/test_decode_inputs: build/$(1)/app/tests/host-sim/test_decode_inputs.o \
		$$(patsubst %.c,build/$(1)/app/%.o,host-sim/decode_inputs.c host-sim/candump_hal.c \
		host-sim/candump_log.c $(NAMED_HOSTSIM_CALIB)) build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
TEST_PROGS += build/$(1)/tests/host-sim/test_plant_vehicle build/$(1)/tests/host-sim/test_decode_inputs
endef
$(foreach v,$(NAMED_HOSTSIM_BOTH),$(eval $(call named_hostsim_map,$(v))))

tests/host-sim/test_cmd_decode.py: build/test/squeal-sim build/test-fixed/squeal-sim
TEST_PROGS += tests/host-sim/test_cmd_decode.py
