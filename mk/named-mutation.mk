# SPDX-License-Identifier: MIT
# Tests written for make mutate's survivors, each named after the module it
# tests (tests/README.md), so that tools/test_map.py gives them to it.
#   tests/tools/test_vcalib_rules_qualifier.py  the qualifier bit: two equal siblings, none chosen
TEST_PROGS += tests/tools/test_vcalib_rules_qualifier.py

# cmocka, both numeric builds, ASan+UBSan (the rules of mk/fd-map.mk)
#   build/<v>/tests/host-sim/test_calib_sections  the key table and sections at their bounds
$(foreach v,$(FD_MAP_VARIANTS),\
  $(eval $(call fd_map_rules,$(v),host-sim,test_calib_sections,,host-sim/calib_text.o host-sim/calib_sections.o)))
#   build/<v>/tests/firmware/protocol/test_e2e_p02_check  P02's configuration bounds and verdicts
$(foreach v,$(FD_MAP_VARIANTS),\
  $(eval $(call fd_map_rules,$(v),firmware/protocol,test_e2e_p02_check,,)))
#   build/<v>/tests/firmware/model/test_squeal_sigma_distance  |g| / sigma and its cap, exact values
$(foreach v,$(FD_MAP_VARIANTS),\
  $(eval $(call fd_map_rules,$(v),firmware/model,test_squeal_sigma_distance,,tests/support/sq_num.o)))
#   build/test/tests/host-sim/oscsim/test_oscsim_map_tally  the map's sums against its own points
build/test/tests/host-sim/oscsim/test_oscsim_map_tally: build/test/app/tests/host-sim/oscsim/test_oscsim_map_tally.o build/test/liboscsim.a build/test/app/host-sim/sim_num.o build/test/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm
TEST_PROGS += build/test/tests/host-sim/oscsim/test_oscsim_map_tally
#   build/test/tests/hal/linux/test_hal_linux_selftest  faults accumulate, no self-test on Linux
build/test/tests/hal/linux/test_hal_linux_selftest: build/test/app/tests/hal/linux/test_hal_linux_selftest.o build/test/app/tests/support/test_contract.o build/test/libhal_linux.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka
TEST_PROGS += build/test/tests/hal/linux/test_hal_linux_selftest
