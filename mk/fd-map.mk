# SPDX-License-Identifier: MIT
# CAN FD input map and AUTOSAR E2E Profile 5: cmocka, both numeric builds,
# ASan+UBSan.
#   build/<v>/tests/firmware/protocol/test_e2e_p05      P05 vs crc_hqx, the published example
#   build/<v>/tests/firmware/protocol/test_crc16_ccitt  CRC-16/CCITT-FALSE vs crc_hqx
#   build/<v>/tests/firmware/protocol/test_can_signal_fd FD signals vs canmatrix
#   build/<v>/tests/firmware/monitor/test_input_rx_fd    FD configs and verdicts
#   build/<v>/tests/host-sim/test_calib_sections_fd      fd / p05 text keys
# The references are generated at build time into build/gen/fd-map/.
FD_MAP_VARIANTS := test test-fixed
FD_MAP_GEN := build/gen/fd-map
FD_MAP_DBC := tests/firmware/protocol/fixtures/fd_signals.dbc

$(FD_MAP_GEN)/e2e_p05_ref.h: tests/firmware/protocol/gen_e2e_p05_vectors.py
	@mkdir -p $(@D)
	$(PYTHON) $< $@
$(FD_MAP_GEN)/can_signal_fd_ref.h: tests/firmware/protocol/gen_can_signal_fd.py $(FD_MAP_DBC)
	@mkdir -p $(@D)
	$(PYTHON) $< $(FD_MAP_DBC) $@

# variant, test directory, test name, generated header, extra objects
define fd_map_rules
build/$(1)/app/tests/$(2)/$(3).o: tests/$(2)/$(3).c $(4)
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) -D_GNU_SOURCE $$(OPT_$(1)) $$(DEF_$$(NUM_$(1))) $$(FW_INC) -Ihost-sim -Itests/support -I$(FD_MAP_GEN) -MMD -MP -c $$< -o $$@
build/$(1)/tests/$(2)/$(3): build/$(1)/app/tests/$(2)/$(3).o build/$(1)/app/tests/support/test_contract.o $(addprefix build/$(1)/app/,$(5)) build/$(1)/libfirmware.a
	@mkdir -p $$(@D)
	$$(CC) $$(OPT_$(1)) -o $$@ $$^ -lcmocka -lm
TEST_PROGS += build/$(1)/tests/$(2)/$(3)
endef
$(foreach v,$(FD_MAP_VARIANTS),\
  $(eval $(call fd_map_rules,$(v),firmware/protocol,test_e2e_p05,$(FD_MAP_GEN)/e2e_p05_ref.h,))\
  $(eval $(call fd_map_rules,$(v),firmware/protocol,test_crc16_ccitt,$(FD_MAP_GEN)/e2e_p05_ref.h,))\
  $(eval $(call fd_map_rules,$(v),firmware/protocol,test_can_signal_fd,$(FD_MAP_GEN)/can_signal_fd_ref.h,))\
  $(eval $(call fd_map_rules,$(v),firmware/monitor,test_input_rx_fd,,))\
  $(eval $(call fd_map_rules,$(v),host-sim,test_calib_sections_fd,,host-sim/calib_text.o host-sim/calib_sections.o)))
