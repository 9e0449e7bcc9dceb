# SPDX-License-Identifier: MIT
"""What a complete --help is, checked on a program's output (tests of tools/ and host-sim/).

run_help() runs a command in an empty scratch folder and says what it wrote
there; the other functions read the text:
  - description(): the first paragraph after the usage, which must end a
    sentence (no description cut mid-way);
  - undocumented_options(): option entries of the option lists without a
    help text (argparse prints "  --opt X" alone then).
"""
import os
import re
import subprocess
import tempfile

SENTENCE_END = (".", ":", ")", "!", "?")
# an option-list entry: "-o FILE, --output FILE", "--flag", "DATA.csv", "{a,b}"
_OPT = r"-{1,2}[\w-]+(?:[ =][^\s,]+)?"
ENTRY = re.compile(r"(?:%s)(?:, %s)*|[\w.{},|()\[\]-]+" % (_OPT, _OPT))


def run_help(cmd, timeout_s=60):
    """(exit status, stdout+stderr, files written to the working folder)."""
    with tempfile.TemporaryDirectory(prefix="help.") as tmp:
        try:
            r = subprocess.run(cmd, cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               timeout=timeout_s, stdin=subprocess.DEVNULL)
            rc, out = r.returncode, r.stdout
        except subprocess.TimeoutExpired as e:
            rc, out = "timeout", (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) \
                else (e.stdout or "")
        written = sorted(os.listdir(tmp))
    return rc, out, written


def usage_lines(text):
    lines = text.splitlines()
    out = []
    for i, line in enumerate(lines):
        if line.startswith("usage:") or (out and line.startswith(" ") and i == len(out)):
            out.append(line)
        elif out:
            break
    return out


def description(text):
    """The first paragraph after the usage block."""
    rest = text.splitlines()[len(usage_lines(text)):]
    para = []
    for line in rest:
        if line.strip():
            para.append(line.strip())
        elif para:
            break
    return " ".join(para)


def first_sentence_complete(text):
    d = description(text)
    return bool(d) and not d.startswith("-") and d.endswith(SENTENCE_END)


def undocumented_options(text):
    """Option entries (two-space indent, starting with - or a name) that have no help text."""
    lines = text.splitlines()
    out = []
    in_list = False
    for i, line in enumerate(lines):
        if re.match(r"^[A-Za-z].*:$", line) and not line.startswith("usage:"):
            in_list = True
            continue
        if not line.strip():
            in_list = False if i + 1 < len(lines) and not lines[i + 1].startswith("  ") else in_list
            continue
        if not in_list:
            continue
        m = re.match(r"^  (\S.*?)(?:\s{2,}(\S.*))?$", line)
        if not m or line.startswith("   "):
            continue
        entry, help_text = m.group(1), m.group(2)
        if not ENTRY.fullmatch(entry):
            continue  # prose of an epilog, not an option entry
        if help_text:
            continue
        nxt = lines[i + 1] if i + 1 < len(lines) else ""
        indent = len(nxt) - len(nxt.lstrip())
        if nxt.strip() and indent > 2:
            continue
        out.append(entry)
    return out
