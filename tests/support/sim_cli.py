# SPDX-License-Identifier: MIT
"""What the squeal-sim command-line tests share: the two release programs
(float, fixed) and their sanitizer builds, one way to run a command, and the counting of checks that
ends with the runner's "RESULT: N passed, M failed" line."""

import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SIMS = {build: os.path.join(ROOT, "build", variant, "squeal-sim")
        for build, variant in (("float", "host"), ("fixed", "host-fixed"))}
# the sanitizer builds (ASan + UBSan) of the same two
SAN_SIMS = {build: os.path.join(ROOT, "build", variant, "squeal-sim")
            for build, variant in (("float", "test"), ("fixed", "test-fixed"))}


def run(argv, cwd=None, timeout=300):
    """(exit status, stdout, stderr) of argv."""
    p = subprocess.run(argv, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


class Results:
    """result(ok, what) counts a check and names a failed one."""

    def __init__(self):
        self.counts = {True: 0, False: 0}

    def __call__(self, ok, what):
        self.counts[bool(ok)] += 1
        if not ok:
            print("FAIL  " + what)

    def each_build(self, check):
        """check(build, sim) for each program that was built."""
        for build, sim in SIMS.items():
            if os.access(sim, os.X_OK):
                check(build, sim)
            else:
                self(False, "%s missing (run make)" % sim)

    def finish(self):
        print("RESULT: %d passed, %d failed" % (self.counts[True], self.counts[False]))
        return 0 if self.counts[False] == 0 else 1
