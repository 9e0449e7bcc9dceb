# SPDX-License-Identifier: MIT
# The oscillator simulator (host-sim/oscsim): ground truth for the model.
#   build/<v>/liboscsim.a      simulator + map/simulate commands (needs
#                              libfirmware.a and host-sim/sim_num.o of <v>)
#   build/<v>/oscsim           stand-alone driver: oscsim map|simulate
#   make plots                 pictures into build/plots/ (mk/plots.mk)
# For squeal-sim: link $(OSCSIM_LIB_host) and call oscsim_cmd_map /
# oscsim_cmd_simulate (host-sim/oscsim/oscsim_cmd.h).

OSCSIM_SRCS := host-sim/oscsim/oscsim.c host-sim/oscsim/oscsim_map.c \
	host-sim/oscsim/oscsim_cmd.c
OSCSIM_VARIANTS := host host-fixed test test-fixed
OSCSIM_NUM_SRC := host-sim/sim_num.c

define oscsim_rules
build/$(1)/liboscsim.a: $$(patsubst %.c,build/$(1)/app/%.o,$$(OSCSIM_SRCS))
	@rm -f $$@
	ar rcs $$@ $$^
OSCSIM_LIB_$(1) := build/$(1)/liboscsim.a
build/$(1)/oscsim: build/$(1)/app/host-sim/oscsim/oscsim_main.o build/$(1)/liboscsim.a build/$(1)/app/$(OSCSIM_NUM_SRC:.c=.o) build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lm
endef
$(foreach v,$(OSCSIM_VARIANTS),$(eval $(call oscsim_rules,$(v))))

ALL_TARGETS += build/host/oscsim

# Unit tests of the simulator against hand-derived closed forms (ASan+UBSan).
build/test/tests/host-sim/oscsim/test_oscsim: build/test/app/tests/host-sim/oscsim/test_oscsim.o build/test/liboscsim.a \
		build/test/app/$(OSCSIM_NUM_SRC:.c=.o) build/test/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka -lm
TEST_PROGS += build/test/tests/host-sim/oscsim/test_oscsim

# Agreement of the model (float and fixed) with simulation over the (a, v0)
# plane, 40 x 40 per brake. Release builds: the sweep is the heavy part and
# the simulator already runs under the sanitizers in test_oscsim.
OSCSIM_AGREE_VARIANTS := host host-fixed
define oscsim_agree_rules
build/$(1)/tests/host-sim/oscsim/test_oscsim_map_agreement: build/$(1)/app/tests/host-sim/oscsim/test_oscsim_map_agreement.o build/$(1)/liboscsim.a build/$(1)/app/$(OSCSIM_NUM_SRC:.c=.o) build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
endef
$(foreach v,$(OSCSIM_AGREE_VARIANTS),$(eval $(call oscsim_agree_rules,$(v))))
TEST_PROGS += $(foreach v,$(OSCSIM_AGREE_VARIANTS),build/$(v)/tests/host-sim/oscsim/test_oscsim_map_agreement)

# Cross-check against scipy's solve_ivp and docs/model.md section 6.
tests/host-sim/oscsim/test_oscsim_scipy.py: build/host/oscsim
TEST_PROGS += tests/host-sim/oscsim/test_oscsim_scipy.py

# make bench: the full-grid agreement figures with timings.
ALL_TARGETS += build/host-fixed/oscsim
tests/host-sim/oscsim/bench_oscsim_agreement.sh: build/host/oscsim build/host-fixed/oscsim
BENCH_PROGS += tests/host-sim/oscsim/bench_oscsim_agreement.sh

