/* SPDX-License-Identifier: MIT */
/*
 * squeal-replay: `squeal-sim replay` as its own program, because it runs the
 * firmware on the in-memory HAL (hal/vbus, libhal_vbus.a) while squeal-sim's
 * other commands run it on SocketCAN (libhal_linux.a): a HAL backend is
 * chosen at link time, one per program. squeal-sim replay execs this
 * program with the same arguments; it may also be run directly.
 */
#include "sim_commands.h"

int main(int argc, char **argv)
{
	return cmd_replay(argc, argv);
}
