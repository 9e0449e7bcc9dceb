# SPDX-License-Identifier: MIT
# Guest half of tests/system/integration/run-two-bus.sh (POSIX sh; run by
# tests/system/vcan/guest.sh --vcan1): the ECU on two buses, inputs from vcan0 in
# listen-only, outputs on vcan1:
#   squeal-sim ecu --iface vcan0 --out-iface vcan1 --listen-only
# while plant sends the stop scenario on vcan0. Both buses are captured;
# the checks count identifiers in the captures (the DBC's: inputs 0x110,
# 0x111; outputs 0x300..0x303).
set -u
sim=${SQ_SIM:-build/host/squeal-sim}
in_if=${SQ_VCAN:-vcan0}
out_if=${SQ_VCAN1:-vcan1}
tmp=${SQ_OUT:-/tmp}
pass=0
fail=0
check() { # status, what
	if [ "$1" = 0 ]; then pass=$((pass + 1)); echo "PASS  $2"; else fail=$((fail + 1)); echo "FAIL  $2"; fi
}

candump -L "$in_if" >"$tmp/in.cap" &
c0=$!
candump -L "$out_if" >"$tmp/out.cap" &
c1=$!
$sim ecu --iface "$in_if" --out-iface "$out_if" --listen-only --duration 4 2>"$tmp/ecu.txt" &
ecu=$!
sleep 0.5
$sim plant --iface "$in_if" --scenario stop --duration 3 --quiet 2>"$tmp/plant.txt"
wait "$ecu"
ecu_rc=$?
sleep 0.2
kill "$c0" "$c1" 2>/dev/null
wait "$c0" "$c1" 2>/dev/null

n_in=$(grep -c " $in_if 11[01]#" "$tmp/in.cap")
n_in_other=$(grep -vc " $in_if 11[01]#" "$tmp/in.cap")
n_status=$(grep -c " $out_if 300#" "$tmp/out.cap")
n_out_inputs=$(grep -c " $out_if 11[01]#" "$tmp/out.cap")
used=$(sed -n 's/.*speed_used=\([0-9]*\).*/\1/p' "$tmp/ecu.txt")
check "$ecu_rc" "ecu --iface $in_if --out-iface $out_if --listen-only: exit 0"
check "$([ "$n_in" -ge 500 ]; echo $?)" "plant's inputs on $in_if ($n_in frames)"
check "$([ "${used:-0}" -ge 250 ]; echo $?)" "the ECU used the inputs of $in_if (speed_used=${used:-?})"
check "$([ "$n_in_other" = 0 ]; echo $?)" "nothing but the inputs on the listen-only $in_if ($n_in_other other frames)"
check "$([ "$n_status" -ge 300 ]; echo $?)" "SquealStatus on $out_if ($n_status frames in 4 s)"
check "$([ "$n_out_inputs" = 0 ]; echo $?)" "no input frame crosses to $out_if"
check "$(grep -q 'in_listen_only=1 in_tx_refused_listen_only=0' "$tmp/ecu.txt"; echo $?)" \
	"input bus listen-only, and the firmware never tried to send there"
[ "$fail" = 0 ] || { echo "--- ecu summary"; cat "$tmp/ecu.txt"; }
echo "RESULT: $pass passed, $fail failed"
[ "$fail" = 0 ]
