# SPDX-License-Identifier: MIT
# Fault injection, memory checks and the soak:
#   build/<v>/tests/firmware/app/test_squeal_app_fault_injection   cmocka, test HAL, both numeric builds,
#                                    ASan+UBSan: dropouts, counter wrap/jumps,
#                                    CRC storms, DLC errors, bus-off, TX full
#                                    for 5 s, clock jump, 10^6 healthy steps
#   tests/system/soak/memcheck-replay.sh    replay of a plant log under valgrind
#                                    memcheck (errors, leaks) on the release
#                                    build; in make test with 10^4 frames
#                                    (SOAK_MEMCHECK_FRAMES), 10^5 by hand
#   tests/system/soak/soak-replay.sh        make soak: 10^7 frames plant -> replay
#                                    through a pipe, faults mixed in, counts
#                                    checked, peak RSS at 10^5 and 10^7
#                                    (several minutes: not in make test)

SOAK_TEST_VARIANTS := test test-fixed

define soak_test_rules
build/$(1)/app/tests/firmware/app/test_squeal_app_fault_injection.o: tests/firmware/app/test_squeal_app_fault_injection.c build/monitor/monitor_expect.h
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) -D_GNU_SOURCE $$(OPT_$(1)) $$(DEF_$$(NUM_$(1))) $$(FW_INC) -Itests/support -Ibuild/monitor -MMD -MP -c $$< -o $$@
build/$(1)/tests/firmware/app/test_squeal_app_fault_injection: build/$(1)/app/tests/firmware/app/test_squeal_app_fault_injection.o build/$(1)/app/tests/support/test_hal.o build/$(1)/app/tests/support/test_app_drive.o build/$(1)/libfirmware.a build/$(1)/libhal_vbus.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(SOAK_TEST_VARIANTS),$(eval $(call soak_test_rules,$(v))))

TEST_PROGS += $(foreach v,$(SOAK_TEST_VARIANTS),build/$(v)/tests/firmware/app/test_squeal_app_fault_injection)

# The soak's independent reference: counts of a plant log (own CRC-8)
build/host/soak_log_count: tests/system/soak/log_count.c build/monitor/monitor_expect.h
	@mkdir -p $(@D)
	$(CC) $(WARN) -D_GNU_SOURCE -O2 -Ibuild/monitor -o $@ $<

# make test: short memory check (~10 s)
tests/system/soak/memcheck-short.sh: build/host/squeal-sim build/host-fixed/squeal-sim
TEST_PROGS += tests/system/soak/memcheck-short.sh

# make soak: the 10^7-frame soak, then the full memory check (10^5 frames
# under valgrind, 10^7 streamed). A few minutes; figures in the output.
# SOAK_FRAMES=... for another length (tests/system/soak/soak-replay.sh).
.PHONY: soak soak-replay soak-memcheck
soak: soak-replay soak-memcheck
soak-replay: build/host/squeal-sim build/host/soak_log_count
	tests/system/soak/soak-replay.sh
soak-memcheck: build/host/squeal-sim build/host-fixed/squeal-sim
	tests/system/soak/memcheck-replay.sh
