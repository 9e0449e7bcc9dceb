# SPDX-License-Identifier: MIT
# Shared by the target-in-the-loop scripts (source it): PASS/FAIL counting
# and one QEMU run of an ECU test image with semihosting.
pass=0; fail=0
check() { # description, condition...
	local d=$1; shift
	if "$@"; then pass=$((pass + 1)); echo "PASS: $d"; else fail=$((fail + 1)); echo "FAIL: $d"; fi
}
run_qemu() { # elf log
	timeout 60 qemu-system-arm -M netduinoplus2 -nographic -monitor none -serial none \
		-semihosting-config enable=on,target=native -kernel "$1" >"$2" 2>&1
}
finish() {
	echo "RESULT: $pass passed, $fail failed"
	[ "$fail" = 0 ]
}
