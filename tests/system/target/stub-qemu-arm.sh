#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Stand-in for qemu-system-arm in the negative control of run-ecu-boot.sh
# (tests/system/target/test-ecu-boot-control.sh): prints the semihosting events a
# boot of the -kernel image would print, without running it.
#   STUB_ECU=good  the events of a correct image (every check must pass)
#   STUB_ECU=bad   the same, but a wrong fault vector (3), CFSR 0, one
#                  watchdog kick (the last at 5 ms) and a time 100 ms ahead
#                  of the millisecond tick
# The fault record's PC points into stm32_test_event of the image given, so
# the addr2line check sees a real address.
set -u
kernel=
while [ $# -gt 0 ]; do
	[ "$1" = -kernel ] && kernel=$2
	shift
done
mode=${STUB_ECU:-bad}
kicks=1999; last=2000; time_ms=2000; vector=6; cfsr=02000000
if [ "$mode" = bad ]; then
	kicks=1; last=5; time_ms=2100; vector=3; cfsr=00000000
fi
summary() { # reset reason
	echo "EVT summary uptime_ms=2000 kicks=$kicks last_kick_ms=$last idle_calls=150000" \
		"time_back=0 time_ms=$time_ms faults=0x00000003 can_state=4 reset_reason=$1 core_mhz=16"
}
boot() {
	echo "EVT fault value=1"
	echo "EVT boot value=16000000"
}
after_reset() {
	echo "EVT fault value=2"
	echo "EVT can_init_timeout value=10000"
	echo "EVT wdg_start value=100"
	echo "EVT wdg_kick first"
	echo "EVT main_loop uptime_ms=40"
}
boot
case $kernel in
*faulttest*)
	echo "EVT reset_reason value=6"
	after_reset
	addr=$(arm-none-eabi-nm "$kernel" | awk '$3 == "stm32_test_event" {print $1}')
	pc=$(printf '%08x' $(( (16#${addr:-0} & ~1) + 4 )))
	echo "EVT fault vector=$vector pc=0x$pc cfsr=0x$cfsr"
	boot
	echo "EVT reset_reason value=4 fault_vector=$vector fault_pc=0x$pc fault_cfsr=0x$cfsr fault_count=1"
	after_reset
	summary 4
	;;
*)
	echo "EVT reset_reason value=6"
	after_reset
	summary 6
	;;
esac
exit 0
