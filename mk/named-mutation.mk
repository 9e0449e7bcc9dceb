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
#   build/test/tests/host-sim/test_plant_scenario_rows  a negative force refused, a row's time gives its values
build/test/tests/host-sim/test_plant_scenario_rows: build/test/app/tests/host-sim/test_plant_scenario_rows.o build/test/app/host-sim/plant_scenario.o
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm
TEST_PROGS += build/test/tests/host-sim/test_plant_scenario_rows
#   build/test/tests/firmware/model/test_sq_mathf_clamp  sq_expf's clamp to [-87, 88] (float build only)
build/test/tests/firmware/model/test_sq_mathf_clamp: build/test/app/tests/firmware/model/test_sq_mathf_clamp.o build/test/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm
TEST_PROGS += build/test/tests/firmware/model/test_sq_mathf_clamp
#   build/test/tests/hal/stm32g4/test_fdcan_timing_bounds  the rates' bounds (pure arithmetic)
build/test/tests/hal/stm32g4/test_fdcan_timing_bounds: tests/hal/stm32g4/test_fdcan_timing_bounds.c \
		hal/stm32g4/fdcan_timing.c hal/stm32g4/fdcan.h
	@mkdir -p $(@D)
	$(CC) $(WARN) -O1 -g $(SAN) $(FW_INC) -Ihal/stm32g4 -Ihal/stm32f4 -o $@ tests/hal/stm32g4/test_fdcan_timing_bounds.c \
		hal/stm32g4/fdcan_timing.c -lcmocka
TEST_PROGS += build/test/tests/hal/stm32g4/test_fdcan_timing_bounds
#   build/test/tests/host-sim/test_candump_hal_error  an error frame's identifier masked
build/test/tests/host-sim/test_candump_hal_error: build/test/app/tests/host-sim/test_candump_hal_error.o build/test/app/host-sim/candump_log.o build/test/app/host-sim/candump_hal.o
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka
TEST_PROGS += build/test/tests/host-sim/test_candump_hal_error
#   build/test/tests/hal/stm32f4/test_bxcan_bitrate  a rate beyond 1000 kbit/s refused before its product wraps
build/test/tests/hal/stm32f4/test_bxcan_bitrate: tests/hal/stm32f4/test_bxcan_bitrate.c $(BXCAN_SIM_DEPS)
	@mkdir -p $(@D)
	$(CC) $(BXCAN_SIM_CFLAGS) -o $@ tests/hal/stm32f4/test_bxcan_bitrate.c $(BXCAN_SIM_SRCS) -lcmocka
TEST_PROGS += build/test/tests/hal/stm32f4/test_bxcan_bitrate
#   build/<v>/tests/host-sim/test_cli_args_bounds  numeric options at both ends
define named_mutation_cli_bounds
build/$(1)/tests/host-sim/test_cli_args_bounds: build/$(1)/app/tests/host-sim/test_cli_args_bounds.o build/$(1)/app/$(CLI_ARGS_SRC:.c=.o)
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka
TEST_PROGS += build/$(1)/tests/host-sim/test_cli_args_bounds
endef
$(foreach v,test test-fixed,$(eval $(call named_mutation_cli_bounds,$(v))))
#   build/<v>/tests/hal/vbus/test_hal_vbus_can_rx  the receive queue's end, arrival time, rate bounds
$(foreach v,$(HAL_VBUS_TEST_VARIANTS),$(eval $(call hal_vbus_test_rules,$(v),tests/hal/vbus/test_hal_vbus_can_rx)))
TEST_PROGS += $(foreach v,$(HAL_VBUS_TEST_VARIANTS),build/$(v)/tests/hal/vbus/test_hal_vbus_can_rx)
#   tests/tools/test_dbc_tolerant_empty.py  a DBC file whose messages all go is refused
TEST_PROGS += tests/tools/test_dbc_tolerant_empty.py
# ---- hal
#   build/test/tests/hal/linux/test_hal_linux_calib_verify  a read-back that differs is SQ_EIO (write() wrapped)
#   build/test/tests/hal/linux/test_hal_linux_idle_deadline  the watchdog's exact deadline (hal_time_us wrapped)
#   build/test/tests/hal/linux/test_hal_linux_can_open  name length and socket errors (socket() wrapped)
HAL_LINUX_WRAPPED := test_hal_linux_calib_verify:write test_hal_linux_idle_deadline:hal_time_us \
	test_hal_linux_can_open:socket
define hal_linux_wrapped_test
build/test/tests/hal/linux/$(1): build/test/app/tests/hal/linux/$(1).o build/test/app/tests/support/test_contract.o build/test/libhal_linux.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_test) -Wl,--wrap=$(2) -o $$@ $$^ -lcmocka
TEST_PROGS += build/test/tests/hal/linux/$(1)
endef
$(foreach t,$(HAL_LINUX_WRAPPED),$(eval $(call hal_linux_wrapped_test,$(word 1,$(subst :, ,$(t))),$(word 2,$(subst :, ,$(t))))))

# ---- tools
#   tests/tools/test_vehicle_calib_limits.py  the period, P02 list, P01 counter step and efficiency bounds
TEST_PROGS += tests/tools/test_vehicle_calib_limits.py
#   tests/tools/test_fit_friction_checks.py  too few speeds, a negative speed, a not identified, the upper bounds
TEST_PROGS += tests/tools/test_fit_friction_checks.py
#   tests/tools/test_fit_modal_checks.py  D = 1, D not identified, a zero magnitude, uneven sampling
TEST_PROGS += tests/tools/test_fit_modal_checks.py
#   tests/tools/test_calibfit_parts.py  a row's field count, the 95 % quantiles, a file or stdout
TEST_PROGS += tests/tools/test_calibfit_parts.py
#   tests/tools/test_live_view_frames.py  the state names, the trail's need of both values, the 10 s window
TEST_PROGS += tests/tools/test_live_view_frames.py
#   tests/tools/test_gen_fleet_logs_layout.py  drive n in car n mod 8, the broken kinds, --broken < --count
TEST_PROGS += tests/tools/test_gen_fleet_logs_layout.py
#   tests/tools/plots/test_plotlib_classify.py  a point's class by the closed forms, the Hopf border itself
TEST_PROGS += tests/tools/plots/test_plotlib_classify.py
#   tests/tools/plots/test_plot_map_counts.py  the disagreeing points and the legend's entry for them
TEST_PROGS += tests/tools/plots/test_plot_map_counts.py
#   tests/tools/plots/test_plot_calib_bands_borders.py  g(s), ln N_H, ln N_S, the 5/50/95 % borders
TEST_PROGS += tests/tools/plots/test_plot_calib_bands_borders.py
#   tests/tools/plots/test_plot_drive_read.py  the decode table's point (inputs, then the monitor's), state names
TEST_PROGS += tests/tools/plots/test_plot_drive_read.py
#   tests/tools/plots/test_plot_phase_points.py  steady sliding, the sample rows, the bistable starts
TEST_PROGS += tests/tools/plots/test_plot_phase_points.py
