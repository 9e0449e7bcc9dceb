# SPDX-License-Identifier: MIT
# Benchmarks of the squeal model (figures only, never pass/fail):
#   build/host/bench_model        float build, -O2, no sanitizers
#   build/host-fixed/bench_model  fixed build
#   tests/bench/bench-model.sh    both builds, callgrind counts, brute force
# and the test of the brute-force reference against model.md section 6:
#   build/test/test_brute_force
BENCH_MODEL_VARIANTS := host host-fixed
BENCH_MODEL_SRCS := tests/bench/bench_model.c tests/bench/brute_force.c host-sim/sim_num.c

define bench_model_rules
build/$(1)/bench_model: $$(patsubst %.c,build/$(1)/app/%.o,$$(BENCH_MODEL_SRCS)) build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lm
endef
$(foreach v,$(BENCH_MODEL_VARIANTS),$(eval $(call bench_model_rules,$(v))))

build/test/test_brute_force: build/test/app/tests/bench/test_brute_force.o build/test/app/tests/bench/brute_force.o
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm

# make builds what the script runs; the script builds nothing.
tests/bench/bench-model.sh: $(foreach v,$(BENCH_MODEL_VARIANTS),build/$(v)/bench_model)

ALL_TARGETS += $(foreach v,$(BENCH_MODEL_VARIANTS),build/$(v)/bench_model)
BENCH_PROGS += tests/bench/bench-model.sh
TEST_PROGS += build/test/test_brute_force
