#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
#
# guest.sh: run a test script on a real SocketCAN vcan0.
#
# The build machines' kernel has no CAN (no CONFIG_CAN: no vcan, no PF_CAN), so this
# boots Debian's own kernel under qemu-system-x86_64 (TCG) with a tiny
# initramfs: busybox, the CAN modules, can-utils, and the files you add. The
# guest creates vcan0 (and vcan1 with --vcan1), runs the script from /work
# (a copy of the repository paths you added), prints its output and powers
# off. When this host already has a usable vcan0 the same script runs here
# natively instead (no qemu), from the repository root. A guest run costs
# about 8-10 s of boot and power-off on top of the test (measured here).
#
# Usage:
#   tests/system/vcan/guest.sh --run SCRIPT [options] [-- SCRIPT-ARGS...]
# Options:
#   --add PATH      copy PATH (file or directory) into the guest. A path inside
#                   the repository keeps its repository-relative path under
#                   /work (so `build/host/squeal-sim` works in the script from
#                   the guest's cwd /work, exactly as natively from the repo
#                   root); an absolute path outside it keeps its absolute path
#                   (e.g. --add /usr/sbin/tc). ELF files bring the shared
#                   libraries ldd lists. Repeatable.
#   --vcan1         also create vcan1.
#   --out DIR       after the run, copy the guest's $SQ_OUT directory (/out)
#                   back into DIR on the host (tar+base64 over the console).
#   --timeout SECS  whole-run limit (default 180); the run fails when it hits.
#   --mem MB        guest memory (default 256).
#   --console FILE  also keep the guest's whole console output in FILE.
#   --guest         always use the QEMU guest, even if this host has vcan0
#                   (also: SQ_VCAN_MODE=guest; SQ_VCAN_MODE=native forbids qemu).
#   --fetch-only    only download/unpack the kernel into the cache, then exit.
# The test script:
#   runs under busybox sh in the guest (dash/sh natively): write POSIX sh. Its
#   cwd is the repository root (natively) or /work (guest). Environment:
#     SQ_GUEST=1|0  1 inside the qemu guest (root, may `ip link`, `tc`, insmod),
#                   0 when native (usually not root: skip privileged steps)
#     SQ_VCAN=vcan0 the interface to use; SQ_VCAN1=vcan1 with --vcan1
#     SQ_OUT=DIR    a directory whose contents --out brings back
#   Its exit code is this script's exit code. Print "RESULT: N passed, M failed"
#   if you count tests (tests/run-tests.sh reads it).
#   Busybox sh runs its own applets before searching PATH: call an added
#   tool that shares an applet's name by its full path (/usr/sbin/tc, not tc).
#   candump 2020.11 refuses -L with -e: capture error frames in -L logs with
#   an error mask filter instead: candump -L vcan0,0:0,#FFFFFFFF.
#   Guest tools: busybox applets, candump cansend cangen canplayer canbusload
#   cangw cansequence, and the kernel modules can, can-raw, can-dev, vcan,
#   can-gw, sch_tbf (already loaded).
# Exit codes: the test's exit code; 124 timeout; 2 usage; 3 no kernel (could
# not fetch: Debian's archive is needed once); 4 guest did not run the test.
#
# The kernel is Debian's linux-image-amd64 (resolved with apt-cache depends),
# fetched once with apt-get download and cached in tests/system/vcan/cache/ (vmlinuz
# and the few modules only; gitignored; SQ_VCAN_CACHE=DIR puts it elsewhere,
# e.g. to share it between checkouts). Delete that directory to refetch.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
cache=${SQ_VCAN_CACHE:-$here/cache}

# Modules in load order (vcan needs can-dev; can-raw needs can).
MODULES="kernel/net/can/can.ko kernel/net/can/can-raw.ko
kernel/drivers/net/can/dev/can-dev.ko kernel/drivers/net/can/vcan.ko
kernel/net/can/can-gw.ko kernel/net/sched/sch_tbf.ko"
CAN_TOOLS="candump cansend cangen canplayer canbusload cangw cansequence"

die() {
	local code=$1
	shift
	echo "guest.sh: $*" >&2
	exit "$code"
}

