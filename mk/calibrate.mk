# SPDX-License-Identifier: MIT
# Calibrating a brake from measurements:
#   build/test{,-fixed}/tests/firmware/model/test_squeal_sigma    firmware/model/squeal_sigma.h against
#                                     Monte Carlo (tests/support/golden/sigma_vectors.csv)
#   tests/tools/test_fit_*.py         the fitting tools on synthetic data
#                                     (recovery, 95 % coverage, bad files)
#   make sigma-golden                 regenerate the Monte Carlo file

SIGMA_TEST_VARIANTS := test test-fixed

define sigma_test_rules
build/$(1)/tests/firmware/model/test_squeal_sigma: build/$(1)/app/tests/firmware/model/test_squeal_sigma.o build/$(1)/app/tests/support/sq_num.o build/$(1)/app/tests/support/test_contract.o build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(SIGMA_TEST_VARIANTS),$(eval $(call sigma_test_rules,$(v))))

TEST_PROGS += $(foreach v,$(SIGMA_TEST_VARIANTS),build/$(v)/tests/firmware/model/test_squeal_sigma) tests/firmware/model/check_squeal_sigma_golden.py

.PHONY: sigma-golden
sigma-golden:
	$(PYTHON) tests/support/reference/gen_sigma_reference.py -o tests/support/golden/sigma_vectors.csv

# The fitting tools (numpy/scipy). The CLI test also runs today's
# `squeal-sim replay --calib` on a written calibration.
CALIB_FIT_TESTS := tests/tools/test_fit_friction.py tests/tools/test_fit_modal.py \
	tests/tools/test_fit_friction_cli.py tests/host-sim/test_cmd_classify_sigma.py \
	tests/tools/test_calibfit_user.py
tests/tools/test_fit_friction_cli.py: build/host/squeal-sim
# A user's whole path: fits -> calibration -> classify/replay --calib, both builds
tests/host-sim/test_cmd_classify_sigma.py tests/tools/test_calibfit_user.py: build/host/squeal-sim \
	build/host-fixed/squeal-sim
TEST_PROGS += $(CALIB_FIT_TESTS)

# `make plots` also draws the documented calibration example (README,
# "Calibrating a brake"): the two fits and the map with its border bands.
CALIB_EX := docs/examples
CALIB_EX_DYNO := --pad-radius-m 0.12 --piston-area-mm2 2000 --faces 2
CALIB_EX_MASS := --mass-kg 0.9 --mass-sd-kg 0.01
.PHONY: plots-calib
plots-calib: deps-demo
	@mkdir -p build/plots
	$(PYTHON) tools/fit_friction.py $(CALIB_EX)/dyno.csv $(CALIB_EX_DYNO) --base docs/calib-example.txt -o build/plots/example-friction.cal --plot build/plots/calib_friction.png
	$(PYTHON) tools/fit_modal.py $(CALIB_EX)/tap_test.wav $(CALIB_EX_MASS) --base build/plots/example-friction.cal -o build/plots/example-brake.cal --plot build/plots/calib_tap_test.png
	$(PYTHON) tools/plots/plot_calib_bands.py build/plots/example-brake.cal --out build/plots

