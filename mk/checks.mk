# SPDX-License-Identifier: MIT
# The suite's own checks (issue 15): the test runner's self-test (skip
# counting, CI's expected skips) and the negative controls of checks that
# must be able to fail. make mutate: the mutation score (a bench figure).
TEST_PROGS += tests/support/test-run-tests.sh
