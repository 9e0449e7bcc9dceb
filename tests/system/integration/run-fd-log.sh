#!/bin/sh
# SPDX-License-Identifier: MIT
# make test entry: CAN FD logs on a real vcan0 (MTU 72) in the QEMU guest of
# tests/system/vcan/guest.sh (natively where this host has vcan0):
#   1. an FD log (`squeal-sim plant --calib FD --log` of an FD layout with
#      P05, then frames of every FD length with flags digits 0..3 written
#      here) played by canplayer: candump -L of the bus gives the same frame
#      text, line for line (only the timestamps differ, and FDF is set);
#   2. `plant --iface` of that FD layout -> `ecu`: the ECU classifies from
#      the FD frames, with the same states as `squeal-sim replay` of the
#      captured input frames offline.
# Prints "RESULT: N passed, M failed". About 30-60 s (boot included).
set -u
cd "$(dirname "$0")/../../.." || exit 1
make -s build/host/squeal-sim || exit 1
sim=build/host/squeal-sim
cal=tests/host-sim/fd_p05.cal
out=$(mktemp -d "${TMPDIR:-/tmp}/sq-fdlog.XXXXXX")
trap 'rm -rf "$out"' EXIT
pass=0
fail=0
check() { # condition-status message
	if [ "$1" = 0 ]; then pass=$((pass + 1)); echo "PASS: $2"; else fail=$((fail + 1)); echo "FAIL: $2"; fi
}

# the plant's FD lines (0..2 s), then every FD length 0..64 with flags
# 0..3, standard and extended identifiers (from 3 s)
"$sim" plant --calib "$cal" --scenario stop --duration 2 --log "$out/fd-in.log" --quiet
grep -q '##' "$out/fd-in.log"
check $? "plant --calib FD --log writes ## lines"
/usr/bin/python3 - "$out/fd-in.log" <<'PY'
import random, sys
rnd = random.Random(7)
lens = [0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64]
t = 3000000
with open(sys.argv[1], "a") as f:
    for n in lens:
        for flags in range(4):
            for ext in (False, True):
                ident = "%08X" % rnd.getrandbits(29) if ext else "%03X" % rnd.randrange(0x700, 0x7F0)
                data = "".join("%02X" % rnd.getrandbits(8) for _ in range(n))
                f.write("(%010d.%06d) vcan0 %s##%X%s\n" % (t // 1000000, t % 1000000, ident, flags, data))
                t += 2000
PY

rc=0
tests/system/vcan/guest.sh --timeout 170 --run tests/system/integration/guest-fd-log.sh \
	--add build/host/squeal-sim --add tests/system --add tests/host-sim --add "$out/fd-in.log" \
	--out "$out" -- "$out/fd-in.log" || rc=$?
if [ "$rc" != 0 ]; then
	echo "guest run failed (exit $rc)"
	echo "RESULT: $pass passed, $((fail + 1)) failed"
	exit 1
fi

grep -q '^mtu=72$' "$out/fd.mtu"
check $? "vcan0 has MTU 72 ($(cat "$out/fd.mtu"))"
test "$(cat "$out/fd-play.player-rc")" = 0
check $? "canplayer played the FD log"
# the frame field (3rd) of every line, in order: the same text, but the
# hand-written lines' digits 0..3 come back with FDF (4) set, as the
# kernel (6.1.0-57) marks every FD frame it delivers; the plant's lines
# (our writer) already carry it
cut -d' ' -f3 "$out/fd-in.log" | sed -E 's/##0/##4/; s/##1/##5/; s/##2/##6/; s/##3/##7/' >"$out/want.txt"
cut -d' ' -f3 "$out/fd-play.cap" >"$out/got.txt"
cmp -s "$out/want.txt" "$out/got.txt"
check $? "candump -L gives the same lines as the FD log ($(wc -l <"$out/want.txt") frames, $(wc -l <"$out/got.txt") captured)"
cut -d' ' -f3 "$out/fd-in.log" | grep -E '^0[AB]0##' >"$out/plant-want.txt"
grep -E '^0[AB]0##' "$out/got.txt" >"$out/plant-got.txt"
test -s "$out/plant-want.txt" && cmp -s "$out/plant-want.txt" "$out/plant-got.txt"
check $? "the plant's ## lines (our writer) come back from candump byte for byte ($(wc -l <"$out/plant-want.txt") lines)"

test "$(cat "$out/fd-live.plant-rc")" = 0 && test "$(cat "$out/fd-live.ecu-rc")" = 0
check $? "plant --iface and ecu of the FD layout ran"
used=$(tr ' ' '\n' <"$out/fd-live.ecu" | awk -F= '$1 ~ /_used$/ {s += $2} END {print s + 0}')
test "$used" -gt 0
check $? "ecu used FD input frames ($used)"
# live states (the ECU's status frames on the bus) against replay offline of
# the captured input frames: the same sequence of states
# of the model (FAULT left out: in the TCG guest the emulated scheduler runs
# the plant late at times, a stale input the offline replay cannot see)
states() { # decode output -> distinct consecutive model states
	awk '/SquealStatus/ { for (i = 1; i <= NF; i++) if ($i ~ /^state=/ && $i != "state=fault") print $i }' | uniq
}
"$sim" decode "$out/fd-live.cap" 2>/dev/null | states >"$out/live.states"
grep -v ' 30[0-3]#' "$out/fd-live.cap" >"$out/fd-live-inputs.log" || true
"$sim" replay --calib "$cal" "$out/fd-live-inputs.log" 2>/dev/null | "$sim" decode - 2>/dev/null |
	states >"$out/offline.states"
test -s "$out/live.states" && cmp -s "$out/live.states" "$out/offline.states"
check $? "live states = offline replay states ($(tr '\n' ' ' <"$out/live.states"))"
mkdir -p build/test-logs/fd-log
cp "$out"/* build/test-logs/fd-log/ 2>/dev/null || true
echo "RESULT: $pass passed, $fail failed"
test "$fail" = 0
