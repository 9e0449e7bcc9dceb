# SPDX-License-Identifier: MIT
# Benchmarks of the squeal model (figures only, never pass/fail):
#   build/host/tests/firmware/model/bench_squeal_model        float build, -O2, no sanitizers
#   build/host-fixed/tests/firmware/model/bench_squeal_model  fixed build
#   tests/firmware/model/bench_squeal_model.sh    both builds, callgrind counts, brute force
# and the test of the brute-force reference against the model's tabulated cycles:
#   build/test/tests/support/test_brute_force
#
# make bench runs BENCH_PROGS, the quick figures (under 10 minutes on two
# cores); make bench-full adds BENCH_FULL_PROGS, the slow ones. A fragment
# adds a slow benchmark with BENCH_FULL_PROGS += PROG. The slow ones here:
#   tools/mutate.py                  the mutation score (make mutate; docs/mutation.md)
#   tests/system/soak/soak-replay.sh 10^7 frames through replay (make soak-replay)
BENCH_MODEL_VARIANTS := host host-fixed
BENCH_MODEL_SRCS := tests/firmware/model/bench_squeal_model.c tests/support/brute_force.c host-sim/sim_num.c

define bench_model_rules
build/$(1)/tests/firmware/model/bench_squeal_model: $$(patsubst %.c,build/$(1)/app/%.o,$$(BENCH_MODEL_SRCS)) build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lm
endef
$(foreach v,$(BENCH_MODEL_VARIANTS),$(eval $(call bench_model_rules,$(v))))

build/test/tests/support/test_brute_force: build/test/app/tests/support/test_brute_force.o build/test/app/tests/support/brute_force.o
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm

# make builds what the script runs; the script builds nothing.
tests/firmware/model/bench_squeal_model.sh: $(foreach v,$(BENCH_MODEL_VARIANTS),build/$(v)/tests/firmware/model/bench_squeal_model)

ALL_TARGETS += $(foreach v,$(BENCH_MODEL_VARIANTS),build/$(v)/tests/firmware/model/bench_squeal_model)
BENCH_PROGS += tests/firmware/model/bench_squeal_model.sh
TEST_PROGS += build/test/tests/support/test_brute_force

# make builds what they run (mutate.py builds its own scratch tree)
tests/system/soak/soak-replay.sh: build/host/squeal-sim build/host/soak_log_count
BENCH_FULL_PROGS += tools/mutate.py tests/system/soak/soak-replay.sh
