# SPDX-License-Identifier: MIT
# Offline replay of candump logs and the decoder (issue 4):
#   host-sim/candump_log.c   candump -L parser/writer (squeal-sim replay/decode)
#   build/test/test_candump_log   cmocka, ASan+UBSan
REPLAY_SIM_SRCS := host-sim/candump_log.c

build/test/test_candump_log: build/test/app/tests/unit/test_candump_log.o build/test/app/host-sim/candump_log.o
	$(CC) $(OPT_test) -o $@ $^ -lcmocka

TEST_PROGS += build/test/test_candump_log
