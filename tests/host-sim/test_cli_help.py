#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim's command line as a whole (host-sim/cli_args.c and the option
tables of every subcommand), both numeric builds:

  - every command of squeal_sim.c's table is listed by `squeal-sim --help`;
  - `squeal-sim CMD --help` (and -h) exits 0, prints "usage: squeal-sim CMD"
    and a description on stdout, nothing on stderr, and leaves the working
    directory as it was (no side effects);
  - every option the command's parser accepts is listed in that help with a
    description: the list of options is read from the option tables in
    host-sim/ (the CLI_OPT_*("name", ...) rows of the table that the
    command's cli_spec_t names with CLI_SPEC_OPTS), not written here by hand;
  - an option a table does not have is one line "squeal-sim CMD: ..." on
    stderr and exit 2;
  - `squeal-sim --version` prints the version written in
    host-sim/sim_version.h and the numeric build.
Prints "RESULT: N passed, M failed". Run from the repository root.
"""
import glob
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "support"))
from sim_cli import ROOT, Results, run  # noqa: E402

result = Results()


def strip_comments(text):
    return re.sub(r"/\*.*?\*/", "", text, flags=re.S)


def commands_of_main():
    """The subcommands of squeal_sim.c's table: { "name", function, "summary" }."""
    text = strip_comments(open(os.path.join(ROOT, "host-sim", "squeal_sim.c")).read())
    table = re.search(r"commands\[\]\s*=\s*\{(.*?)\n\};", text, re.S).group(1)
    return re.findall(r'\{\s*"([a-z-]+)",\s*\w+,', table)


def option_tables():
    """{command: [(name, letter)]} from every cli_spec_t in host-sim/."""
    found = {}
    for path in glob.glob(os.path.join(ROOT, "host-sim", "**", "*.c"), recursive=True):
        text = strip_comments(open(path).read())
        tables = []  # (position, name, rows): a spec names the table above it
        for m in re.finditer(r"cli_opt_t\s+(\w+)\[\]\s*=\s*\{(.*?)\n\s*\};", text, re.S):
            rows = re.findall(r'CLI_OPT_(\w+)\(\s*"([a-z0-9-]+)"\s*,\s*([^,]*)', m.group(2))
            tables.append((m.start(), m.group(1),
                           [(name, letter.strip() if kind == "FLAG" else "0")
                            for kind, name, letter in rows]))
        for m in re.finditer(r"cli_spec_t\s+spec\s*=\s*\{(.*?)\n\s*\};", text, re.S):
            body = m.group(1)
            cmd = re.search(r'\.cmd\s*=\s*"([a-z-]+)"', body).group(1)
            opts = re.search(r"CLI_SPEC_OPTS\((\w+)\)", body)
            above = [t for t in tables if opts is not None and t[0] < m.start() and
                     t[1] == opts.group(1)]
            found[cmd] = above[-1][2] if above else []
    return found


def check_build(build, sim, commands, tables):
    rc, out, err = run([sim, "--help"], ROOT)
    for cmd in commands:
        result(rc == 0 and re.search(r"^  %s " % re.escape(cmd), out, re.M) is not None,
               "%s: squeal-sim --help lists %s" % (build, cmd))
    for cmd in commands:
        result(cmd in tables, "%s: %s has an option table (cli_spec_t)" % (build, cmd))
        options = tables.get(cmd, [])
        for flag in ("--help", "-h"):
            with tempfile.TemporaryDirectory() as cwd:
                rc, out, err = run([sim, cmd, flag], cwd)
                left = os.listdir(cwd)
            result(rc == 0 and out.startswith("usage: squeal-sim " + cmd) and err == "" and
                   left == [],
                   "%s: %s %s: exit 0, usage on stdout, nothing on stderr, no files: rc %d, "
                   "stderr %r, files %r" % (build, cmd, flag, rc, err[:200], left))
        paragraphs = out.split("\n\n")
        result(len(paragraphs) >= 3 and len(paragraphs[1].strip()) > 40,
               "%s: %s --help has a description" % (build, cmd))
        for name, letter in options:
            line = re.search(r"^  (?:-\w, )?--%s\b.*$" % re.escape(name), out, re.M)
            described = line is not None and len(line.group(0).split()) >= 3
            result(described, "%s: %s --help lists --%s with a description" % (build, cmd, name))
            if letter not in ("0", "'\\0'"):
                result(re.search(r"^  -%s, --%s\b" % (letter.strip("'"), re.escape(name)), out,
                                 re.M) is not None,
                       "%s: %s --help names -%s" % (build, cmd, letter.strip("'")))
        rc, out, err = run([sim, cmd, "--no-such-option"], ROOT)
        lines = [l for l in err.splitlines() if l.strip()]
        result(rc == 2 and len(lines) == 1 and lines[0].startswith("squeal-sim %s: " % cmd),
               "%s: %s --no-such-option: one line, exit 2: rc %d, %r" % (build, cmd, rc, err))
    header = open(os.path.join(ROOT, "host-sim", "sim_version.h")).read()
    version = re.search(r'#define SQUEAL_SIM_VERSION "([^"]+)"', header).group(1)
    rc, out, err = run([sim, "--version"], ROOT)
    result(rc == 0 and err == "" and
           out == "squeal-sim %s (numeric build: %s)\n" % (version, build),
           "%s: --version: %r" % (build, out))


def main():
    commands = commands_of_main()
    tables = option_tables()
    result(len(commands) >= 9, "squeal_sim.c's command table read (%d commands)" % len(commands))
    result(sum(len(v) for v in tables.values()) >= 60,
           "option tables read (%d options)" % sum(len(v) for v in tables.values()))
    result.each_build(lambda build, sim: check_build(build, sim, commands, tables))
    return result.finish()


if __name__ == "__main__":
    sys.exit(main())
