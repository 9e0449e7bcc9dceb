# SPDX-License-Identifier: MIT
# The ECU images (bare metal, arm-none-eabi) and their target-in-the-loop tests.
#
#   make firmware                               build/stm32f4/squeal-monitor.{elf,bin,hex,map}
#   make firmware NUMERIC=fixed TARGET=stm32f103  build/stm32f103/... (Cortex-M3, no FPU,
#                                               checked free of floating point)
#   make firmware TARGET=stm32g474              build/stm32g474/... (FDCAN, CAN FD frames)
#   make flash [DRY_RUN=1] [TARGET=...]         OpenOCD + ST-LINK (tools/flash.sh)
#   make stack-usage                            worst-case stack per entry point
#
# Every configuration compiles firmware/, hal/ and tests with its own flags
# into build/<config>/fw/, so the host variants are never mixed in.

ARM_CC := arm-none-eabi-gcc
ARM_OBJCOPY := arm-none-eabi-objcopy
ARM_SIZE := arm-none-eabi-size
ARM_NM := arm-none-eabi-nm
QEMU_ARM := qemu-system-arm

TARGET ?= stm32f4

CPU_stm32f4 := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
CPU_stm32f103 := -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
CPU_stm32g474 := $(CPU_stm32f4)
LDS_stm32f4 := linker/stm32f405xg.ld
LDS_stm32f103 := linker/stm32f103xb.ld
LDS_stm32g474 := linker/stm32g474xe.ld
# chip.h comes from the chip directory (never next to the shared files, where
# #include "..." would find it first); the F103 port reuses the generic parts.
HAL_INC_stm32f4 := -Ihal/stm32f4/stm32f405 -Ihal/stm32f4
HAL_INC_stm32f103 := -Ihal/stm32f103/stm32f103xb -Ihal/stm32f4
HAL_INC_stm32g474 := -Ihal/stm32g4/stm32g474 -Ihal/stm32g4 -Ihal/stm32f4
HAL_GENERIC := startup.c systick.c iwdg.c calib_flash.c board.c selftest.c \
	platform_faults.c libc_min.c can_queue.c
