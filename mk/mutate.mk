# SPDX-License-Identifier: MIT
# The module -> tests map (tools/test_map.py): every module with logic has a
# test named after it. make mutate itself (mk/checks.mk) is neither in make
# test nor in make bench: a figure of its own, about 15 minutes.
TEST_PROGS += tests/tools/check_test_map.sh

# tests named after the tools modules they test (tests/README.md)
#   tests/tools/test_vcalib_rules.py  number rules, raw limits, "not available" codes
#   tests/tools/test_drive_common.py  a calibration's corners and identifiers
TEST_PROGS += tests/tools/test_vcalib_rules.py tests/tools/test_drive_common.py
