#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every module with logic has a test named after it under tests/ (the rule of
# tests/README.md; tools/test_map.py derives the map from the paths, and
# make mutate meets each module's tests through it). One counted check per
# module: "RESULT: N passed, M failed".
cd "$(dirname "$0")/../.." || exit 1
exec /usr/bin/python3 tools/test_map.py --check
