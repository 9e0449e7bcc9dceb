#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Budgets of the ECU images (figures, never pass/fail):
#   - flash and RAM of each image (linker accounting, tests/system/target/size-report.sh),
#   - worst-case stack (tools/stack_usage.py),
#   - instructions per classification (the golden vectors, tv_target.c) and
#     per 1 ms monitor step (bench_step.c) on the Cortex-M4F (float) and the
#     Cortex-M3 (fixed), and on the STM32G474 image's HAL (float; its step
#     also with four corners on inputs in 64-byte CAN FD frames with E2E
#     P05, bench_step.c's BENCHFD4 / BENCHFDS4), under "qemu-system-arm -icount shift=0": virtual
#     time advances 1 ns per instruction, SysTick counts virtual time, and a
#     loop of 200000 known instructions converts ticks to instructions. The
#     timer reads around each measured call (a few tens of instructions) are
#     subtracted. QEMU counts instructions, not cycles: a real M4 at 168 MHz
#     with flash wait states needs more cycles than instructions.
set -u
cd "$(dirname "$0")/../../.."
echo "-- image sizes"
# the G4's RAM includes its FD frame queues (64-byte frames)
for elf in build/stm32f4/squeal-monitor.elf build/stm32f103/squeal-monitor.elf \
	build/stm32g474/squeal-monitor.elf; do
	tests/system/target/size-report.sh "$elf"
done
echo "-- worst-case stack (main loop + every interrupt nested + exception frames)"
for cfg in stm32f4 stm32f103 stm32g474; do
	printf '%-10s ' "$cfg"
	/usr/bin/python3 tools/stack_usage.py "build/$cfg/squeal-monitor.elf" "build/$cfg/fw" | tail -1
done
qemu() { # machine elf
	timeout 300 qemu-system-arm -M "$1" -icount shift=0 -nographic -monitor none -serial none \
		-semihosting-config enable=on,target=native -kernel "$2" 2>&1
}
kv() { echo "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }
echo "-- instructions (qemu-system-arm -icount shift=0)"
for m in "M4F-float netduinoplus2 build/tv-m4f/model-vectors.elf build/bench-m4f/bench-step.elf" \
	 "M3-fixed  netduino2 build/tv-m3/model-vectors.elf build/bench-m3/bench-step.elf" \
	 "G4-float  netduinoplus2 build/tv-g4/model-vectors.elf build/bench-g4/bench-step.elf"; do
	set -- $m
	name=$1 machine=$2 tv=$3 bs=$4
	t=$(qemu "$machine" "$tv" | grep '^TIMING')
	out=$(qemu "$machine" "$bs")
	b=$(echo "$out" | grep '^BENCH ')
	if [ -z "$t" ] || [ -z "$b" ]; then
		echo "$name: run failed"; continue
	fi
	awk -v name="$name" \
	    -v n="$(kv "$t" n)" -v hi="$(kv "$t" ticks_total_hi)" -v lo="$(kv "$t" ticks_total_lo)" \
	    -v tmax="$(kv "$t" ticks_max)" -v cal="$(kv "$t" cal_ticks)" -v cali="$(kv "$t" cal_insns)" \
	    -v steps="$(kv "$b" steps)" -v stot="$(kv "$b" ticks_total)" -v sf="$(kv "$b" steps_with_frames)" \
	    -v sft="$(kv "$b" ticks_frames)" -v smax="$(kv "$b" ticks_max)" -v ov="$(kv "$b" overhead_ticks)" \
	    -v bcal="$(kv "$b" cal_ticks)" -v cls="$(kv "$b" classifications)" 'BEGIN {
		k = cali / cal; kb = cali / bcal
		printf "%s classify:    mean %6.0f  max %6.0f instructions (%d classifications, golden vectors)\n",
			name, ((hi * 4294967296 + lo) / n - ov) * k, (tmax - ov) * k, n
		printf "%s 1 ms step:   mean %6.0f  max %6.0f instructions (%d steps)\n",
			name, (stot / steps - ov) * kb, (smax - ov) * kb, steps
		printf "%s   with input frames + classification: mean %6.0f (%d steps, %d classifications)\n",
			name, (sft / sf - ov) * kb, sf, cls
		printf "%s   without frames: mean %6.0f\n", name, ((stot - sft) / (steps - sf) - ov) * kb
	}'
	for tag in BENCH4 BENCHS BENCHS4 BENCHFD4 BENCHFDS4; do
		bx=$(echo "$out" | grep "^$tag ")
		case $tag in
		BENCH4) what="1 ms step, 4 corners:" ;;
		BENCHS) what="1 ms step, sigma on:" ;;
		BENCHS4) what="1 ms step, 4 corners, sigma on:" ;;
		BENCHFD4) what="1 ms step, 4 corners, FD 64-byte P05 inputs:" ;;
		BENCHFDS4) what="1 ms step, 4 corners, FD 64-byte P05 inputs, sigma on:" ;;
		esac
		[ -n "$bx" ] && awk -v name="$name" -v what="$what" -v cali="$(kv "$bx" cal_insns)" \
		    -v bcal="$(kv "$bx" cal_ticks)" -v steps="$(kv "$bx" steps)" \
		    -v stot="$(kv "$bx" ticks_total)" -v smax="$(kv "$bx" ticks_max)" \
		    -v sft="$(kv "$bx" ticks_frames)" -v sf="$(kv "$bx" steps_with_frames)" \
		    -v ov="$(kv "$bx" overhead_ticks)" -v cls="$(kv "$bx" classifications)" 'BEGIN {
			kb = cali / bcal
			printf "%s %s mean %6.0f  max %6.0f instructions (%d steps, %d classifications; with frames mean %6.0f)\n",
				name, what, (stot / steps - ov) * kb, (smax - ov) * kb, steps, cls,
				(sft / sf - ov) * kb
		}'
	done
done
