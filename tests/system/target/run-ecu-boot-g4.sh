#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The STM32G474 ECU image (FDCAN) boots on qemu-system-arm as the F4 image
# does: run-ecu-boot.sh's checks on build/stm32g474-ecutest.
ECU_BOOT_TARGET=stm32g474 exec "$(dirname "$0")/run-ecu-boot.sh"
