# SPDX-License-Identifier: MIT
# Tests of firmware/model against the independent reference
# (tests/support/reference/squeal_reference.py):
#   build/test{,-fixed}/tests/firmware/model/test_squeal_model        golden vectors (tests/support/golden/model_vectors.csv)
#   build/test{,-fixed}/tests/firmware/model/test_squeal_model_props  properties and bit-pattern robustness
#   tests/host-sim/test_cmd_classify.py        squeal-sim classify, both builds
#   make golden                           regenerate the golden vectors

MODEL_TEST_VARIANTS := test test-fixed
MODEL_TEST_SUPPORT := tests/support/sq_num.c tests/support/test_contract.c

define model_test_rules
build/$(1)/tests/firmware/model/test_squeal_model: build/$(1)/app/tests/firmware/model/test_squeal_model.o $$(patsubst %.c,build/$(1)/app/%.o,$$(MODEL_TEST_SUPPORT)) build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
build/$(1)/tests/firmware/model/test_squeal_model_props: build/$(1)/app/tests/firmware/model/test_squeal_model_props.o $$(patsubst %.c,build/$(1)/app/%.o,$$(MODEL_TEST_SUPPORT)) build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(MODEL_TEST_VARIANTS),$(eval $(call model_test_rules,$(v))))

TEST_PROGS += $(foreach v,$(MODEL_TEST_VARIANTS),build/$(v)/tests/firmware/model/test_squeal_model build/$(v)/tests/firmware/model/test_squeal_model_props)

# The CLI test runs both host programs (built by mk/host.mk).
tests/host-sim/test_cmd_classify.py: build/host/squeal-sim build/host-fixed/squeal-sim
TEST_PROGS += tests/host-sim/test_cmd_classify.py

.PHONY: golden
golden:
	$(PYTHON) tests/support/reference/squeal_reference.py --self-check
	$(PYTHON) tests/support/reference/gen_model_vectors.py -o tests/support/golden/model_vectors.csv

# The reference against docs/model.md, and the golden file against the reference.
TEST_PROGS += tests/firmware/model/check_squeal_model_golden.py

# fixmath against libm at its documented accuracy (fixed build only)
build/test-fixed/tests/firmware/model/test_fixmath: build/test-fixed/app/tests/firmware/model/test_fixmath.o build/test-fixed/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test-fixed) -o $@ $^ -lcmocka -lm
TEST_PROGS += build/test-fixed/tests/firmware/model/test_fixmath

# the model adapter's integer view at its rounding rules, both builds
define model_adapter_test_rules
build/$(1)/tests/firmware/monitor/test_model_adapter: build/$(1)/app/tests/firmware/monitor/test_model_adapter.o $$(patsubst %.c,build/$(1)/app/%.o,$$(MODEL_TEST_SUPPORT)) build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(MODEL_TEST_VARIANTS),$(eval $(call model_adapter_test_rules,$(v))))
TEST_PROGS += $(foreach v,$(MODEL_TEST_VARIANTS),build/$(v)/tests/firmware/monitor/test_model_adapter)

# sq_mathf against the host's double libm in ulp; the float build only (the
# fixed build has no float functions)
build/test/tests/firmware/model/test_sq_mathf: build/test/app/tests/firmware/model/test_sq_mathf.o build/test/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm
TEST_PROGS += build/test/tests/firmware/model/test_sq_mathf
