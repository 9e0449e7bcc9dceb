# SPDX-License-Identifier: MIT
# Brake-squeal monitor: one Makefile for host programs, tests, benchmarks and
# the ECU images. Area-specific rules live in mk/*.mk and add themselves to
# the lists below (TEST_PROGS, BENCH_PROGS, BENCH_FULL_PROGS, ALL_TARGETS).
#
#   make            host programs: build/host/squeal-sim (float),
#                   build/host-fixed/squeal-sim (fixed point)
#   make test       every test; ends with "N passed, N failed, N skipped"
#   make bench      the quick benchmarks (figures, never pass/fail; under 10 min)
#   make bench-full those and the slow ones (mutation score, callgrind of
#                   every poll, the long soak)
#   make demo       the main job (see README)

.DEFAULT_GOAL := all
SHELL := /bin/bash
PYTHON ?= /usr/bin/python3
CC ?= cc
ifeq ($(origin CC),default)
CC := gcc
endif
NUMERIC ?= float

FW_DIRS := firmware/model firmware/protocol firmware/monitor firmware/app
FW_SRCS := $(sort $(wildcard $(addsuffix /*.c,$(FW_DIRS))))
FW_INC := $(addprefix -I,$(FW_DIRS)) -Ihal

# Warnings for all our C. firmware/ additionally builds freestanding.
WARN := -std=c11 -Wall -Wextra -Wconversion -Wsign-conversion -Wshadow \
	-Wstrict-prototypes -Wmissing-prototypes -Wundef -Wcast-align \
	-Wdouble-promotion -Wformat=2 -Werror
FW_FLAGS := -ffreestanding
SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
DEF_fixed := -DSQUEAL_NUMERIC_FIXED
DEF_float :=
# x86 general-purpose registers only: the fixed build must not contain a
# floating-point operation, and this makes the compiler refuse one.
FIXED_ONLY_INT := -mgeneral-regs-only

# Build variants: name, numeric, extra flags
#   host        release float      host-fixed  release fixed
#   test        ASan+UBSan float   test-fixed  ASan+UBSan fixed
VARIANTS := host host-fixed test test-fixed
NUM_host := float
NUM_host-fixed := fixed
NUM_test := float
NUM_test-fixed := fixed
OPT_host := -O2 -g
OPT_host-fixed := -O2 -g
OPT_test := -O1 -g $(SAN)
OPT_test-fixed := -O1 -g $(SAN)

define variant_rules
build/$(1)/fw/%.o: %.c
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) $$(FW_FLAGS) $$(OPT_$(1)) $$(DEF_$$(NUM_$(1))) $$(if $$(filter fixed,$$(NUM_$(1))),$$(FIXED_ONLY_INT)) $$(FW_INC) -MMD -MP -c $$< -o $$@
build/$(1)/app/%.o: %.c
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) -D_GNU_SOURCE $$(OPT_$(1)) $$(DEF_$$(NUM_$(1))) $$(FW_INC) -Ihost-sim -Ihal/linux -Ihal/vbus -Itests/support -Itests/hal -MMD -MP -c $$< -o $$@
build/$(1)/libfirmware.a: $$(patsubst %.c,build/$(1)/fw/%.o,$$(FW_SRCS)) build/$(1)/app/$$(HAL_CONTRACT_HOST:.c=.o)
	@rm -f $$@
	ar rcs $$@ $$^
endef
# On the host the firmware library carries hal.h's default contract handler
# (print FILE:LINE, abort) as its own member, so every host program that
# links libfirmware.a has one; a HAL backend library or a test that defines
# hal_contract_failed itself is linked first and wins.
HAL_CONTRACT_HOST := hal/host/hal_contract_abort.c
$(foreach v,$(VARIANTS),$(eval $(call variant_rules,$(v))))

LDLIBS_host := -lm

TEST_PROGS :=
BENCH_PROGS :=
BENCH_FULL_PROGS :=
ALL_TARGETS :=

include $(sort $(wildcard mk/*.mk))

# squeal-sim: defined after every fragment has added to SIM_SRCS/SIM_LIBS_*
define sim_program
build/$(1)/squeal-sim: $$(patsubst %.c,build/$(1)/app/%.o,$$(sort $$(SIM_SRCS))) $$(SIM_LIBS_$(1)) build/$(1)/libfirmware.a
	$$(CC) $$(OPT_$(1)) -o $$@ $$(patsubst %.c,build/$(1)/app/%.o,$$(sort $$(SIM_SRCS))) $$(SIM_LIBS_$(1)) build/$(1)/libfirmware.a -lm
endef
$(foreach v,$(VARIANTS),$(eval $(call sim_program,$(v))))

.PHONY: all test bench bench-full demo clean
all: $(ALL_TARGETS)

# The README's commands install what they need (tools/ensure-deps.sh), then
# build; the test runner's summary line is the last line printed.
.PHONY: deps-test deps-demo
deps-test:
	@tools/ensure-deps.sh test
deps-demo:
	@tools/ensure-deps.sh demo

test: deps-test
	@mkdir -p build
	@$(MAKE) --no-print-directory -j$$(nproc) $(TEST_PROGS) >build/test-build.log 2>&1 || { tail -n 40 build/test-build.log; exit 1; }
	@tests/run-tests.sh $(TEST_PROGS)

# make builds what the bench programs run; tests/support/run-bench.sh runs
# them with progress on a terminal and their times at the end.
bench: $(BENCH_PROGS)
	@tests/support/run-bench.sh $(BENCH_PROGS)
bench-full: $(BENCH_PROGS) $(BENCH_FULL_PROGS)
	@tests/support/run-bench.sh $(BENCH_PROGS) $(BENCH_FULL_PROGS)

clean:
	rm -rf build

-include $(shell find build -name '*.d' 2>/dev/null)
