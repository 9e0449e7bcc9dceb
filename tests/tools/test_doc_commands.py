#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Every command shown in README.md and docs/*.md runs as written.

The fenced blocks are read by their info string:
  ```sh            run as one bash script (set -e -o pipefail) in a scratch
                   folder that links every top-level entry of the checkout,
                   so `build/host/squeal-sim` and `tools/x.py` resolve and
                   whatever a command writes lands in the scratch folder
  ```console       each `$ COMMAND` (with `\\` continuations) is run the same
                   way; the lines up to the next `$` are its expected stdout
  ```sh hardware   needs a CAN interface, root or a probe; and
  ```sh no-run     too long for a test (make test, make demo, make flash):
                   each command is only checked to exist: a `make TARGET`
                   has a rule, a program of this tree answers --help with
                   exit 0, another program (candump, ip, openocd) is on PATH
  ```text          not commands (formulas, synopses): not read
A `make` line in a ```sh block is checked like a no-run one (its rule
exists): building is what the rest of make test does.
One counted check per block (per command for the existence checks).
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
FENCE = re.compile(r"^```(\S*)(?:[ \t]+(\S+))?[ \t]*$")
TIMEOUT_S = 120

passed = failed = 0


def check(ok, what, detail=""):
    global passed, failed
    print(("PASS  " if ok else "FAIL  ") + what)
    if not ok and detail:
        for line in detail.rstrip().splitlines()[-15:]:
            print("      " + line)
    if ok:
        passed += 1
    else:
        failed += 1


def blocks(path):
    """(first line number, language, marker, lines) of each fenced block."""
    out, cur = [], None
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip("\n")
            m = FENCE.match(line)
            if cur is None and m and m.group(1):
                cur = (n + 1, m.group(1), m.group(2) or "", [])
            elif cur is not None and line.strip() == "```":
                out.append(cur)
                cur = None
            elif cur is not None:
                cur[3].append(line)
    return out


def logical_lines(lines):
    """Lines joined at trailing backslashes."""
    out, acc = [], ""
    for line in lines:
        if line.rstrip().endswith("\\"):
            acc += line.rstrip()[:-1] + " "
        else:
            out.append(acc + line)
            acc = ""
    if acc:
        out.append(acc)
    return out


def strip_comment(line):
    """The command without its trailing # comment (a # inside quotes stays)."""
    try:
        lex = shlex.shlex(line, posix=True, punctuation_chars=True)
        lex.commenters = "#"
        lex.whitespace_split = True
        return " ".join(shlex.quote(t) if not re.fullmatch(r"[|&;<>()]+", t) else t for t in lex)
    except ValueError:
        return line.split(" #", 1)[0]


def simple_commands(line):
    """The words of each simple command of a shell line (split at | && || ; &)."""
    words = strip_comment(line)
    out, cur = [], []
    for tok in shlex.split(words.replace("&&", " ; ").replace("||", " ; ").replace("|", " ; ")
                           .replace("&", " ; ").replace(";", " ; ")):
        if tok == ";":
            if cur:
                out.append(cur)
            cur = []
        else:
            cur.append(tok)
    if cur:
        out.append(cur)
    return out


def make_targets():
    """Every target with a rule in the Makefile and its fragments."""
    with tempfile.NamedTemporaryFile("w", suffix=".mk", delete=False) as f:
        f.write("__doc_commands_db:\n\t@:\n")
        extra = f.name
    try:
        db = subprocess.run(["make", "-p", "-f", "Makefile", "-f", extra, "__doc_commands_db"], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, timeout=60).stdout
    finally:
        os.unlink(extra)
    return {m.group(1) for m in re.finditer(r"^([A-Za-z0-9_.\-/]+):(?!=)", db, re.M)}


TARGETS = None