HAL_BXCAN := bxcan.c bxcan_timing.c
# -DHAL_CAN_CLASSIC_ONLY for the bxCAN images only: bxCAN is a classic
# controller, so its frames hold 8 data bytes (hal.h's HAL_CAN_MAX_DLEN) and
# its RAM stays the classic one; FD frames are refused there (SQ_ENOTSUP).
# The G4's FDCAN carries FD frames (HAL_CAN_MAX_DLEN 64).
CANFLAGS_stm32f4 := -DHAL_CAN_CLASSIC_ONLY
CANFLAGS_stm32f103 := -DHAL_CAN_CLASSIC_ONLY
CANFLAGS_stm32f2 := -DHAL_CAN_CLASSIC_ONLY
CANFLAGS_stm32g474 :=
# the rules every backend shares (hal/common/: frame and filter checks, the
# bus-state change)
HAL_COMMON := $(sort $(wildcard hal/common/*.c))
# chip_common.c: the clock rates and flash unlock every chip shares;
# hse_meter.c: the crystal against the HSI (F4, G4)
HAL_SRCS_stm32f4 := $(addprefix hal/stm32f4/,$(HAL_GENERIC) $(HAL_BXCAN) chip_common.c clock.c hse_meter.c can_pins.c flash.c) $(HAL_COMMON)
HAL_SRCS_stm32f103 := $(addprefix hal/stm32f4/,$(HAL_GENERIC) $(HAL_BXCAN) chip_common.c) $(sort $(wildcard hal/stm32f103/*.c)) $(HAL_COMMON)
# the G4: the generic files, its chip part and FDCAN driver (hal/stm32g4/)
HAL_SRCS_stm32g474 := $(addprefix hal/stm32f4/,$(HAL_GENERIC) chip_common.c hse_meter.c) $(sort $(wildcard hal/stm32g4/*.c)) $(HAL_COMMON)
# Test images only (-DSQ_TARGET_TEST): semihosting, the drivers' event sink
# and the test run around the firmware; never in an ECU image.
HAL_TEST_SRCS := $(addprefix hal/stm32f4/,semihost.c test_events.c test_run.c)

# The firmware's entry point; a stand-in until firmware/app/ has its C files.
APP_SRCS := $(sort $(wildcard firmware/app/*.c))
ifeq ($(APP_SRCS),)
APP_SRCS := hal/stm32f4/placeholder_app.c
endif
FW_TARGET_SRCS := $(sort $(FW_SRCS) $(APP_SRCS))

# -ffp-contract=off: no fused multiply-add, so float results are the host's
# bit for bit. -fstack-usage/-fcallgraph-info feed tools/stack_usage.py.
# The CAN frame size per controller: CANFLAGS_<chip> above.
ARM_CFLAGS := $(WARN) -ffreestanding -fno-common -ffunction-sections -fdata-sections \
	-ffp-contract=off -fstack-usage -fcallgraph-info=su -Os -g
ARM_LDFLAGS := -nostdlib -nostartfiles -Wl,--gc-sections -Wl,--no-warn-rwx-segments

# arm_config: name, target chip, numeric, extra flags, sources, linker script
define arm_config
$(1)_OBJS := $$(patsubst %.c,build/$(1)/fw/%.o,$(5))
build/$(1)/fw/%.o: %.c
	@mkdir -p $$(@D)
	$$(ARM_CC) $$(ARM_CFLAGS) $$(CPU_$(2)) $$(CANFLAGS_$(2)) $$(DEF_$(3)) $(4) $$(FW_INC) $$(HAL_INC_$(2)) \
		-Itests/target -Ibuild/$(1) -MMD -MP -c $$< -o $$@
.SECONDARY: $$($(1)_OBJS)
build/$(1)/%.elf: $$($(1)_OBJS) $(6)
	@mkdir -p $$(@D)
	$$(ARM_CC) $$(CPU_$(2)) $$(ARM_LDFLAGS) $$(LDX_$(1)) -T $(6) -Wl,-Map=$$(@:.elf=.map) \
		$$($(1)_OBJS) -lgcc -o $$@
build/$(1)/%.bin: build/$(1)/%.elf
	$$(ARM_OBJCOPY) -O binary --gap-fill 0xff $$< $$@
build/$(1)/%.hex: build/$(1)/%.elf
	$$(ARM_OBJCOPY) -O ihex $$< $$@
endef

# The ECU images
$(eval $(call arm_config,stm32f4,stm32f4,float,,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32f4),$(LDS_stm32f4)))
$(eval $(call arm_config,stm32f103,stm32f103,fixed,,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32f103),$(LDS_stm32f103)))
# Other numeric modes on request (make firmware NUMERIC=fixed): build/stm32f4-fixed/ ...
$(eval $(call arm_config,stm32f4-fixed,stm32f4,fixed,,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32f4),$(LDS_stm32f4)))
$(eval $(call arm_config,stm32f103-float,stm32f103,float,,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32f103),$(LDS_stm32f103)))
# The STM32G474 (FDCAN): the F4's app, model and monitor objects' flags
$(eval $(call arm_config,stm32g474,stm32g474,float,,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32g474),$(LDS_stm32g474)))
$(eval $(call arm_config,stm32g474-fixed,stm32g474,fixed,,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32g474),$(LDS_stm32g474)))

NATIVE_NUM_stm32f4 := float
NATIVE_NUM_stm32f103 := fixed
NATIVE_NUM_stm32g474 := float
FW_CONFIG := $(TARGET)$(if $(filter $(NATIVE_NUM_$(TARGET)),$(NUMERIC)),,-$(NUMERIC))
FW_IMAGE := build/$(FW_CONFIG)/squeal-monitor

.PHONY: firmware flash stack-usage
firmware: $(FW_IMAGE).elf $(FW_IMAGE).bin $(FW_IMAGE).hex
	@echo "== $(FW_IMAGE).elf ($(TARGET), $(NUMERIC))"
	@$(ARM_SIZE) $(FW_IMAGE).elf
	@tests/system/target/size-report.sh $(FW_IMAGE).elf
	@$(PYTHON) tools/stack_usage.py $(FW_IMAGE).elf build/$(FW_CONFIG)/fw | tail -1
	$(if $(filter fixed,$(NUMERIC)),tests/system/target/check-no-float.sh $(FW_IMAGE).elf)

stack-usage: $(FW_IMAGE).elf
	$(PYTHON) tools/stack_usage.py $(FW_IMAGE).elf build/$(FW_CONFIG)/fw

flash: $(FW_IMAGE).elf
	tools/flash.sh $(if $(DRY_RUN),--dry-run) --target $(TARGET) $(FW_IMAGE).elf

ALL_TARGETS += build/stm32f4/squeal-monitor.elf build/stm32f4/squeal-monitor.bin build/stm32f103/squeal-monitor.elf \
	build/stm32f4/squeal-monitor.hex

# ---- target-in-the-loop test images ---------------------------------------

# The ECU image with semihosting events (boot, faults, watchdog, summary).
$(eval $(call arm_config,stm32f4-ecutest,stm32f4,float,-DSQ_TARGET_TEST,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32f4) $(HAL_TEST_SRCS),$(LDS_stm32f4)))

# The model over the golden vectors: Cortex-M4F float on netduinoplus2,
# Cortex-M3 fixed on netduino2 (STM32F205: the F4's memory map and
# peripherals without FPU, so it runs the F4 HAL built for the M3), and the
# same tv_run.c on the host builds; tests/system/target/run-golden.sh compares.
CPU_stm32f2 := -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
HAL_INC_stm32f2 := $(HAL_INC_stm32f4)
FW_LIB_SRCS := $(filter-out firmware/app/%,$(FW_SRCS))
TV_SRCS := tests/system/target/tv_run.c tests/system/target/tv_target.c

build/tv/model_vectors_%.c: tests/support/golden/model_vectors.csv tests/system/target/gen_vectors.py
	@mkdir -p $(@D)
	$(PYTHON) tests/system/target/gen_vectors.py --numeric $* $< $@

$(eval $(call arm_config,tv-m4f,stm32f4,float,-DSQ_TARGET_TEST,$(FW_LIB_SRCS) $(HAL_SRCS_stm32f4) $(HAL_TEST_SRCS) $(TV_SRCS) build/tv/model_vectors_float.c,$(LDS_stm32f4)))
$(eval $(call arm_config,tv-m3,stm32f2,fixed,-DSQ_TARGET_TEST,$(FW_LIB_SRCS) $(HAL_SRCS_stm32f4) $(HAL_TEST_SRCS) $(TV_SRCS) build/tv/model_vectors_fixed.c,$(LDS_stm32f4)))
# ... and the same vectors inside the STM32G474 image (its HAL, its link),
# both numeric builds on the Cortex-M4F (netduinoplus2: the G4's flash and
# SRAM addresses; its RCC and FDCAN are absent there and read 0)
# (the vectors' table is larger than the G4's flash bank 1; these images
# never write calibration, linker/stm32g474xe.ld)
LDX_tv-g4 := -Wl,--defsym,__image_spans_banks=1
LDX_tv-g4-fixed := $(LDX_tv-g4)
$(eval $(call arm_config,tv-g4,stm32g474,float,-DSQ_TARGET_TEST,$(FW_LIB_SRCS) $(HAL_SRCS_stm32g474) $(HAL_TEST_SRCS) $(TV_SRCS) build/tv/model_vectors_float.c,$(LDS_stm32g474)))
$(eval $(call arm_config,tv-g4-fixed,stm32g474,fixed,-DSQ_TARGET_TEST,$(FW_LIB_SRCS) $(HAL_SRCS_stm32g474) $(HAL_TEST_SRCS) $(TV_SRCS) build/tv/model_vectors_fixed.c,$(LDS_stm32g474)))

build/host/tv-digest: build/host/app/tests/system/target/tv_run.o build/host/app/tests/system/target/tv_host.o \
		build/host/app/build/tv/model_vectors_float.o build/host/libfirmware.a
	@mkdir -p $(@D)
	$(CC) -o $@ $^ -lm
build/host-fixed/tv-digest: build/host-fixed/app/tests/system/target/tv_run.o build/host-fixed/app/tests/system/target/tv_host.o \
		build/host-fixed/app/build/tv/model_vectors_fixed.o build/host-fixed/libfirmware.a
	@mkdir -p $(@D)
	$(CC) -o $@ $^ -lm

# bxCAN bit timing: pure arithmetic, tested on the host (cmocka)
build/test/tests/hal/stm32f4/test_bxcan_timing: tests/hal/stm32f4/test_bxcan_timing.c hal/stm32f4/bxcan_timing.c hal/stm32f4/bxcan.h
	@mkdir -p $(@D)
	$(CC) $(WARN) -O2 -g $(FW_INC) -Ihal/stm32f4 -Itests/support -o $@ tests/hal/stm32f4/test_bxcan_timing.c hal/stm32f4/bxcan_timing.c -lcmocka

# Two-slot calibration storage over a simulated NOR flash (power cut at every
# byte); the slot geometry comes from the link, as on the target. No PIE:
# the slot size is an absolute linker symbol.
build/test/tests/hal/stm32f4/test_calib_flash: tests/hal/stm32f4/test_calib_flash.c hal/stm32f4/calib_flash.c hal/stm32f4/stm32_board.h \
		tests/support/regsim/calib_pattern.h
	@mkdir -p $(@D)
	$(CC) $(WARN) -O1 -g $(SAN) -fno-pie -no-pie $(FW_INC) -Ihal/stm32f4/stm32f405 -Ihal/stm32f4 -Itests/support -o $@ \
		tests/hal/stm32f4/test_calib_flash.c hal/stm32f4/calib_flash.c -lcmocka \
		-Wl,--defsym,__calib_start=calib_flash_sim,--defsym,__calib_slot_size=2048,--defsym,__calib_slot_count=2
TEST_PROGS += build/test/tests/hal/stm32f4/test_calib_flash

# Target-in-the-loop tests: the scripts run QEMU on images make builds first.
tests/system/target/run-golden.sh: build/tv-m4f/model-vectors.elf build/tv-m3/model-vectors.elf \
	build/tv-g4/model-vectors.elf build/tv-g4-fixed/model-vectors.elf \
	build/host/tv-digest build/host-fixed/tv-digest
tests/system/target/run-ecu-boot.sh: build/stm32f4-ecutest/squeal-monitor.elf build/stm32f4-faulttest/squeal-monitor.elf
tests/system/target/check-images.sh: build/stm32f4/squeal-monitor.elf build/stm32f103/squeal-monitor.elf \
	build/stm32f103-float/squeal-monitor.elf
# the G4 (FDCAN) image boots the same way; its ECU image is built too
tests/system/target/run-ecu-boot-g4.sh: build/stm32g474-ecutest/squeal-monitor.elf build/stm32g474/squeal-monitor.elf
TEST_PROGS += build/test/tests/hal/stm32f4/test_bxcan_timing tests/system/target/check-images.sh tests/system/target/run-golden.sh \
	tests/system/target/run-ecu-boot.sh tests/system/target/run-ecu-boot-g4.sh

# Bench images: the 1 ms monitor step on the M4F (float) and the M3 (fixed).
BENCH_STEP_SRCS := $(FW_LIB_SRCS) tests/system/target/bench_step.c
$(eval $(call arm_config,bench-m4f,stm32f4,float,-DSQ_TARGET_TEST,$(BENCH_STEP_SRCS) $(HAL_SRCS_stm32f4) $(HAL_TEST_SRCS),$(LDS_stm32f4)))
$(eval $(call arm_config,bench-m3,stm32f2,fixed,-DSQ_TARGET_TEST,$(BENCH_STEP_SRCS) $(HAL_SRCS_stm32f4) $(HAL_TEST_SRCS),$(LDS_stm32f4)))
tests/system/target/bench-target.sh: build/stm32f4/squeal-monitor.elf build/stm32f103/squeal-monitor.elf \
	build/tv-m4f/model-vectors.elf build/tv-m3/model-vectors.elf \
	build/bench-m4f/bench-step.elf build/bench-m3/bench-step.elf
BENCH_PROGS += tests/system/target/bench-target.sh
# ... and on the G4 (float, its HAL): the same steps plus four corners on
# inputs in 64-byte FD frames with E2E P05 (BENCHFD*); its ECU image's
# flash, RAM (FD frame queues) and stack
$(eval $(call arm_config,bench-g4,stm32g474,float,-DSQ_TARGET_TEST,$(BENCH_STEP_SRCS) $(HAL_SRCS_stm32g474) $(HAL_TEST_SRCS),$(LDS_stm32g474)))
tests/system/target/bench-target.sh: build/stm32g474/squeal-monitor.elf build/bench-g4/bench-step.elf \
	build/tv-g4/model-vectors.elf
# ... and one that divides by zero once it runs, to test the fault path
$(eval $(call arm_config,stm32f4-faulttest,stm32f4,float,-DSQ_TARGET_TEST -DSQ_TARGET_TEST_FAULT,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32f4) $(HAL_TEST_SRCS),$(LDS_stm32f4)))
# ... one whose stack overflows on purpose (the fault handler on a broken stack)
$(eval $(call arm_config,stm32f4-stacktest,stm32f4,float,-DSQ_TARGET_TEST -DSQ_TARGET_TEST_FAULT -DSQ_TARGET_TEST_STACK_OVERFLOW,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32f4) $(HAL_TEST_SRCS),$(LDS_stm32f4)))
tests/system/target/run-ecu-stack-overflow.sh: build/stm32f4-stacktest/squeal-monitor.elf
tests/system/target/run-ecu-selftest.sh: build/stm32f4-ecutest/squeal-monitor.elf build/stm32f4-faulttest/squeal-monitor.elf
TEST_PROGS += tests/system/target/run-ecu-stack-overflow.sh tests/system/target/run-ecu-selftest.sh
# ... and one that takes the clock security system's NMI (the crystal stops)
$(eval $(call arm_config,stm32f4-nmitest,stm32f4,float,-DSQ_TARGET_TEST -DSQ_TARGET_TEST_FAULT -DSQ_TARGET_TEST_NMI,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32f4) $(HAL_TEST_SRCS),$(LDS_stm32f4)))
tests/system/target/run-ecu-selftest.sh: build/stm32f4-nmitest/squeal-monitor.elf
# ... and one with a programming error (hal_contract_failed: file and line recorded, reset)
$(eval $(call arm_config,stm32f4-contracttest,stm32f4,float,-DSQ_TARGET_TEST -DSQ_TARGET_TEST_FAULT -DSQ_TARGET_TEST_CONTRACT,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32f4) $(HAL_TEST_SRCS),$(LDS_stm32f4)))
tests/system/target/run-ecu-contract.sh: build/stm32f4-contracttest/squeal-monitor.elf
TEST_PROGS += tests/system/target/run-ecu-contract.sh
# ... and the STM32G474 image with semihosting events, run under QEMU on
# netduinoplus2 (flash at 0x08000000, SRAM at 0x20000000; no G4 RCC, no
# FDCAN there: clock fallback and CAN init faults, bounded waits)
$(eval $(call arm_config,stm32g474-ecutest,stm32g474,float,-DSQ_TARGET_TEST,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32g474) $(HAL_TEST_SRCS),$(LDS_stm32g474)))
# ... and its NMI handler (flash ECC check first) on a non-ECC NMI
$(eval $(call arm_config,stm32g474-nmitest,stm32g474,float,-DSQ_TARGET_TEST -DSQ_TARGET_TEST_FAULT -DSQ_TARGET_TEST_NMI,$(FW_TARGET_SRCS) $(HAL_SRCS_stm32g474) $(HAL_TEST_SRCS),$(LDS_stm32g474)))
tests/system/target/run-ecu-nmi-g4.sh: build/stm32g474-nmitest/squeal-monitor.elf
TEST_PROGS += tests/system/target/run-ecu-nmi-g4.sh
