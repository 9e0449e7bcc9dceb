#!/bin/sh
# SPDX-License-Identifier: MIT
# Stand-in for unpack_random in tests/firmware/protocol/test_squeal_msgs_unpack_control.sh:
# the real output with one defect, chosen by UNPACK_DEFECT:
#   bit     one unpacked DiscSpeed_radps off by its lowest bit (the first)
#   accept  every refused PadForce frame reported as unpacked (rc=0)
set -eu
real=${UNPACK_RANDOM_REAL:-build/test/tests/firmware/protocol/unpack_random}
case ${UNPACK_DEFECT:-bit} in
bit) "$real" "$@" | awk '!done && match($0, /DiscSpeed_radps=[0-9]+/) { done = 1
		v = substr($0, RSTART + 16, RLENGTH - 16); b = v % 2
		$0 = substr($0, 1, RSTART + 15) (b ? v - 1 : v + 1) substr($0, RSTART + RLENGTH) } { print }' ;;
accept) "$real" "$@" | sed -E 's/^(PadForce .*) rc=-74$/\1 rc=0/' ;;
esac
