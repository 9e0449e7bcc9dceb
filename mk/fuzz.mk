# SPDX-License-Identifier: MIT
# libFuzzer targets (tests/support/fuzz/), built with clang and ASan+UBSan:
#   build/fuzz/bin/fuzz_model_float  model, float build: any bit pattern
#   build/fuzz/bin/fuzz_model_fixed  model, fixed build: any int32
#   build/fuzz/bin/fuzz_msgs         every unpack, E2E P01 check, receive
#   build/fuzz/bin/fuzz_calib_block  calibration block decode/encode
#   build/fuzz/bin/fuzz_monitor      monitor under arbitrary frames and time
#   build/fuzz/bin/fuzz_monitor_fixed  the same, fixed build (model adapter)
#   (fuzz_candump, fuzz_calib_text{,_fixed} when host-sim's parsers exist)
#
#   make fuzz                 each target FUZZ_SECONDS (300) on its corpus,
#                             prints execs/s and coverage (cov/ft)
#   make test                 runs tests/support/fuzz/run-fuzz.sh: each target
#                             FUZZ_TEST_SECONDS (10); any crash, timeout,
#                             leak or sanitizer report fails
#   make fuzz-seeds           regenerate tests/support/fuzz/corpus/ (gen-seeds.sh)
#   make fuzz-coverage        line coverage reached by the seeds + corpora
# Firmware objects get their own clang variants build/fuzz{,-fixed}/ so the
# gcc builds are not touched.

FUZZ_CC ?= clang-14
FUZZ_SECONDS ?= 300
FUZZ_TEST_SECONDS ?= 10
export FUZZ_SECONDS FUZZ_TEST_SECONDS
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_CFLAGS := -O1 -g $(FUZZ_SAN) -fsanitize=fuzzer-no-link
FUZZ_LDFLAGS := -g $(FUZZ_SAN) -fsanitize=fuzzer
FUZZ_BIN := build/fuzz/bin

# fuzzcov: the same harnesses with source coverage instead of sanitizers,
# to replay a corpus and report line coverage (make fuzz-coverage)
FUZZ_VARIANTS := fuzz fuzz-fixed fuzzcov fuzzcov-fixed
NUM_fuzz := float
NUM_fuzz-fixed := fixed
NUM_fuzzcov := float
NUM_fuzzcov-fixed := fixed
FUZZ_COV_FLAGS := -fprofile-instr-generate -fcoverage-mapping
CFLAGS_fuzz := $(FUZZ_CFLAGS)
CFLAGS_fuzz-fixed := $(FUZZ_CFLAGS)
CFLAGS_fuzzcov := -O1 -g $(FUZZ_COV_FLAGS) -fsanitize=fuzzer-no-link
CFLAGS_fuzzcov-fixed := $(CFLAGS_fuzzcov)

define fuzz_variant_rules
build/$(1)/fw/%.o: %.c
	@mkdir -p $$(@D)
	$$(FUZZ_CC) $$(WARN) $$(FW_FLAGS) $$(CFLAGS_$(1)) $$(DEF_$$(NUM_$(1))) $$(FW_INC) -MMD -MP -c $$< -o $$@
build/$(1)/app/%.o: %.c
	@mkdir -p $$(@D)
	$$(FUZZ_CC) $$(WARN) -D_GNU_SOURCE $$(CFLAGS_$(1)) $$(DEF_$$(NUM_$(1))) $$(FW_INC) -Ihost-sim -Ihal/linux -Itests/support -Itests/support/fuzz -MMD -MP -c $$< -o $$@
build/$(1)/libfirmware.a: $$(patsubst %.c,build/$(1)/fw/%.o,$$(FW_SRCS)) build/$(1)/app/$$(HAL_CONTRACT_HOST:.c=.o)
	@rm -f $$@
	ar rcs $$@ $$^
endef
$(foreach v,$(FUZZ_VARIANTS),$(eval $(call fuzz_variant_rules,$(v))))

# name, variant, harness source, extra objects (given for the fuzz variant;
# the coverage twin build/fuzzcov/bin/<name> uses the same paths in fuzzcov)
define fuzz_target
$(FUZZ_BIN)/$(1): build/$(2)/app/$(3:.c=.o) $(4) build/$(2)/libfirmware.a
	@mkdir -p $$(@D)
	$$(FUZZ_CC) $$(FUZZ_LDFLAGS) -o $$@ $$^ -lm
