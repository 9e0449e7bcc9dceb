# SPDX-License-Identifier: MIT
"""The counter of the tests that name each check and print one line per
check ("PASS  name  detail" / "FAIL  name  detail"), ending with the
runner's "RESULT: N passed, M failed"."""


class NamedChecks:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def __call__(self, name, ok, detail=""):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
        print(f"{'PASS' if ok else 'FAIL'}  {name}  {detail}")

    def finish(self):
        """Prints the RESULT line; the exit status (0 when nothing failed)."""
        print(f"RESULT: {self.passed} passed, {self.failed} failed")
        return 0 if self.failed == 0 else 1
