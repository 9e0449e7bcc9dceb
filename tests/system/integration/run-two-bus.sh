#!/bin/sh
# SPDX-License-Identifier: MIT
# make test entry: squeal-sim ecu on two buses (vcan0 listen-only inputs,
# vcan1 outputs) in the QEMU guest of tests/system/vcan/guest.sh --vcan1, checked
# in the guest by tests/system/integration/guest-two-bus.sh. About 20 s.
set -eu
cd "$(dirname "$0")/../../.."
make -s build/host/squeal-sim
exec tests/system/vcan/guest.sh --timeout 170 --vcan1 --run tests/system/integration/guest-two-bus.sh \
	--add build/host/squeal-sim --add build/host/squeal-replay
