# SPDX-License-Identifier: MIT
# Tests named after host-sim modules that had none (cmocka, ASan+UBSan):
#   tests/host-sim/test_sim_num.c          double <-> model numbers, both builds
#   tests/host-sim/test_plant_scenario.c   built-in scenarios, scenario files
#   tests/host-sim/oscsim/test_oscsim_cmd.py  oscsim map/simulate vs model.md's
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
