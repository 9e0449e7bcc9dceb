# SPDX-License-Identifier: MIT
# The module -> tests map (tools/test_map.py): every module with logic has a
# test named after it. make mutate itself (mk/checks.mk) is neither in make
# test nor in make bench: a figure of its own, about 15 minutes.
TEST_PROGS += tests/tools/check_test_map.sh

# tests named after the tools modules they test (tests/README.md)
#   tests/tools/test_vcalib_rules.py  number rules, raw limits, "not available" codes
#   tests/tools/test_drive_common.py  a calibration's corners and identifiers
TEST_PROGS += tests/tools/test_vcalib_rules.py tests/tools/test_drive_common.py

# tests named after the host-sim modules they test
#   tests/host-sim/test_cmd_ecu.py  squeal-sim ecu's options, without a CAN interface
tests/host-sim/test_cmd_ecu.py: build/host/squeal-sim
TEST_PROGS += tests/host-sim/test_cmd_ecu.py
