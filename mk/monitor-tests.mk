# SPDX-License-Identifier: MIT
# Tests of firmware/monitor and firmware/app through the in-memory test HAL
# (tests/support/test_hal.c), both numeric builds, ASan+UBSan:
#   build/<v>/tests/firmware/monitor/test_monitor        braking manoeuvre, warning levels, debounce,
#                                 periodic TX and E2E of every outgoing frame
#   build/<v>/tests/firmware/monitor/test_monitor_faults every input fault, through protected frames
#   build/<v>/tests/firmware/monitor/test_monitor_bounds each rule exactly at its bound (make mutate)
#   build/<v>/tests/firmware/monitor/test_calib          calibration block: CRC-32, round trip, ranges
#   build/<v>/tests/firmware/app/test_squeal_app            scheduler + HAL: calibration storage, CAN
#                                 status, bus-off, TX queue full, watchdog
# Expected border speeds and the DBC's data IDs come from
# tests/firmware/monitor/gen_monitor_expect.py (scipy reference) into
# build/monitor/monitor_expect.h.
#   build/host/tests/firmware/monitor/bench_monitor_step  callgrind driver (make monitor-cost)

MONITOR_TEST_VARIANTS := test test-fixed
MONITOR_TESTS := tests/firmware/monitor/test_monitor tests/firmware/monitor/test_monitor_faults \
	tests/firmware/monitor/test_calib tests/firmware/app/test_squeal_app \
	tests/firmware/monitor/test_monitor_bounds tests/firmware/app/test_squeal_app_buses \
	tests/firmware/monitor/test_monitor_sigma tests/firmware/app/test_squeal_app_selftest
MONITOR_EXPECT_H := build/monitor/monitor_expect.h

$(MONITOR_EXPECT_H): tests/firmware/monitor/gen_monitor_expect.py tests/support/reference/squeal_reference.py firmware/protocol/squeal.dbc
	@mkdir -p $(@D)
	$(PYTHON) tests/firmware/monitor/gen_monitor_expect.py firmware/protocol/squeal.dbc $@

define monitor_test_rules
build/$(1)/app/$(2).o: $(2).c $(MONITOR_EXPECT_H)
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) -D_GNU_SOURCE $$(OPT_$(1)) $$(DEF_$$(NUM_$(1))) $$(FW_INC) -Itests/support -Ihal/vbus -Ibuild/monitor -MMD -MP -c $$< -o $$@
build/$(1)/$(2): build/$(1)/app/$(2).o build/$(1)/app/tests/support/test_hal.o \
		build/$(1)/app/tests/support/test_app_drive.o build/$(1)/app/tests/support/test_contract.o \
		build/$(1)/libfirmware.a build/$(1)/libhal_vbus.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(MONITOR_TEST_VARIANTS),$(foreach t,$(MONITOR_TESTS),$(eval $(call monitor_test_rules,$(v),$(t)))))

TEST_PROGS += $(foreach v,$(MONITOR_TEST_VARIANTS),$(foreach t,$(MONITOR_TESTS),build/$(v)/$(t)))

# Cost of the 1 ms task (callgrind), figures for `make bench`.
MONITOR_COST_VARIANTS := host host-fixed
define monitor_cost_rules
build/$(1)/tests/firmware/monitor/bench_monitor_step: build/$(1)/app/tests/firmware/monitor/bench_monitor_step.o build/$(1)/app/tests/support/test_hal.o build/$(1)/libfirmware.a build/$(1)/libhal_vbus.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lm
endef
$(foreach v,$(MONITOR_COST_VARIANTS),$(eval $(call monitor_cost_rules,$(v))))
tests/firmware/monitor/bench_monitor_cost.sh: $(foreach v,$(MONITOR_COST_VARIANTS),build/$(v)/tests/firmware/monitor/bench_monitor_step)
# callgrind of every poll of four runs: minutes, so in make bench-full
BENCH_FULL_PROGS += tests/firmware/monitor/bench_monitor_cost.sh
.PHONY: monitor-cost
monitor-cost: tests/firmware/monitor/bench_monitor_cost.sh
	tests/firmware/monitor/bench_monitor_cost.sh
BENCH_PROGS += tests/firmware/monitor/bench_monitor_ram.sh

# The input stage's one verdict per frame (order of the checks, reason
# names, na_raw2) on fixture layout A, E2E P02 keeping byte 1's high
# nibble (CRCs from two independent Python references), and the
# uncertainty following the classification's criterion (exact or cubic,
# against tests/support/reference/sigma_cubic_ref.py), both builds.
#   build/<v>/tests/firmware/monitor/test_input_rx_verdict
#   build/<v>/tests/firmware/protocol/test_e2e_p02
#   build/<v>/tests/firmware/model/test_squeal_sigma_criterion
define input_verdict_rules
build/$(1)/tests/firmware/monitor/test_input_rx_verdict: build/$(1)/app/tests/firmware/monitor/test_input_rx_verdict.o build/$(1)/app/tests/support/map_fixture.o build/$(1)/app/tests/support/test_contract.o build/$(1)/app/host-sim/calib_text.o build/$(1)/app/host-sim/calib_sections.o build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
build/$(1)/tests/firmware/protocol/test_e2e_p02: build/$(1)/app/tests/firmware/protocol/test_e2e_p02.o build/$(1)/app/tests/support/test_contract.o build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
build/$(1)/tests/firmware/model/test_squeal_sigma_criterion: build/$(1)/app/tests/firmware/model/test_squeal_sigma_criterion.o build/$(1)/app/tests/support/sq_num.o build/$(1)/app/tests/support/test_contract.o build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(MONITOR_TEST_VARIANTS),$(eval $(call input_verdict_rules,$(v))))
TEST_PROGS += $(foreach v,$(MONITOR_TEST_VARIANTS),build/$(v)/tests/firmware/monitor/test_input_rx_verdict build/$(v)/tests/firmware/protocol/test_e2e_p02 \
	build/$(v)/tests/firmware/model/test_squeal_sigma_criterion)

# The input map's and corners' meaning (calib_map.c), both builds:
#   build/<v>/tests/firmware/monitor/test_calib_map
define calib_map_test_rules
build/$(1)/tests/firmware/monitor/test_calib_map: build/$(1)/app/tests/firmware/monitor/test_calib_map.o build/$(1)/app/tests/support/test_contract.o build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(MONITOR_TEST_VARIANTS),$(eval $(call calib_map_test_rules,$(v))))
TEST_PROGS += $(foreach v,$(MONITOR_TEST_VARIANTS),build/$(v)/tests/firmware/monitor/test_calib_map)
