#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Makes the README's commands set-up-free: checks that the Debian packages a
# purpose needs are installed and installs the missing ones (apt-get, as
# root), else prints the one apt-get line that does. Cheap when everything is
# there (one dpkg-query per package).
#   usage: tools/ensure-deps.sh demo|plots|fleet|vehicle|live|flash|test
# Each list is what that purpose's programs really import or run:
#   demo     squeal-sim, tools/demo_timeline.py, tools/plots/ (matplotlib,
#            numpy, and scipy for the closed-form borders in plotlib.py)
#   plots    the same plus the calibration fitters (scipy.optimize)
#   fleet    tools/fleet.py: the demo's plus Dask (dask, distributed)
#   vehicle  tools/vehicle_calib.py: canmatrix; candump to record a drive
#   live     tools/live_view.py: python-can and canmatrix beside the plots
#   flash    tools/flash.sh: OpenOCD
#   test     everything make test builds and runs
set -eu
purpose=${1:-test}
build="make gcc libc6-dev"
plot="python3 python3-numpy python3-scipy python3-matplotlib"
demo="$build $plot"
fleet="$demo python3-dask python3-distributed"
vehicle="python3 python3-canmatrix can-utils"
live="$demo python3-can python3-canmatrix"
flash="gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi openocd"
test="$build clang libclang-rt-14-dev gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi
 libcmocka-dev valgrind cppcheck $plot python3-can
 python3-canmatrix python3-dask python3-distributed can-utils qemu-system-x86 qemu-system-arm busybox-static cpio kmod iproute2"
case "$purpose" in
demo|plots) want=$demo ;;
fleet) want=$fleet ;;
vehicle) want=$vehicle ;;
live) want=$live ;;
flash) want=$flash ;;
test) want=$test ;;
-h|--help) sed -n '3,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
*) echo "usage: tools/ensure-deps.sh demo|plots|fleet|vehicle|live|flash|test" >&2; exit 2 ;;
esac
missing=""
for p in $want; do
	if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
		missing="$missing $p"
	fi
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" != 0 ]; then
	echo "missing Debian packages:$missing (install them: sudo apt-get install --no-install-recommends$missing)" >&2
	exit 1
fi
echo "installing:$missing" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -q >/dev/null
# shellcheck disable=SC2086
apt-get install -y -q --no-install-recommends $missing >/dev/null
