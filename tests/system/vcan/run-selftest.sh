#!/bin/sh
# SPDX-License-Identifier: MIT
# make test entry: hal/linux's self-test on a real vcan0, in the QEMU guest
# (or natively where this host has vcan0). Builds what it needs first.
set -eu
cd "$(dirname "$0")/../../.."
make -s build/test/tests/system/vcan/selftest_hal_linux
exec tests/system/vcan/guest.sh --timeout 240 --run tests/system/vcan/selftest.sh \
	--add build/test/tests/system/vcan/selftest_hal_linux --add /usr/sbin/tc
