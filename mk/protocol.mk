# SPDX-License-Identifier: MIT
# firmware/protocol tests (the protocol sources themselves are compiled into
# libfirmware.a by the top-level Makefile):
#   build/test/tests/firmware/protocol/test_squeal_msgs     cmocka, ASan+UBSan
#   build/<v>/tests/firmware/protocol/test_crc8_p01  CRC-8 P01 and SAE J1850, both builds
#   build/<v>/tests/firmware/protocol/test_e2e_p01   E2E P01 1A protect/check, both builds
#   build/<v>/tests/firmware/protocol/test_can_signal DBC bit layouts, both builds
#   build/test/tests/firmware/protocol/emit_frames   packs+protects frames, prints the
#                                           C descriptor table (host helper)
#   tests/firmware/protocol/check_squeal_msgs_dbc.py        C defines/descriptors == DBC
#   tests/firmware/protocol/test_squeal_msgs_canmatrix.py  canmatrix decodes our frames
#   tests/firmware/protocol/test_squeal_msgs_unpack.py     our input unpackers == canmatrix
#                                           on random frames (unpack_random.c)

PROTOCOL_TEST_BIN := build/test/tests/firmware/protocol/test_squeal_msgs
PROTOCOL_EMIT := build/test/tests/firmware/protocol/emit_frames

$(PROTOCOL_TEST_BIN): build/test/app/tests/firmware/protocol/test_squeal_msgs.o build/test/app/tests/support/p01_frames.o \
		build/test/app/tests/support/test_contract.o build/test/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^ -lcmocka

# CRC-8 P01 and E2E P01 on their own, both numeric builds (the P01 fixtures
# and the bitwise reference CRC: tests/support/p01_frames.c)
PROTOCOL_P01_TESTS := tests/firmware/protocol/test_crc8_p01 tests/firmware/protocol/test_e2e_p01
define protocol_p01_rules
build/$(1)/$(2): build/$(1)/app/$(2).o build/$(1)/app/tests/support/p01_frames.o build/$(1)/app/tests/support/test_contract.o build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka
endef
$(foreach v,test test-fixed,$(foreach t,$(PROTOCOL_P01_TESTS),$(eval $(call protocol_p01_rules,$(v),$(t)))))
TEST_PROGS += $(foreach v,test test-fixed,$(foreach t,$(PROTOCOL_P01_TESTS),build/$(v)/$(t)))

define protocol_signal_rules
build/$(1)/tests/firmware/protocol/test_can_signal: build/$(1)/app/tests/firmware/protocol/test_can_signal.o build/$(1)/app/tests/support/test_contract.o build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka
endef
$(foreach v,test test-fixed,$(eval $(call protocol_signal_rules,$(v))))
TEST_PROGS += $(foreach v,test test-fixed,build/$(v)/tests/firmware/protocol/test_can_signal)

$(PROTOCOL_EMIT): build/test/app/tests/firmware/protocol/emit_frames.o build/test/app/tests/support/any_msg.o build/test/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^

# The Python checks run the emitter: build it first.
tests/firmware/protocol/check_squeal_msgs_dbc.py tests/firmware/protocol/test_squeal_msgs_canmatrix.py: $(PROTOCOL_EMIT)

TEST_PROGS += $(PROTOCOL_TEST_BIN) tests/firmware/protocol/check_squeal_msgs_dbc.py \
	tests/firmware/protocol/test_squeal_msgs_canmatrix.py

# The protocol layer must build for the ECUs too (freestanding, hard-float
# Cortex-M4F and soft Cortex-M3), with the same warnings.
PROTOCOL_SRCS := $(wildcard firmware/protocol/*.c)
ARM_CC ?= arm-none-eabi-gcc
build/arm-check/protocol.stamp: $(PROTOCOL_SRCS) $(wildcard firmware/protocol/*.h)
	@mkdir -p $(@D)
	for f in $(PROTOCOL_SRCS); do \
		$(ARM_CC) $(WARN) $(FW_FLAGS) -Os -mcpu=cortex-m4 -mthumb -mfloat-abi=hard \
			-mfpu=fpv4-sp-d16 $(FW_INC) -c $$f -o build/arm-check/m4-$$(basename $$f .c).o || exit 1; \
		$(ARM_CC) $(WARN) $(FW_FLAGS) -Os -mcpu=cortex-m3 -mthumb -mfloat-abi=soft \
			$(FW_INC) -c $$f -o build/arm-check/m3-$$(basename $$f .c).o || exit 1; \
	done
	touch $@
ALL_TARGETS += build/arm-check/protocol.stamp

# Host figures (release build): make bench
PROTOCOL_BENCH := build/host/tests/firmware/protocol/bench_squeal_msgs
$(PROTOCOL_BENCH): build/host/app/tests/firmware/protocol/bench_squeal_msgs.o build/host/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_host) -o $@ $^
BENCH_PROGS += $(PROTOCOL_BENCH)

# Input unpackers on random frames vs canmatrix (tests/firmware/protocol/unpack_random.c)
PROTOCOL_UNPACK_RANDOM := build/test/tests/firmware/protocol/unpack_random
$(PROTOCOL_UNPACK_RANDOM): build/test/app/tests/firmware/protocol/unpack_random.o build/test/libfirmware.a
	@mkdir -p $(@D)
	$(CC) $(OPT_test) -o $@ $^
tests/firmware/protocol/test_squeal_msgs_unpack.py: $(PROTOCOL_UNPACK_RANDOM)
TEST_PROGS += tests/firmware/protocol/test_squeal_msgs_unpack.py
