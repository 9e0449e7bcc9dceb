# SPDX-License-Identifier: MIT
# The monitor on a vehicle's bus, Python side:
#   tools/vehicle_calib.py                  calibration text (+ outputs DBC) from a vehicle DBC
#   tests/tools/fixtures/*.dbc, unseen/     fixture layouts written by the project
#   tools/dbc_tolerant.py, vcalib_rules.py  its DBC reader for files from the field, its signal rules
#   tests/tools/test_vehicle_calib.py     the tool vs canmatrix, refusals, --dbc-out, --base,
#                                           and the self-tests of the harnesses (no C needed)
#   tests/tools/test_vehicle_calib_field.py     field DBC layouts (tests/tools/fixtures/field/): ranges, not
#                                           available, qualifiers, bad lines, mux, buses, units (no C)
#   tests/tools/test_vehicle_calib_crosscheck.py  decode --calib --inputs-csv == canmatrix, random frames
#   tests/tools/test_vehicle_calib_e2e.py       drive -> replay --calib -> outputs vs the reference
#   tests/tools/test_vehicle_calib_unseen.py    a layout no other test uses (tests/tools/fixtures/unseen/)
#   tests/system/realcan/test_realcan_sweep.py     every integer signal of the real DBC files of the
#                                           realcan collection beside the repository (a counted
#                                           skip without it)
#   tests/system/realcan/test_realcan_drives.py    the recorded drives of that collection: calibrated
#                                           from their DBC only, replayed, checked (a counted skip
#                                           without it); --table prints the figures
# The crosscheck, e2e and unseen tests run the sanitizer builds of squeal-sim
# (float and fixed), each also as the tool's calib-check; the sweep runs
# build/host/squeal-sim, the tool's default checker.
VEHICLE_SIM_TESTS := tests/tools/test_vehicle_calib_crosscheck.py tests/tools/test_vehicle_calib_e2e.py \
	tests/tools/test_vehicle_calib_unseen.py
$(VEHICLE_SIM_TESTS): build/test/squeal-sim build/test-fixed/squeal-sim

tests/system/realcan/test_realcan_sweep.py tests/system/realcan/test_realcan_drives.py: build/host/squeal-sim

TEST_PROGS += tests/tools/test_vehicle_calib.py tests/tools/test_vehicle_calib_field.py $(VEHICLE_SIM_TESTS) \
	tests/system/realcan/test_realcan_sweep.py tests/system/realcan/test_realcan_drives.py
