# SPDX-License-Identifier: MIT
# The suite's own checks: the test runner's self-test (skip
# counting, CI's expected skips) and the negative controls of checks that
# must be able to fail. make mutate: the mutation score (a bench figure).
TEST_PROGS += tests/support/test-run-tests.sh

# the shared check helpers (check, all_of, any_of) can fail
TEST_PROGS += tests/support/test-checks-lib.sh

# run-ecu-boot.sh on a stub emulator: a bad boot fails exactly its six checks
tests/system/target/test-ecu-boot-control.sh: build/stm32f4-ecutest/squeal-monitor.elf \
	build/stm32f4-faulttest/squeal-monitor.elf
TEST_PROGS += tests/system/target/test-ecu-boot-control.sh

# check-calib-write-path.sh: an image that was not built is a counted skip
TEST_PROGS += tests/system/static/test-calib-write-path-control.sh

# test_demo.sh with a demo that draws no picture (a stale one left in place)
tests/system/demo/test-demo-control.sh: build/host/squeal-sim
TEST_PROGS += tests/system/demo/test-demo-control.sh

# cppcheck-misra.sh: a missing or failing addon, no files, a row over budget
TEST_PROGS += tests/system/static/test-cppcheck-misra-control.sh

# test_unpack_crosscheck.py with an unpacker one bit off / accepting bad frames
tests/firmware/protocol/test_squeal_msgs_unpack_control.sh: build/test/tests/firmware/protocol/unpack_random
TEST_PROGS += tests/firmware/protocol/test_squeal_msgs_unpack_control.sh

# the mutant list still applies to the sources (nothing is built or run)
TEST_PROGS += tests/support/check-mutants.sh

# Mutation score (tools/mutate.py, mutants in tools/mutants.txt): a scratch
# copy in build/mutate/, one mutant at a time, only the tests of the mutated
# module (tools/test_map.py); within 15 minutes on two cores, builds kept in
# build/mutate/tree. A figure (docs/mutation.md), in neither make test nor
# make bench.
.PHONY: mutate
mutate:
	@$(PYTHON) tools/mutate.py
