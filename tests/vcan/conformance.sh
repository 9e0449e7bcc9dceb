# SPDX-License-Identifier: MIT
# Guest script for the HAL conformance suite on SocketCAN (run by
# tests/vcan/guest.sh --vcan1; POSIX sh): bus 0 on $SQ_VCAN, bus 1 on
# $SQ_VCAN1. Without a second interface the suite runs on one bus.
#
# In the guest it runs twice: first with the interfaces at MTU 16 (classic
# only: FD frames must be refused, and hal/linux must say "CAN FD off" once
# per interface however often it opens it), then at MTU 72 (CAN FD: the FD
# round trips). Natively (not root) it runs once on the interfaces as they
# are. The last line sums every run: RESULT: N passed, M failed, K skipped.
set -u
SQ_VCAN1=${SQ_VCAN1:-}
SQ_TC=
# root in the guest: tc can stall a bus's TX path (the queue-full check)
if [ "$SQ_GUEST" = 1 ]; then SQ_TC=/usr/sbin/tc; fi
export SQ_VCAN SQ_VCAN1 SQ_TC
ifaces="$SQ_VCAN${SQ_VCAN1:+ $SQ_VCAN1}"
tmp=${TMPDIR:-/tmp}/sq-conformance.$$
mkdir -p "$tmp"
passed=0
failed=0
skipped=0

# one PASS/FAIL line of this script's own, counted with the suite's
check() {
	if [ "$1" = 0 ]; then
		echo "PASS  hal-conformance [socketcan] $2"
		passed=$((passed + 1))
	else
		echo "FAIL  hal-conformance [socketcan] $2 ($3)"
		failed=$((failed + 1))
	fi
}

# run_suite LABEL: the suite once, its lines shown, its RESULT added up;
# stderr kept in $tmp/LABEL.err
run_suite() {
	echo "# run: $1"
	build/test/hal-conformance-socketcan >"$tmp/$1.out" 2>"$tmp/$1.err"
	rc=$?
	grep -v '^RESULT:' "$tmp/$1.out"
	sed 's/^/# stderr: /' "$tmp/$1.err"
	line=$(grep -E '^RESULT: [0-9]+ passed, [0-9]+ failed' "$tmp/$1.out" | tail -n 1)
	if [ -z "$line" ]; then
		check 1 "$1: the suite ran to its RESULT line" "exit $rc, no RESULT"
		return
	fi
	p=$(echo "$line" | sed -E 's/^RESULT: ([0-9]+) passed.*/\1/')
	f=$(echo "$line" | sed -E 's/^RESULT: [0-9]+ passed, ([0-9]+) failed.*/\1/')
	s=$(echo "$line" | sed -nE 's/.*, ([0-9]+) skipped.*/\1/p')
	passed=$((passed + p))
	failed=$((failed + f))
	skipped=$((skipped + ${s:-0}))
}

set_mtu() {
	for ifc in $ifaces; do
		ip link set "$ifc" down && ip link set "$ifc" mtu "$1" && ip link set "$ifc" up ||
			check 1 "ip link set $ifc mtu $1" "failed"
	done
}

if [ "$SQ_GUEST" = 1 ]; then
	set_mtu 16
	run_suite mtu16
	for ifc in $ifaces; do
		want="$ifc: MTU 16, CAN FD off (ip link set $ifc mtu 72)"
		n=$(grep -cxF "$want" "$tmp/mtu16.err")
		check "$([ "$n" = 1 ] && echo 0 || echo 1)" \
			"$ifc at MTU 16: \"CAN FD off\" said once over every re-open" "said $n times"
	done
	set_mtu 72
	run_suite mtu72
	n=$(grep -c 'CAN FD off' "$tmp/mtu72.err")
	check "$([ "$n" = 0 ] && echo 0 || echo 1)" "at MTU 72: CAN FD on, nothing said" \
		"said $n times"
else
	run_suite native
fi
rm -rf "$tmp"
echo "RESULT: $passed passed, $failed failed, $skipped skipped"
[ "$failed" = 0 ]