usage() {
	sed -n '3,/^set -euo/p' "${BASH_SOURCE[0]}" | sed -e '/^set -euo/d' -e 's/^# \{0,1\}//' >&2
	exit 2
}

script=""
adds=()
vcan1=0
outdir=""
timeout_s=180
mem_mb=256
console_copy=""
mode=${SQ_VCAN_MODE:-auto}
fetch_only=0
script_args=()
while [ $# -gt 0 ]; do
	case "$1" in
	--run) [ $# -ge 2 ] || usage; script=$2; shift 2 ;;
	--add) [ $# -ge 2 ] || usage; adds+=("$2"); shift 2 ;;
	--vcan1) vcan1=1; shift ;;
	--out) [ $# -ge 2 ] || usage; outdir=$2; shift 2 ;;
	--timeout) [ $# -ge 2 ] || usage; timeout_s=$2; shift 2 ;;
	--mem) [ $# -ge 2 ] || usage; mem_mb=$2; shift 2 ;;
	--console) [ $# -ge 2 ] || usage; console_copy=$2; shift 2 ;;
	--guest) mode=guest; shift ;;
	--fetch-only) fetch_only=1; shift ;;
	--) shift; script_args=("$@"); break ;;
	-h|--help) usage ;;
	*) echo "guest.sh: unknown argument '$1'" >&2; usage ;;
	esac
done
if [ "$fetch_only" = 0 ]; then
	[ -n "$script" ] || usage
	[ -f "$script" ] || die 2 "no such test script: $script"
fi

# ---- native: this host has a working vcan0 ----------------------------------

host_has_vcan() {
	local ifc
	for ifc in "$@"; do
		ip link show "$ifc" >/dev/null 2>&1 || return 1
		/usr/bin/python3 - "$ifc" >/dev/null 2>&1 <<'EOF' || return 1
import socket, sys
s = socket.socket(socket.AF_CAN, socket.SOCK_RAW, socket.CAN_RAW)
s.bind((sys.argv[1],))
EOF
	done
	return 0
}

run_native() {
	local out script_abs rc tmp_out=""
	if [ -n "$outdir" ]; then
		mkdir -p "$outdir"
		out=$(cd "$outdir" && pwd)
	else
		tmp_out=$(mktemp -d)
		out=$tmp_out
	fi
	script_abs=$(realpath "$script")
	echo "guest.sh: this host has a usable vcan0: running $script natively" >&2
	cd "$root"
	if [ "$vcan1" = 1 ]; then export SQ_VCAN1=vcan1; fi
	set +e
	SQ_GUEST=0 SQ_VCAN=vcan0 SQ_OUT=$out \
		timeout "$timeout_s" sh "$script_abs" ${script_args[@]+"${script_args[@]}"}
	rc=$?
	set -e
	if [ -n "$tmp_out" ]; then rm -rf "$tmp_out"; fi
	return "$rc"
}

if [ "$fetch_only" = 0 ] && [ "$mode" != guest ]; then
	ifaces=(vcan0)
	if [ "$vcan1" = 1 ]; then ifaces+=(vcan1); fi
	if host_has_vcan "${ifaces[@]}"; then
		rc=0
		run_native || rc=$?
		exit "$rc"
	fi
	if [ "$mode" = native ]; then
		die 4 "SQ_VCAN_MODE=native but this host has no usable ${ifaces[*]}"
	fi
fi

# ---- the guest kernel: fetched once, cached ----------------------------------

