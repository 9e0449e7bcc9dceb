# SPDX-License-Identifier: MIT
# Guest half of tests/system/integration/bench-live.sh (POSIX sh; QEMU guest of
# tests/system/vcan/guest.sh, or natively). Captures only; bench_live.py on the host
# computes the figures. All times are the guest's EMULATED time (TCG).
#   lat-idle.cap   latency scenario, nothing else on the bus
#   lat-load.cap   the same with a cangen flood on an identifier the ECU's
#                  kernel filter drops (CPU and bus load beside it)
#   rate-ecu-*     plant at full speed -> ecu, plant/ecu summaries
#   rate-cd-*      plant at full speed -> plain candump -d, its log
set -u
sim=${SQ_SIM:-build/host/squeal-sim}
ifc=${SQ_VCAN:-vcan0}
out=${SQ_OUT:-/tmp}
cal=tests/system/integration/vcan.cal
flood_s=${1:-5}

latency() {
	candump -L "$ifc" >"$out/lat-$1.cap" &
	cap=$!
	$sim ecu --iface "$ifc" --calib "$cal" 2>"$out/lat-$1.ecu" &
	ecu=$!
	sleep 0.5
	$sim plant --iface "$ifc" --scenario tests/system/integration/latency-steps.txt \
		2>"$out/lat-$1.plant"
	kill -TERM "$ecu"; wait "$ecu"
	sleep 0.2
	kill -INT "$cap"; wait "$cap" 2>/dev/null
}

latency idle
cangen "$ifc" -I 7F0 -L 8 -D i -g 0 2>/dev/null &
gen=$!
latency load
kill "$gen"; wait "$gen" 2>/dev/null

# plant_flood RATE NAME: the plant at RATE frames/s per message into the
# consumer just started, for flood_s; its messages to NAME.plant.
plant_flood() {
	sleep 0.5
	timeout -s INT "$flood_s" $sim plant --iface "$ifc" --scenario point \
		--v0 3 --force 9000 --rate-hz "$1" --duration 100000 \
		2>"$out/$2.plant"
	sleep 0.3
}
# Highest input rate with zero loss: the plant as fast as it can (one
# vCPU: sender and receiver share it), each consumer in turn. If the ECU
# lost anything, retry at lower plant rates (frames/s per message).
for rate in 1000000 4000 2000 1000 500; do
	$sim ecu --iface "$ifc" --calib "$cal" 2>"$out/rate-ecu-$rate.ecu" &
	ecu=$!
	plant_flood "$rate" "rate-ecu-$rate"
	kill -TERM "$ecu"; wait "$ecu"
	if grep -q 'hal_rx_kernel_drops=0 ' "$out/rate-ecu-$rate.ecu" &&
	   grep -q 'speed_e2e_lost=0 ' "$out/rate-ecu-$rate.ecu" &&
	   grep -q 'force_e2e_lost=0 ' "$out/rate-ecu-$rate.ecu"; then
		break
	fi
done
for rate in 1000000 4000 2000 1000 500; do
	candump -d -L "$ifc" >"$out/rate-cd-$rate.log" &
	cd=$!
	plant_flood "$rate" "rate-cd-$rate"
	kill -INT "$cd"; wait "$cd" 2>/dev/null
	grep -q DROPCOUNT "$out/rate-cd-$rate.log" || break
done
# the same full-speed flood into an ECU with a deeper socket queue (root in
# the guest may raise net.core.rmem_max; 4 MiB instead of ~208 KiB)
if [ "${SQ_GUEST:-0}" = 1 ]; then
	echo 8388608 >/proc/sys/net/core/rmem_max
	$sim ecu --iface "$ifc" --calib "$cal" --rcvbuf 4194304 2>"$out/deep-ecu.ecu" &
	ecu=$!
	plant_flood 1000000 deep-ecu
	kill -TERM "$ecu"; wait "$ecu"
fi
# The cheapest sender vcan has: cangen back to back on DiscSpeed's
# identifier (random payloads: the ECU counts them as CRC errors, but must
# still take every one off the socket), into each consumer.
# cangen_flood NAME: the flood into the consumer just started, its start and
# end uptime (s) to NAME.time for the host's rate.
cangen_flood() {
	sleep 0.5
	t0=$(cat /proc/uptime | cut -d' ' -f1)
	timeout -s INT "$flood_s" cangen "$ifc" -I 110 -L 4 -D r -g 0 2>/dev/null
	t1=$(cat /proc/uptime | cut -d' ' -f1)
	echo "$t0 $t1" >"$out/$1.time"
	sleep 0.3
}
$sim ecu --iface "$ifc" --calib "$cal" 2>"$out/gen-ecu.ecu" &
ecu=$!
cangen_flood gen-ecu
kill -TERM "$ecu"; wait "$ecu"
candump -d -L "$ifc" >"$out/gen-cd.log" &
cd=$!
cangen_flood gen-cd
kill -INT "$cd"; wait "$cd" 2>/dev/null
echo "bench: done"
