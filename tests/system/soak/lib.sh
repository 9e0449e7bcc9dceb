# shellcheck shell=bash
# SPDX-License-Identifier: MIT
# Shared by the soak scripts (sourced): pass/fail counting and the memory
# probe of a streaming replay.
#
# Peak RSS (VmHWM, /usr/bin/time %M) of the same replay varies by ~260 kB
# from run to run (13 % of 2 MB): file-backed pages of the binary and libc
# come in by fault-around, in up to 64 kB steps, depending on the page
# cache. The process's own memory (RssAnon: heap, stack, data) does not
# vary. So the probe holds the replay's input open after the last line,
# waits until the replay has read everything and sleeps in read(), and then
# reads /proc/PID/status (VmHWM, VmRSS, RssAnon, RssFile) and /proc/PID/stat
# (CPU time) while the process still lives, before its summary and exit.

soak_pass=0
soak_fail=0
check() { # name result(0 = ok) detail-if-failed
	if [ "$2" = 0 ]; then
		soak_pass=$((soak_pass + 1))
		echo "  ok    $1"
	else
		soak_fail=$((soak_fail + 1))
		echo "  FAIL  $1: $3"
	fi
}

# Wait until process $1 has read all its input and sleeps: its read count
# (/proc/PID/io rchar) unchanged for 0.1 s and state S.
wait_reader_idle() {
	local pid=$1 prev=-1 cur st
	while :; do
		cur=$(awk '$1 == "rchar:" {print $2}' "/proc/$pid/io" 2>/dev/null) || return 1
		st=$(awk '{print $3}' "/proc/$pid/stat" 2>/dev/null) || return 1
		if [ "$cur" = "$prev" ] && [ "$st" = S ]; then
			return 0
		fi
		prev=$cur
		sleep 0.1
	done
}

# "VmHWM VmRSS RssAnon RssFile cpu_s" of a live process, kB and seconds
proc_mem() {
	local pid=$1 tck
	tck=$(getconf CLK_TCK)
	awk '$1 == "VmHWM:" {h = $2} $1 == "VmRSS:" {r = $2} $1 == "RssAnon:" {a = $2}
	     $1 == "RssFile:" {f = $2} END {printf "%s %s %s %s", h, r, a, f}' "/proc/$pid/status"
	awk -v t="$tck" '{printf " %.2f\n", ($14 + $15) / t}' "/proc/$pid/stat"
}
