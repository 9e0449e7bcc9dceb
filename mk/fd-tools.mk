# SPDX-License-Identifier: MIT
# CAN FD on a vehicle's bus, Python side:
#   tools/vehicle_calib.py, vcalib_rules.py, dbc_tolerant.py  FD messages, E2E P05, ## logs
#   tests/tools/fixtures/                    FD fixture layouts written by the project (+ unseen/)
#   tests/tools/test_vehicle_calib_fd.py     the tool vs canmatrix on the FD layouts, refusals,
#                                            --log, random FD frames vs canmatrix (no C)
#   tests/tools/test_vehicle_calib_fd_unseen.py  the held-out FD layout end to end through
#                                            squeal-sim replay (both sanitizer builds); a counted
#                                            skip while calib-check refuses an FD calibration
tests/tools/test_vehicle_calib_fd_unseen.py: build/test/squeal-sim build/test-fixed/squeal-sim

TEST_PROGS += tests/tools/test_vehicle_calib_fd.py tests/tools/test_vehicle_calib_fd_unseen.py