FUZZ_TARGETS += $(FUZZ_BIN)/$(1)
build/fuzzcov/bin/$(1): build/$(subst fuzz,fuzzcov,$(2))/app/$(3:.c=.o) $(subst build/fuzz-fixed/,build/fuzzcov-fixed/,$(subst build/fuzz/,build/fuzzcov/,$(4))) build/$(subst fuzz,fuzzcov,$(2))/libfirmware.a
	@mkdir -p $$(@D)
	$$(FUZZ_CC) -g $$(FUZZ_COV_FLAGS) -fsanitize=fuzzer -o $$@ $$^ -lm
FUZZ_COV_TARGETS += build/fuzzcov/bin/$(1)
endef

FUZZ_TARGETS :=
FUZZ_COV_TARGETS :=
$(eval $(call fuzz_target,fuzz_model_float,fuzz,tests/firmware/model/fuzz_squeal_model.c))
$(eval $(call fuzz_target,fuzz_model_fixed,fuzz-fixed,tests/firmware/model/fuzz_squeal_model.c))
$(eval $(call fuzz_target,fuzz_msgs,fuzz,tests/firmware/protocol/fuzz_squeal_msgs.c,build/fuzz/app/tests/support/any_msg.o))
$(eval $(call fuzz_target,fuzz_calib_block,fuzz,tests/firmware/monitor/fuzz_calib.c))
$(eval $(call fuzz_target,fuzz_monitor,fuzz,tests/firmware/monitor/fuzz_monitor.c))
$(eval $(call fuzz_target,fuzz_monitor_fixed,fuzz-fixed,tests/firmware/monitor/fuzz_monitor.c))
# host-sim's parsers (once they exist)
ifeq ($(words $(wildcard host-sim/candump_log.c tests/host-sim/fuzz_candump_log.c)),2)
$(eval $(call fuzz_target,fuzz_candump,fuzz,tests/host-sim/fuzz_candump_log.c,build/fuzz/app/host-sim/candump_log.o))
endif
ifeq ($(words $(wildcard host-sim/calib_text.c tests/host-sim/fuzz_calib_text.c)),2)
$(eval $(call fuzz_target,fuzz_calib_text,fuzz,tests/host-sim/fuzz_calib_text.c,build/fuzz/app/host-sim/calib_text.o build/fuzz/app/host-sim/calib_sections.o))
# the same properties in the fixed build ("what validates sets up" in both)
$(eval $(call fuzz_target,fuzz_calib_text_fixed,fuzz-fixed,tests/host-sim/fuzz_calib_text.c,build/fuzz-fixed/app/host-sim/calib_text.o build/fuzz-fixed/app/host-sim/calib_sections.o))
endif

export FUZZ_TARGETS

.PHONY: fuzz fuzz-build fuzz-seeds fuzz-coverage
# Line coverage of the code under test, from the seeds and the corpora that
# make fuzz grew (build/fuzz-corpus/): tests/support/fuzz/fuzz-coverage.sh
fuzz-coverage: $(FUZZ_COV_TARGETS)
	tests/support/fuzz/fuzz-coverage.sh $(FUZZ_COV_TARGETS)
fuzz-build: $(FUZZ_TARGETS)
fuzz: $(FUZZ_TARGETS)
	tests/support/fuzz/run-fuzz.sh --mode fuzz --seconds $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# Seed corpora: written by a small C program through the firmware's own
# encoders (valid frames and blocks are the interesting starting points).
FUZZ_SEEDGEN := build/host/tests/support/fuzz/gen_seeds
$(FUZZ_SEEDGEN): build/host/app/tests/support/fuzz/gen_seeds.o build/host/app/host-sim/candump_log.o \
		build/host/app/host-sim/calib_text.o build/host/app/host-sim/calib_sections.o build/host/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_host) -o $@ $^ -lm
fuzz-seeds: $(FUZZ_SEEDGEN)
	tests/support/fuzz/gen-seeds.sh $(FUZZ_SEEDGEN)

# make test: every target for a short, bounded time.
tests/support/fuzz/run-fuzz.sh: $(FUZZ_TARGETS)
TEST_PROGS += tests/support/fuzz/run-fuzz.sh

# Calibration write protection (cmocka, the whole app on the test HAL under
# a flood of random and spoofed frames), both numeric builds, ASan+UBSan.
# --wrap counts every call of hal_calib_write.
define calib_wp_rules
build/$(1)/tests/firmware/app/test_squeal_app_calib_write: build/$(1)/app/tests/firmware/app/test_squeal_app_calib_write.o build/$(1)/app/tests/support/test_hal.o build/$(1)/libfirmware.a build/$(1)/libhal_vbus.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -Wl,--wrap=hal_calib_write -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,test test-fixed,$(eval $(call calib_wp_rules,$(v))))
TEST_PROGS += build/test/tests/firmware/app/test_squeal_app_calib_write build/test-fixed/tests/firmware/app/test_squeal_app_calib_write
