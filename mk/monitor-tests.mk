# SPDX-License-Identifier: MIT
# Tests of firmware/monitor and firmware/app through the in-memory test HAL
# (tests/support/test_hal.c), both numeric builds, ASan+UBSan:
#   build/<v>/test_monitor        braking manoeuvre, warning levels, debounce,
#                                 periodic TX and E2E of every outgoing frame
#   build/<v>/test_monitor_faults every input fault, through protected frames
#   build/<v>/test_monitor_bounds each rule exactly at its bound (make mutate)
#   build/<v>/test_calib          calibration block: CRC-32, round trip, ranges
#   build/<v>/test_app            scheduler + HAL: calibration storage, CAN
#                                 status, bus-off, TX queue full, watchdog
# Expected border speeds and the DBC's data IDs come from
# tests/monitor/gen_monitor_expect.py (scipy reference) into
# build/monitor/monitor_expect.h.
#   build/host/monitor_step_cost  callgrind driver (make monitor-cost)

MONITOR_TEST_VARIANTS := test test-fixed
MONITOR_TESTS := test_monitor test_monitor_faults test_calib test_app test_monitor_bounds test_app_buses \
	test_monitor_sigma \
	test_app_selftest
MONITOR_EXPECT_H := build/monitor/monitor_expect.h

$(MONITOR_EXPECT_H): tests/monitor/gen_monitor_expect.py tests/reference/squeal_reference.py firmware/protocol/squeal.dbc
	@mkdir -p $(@D)
	$(PYTHON) tests/monitor/gen_monitor_expect.py firmware/protocol/squeal.dbc $@

define monitor_test_rules
build/$(1)/app/tests/unit/$(2).o: tests/unit/$(2).c $(MONITOR_EXPECT_H)
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) -D_GNU_SOURCE $$(OPT_$(1)) $$(DEF_$$(NUM_$(1))) $$(FW_INC) -Itests/support -Ihal/vbus -Ibuild/monitor -MMD -MP -c $$< -o $$@
build/$(1)/$(2): build/$(1)/app/tests/unit/$(2).o build/$(1)/app/tests/support/test_hal.o \
		build/$(1)/app/tests/support/test_app_drive.o build/$(1)/app/tests/support/test_contract.o \
		build/$(1)/libfirmware.a build/$(1)/libhal_vbus.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(MONITOR_TEST_VARIANTS),$(foreach t,$(MONITOR_TESTS),$(eval $(call monitor_test_rules,$(v),$(t)))))

TEST_PROGS += $(foreach v,$(MONITOR_TEST_VARIANTS),$(foreach t,$(MONITOR_TESTS),build/$(v)/$(t)))

# Cost of the 1 ms task (callgrind), figures for `make bench`.
MONITOR_COST_VARIANTS := host host-fixed
define monitor_cost_rules
build/$(1)/monitor_step_cost: build/$(1)/app/tests/monitor/monitor_step_cost.o build/$(1)/app/tests/support/test_hal.o build/$(1)/libfirmware.a build/$(1)/libhal_vbus.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lm
endef
$(foreach v,$(MONITOR_COST_VARIANTS),$(eval $(call monitor_cost_rules,$(v))))
tests/monitor/monitor-cost.sh: $(foreach v,$(MONITOR_COST_VARIANTS),build/$(v)/monitor_step_cost)
BENCH_PROGS += tests/monitor/monitor-cost.sh
.PHONY: monitor-cost
monitor-cost: tests/monitor/monitor-cost.sh
	tests/monitor/monitor-cost.sh
BENCH_PROGS += tests/monitor/monitor-ram.sh

# The input stage's one verdict per frame (order of the checks, reason
# names, na_raw2) on fixture layout A, E2E P02 keeping byte 1's high
# nibble (CRCs from two independent Python references), and the
# uncertainty following the classification's criterion (exact or cubic,
# against tests/reference/sigma_cubic_ref.py), both builds.
#   build/<v>/test_input_verdict
#   build/<v>/test_e2e_p02
#   build/<v>/test_sigma_criterion
define input_verdict_rules
build/$(1)/test_input_verdict: build/$(1)/app/tests/unit/test_input_verdict.o build/$(1)/app/tests/support/test_contract.o build/$(1)/app/host-sim/calib_text.o build/$(1)/app/host-sim/calib_sections.o build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
build/$(1)/test_e2e_p02: build/$(1)/app/tests/unit/test_e2e_p02.o build/$(1)/app/tests/support/test_contract.o build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
build/$(1)/test_sigma_criterion: build/$(1)/app/tests/unit/test_sigma_criterion.o build/$(1)/app/tests/support/sq_num.o build/$(1)/app/tests/support/test_contract.o build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(MONITOR_TEST_VARIANTS),$(eval $(call input_verdict_rules,$(v))))
TEST_PROGS += $(foreach v,$(MONITOR_TEST_VARIANTS),build/$(v)/test_input_verdict build/$(v)/test_e2e_p02 \
	build/$(v)/test_sigma_criterion)
