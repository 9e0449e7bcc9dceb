#!/bin/sh
# SPDX-License-Identifier: MIT
# make test entry: the HAL conformance suite (tests/hal/conformance.c) on
# hal/linux with two real SocketCAN buses, vcan0 and vcan1, in the QEMU
# guest (or natively where this host has both). Builds what it needs first.
set -eu
cd "$(dirname "$0")/../.."
make -s build/test/hal-conformance-socketcan
exec tests/vcan/guest.sh --timeout 240 --vcan1 --run tests/vcan/conformance.sh \
	--add build/test/hal-conformance-socketcan --add /usr/sbin/tc
