#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/flash.sh without hardware: --dry-run prints the OpenOCD command; a
missing openocd is one line naming Debian's package, exit 1; OpenOCD's
"no device found" / "Error: open failed" (no ST-LINK reached) and a target
that does not answer each get one line saying what to check, exit 1; a
successful run exits 0. OpenOCD is replaced by a stub on PATH that prints
what the real one prints in each case.
"""
import os
import stat
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
FLASH = os.path.join(ROOT, "tools", "flash.sh")

_C = Checks()


def check(ok, what, detail=""):
    _C.check(ok, what + ("" if ok or not detail else ": " + detail))


def run(args, path, cwd):
    env = dict(os.environ, PATH=path)
    return subprocess.run(["/bin/bash", FLASH] + args, cwd=cwd, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True, timeout=30)


def stub(folder, text, rc):
    p = os.path.join(folder, "openocd")
    with open(p, "w") as f:
        f.write("#!/bin/sh\ncat >&2 <<'X'\n%s\nX\nexit %d\n" % (text, rc))
    os.chmod(p, os.stat(p).st_mode | stat.S_IEXEC)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        elf = os.path.join(tmp, "img.elf")
        open(elf, "w").close()
        bare = os.path.join(tmp, "bin")
        os.mkdir(bare)
        for tool in ("mktemp", "tee", "grep", "rm", "cat"):
            os.symlink("/usr/bin/" + tool if os.path.exists("/usr/bin/" + tool) else "/bin/" + tool,
                       os.path.join(bare, tool))
        r = run(["--dry-run", elf], bare, tmp)
        check(r.returncode == 0 and r.stdout.strip() == 'openocd -f interface/stlink.cfg -f target/stm32f4x.cfg '
              '-c "program %s verify reset exit"' % elf, "--dry-run prints the command", r.stdout + r.stderr)
        r = run([elf], bare, tmp)
        check(r.returncode == 1 and r.stderr.count("\n") == 1 and "apt-get install openocd" in r.stderr,
              "no openocd: one line naming the package, exit 1", r.stderr)
        cases = (("Error: open failed\nin procedure 'program'", 1, "no ST-LINK probe reached"),
                 ("Info : clock speed 1000 kHz\nError: libusb_open() failed with LIBUSB_ERROR_ACCESS\n"
                  "Error: no device found", 1, "no ST-LINK probe reached"),
                 ("Info : Target voltage: 0.004\nError: init mode failed (unable to connect to the target)", 1,
                  "the MCU does not"),
                 ("** Programming Finished **\n** Verified OK **", 0, None))
        for text, rc, says in cases:
            stub(bare, text, rc)
            r = run([elf], bare, tmp)
            first = text.splitlines()[-1]
            if says:
                check(r.returncode == 1 and says in r.stderr and r.stderr.count("flash.sh:") == 1,
                      "OpenOCD '%s': one line '%s...', exit 1" % (first, says), r.stderr)
            else:
                check(r.returncode == 0 and "flash.sh:" not in r.stderr + r.stdout and "Verified OK" in r.stdout,
                      "a successful flash: OpenOCD's lines, exit 0", r.stdout + r.stderr)
    return _C.finish()


if __name__ == "__main__":
    sys.exit(main())
