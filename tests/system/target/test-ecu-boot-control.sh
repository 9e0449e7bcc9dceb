#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Negative control of tests/system/target/run-ecu-boot.sh: run it on the stub
# emulator tests/system/target/stub-qemu-arm.sh instead of QEMU.
#   STUB_ECU=good  every one of its checks passes;
#   STUB_ECU=bad   (wrong fault vector, CFSR 0, one watchdog kick, a wrong
#                  time) exactly the six checks of those conditions fail.
# The images are needed only for their file names and the fault record's
# PC (addr2line). Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
tmp=$(mktemp -d build/ecu-boot-control.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/support/checks.sh
. tests/support/checks.sh
run_stub() { # mode -> $tmp/<mode>.out
	QEMU_ARM=tests/system/target/stub-qemu-arm.sh STUB_ECU=$1 ECU_BOOT_LOGDIR=$tmp/$1 \
		tests/system/target/run-ecu-boot.sh >"$tmp/$1.out" 2>&1
}
run_stub good
sed 's/^/  good | /' "$tmp/good.out" | grep -E 'PASS|FAIL|RESULT'
good=$(grep '^RESULT:' "$tmp/good.out")
check "stub with a correct boot: every check passes ($good)" \
	grep -qE '^RESULT: [1-9][0-9]* passed, 0 failed' "$tmp/good.out"
run_stub bad
rc=$?
sed 's/^/  bad  | /' "$tmp/bad.out" | grep -E 'PASS|FAIL|RESULT'
want=$(printf '%s\n' \
	"hal_time_us() agrees with the millisecond tick" \
	"watchdog kicked at least every other ms of the loop" \
	"still kicking at the end" \
	"UsageFault (vector 6) taken" \
	"CFSR says DIVBYZERO (bit 25)" \
	"second boot reports HAL_RESET_FAULT with the recorded vector")
got=$(sed -nE 's/^FAIL: (.*)$/\1/p' "$tmp/bad.out" | sed -E 's/ \(.*[0-9?] .*\)$//')
check "bad boot: the script fails (exit $rc)" [ "$rc" != 0 ]
check "bad boot: exactly the six checks of the wrong values fail (got: $(echo "$got" | tr '\n' ';'))" \
	[ "$got" = "$want" ]
n_good=$(sed -nE 's/^RESULT: ([0-9]+) passed.*/\1/p' "$tmp/good.out")
check "bad boot: RESULT $((n_good - 6)) passed, 6 failed" \
	grep -qx "RESULT: $((n_good - 6)) passed, 6 failed" "$tmp/bad.out"
checks_done
