# SPDX-License-Identifier: MIT
# Issue 12, calibrating a brake from measurements:
#   build/test{,-fixed}/test_sigma    firmware/model/squeal_sigma.h against
#                                     Monte Carlo (tests/golden/sigma_vectors.csv)
#   tests/calibrate/test_fit_*.py     the fitting tools on synthetic data
#                                     (recovery, 95 % coverage, bad files)
#   make sigma-golden                 regenerate the Monte Carlo file

SIGMA_TEST_VARIANTS := test test-fixed

define sigma_test_rules
build/$(1)/test_sigma: build/$(1)/app/tests/unit/test_sigma.o build/$(1)/app/tests/support/sq_num.o build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(SIGMA_TEST_VARIANTS),$(eval $(call sigma_test_rules,$(v))))

TEST_PROGS += $(foreach v,$(SIGMA_TEST_VARIANTS),build/$(v)/test_sigma)

.PHONY: sigma-golden
sigma-golden:
	$(PYTHON) tests/reference/gen_sigma_reference.py -o tests/golden/sigma_vectors.csv

# The fitting tools (numpy/scipy). The CLI test also runs today's
# `squeal-sim replay --calib` on a written calibration.
CALIB_FIT_TESTS := tests/calibrate/test_fit_friction.py tests/calibrate/test_fit_modal.py \
	tests/calibrate/test_fit_cli.py
tests/calibrate/test_fit_cli.py: build/host/squeal-sim
TEST_PROGS += $(CALIB_FIT_TESTS)
