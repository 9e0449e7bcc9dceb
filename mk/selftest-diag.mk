# SPDX-License-Identifier: MIT
# SquealDiag page 4, the bring-up self-test: the monitor alone,
# both numeric builds, no HAL (the monitor is platform-free).
define selftest_diag_rules
build/$(1)/tests/firmware/monitor/test_monitor_selftest: tests/firmware/monitor/test_monitor_selftest.c build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) -D_GNU_SOURCE $$(OPT_$(1)) $$(DEF_$$(NUM_$(1))) $$(FW_INC) -Itests/support -o $$@ $$< build/$(1)/libfirmware.a -lcmocka -lm
TEST_PROGS += build/$(1)/tests/firmware/monitor/test_monitor_selftest
endef
$(foreach v,test test-fixed,$(eval $(call selftest_diag_rules,$(v))))