fetch_kernel() {
	local pkg tmp deb kver dst m
	command -v apt-cache >/dev/null && command -v apt-get >/dev/null \
		&& command -v dpkg >/dev/null \
		|| die 3 "cannot fetch the guest kernel: apt-get/apt-cache/dpkg missing (a Debian host is needed once; the kernel is then cached in $cache)"
	pkg=$(apt-cache depends linux-image-amd64 2>/dev/null \
		| awk '/Depends: linux-image-[0-9]/ { print $2; exit }')
	[ -n "$pkg" ] || die 3 "cannot fetch the guest kernel: 'apt-cache depends linux-image-amd64' names no kernel package (run apt-get update; Debian's archive is needed once)"
	tmp=$(mktemp -d "$cache/fetch.XXXXXX")
	echo "guest.sh: fetching $pkg from Debian's archive (once; cached in $cache)" >&2
	if ! (cd "$tmp" && apt-get download -q "$pkg" >apt.log 2>&1); then
		sed 's/^/    /' "$tmp/apt.log" >&2
		rm -rf "$tmp"
		die 3 "cannot fetch the guest kernel '$pkg' with apt-get download (offline? Debian's archive is needed once; the test cannot run without it)"
	fi
	deb=$(ls "$tmp"/*.deb)
	dpkg -x "$deb" "$tmp/x" || { rm -rf "$tmp"; die 3 "dpkg -x $deb failed"; }
	kver=$(ls "$tmp/x/lib/modules" | head -n 1)
	dst="$cache/kernel-$kver"
	rm -rf "$dst"
	mkdir -p "$dst/modules"
	cp "$tmp/x/boot/vmlinuz-$kver" "$dst/vmlinuz"
	for m in $MODULES; do
		cp "$tmp/x/lib/modules/$kver/$m" "$dst/modules/" \
			|| { rm -rf "$tmp"; die 3 "kernel $kver has no $m"; }
	done
	echo "$pkg" >"$dst/package"
	rm -rf "$tmp"
	ln -sfn "kernel-$kver" "$cache/kernel"
}

mkdir -p "$cache"
(
	flock 9
	if [ ! -f "$cache/kernel/vmlinuz" ] || [ ! -f "$cache/kernel/package" ]; then
		fetch_kernel
	fi
) 9>"$cache/.lock"
kdir="$cache/kernel"
[ -f "$kdir/vmlinuz" ] || die 3 "no guest kernel in $kdir"
if [ "$fetch_only" = 1 ]; then
	echo "guest.sh: guest kernel $(cat "$kdir/package") ready in $kdir" >&2
	exit 0
fi

command -v qemu-system-x86_64 >/dev/null || die 4 "qemu-system-x86_64 missing (apt-get install qemu-system-x86)"
[ -x /bin/busybox ] || die 4 "/bin/busybox missing (apt-get install busybox-static)"
for t in $CAN_TOOLS; do
	command -v "$t" >/dev/null || die 4 "$t missing (apt-get install can-utils)"
done

# ---- the initramfs -----------------------------------------------------------

work=$(mktemp -d "${TMPDIR:-/tmp}/sq-guest.XXXXXX")
trap 'rm -rf "$work"' EXIT
ir="$work/root"
mkdir -p "$ir"/{bin,sbin,usr/bin,usr/sbin,lib/modules,proc,sys,dev,tmp,work,out,etc}
cp /bin/busybox "$ir/bin/busybox"
ln -s busybox "$ir/bin/sh"
cp "$kdir"/modules/*.ko "$ir/lib/modules/"

# copy_in SRC DST: one file or tree into the initramfs, plus the shared
# libraries of every dynamically linked ELF file in it.
copy_libs() {
	local f lib
	f=$1
	[ "$(head -c 4 "$f" 2>/dev/null | od -An -c | tr -d ' ')" = '177ELF' ] || return 0
	ldd "$f" 2>/dev/null | awk '/=> \// { print $3 } /^[ \t]*\// { print $1 }' |
		while read -r lib; do
			[ -e "$ir$lib" ] && continue
			mkdir -p "$ir$(dirname "$lib")"
			cp -L "$lib" "$ir$lib"
		done
}

copy_in() {
	local src dst f
	src=$1
	dst=$2
	[ -e "$src" ] || die 2 "--add: no such file: $src"
	mkdir -p "$(dirname "$dst")"
	cp -a -L "$src" "$dst"
	if [ -d "$dst" ]; then
		while IFS= read -r -d '' f; do
			copy_libs "$f"
		done < <(find "$dst" -type f -perm -u+x -print0)
	else
		copy_libs "$dst"
	fi
}

guest_path() {
	local abs
	abs=$(realpath -s "$1")
	case "$abs" in
	"$root"/*) echo "/work/${abs#"$root"/}" ;;
	*) echo "$abs" ;;
	esac
}

for t in $CAN_TOOLS; do
	copy_in "$(command -v "$t")" "$ir/usr/bin/$t"
done
for a in ${adds[@]+"${adds[@]}"}; do
	copy_in "$a" "$ir$(guest_path "$a")"
done
gscript=$(guest_path "$script")
copy_in "$script" "$ir$gscript"

# The script's command line, single-quoted for busybox sh.
quote() {
	printf "'%s'" "$(printf '%s' "$1" | sed "s/'/'\\\\''/g")"
}
{
	printf 'sh %s' "$(quote "$gscript")"
	for a in ${script_args[@]+"${script_args[@]}"}; do
		printf ' %s' "$(quote "$a")"
	done
	printf '\n'
} >"$ir/etc/test-cmd"

want_out=0
[ -n "$outdir" ] && want_out=1
cat >"$ir/init" <<EOF
#!/bin/sh
# SPDX-License-Identifier: MIT
# Generated by tests/system/vcan/guest.sh.
/bin/busybox --install -s /bin
export PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
# /tmp stays on the initramfs (already RAM): added files may live there
mkdir -p /dev/shm /dev/pts
mount -t tmpfs shm /dev/shm
ip link set lo up
fail() {
	echo "@@SQ-GUEST-SETUP-FAILED: \$*@@"
	poweroff -f
}
for m in $(for m in $MODULES; do printf '%s ' "$(basename "$m")"; done); do
	insmod /lib/modules/\$m || fail "insmod \$m"
done
ip link add dev vcan0 type vcan || fail "ip link add vcan0"
ip link set up vcan0 || fail "ip link set up vcan0"
if [ $vcan1 = 1 ]; then
	ip link add dev vcan1 type vcan || fail "ip link add vcan1"
	ip link set up vcan1 || fail "ip link set up vcan1"
	export SQ_VCAN1=vcan1
fi
export SQ_GUEST=1 SQ_VCAN=vcan0 SQ_OUT=/out HOME=/tmp
cd /work
echo "@@SQ-GUEST-BEGIN@@"
. /etc/test-cmd </dev/null
rc=\$?
echo "@@SQ-GUEST-END rc=\$rc@@"
if [ $want_out = 1 ]; then
	echo "@@SQ-OUT-BEGIN@@"
	tar -C /out -cf - . | gzip | base64
	echo "@@SQ-OUT-END@@"
fi
poweroff -f
EOF
chmod +x "$ir/init"
(cd "$ir" && find . -print0 | cpio --null -o -H newc --quiet | gzip -1) >"$work/initrd.gz"

# ---- boot --------------------------------------------------------------------

raw="$work/console.log"
set +e
timeout "$timeout_s" qemu-system-x86_64 -accel tcg -cpu max -m "$mem_mb" \
	-nographic -no-reboot -kernel "$kdir/vmlinuz" -initrd "$work/initrd.gz" \
	-append "console=ttyS0 quiet loglevel=3 panic=-1" </dev/null 2>&1 |
	tr -d '\r' | tee "$raw" |
	awk '/@@SQ-GUEST-BEGIN@@/ { on = 1; next }
	     /@@SQ-GUEST-END rc=/ { sub(/@@SQ-GUEST-END rc=.*/, ""); if (on && length($0)) { print }; on = 0; next }
	     on { print; fflush() }'
qrc=${PIPESTATUS[0]}
set -e
if [ -n "$console_copy" ]; then
	cp "$raw" "$console_copy"
fi

if [ -n "$outdir" ] && grep -q '^@@SQ-OUT-END@@' "$raw"; then
	mkdir -p "$outdir"
	sed -n '/^@@SQ-OUT-BEGIN@@/,/^@@SQ-OUT-END@@/p' "$raw" | sed '1d;$d' |
		base64 -d | tar -xzf - -C "$outdir"
fi
endline=$(grep -ao '@@SQ-GUEST-END rc=[0-9]*@@' "$raw" | tail -n 1 || true)
if [ -n "$endline" ]; then
	rc=$(echo "$endline" | sed -E 's/^@@SQ-GUEST-END rc=([0-9]+)@@.*/\1/')
	exit "$rc"
fi
if [ "$qrc" = 124 ]; then
	echo "guest.sh: timed out after ${timeout_s}s; last console lines:" >&2
	tail -n 20 "$raw" | sed 's/^/    /' >&2
	exit 124
fi
echo "guest.sh: the guest did not finish the test (qemu exit $qrc); last console lines:" >&2
tail -n 30 "$raw" | sed 's/^/    /' >&2
exit 4