def exists_check(words, where):
    """One check that the program of a simple command exists (and answers --help if it is ours)."""
    global TARGETS
    while words and (words[0] == "sudo" or re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*=.*", words[0])):
        words = words[1:]
    if not words:
        return
    prog = words[0]
    if prog == "make":
        if TARGETS is None:
            TARGETS = make_targets()
        goals = [w for w in words[1:] if not w.startswith("-") and "=" not in w] or ["all"]
        missing = [g for g in goals if g not in TARGETS]
        check(not missing, "%s: make %s: has a rule" % (where, " ".join(goals)), "no rule for " + " ".join(missing))
        return
    if "/" in prog:
        path = os.path.join(ROOT, prog)
        if not os.path.exists(path):
            check(False, "%s: %s exists" % (where, prog), "not found (built by make?)")
            return
        cmd = [path] + ([words[1]] if len(words) > 1 and prog.endswith("squeal-sim")
                        and not words[1].startswith("-") else []) + ["--help"]
        with tempfile.TemporaryDirectory() as tmp:
            r = subprocess.run(cmd, cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               timeout=60)
        check(r.returncode == 0, "%s: %s --help exits 0" % (where, " ".join(cmd[:-1]).replace(ROOT + "/", "")),
              r.stdout)
        return
    check(shutil.which(prog) is not None, "%s: %s is on PATH" % (where, prog), "not found")


def run_script(text, cwd):
    return subprocess.run(["bash", "-e", "-o", "pipefail", "-c", text], cwd=cwd, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True, timeout=TIMEOUT_S)


def run_block(lines, where, cwd):
    """A ```sh block: make lines are existence checks, the rest one script."""
    script = []
    for line in logical_lines(lines):
        if re.match(r"^\s*make(\s|$)", line):
            for words in simple_commands(line):
                exists_check(words, where)
        else:
            script.append(line)
    if not any(s.strip() for s in script):
        return
    r = run_script("\n".join(script), cwd)
    check(r.returncode == 0, "%s: runs (exit %d)" % (where, r.returncode), r.stderr + r.stdout)


def run_console(lines, where, cwd):
    """A ```console block: each $ command runs; its stdout is the lines that follow it."""
    cmds = []
    for line in logical_lines(lines):
        if line.startswith("$ "):
            cmds.append([line[2:], []])
        elif cmds:
            cmds[-1][1].append(line)
    for cmd, want in cmds:
        r = run_script(cmd, cwd)
        got = [x.rstrip() for x in r.stdout.rstrip("\n").splitlines()]
        exp = [x.rstrip() for x in want]
        ok = r.returncode == 0 and (not exp or got == exp)
        check(ok, "%s: `%s` runs and prints what is shown" % (where, cmd[:60]),
              r.stderr + "\n--- got:\n" + "\n".join(got) + "\n--- shown:\n" + "\n".join(exp))


def main():
    docs = [os.path.join(ROOT, "README.md")] + sorted(
        os.path.join(ROOT, "docs", f) for f in os.listdir(os.path.join(ROOT, "docs")) if f.endswith(".md"))
    work = tempfile.mkdtemp(prefix="doc-commands.")
    try:
        for doc in docs:
            rel = os.path.relpath(doc, ROOT)
            # each file in its own scratch folder: a page's blocks build on each other, in order
            cwd = os.path.join(work, rel.replace("/", "_"))
            os.mkdir(cwd)
            for e in os.listdir(ROOT):
                if not e.startswith("."):
                    os.symlink(os.path.join(ROOT, e), os.path.join(cwd, e))
            for first, lang, marker, lines in blocks(doc):
                where = "%s:%d" % (rel, first)
                if lang == "sh" and marker in ("hardware", "no-run"):
                    for line in logical_lines(lines):
                        for words in simple_commands(line):
                            exists_check(words, where)
                elif lang == "sh" and not marker:
                    run_block(lines, where, cwd)
                elif lang == "console":
                    run_console(lines, where, cwd)
                elif lang not in ("text", "sh", "console"):
                    check(False, "%s: block kind %r is one of sh, console, text" % (where, lang))
                elif marker:
                    check(False, "%s: marker %r is one of hardware, no-run" % (where, marker))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("RESULT: %d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
