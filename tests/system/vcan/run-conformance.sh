#!/bin/sh
# SPDX-License-Identifier: MIT
# make test entry: the HAL conformance suite (tests/hal/conformance.c) on
# hal/linux with two real SocketCAN buses, vcan0 and vcan1, in the QEMU
# guest (or natively where this host has both). Builds what it needs first.
set -eu
cd "$(dirname "$0")/../../.."
make -s build/test/tests/hal/linux/conf_hal_linux_can
exec tests/system/vcan/guest.sh --timeout 240 --vcan1 --run tests/system/vcan/conformance.sh \
	--add build/test/tests/hal/linux/conf_hal_linux_can --add /usr/sbin/tc
