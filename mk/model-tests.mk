# SPDX-License-Identifier: MIT
# Tests of firmware/model against the independent reference
# (tests/reference/squeal_reference.py):
#   build/test{,-fixed}/test_model        golden vectors (tests/golden/model_vectors.csv)
#   build/test{,-fixed}/test_model_props  properties and bit-pattern robustness
#   tests/cli/test_classify_cli.py        squeal-sim classify, both builds
#   make golden                           regenerate the golden vectors

MODEL_TEST_VARIANTS := test test-fixed
MODEL_TEST_SUPPORT := tests/support/sq_num.c tests/support/test_contract.c

define model_test_rules
build/$(1)/test_model: build/$(1)/app/tests/unit/test_model.o $$(patsubst %.c,build/$(1)/app/%.o,$$(MODEL_TEST_SUPPORT)) build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
build/$(1)/test_model_props: build/$(1)/app/tests/unit/test_model_props.o $$(patsubst %.c,build/$(1)/app/%.o,$$(MODEL_TEST_SUPPORT)) build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(MODEL_TEST_VARIANTS),$(eval $(call model_test_rules,$(v))))

TEST_PROGS += $(foreach v,$(MODEL_TEST_VARIANTS),build/$(v)/test_model build/$(v)/test_model_props)

# The CLI test runs both host programs (built by mk/host.mk).
tests/cli/test_classify_cli.py: build/host/squeal-sim build/host-fixed/squeal-sim
TEST_PROGS += tests/cli/test_classify_cli.py

.PHONY: golden
golden:
	$(PYTHON) tests/reference/squeal_reference.py --self-check
	$(PYTHON) tests/reference/gen_model_vectors.py -o tests/golden/model_vectors.csv

# The reference against model.md, and the golden file against the reference.
TEST_PROGS += tests/reference/check_golden.py

# fixmath against libm at its documented accuracy (fixed build only)
build/test-fixed/test_fixmath: build/test-fixed/app/tests/unit/test_fixmath.o build/test-fixed/libfirmware.a
	$(CC) $(OPT_test-fixed) -o $@ $^ -lcmocka -lm
TEST_PROGS += build/test-fixed/test_fixmath

# the model adapter's integer view at its rounding rules, both builds
define model_adapter_test_rules
build/$(1)/test_model_adapter: build/$(1)/app/tests/unit/test_model_adapter.o $$(patsubst %.c,build/$(1)/app/%.o,$$(MODEL_TEST_SUPPORT)) build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(MODEL_TEST_VARIANTS),$(eval $(call model_adapter_test_rules,$(v))))
TEST_PROGS += $(foreach v,$(MODEL_TEST_VARIANTS),build/$(v)/test_model_adapter)
