# SPDX-License-Identifier: MIT
# The pictures. `make plots` writes into build/plots/ only (PNG at 150 dpi
# and an SVG beside each): the maps, the phase portraits, a replayed drive
# (the plant's `sweep` scenario through the firmware in virtual time, its
# inputs and outputs decoded) over the map, its live view, a fleet report's
# heat map of generated logs, and the calibration example (mk/calibrate.mk).
# DRIVE_CSV=file.csv draws that file instead of the replayed drive
# (time_s,v0_mps,force_n,state,warning or decode --csv).
# `make docs-img` refreshes the committed docs/img/ from build/plots/: the
# PNGs, and the SVGs under DOCS_SVG_MAX bytes.
PLOT_GRID ?= 100
DRIVE_SCENARIO ?= sweep
LIVE_SCENARIO ?= stop
LIVE_AFTER_S ?= 5.2
FLEET_PLOT_LOGS ?= 40
DOCS_SVG_MAX ?= 300000
DOCS_IMG := stability_map stability_map_variations phase_portraits drive live_view \
	fleet_heatmap calib_friction calib_tap_test calib_bands

.PHONY: plots plots-maps plots-drive plots-live plots-fleet docs-img
plots: plots-maps plots-drive plots-live plots-fleet plots-calib

plots-maps: deps-demo build/host/oscsim
	@mkdir -p build/plots
	build/host/oscsim map --grid $(PLOT_GRID) --brake all --no-linear --csv build/plots/map.csv >build/plots/map-summary.txt
	$(PYTHON) tools/plots/plot_map.py build/plots/map.csv --out build/plots
	$(PYTHON) tools/plots/plot_phase.py --sim build/host/oscsim --out build/plots

plots-drive: deps-demo build/host/squeal-sim
	@mkdir -p build/plots
ifeq ($(DRIVE_CSV),)
	build/host/squeal-sim plant --log build/plots/drive-in.log --scenario $(DRIVE_SCENARIO) --quiet
	build/host/squeal-sim replay build/plots/drive-in.log >build/plots/drive-out.log 2>build/plots/drive-replay.txt
	sort -s -k1,1 build/plots/drive-in.log build/plots/drive-out.log | build/host/squeal-sim decode --csv >build/plots/drive.csv
	$(PYTHON) tools/plots/plot_drive.py build/plots/drive.csv --out build/plots --name drive
else
	$(PYTHON) tools/plots/plot_drive.py $(DRIVE_CSV) --out build/plots --name drive
endif

# the live view of a braking stop, snapshotted while it squeals
plots-live: deps-demo build/host/squeal-sim
	@mkdir -p build/plots
	build/host/squeal-sim plant --log build/plots/live-in.log --scenario $(LIVE_SCENARIO) --quiet
	build/host/squeal-sim replay build/plots/live-in.log >build/plots/live-out.log 2>/dev/null
	$(PYTHON) tools/live_view.py --log build/plots/live-out.log --snapshot build/plots/live_view.png --after $(LIVE_AFTER_S)

# a fleet report of generated logs (a few broken ones: counted apart)
plots-fleet: deps-demo build/host/squeal-sim
	@rm -rf build/plots/fleet-logs build/plots/fleet-report
	$(PYTHON) tools/gen_fleet_logs.py --out build/plots/fleet-logs --count $(FLEET_PLOT_LOGS) --broken 3 --seed 5 >/dev/null
	$(PYTHON) tools/fleet.py --dir build/plots/fleet-logs -o build/plots/fleet-report --workers 2 >build/plots/fleet.txt 2>&1
	cp build/plots/fleet-report/heatmap.png build/plots/fleet_heatmap.png
	cp build/plots/fleet-report/heatmap.svg build/plots/fleet_heatmap.svg

docs-img:
	@for n in $(DOCS_IMG); do test -f build/plots/$$n.png || { echo "docs-img: build/plots/$$n.png missing: run make plots first" >&2; exit 1; }; done
	@mkdir -p docs/img
	@for n in $(DOCS_IMG); do cp build/plots/$$n.png docs/img/; \
		if [ $$(stat -c %s build/plots/$$n.svg) -lt $(DOCS_SVG_MAX) ]; then cp build/plots/$$n.svg docs/img/; \
		else rm -f docs/img/$$n.svg; fi; done
	@ls -l docs/img

# the heat map's totals, key and labels, from fixture logs without Dask
tests/tools/test_fleet_heatmap.py: build/host/squeal-sim
TEST_PROGS += tests/tools/test_fleet_heatmap.py

# plotlib's style (150 dpi + SVG, names in words, the stretched speed axis)
# and the committed docs/img pictures; each picture is drawn by its own
# tests/tools/plots/test_plot_*.py (mk/named-tools.mk)
TEST_PROGS += tests/tools/plots/test_plotlib.py
