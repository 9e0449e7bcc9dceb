#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Makes the README's two commands set-up-free: checks that the Debian
# packages a purpose needs are installed and installs the missing ones
# (apt-get, as root). Cheap when everything is there (one dpkg-query).
#   tools/ensure-deps.sh demo|test
set -eu
purpose=${1:-test}
build="make gcc libc6-dev"
demo="$build python3 python3-numpy python3-matplotlib"
test="$build clang libclang-rt-14-dev gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi
 libcmocka-dev valgrind cppcheck python3 python3-numpy python3-scipy python3-matplotlib python3-can
 python3-canmatrix python3-dask python3-distributed can-utils qemu-system-x86 qemu-system-arm busybox-static cpio kmod iproute2"
case "$purpose" in
demo) want=$demo ;;
test) want=$test ;;
*) echo "usage: $0 demo|test" >&2; exit 2 ;;
esac
missing=""
for p in $want; do
	if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
		missing="$missing $p"
	fi
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" != 0 ]; then
	echo "missing Debian packages:$missing" >&2
	echo "install them with: sudo apt-get install --no-install-recommends$missing" >&2
	exit 1
fi
echo "installing:$missing" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -q >/dev/null
# shellcheck disable=SC2086
apt-get install -y -q --no-install-recommends $missing >/dev/null
