# SPDX-License-Identifier: MIT
# Guest script for the HAL conformance suite on SocketCAN (run by
# tests/system/vcan/guest.sh --vcan1; POSIX sh): bus 0 on $SQ_VCAN, bus 1 on
# $SQ_VCAN1. Without a second interface the suite runs on one bus.
set -u
SQ_VCAN1=${SQ_VCAN1:-}
SQ_TC=
# root in the guest: tc can stall a bus's TX path (the queue-full check)
if [ "$SQ_GUEST" = 1 ]; then SQ_TC=/usr/sbin/tc; fi
export SQ_VCAN SQ_VCAN1 SQ_TC
exec build/test/tests/hal/linux/conf_hal_linux_can
