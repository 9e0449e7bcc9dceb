# SPDX-License-Identifier: MIT
# Guest half of tests/system/integration/run-vcan.sh (POSIX sh; run by
# tests/system/vcan/guest.sh in the QEMU guest, or natively where vcan0 exists).
# It only runs the programs and captures the bus; every judgement is made on
# the host by tests/support/check_vcan.py from what lands in $SQ_OUT.
#
#   stop.cap       candump -L of plant (stop scenario) -> ecu
#   replay-in.log  plant --log of the stop scenario (virtual time)
#   replay.cap     candump -L while canplayer plays replay-in.log to the ecu
#   faults.cap     candump -L (with error frames) while bad frames are injected
#   faults.inj     what was injected (counts, for the checks)
#   flood.*        ecu summary under a flood of valid frames
#   *.ecu          the ecu's exit summary (stderr), *.plant the plant's
set -u
sim=${SQ_SIM:-build/host/squeal-sim}
ifc=${SQ_VCAN:-vcan0}
out=${SQ_OUT:-/tmp}
cal=tests/system/integration/vcan.cal
flood_hz=${1:-max}
flood_s=${2:-10}
what=${3:-all}

# start_ecu NAME: ecu in the background, summary in $out/NAME.ecu
start_ecu() {
	$sim ecu --iface "$ifc" --calib "$cal" --verbose 2>"$out/$1.ecu" &
	ecu_pid=$!
}

stop_ecu() {
	kill -TERM "$ecu_pid" 2>/dev/null
	wait "$ecu_pid"
	echo "$?" >"$out/$1.ecu-rc"
}

start_capture() {
	# all frames, and error frames through an error-mask filter (candump
	# refuses -L with -e)
	candump -L "$ifc,0:0,#FFFFFFFF" >"$out/$1.cap" &
	cap_pid=$!
}

stop_capture() {
	sleep 0.2
	kill -INT "$cap_pid" 2>/dev/null
	wait "$cap_pid" 2>/dev/null
}

t0=$(date +%s)

if [ "$what" = all ] || [ "$what" = stop ]; then
	# 1. plant -> ecu -> capture, stop scenario
	start_capture stop
	start_ecu stop
	sleep 1
	$sim plant --iface "$ifc" --scenario stop 2>"$out/stop.plant"
	echo "$?" >"$out/stop.plant-rc"
	sleep 0.1
	stop_ecu stop
	stop_capture stop
	echo "stop: done ($(wc -l <"$out/stop.cap") frames captured)"
fi

if [ "$what" = all ] || [ "$what" = replay ]; then
	# 2. a recorded input log played back with canplayer
	$sim plant --log "$out/replay-in.log" --iface "$ifc" --scenario stop --quiet
	start_capture replay
	start_ecu replay
	sleep 1
	canplayer -I "$out/replay-in.log" "$ifc=$ifc"
	echo "$?" >"$out/replay.player-rc"
	sleep 0.1
	stop_ecu replay
	stop_capture replay
	echo "replay: done ($(wc -l <"$out/replay.cap") frames captured)"
fi

if [ "$what" = all ] || [ "$what" = faults ]; then
	# 3. faults on the bus while valid traffic flows (v0 3 m/s, 9 kN)
	start_capture faults
	start_ecu faults
	sleep 0.5
	$sim plant --iface "$ifc" --scenario point --v0 3 --force 9000 --duration 60 \
		2>"$out/faults.plant" &
	plant_pid=$!
	sleep 1
	# bad CRC on both inputs (right length, counter 0..14)
	for i in 1 2 3 4 5; do
		cansend "$ifc" 110#00011027
		cansend "$ifc" 111#00015046
	done
	# wrong DLC on an input identifier: 3 and 8 bytes
	cansend "$ifc" 110#001027
	cansend "$ifc" 110#0001102700000000
	cansend "$ifc" 111#00
	# identifiers the ECU does not use (the kernel filter keeps them out):
	# standard, extended, remote
	cansend "$ifc" 7FF#DEADBEEF
	cansend "$ifc" 12345678#0011
	cansend "$ifc" 123#R
	# error frames: protocol violation, controller problem (RX warning)
	cansend "$ifc" 20000008#0000000000000000
	cansend "$ifc" 20000004#0004000000000000
	cansend "$ifc" 20000008#0000000000000000
	# a burst of random payloads on the speed identifier
	cangen "$ifc" -I 110 -L 4 -D r -g 1 -n 20
	# a burst of random frames on random extended identifiers (random
	# standard ones would also hit the ECU's own output identifiers and
	# spoil the capture's E2E check)
	cangen "$ifc" -e -g 0 -n 200
	{
		echo "bad_crc_speed=5 bad_crc_force=5"
		echo "bad_dlc_speed=2 bad_dlc_force=1"
		echo "error_frames=3"
		echo "random_speed=20 random_any=200"
	} >"$out/faults.inj"
	# end-of-injection marker (an unused identifier), then 1.5 s of clean
	# traffic: the ECU must still be there and back to a model state
	cansend "$ifc" 7FE#00
	sleep 1.5
	kill -INT "$plant_pid"
	wait "$plant_pid"
	echo "$?" >"$out/faults.plant-rc"
	# the ECU is still alive here: stop_ecu collects its exit code
	stop_ecu faults
	stop_capture faults
	echo "faults: done ($(wc -l <"$out/faults.cap") frames captured)"
fi

if [ "$what" = all ] || [ "$what" = flood ]; then
	# 4. a flood of valid frames for flood_s seconds of (emulated) wall
	# time: flood_hz per message, or "max": as fast as the plant can send
	# (it never sleeps once behind its schedule); SIGINT ends it.
	# The ECU gets a 4 MiB socket queue (--rcvbuf; in the guest, as root,
	# net.core.rmem_max is raised to allow it): on one emulated CPU the
	# sender can run for tens of ms while the ECU waits for the CPU, and the
	# default ~208 KiB (about 250 frames) then overflows at full speed. The
	# ECU keeps up on average (make bench: tests/system/integration/bench-live.sh).
	# Natively (not root) the flood runs at 2000 Hz per message instead.
	rate=$flood_hz
	[ "$rate" = max ] && rate=1000000
	rcv=""
	if [ "${SQ_GUEST:-0}" = 1 ]; then
		echo 8388608 >/proc/sys/net/core/rmem_max
		rcv="--rcvbuf 4194304"
	elif [ "$rate" = 1000000 ]; then
		rate=2000
	fi
	# shellcheck disable=SC2086
	$sim ecu --iface "$ifc" --calib "$cal" $rcv 2>"$out/flood.ecu" &
	ecu_pid=$!
	sleep 0.5
	timeout -s INT "$flood_s" $sim plant --iface "$ifc" --scenario point \
		--v0 3 --force 9000 --rate-hz "$rate" --duration 100000 \
		2>"$out/flood.plant"
	sleep 0.3
	stop_ecu flood
	echo "flood_hz=$rate flood_s=$flood_s rcvbuf=$rcv" >"$out/flood.cfg"
	echo "flood: done"
fi

echo "guest part took $(( $(date +%s) - t0 )) s (emulated time)"
exit 0
