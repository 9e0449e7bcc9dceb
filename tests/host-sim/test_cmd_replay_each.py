#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim replay --each LOG... (host-sim/cmd_replay.c): every log is
replayed from a reset ECU, as a run of its own would replay it. Both
numeric builds; the reference is one `replay LOG` run per log:
  - on every log of tests/support/replay_logs.py (scenarios, the sender's
    faults, holes, gaps, vehicle layouts, a vehicle bus), grouped by their
    replay options, with broken logs put between them: an empty file, one
    of only garbage lines, one with malformed lines among its frames, one
    that is not there. A log without frames after a replayed one must not
    report the last log's counters;
  - the documents on --summary-json, one per line in the order of the
    logs, are the single runs' documents plus the log's exit_status and
    error (the single run's exit status and its last failure line on
    stderr, "" for none); first_malformed names the first bad line;
  - stderr is the single runs' stderr one after the other, the exit status
    the worst of theirs; the same documents go to a file;
  - refused with exit 2: several logs without --each, --each without
    --summary-json or without --no-output;
  - the sanitizer builds (ASan + UBSan) on three logs with broken ones
    between them.
Prints "RESULT: N passed, M failed". Run from the repository root."""
import json
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
from sim_cli import SAN_SIMS, Results, run  # noqa: E402
from replay_logs import logs  # noqa: E402

result = Results()
EACH_OUT = ["--no-output", "--summary-json", "-"]


def broken(tmp):
    """Logs that cannot be read, have no frame, or have malformed lines."""
    made = []

    def write(name, text):
        path = os.path.join(tmp, name)
        with open(path, "w") as f:
            f.write(text)
        made.append(path)

    write("empty.log", "")
    write("garbage.log", "not a candump line\n\x01\x02\n")
    good = "".join("(1700000000.%06d) vcan0 110#%02X00161300\n" % (i * 10000, i) for i in range(40))
    write("malformed.log", good + "(1700000001.000000) vcan0 110#ZZ\n" + "junk\n" + good.replace(
        "(1700000000.", "(1700000001."))
    made.append(os.path.join(tmp, "not-there.log"))
    return made


def interleave(paths, bad):
    """paths with a broken log after each of the first ones."""
    out = []
    for i, path in enumerate(paths):
        out += [path] + bad[i:i + 1]
    return out


def single(sim, log, opts):
    rc, out, err = run([sim, "replay", log] + opts + EACH_OUT)
    doc = json.loads(out) if out.strip() else None
    fails = [ln for ln in err.splitlines() if ln.startswith("squeal-sim replay:") or ": no CAN frame in " in ln]
    return rc, doc, err, (fails[-1] if (rc != 0 and fails) else "")


def check_group(build, sim, tmp, opts, paths):
    rc, out, err = run([sim, "replay", "--each"] + paths + opts + EACH_OUT)
    docs = [json.loads(ln) for ln in out.splitlines()]
    result(len(docs) == len(paths), "%s %s: one document per log (%d for %d)"
           % (build, opts, len(docs), len(paths)))
    want_err, want_rc = "", 0
    for path, doc in zip(paths, docs):
        name = os.path.basename(path)
        one_rc, one_doc, one_err, one_fail = single(sim, path, opts)
        want_err += one_err
        want_rc = max(want_rc, one_rc)
        status, error = doc.pop("exit_status", None), doc.pop("error", None)
        result(status == one_rc and error == one_fail,
               "%s %s: exit_status %r and error %r as the run alone gives (%d, %r)"
               % (build, name, status, error, one_rc, one_fail))
        if one_doc is None:
            result(doc == {"format": "squeal-replay-summary", "version": 1, "log": path, "started": False},
                   "%s %s: a log that cannot be opened: what is known of it (%r)" % (build, name, doc))
        else:
            result(doc == one_doc, "%s %s: the document of the run alone" % (build, name))
    result(err == want_err, "%s %s: stderr is the single runs' one after the other" % (build, opts))
    result(rc == want_rc, "%s %s: exit status %d, the worst of the logs' (%d)" % (build, opts, rc, want_rc))
    return docs


def check_build(build, sim):
    with tempfile.TemporaryDirectory() as tmp:
        bad = broken(tmp)
        groups = {}
        for _, path, opts in logs(sim, tmp, result):
            groups.setdefault(tuple(opts), []).append(path)
        for opts, paths in groups.items():
            check_group(build, sim, tmp, list(opts), interleave(paths, bad))
        # the first bad line, by line, column and error text
        docs = check_group(build, sim, tmp, [], bad)
        mal = docs[2]["first_malformed"]
        # column 31: the first byte of "ZZ" after "(1700000001.000000) vcan0 110#"
        result(mal == {"line": 41, "column": 31, "error": mal["error"]} and mal["error"]
               and docs[2]["lines"]["malformed"] == 2,
               "%s: first_malformed is line 41, column 31, with its reason (%r)" % (build, mal))
        result(docs[0]["first_malformed"] is None and docs[0]["lines"]["total"] == 0
               and docs[1]["first_malformed"]["line"] == 1,
               "%s: no bad line in an empty log, line 1 of the garbage" % build)
        # to a file: the same lines
        js = os.path.join(tmp, "each.jsonl")
        rc, _, _ = run([sim, "replay", "--each"] + bad[:3] + ["--no-output", "--summary-json", js])
        _, out, _ = run([sim, "replay", "--each"] + bad[:3] + EACH_OUT)
        with open(js) as f:
            result(rc == 1 and f.read() == out, "%s: --summary-json FILE holds the same lines" % build)
        for argv, what in (([bad[0], bad[1]] + EACH_OUT, "two logs without --each"),
                           (["--each", bad[0], "--no-output"], "--each without --summary-json"),
                           (["--each", bad[0], "--summary-json", js], "--each without --no-output")):
            rc, out, err = run([sim, "replay"] + argv)
            result(rc == 2 and out == "" and "squeal-sim replay:" in err,
                   "%s: %s refused, exit 2 (%d %r)" % (build, what, rc, err[:120]))


def check_sanitized(build, sim):
    """ASan + UBSan: one ECU's state handed from log to log, broken logs between."""
    with tempfile.TemporaryDirectory() as tmp:
        good = [p for _, p, opts in logs(sim, tmp, result) if not opts][:3]
        check_group(build + " (ASan+UBSan)", sim, tmp, [], interleave(good, broken(tmp)))


result.each_build(check_build)
for b, s in SAN_SIMS.items():
    check_sanitized(b, s)
sys.exit(result.finish())
