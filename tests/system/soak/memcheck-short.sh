#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make test: the memory check at 10^4 frames under valgrind (float and
# fixed) and 10^4 vs 10^6 frames without (about 10 s); make soak runs the
# full one (10^5 under valgrind, 10^7 streamed).
exec "$(dirname "$0")/memcheck-replay.sh" 10000 1000000
