# SPDX-License-Identifier: MIT
# Guest half of tests/system/integration/run-fd-log.sh (POSIX sh; run by
# tests/system/vcan/guest.sh in the QEMU guest, or natively where vcan0 exists and
# already has MTU 72). Runs the programs and captures the bus; the host
# judges what lands in $SQ_OUT.
#
#   fd-play.cap  candump -L while canplayer plays LOG ($1: FD frames of
#                every length and flags, and plant --log of an FD layout)
#   fd-live.cap  candump -L of plant --iface (FD layout) -> ecu
#   fd-live.ecu  the ecu's exit summary, fd-live.plant the plant's
set -u
sim=${SQ_SIM:-build/host/squeal-sim}
ifc=${SQ_VCAN:-vcan0}
out=${SQ_OUT:-/tmp}
cal=${SQ_FD_CAL:-tests/host-sim/fd_p05.cal}
log=$1 # the FD log to play (added to the guest at its host path)

if [ "${SQ_GUEST:-0}" = 1 ]; then
	# CAN FD on vcan: the interface's MTU is CANFD_MTU (72)
	ip link set "$ifc" down
	ip link set "$ifc" mtu 72
	ip link set "$ifc" up
fi
echo "mtu=$(cat /sys/class/net/"$ifc"/mtu)" >"$out/fd.mtu"

start_capture() {
	candump -L "$ifc" >"$out/$1.cap" &
	cap_pid=$!
	sleep 0.3
}

stop_capture() {
	sleep 0.3
	kill -INT "$cap_pid" 2>/dev/null
	wait "$cap_pid" 2>/dev/null
}

# 1. canplayer of an FD log: candump must write the same lines
start_capture fd-play
canplayer -I "$log" "$ifc=$ifc"
echo "$?" >"$out/fd-play.player-rc"
stop_capture fd-play
echo "fd-play: done ($(wc -l <"$out/fd-play.cap") frames captured)"

# 2. the FD layout live: plant --iface -> ecu, classified from FD frames
start_capture fd-live
$sim ecu --iface "$ifc" --calib "$cal" --verbose 2>"$out/fd-live.ecu" &
ecu_pid=$!
sleep 1
$sim plant --iface "$ifc" --calib "$cal" --scenario stop 2>"$out/fd-live.plant"
echo "$?" >"$out/fd-live.plant-rc"
sleep 0.2
kill -TERM "$ecu_pid" 2>/dev/null
wait "$ecu_pid"
echo "$?" >"$out/fd-live.ecu-rc"
stop_capture fd-live
echo "fd-live: done ($(wc -l <"$out/fd-live.cap") frames captured)"
exit 0
