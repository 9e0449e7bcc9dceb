/* SPDX-License-Identifier: MIT */
/* Host side of the golden-vector digest: the same tv_run() on the host's
 * own firmware build (build/host or build/host-fixed libfirmware.a). */
#include <stdio.h>

#include "tv_vectors.h"

static void out(const char *line)
{
	(void)fputs(line, stdout);
}

int main(void)
{
	(void)tv_run(out, NULL, NULL, NULL);
	return fflush(stdout) == 0 ? 0 : 1;
}
