# shellcheck shell=bash
# SPDX-License-Identifier: MIT
# Shared by the target-in-the-loop scripts (source it): one QEMU run of an
# ECU test image with semihosting, and the suite's check/all_of/any_of
# (tests/support/checks.sh).
# shellcheck source=tests/support/checks.sh
. tests/support/checks.sh
run_qemu() { # elf log
	timeout 60 qemu-system-arm -M netduinoplus2 -nographic -monitor none -serial none \
		-semihosting-config enable=on,target=native -kernel "$1" >"$2" 2>&1
}
finish() {
	checks_done
}
