# SPDX-License-Identifier: MIT
# Static checks, all in make test:
#   tests/system/static/cppcheck-misra.sh    cppcheck 2.10 + MISRA C:2012 addon on
#                                     firmware/ and hal/, both numeric builds;
#                                     fails on findings not in
#                                     docs/misra-deviations.md, on a row over
#                                     its Count budget, on a cppcheck/addon
#                                     failure, on a canary not flagged
#                                     (--count, make misra-count: everything,
#                                     by rule and area, and per row)
#   tests/system/static/clang-warnings.sh    firmware/ under clang-14 -Weverything
#                                     (minus a documented list) -Werror, host
#                                     and both ECU targets, both builds
#   tests/system/static/check-calib-write-path.sh  no firmware code can reach
#                                     hal_calib_write (libraries and ECU images)
.PHONY: static misra-count
static:
	tests/system/static/cppcheck-misra.sh
	tests/system/static/clang-warnings.sh
misra-count:
	tests/system/static/cppcheck-misra.sh --count

tests/system/static/check-calib-write-path.sh: build/host/libfirmware.a build/host-fixed/libfirmware.a \
	build/stm32f4/squeal-monitor.elf build/stm32f103/squeal-monitor.elf
TEST_PROGS += tests/system/static/cppcheck-misra.sh tests/system/static/clang-warnings.sh \
	tests/system/static/check-calib-write-path.sh
