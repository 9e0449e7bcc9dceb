# SPDX-License-Identifier: MIT
# The host programs: build/host/squeal-sim (float) and build/host-fixed/squeal-sim.
# Other areas add their sources with SIM_SRCS += ... and libraries with
# SIM_LIBS_<variant> += ...

SIM_SRCS += host-sim/squeal_sim.c host-sim/cmd_classify.c host-sim/sim_num.c
# ecu, plant (mk/integration.mk has their tests); they run on hal/linux
SIM_SRCS += host-sim/cmd_ecu.c host-sim/cmd_plant.c host-sim/plant_scenario.c host-sim/plant_vehicle.c host-sim/calib_text.c host-sim/calib_sections.c
SIM_SRCS += host-sim/cmd_calib_check.c
SIM_LIBS_host += build/host/liboscsim.a build/host/libhal_linux.a
SIM_LIBS_host-fixed += build/host-fixed/liboscsim.a build/host-fixed/libhal_linux.a
SIM_LIBS_test += build/test/liboscsim.a build/test/libhal_linux.a
SIM_LIBS_test-fixed += build/test-fixed/liboscsim.a build/test-fixed/libhal_linux.a

# (the link rule is in the top-level Makefile, after every fragment has
# added its sources)

ALL_TARGETS += build/host/squeal-sim build/host-fixed/squeal-sim

.PHONY: demo
demo: deps-demo build/host/squeal-sim
	@tools/demo.sh

# firmware/ builds for both MCUs; the fixed build has no floating point
TEST_PROGS += tests/system/static/check_portable.sh

# the README's main job (tools/demo.sh) end to end
TEST_PROGS += tests/system/demo/test_demo.sh
tests/system/demo/test_demo.sh: build/host/squeal-sim
