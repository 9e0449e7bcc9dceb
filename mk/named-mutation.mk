# SPDX-License-Identifier: MIT
# Tests written for make mutate's survivors, each named after the module it
# tests (tests/README.md), so that tools/test_map.py gives them to it.
#   tests/tools/test_vcalib_rules_qualifier.py  the qualifier bit: two equal siblings, none chosen
TEST_PROGS += tests/tools/test_vcalib_rules_qualifier.py
