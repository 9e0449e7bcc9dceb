# SPDX-License-Identifier: MIT
# Guest script for selftest_hal_linux (run by tests/system/vcan/guest.sh; POSIX sh).
# In the guest (root) it also makes a down interface and a throttled one.
set -u
bin=build/test/tests/system/vcan/selftest_hal_linux
args="--iface $SQ_VCAN"
if [ "$SQ_GUEST" = 1 ]; then
	ip link add dev vcandown type vcan || exit 1
	ip link add dev vcantx type vcan || exit 1
	# 64 kbit/s, 64 bytes of queue: 4 frames (16 bytes each) wait, about
	# 500 frames/s leave: a flood meets a full qdisc (ENOBUFS).
	/usr/sbin/tc qdisc add dev vcantx root tbf rate 64kbit burst 200 limit 64 || exit 1
	ip link set up vcantx || exit 1
	args="$args --down vcandown --tx vcantx"
fi
# shellcheck disable=SC2086
$bin $args
