#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Fleet analysis: replay many candump logs in parallel on Dask and report where and when the brakes ran bistable or unstable.

usage: fleet.py (LOG... | --dir DIR) [--calib FILE] [--scheduler ADDRESS]
                [-o REPORT_DIR] [--workers N] [--sim PATH] [--timeout S]

Each task replays its logs with one `squeal-sim replay --each LOG...
--no-output --summary-json -` (every log from a reset ECU, as a run of its
own; one JSON document per log, as the C side defines it in
host-sim/replay_summary.h). Tasks are sized by work, the bytes of their
logs: several short logs make one task, so that a task's cost is the
replays' and not the scheduler's or a process start per log; a log longer
than a task's share is a task of its own. On a terminal, a progress line
(logs done / total, time left) is kept up to date on stderr.
Without --scheduler a LocalCluster runs --workers replays at a time on this
machine (default: the number of CPUs), as worker threads of this process
up to 4 and as worker processes of up to 4 threads beyond; with
--scheduler tcp://HOST:PORT the same tasks go to an existing cluster
(`dask scheduler`, `dask worker`), one replay at a time per worker thread,
whose workers must see the logs and squeal-sim at the same paths.

A log that cannot be read, is malformed or whose replay fails is listed in
the report with its reason; it never stops the run. The report (-o, default
build/fleet-report):
  state_time.csv   time in each state per log and corner (and ALL rows)
  episodes.csv     every episode: log, corner, state, start/end, warning,
                   v0 and force range, lowest Hopf margin
  cells.csv        time per (v0, force) cell, state and corner (all logs)
  problems.csv     logs that failed or had malformed lines, with the reason
  heatmap.png/.svg the time in each (v0, N) cell, coloured by the state the
                   monitor reported, over the brake's stability borders
  index.html       all of the above on one page
  fleet.json       counts, the speed (logs/s) and the times: job_s (first
                   task submitted to last result), wall_s (with the
                   cluster's start-up), own_cpu_s (this process's CPU in the job)
The borders are the closed forms of docs/model.md computed with scipy
(tools/plots/plotlib.py), each corner's panel for that corner's brake in
--calib (its [corner POS] keys over the flat ones; default: the paper's).
Each corner's frames are found by the identifiers of the calibration
(replay_summary.h), also when they are not the defaults + 0x10 k.
Exit status: 0 report written (also with failed logs), 1 no report, 2 usage.
"""
import csv
import glob
import html
import json
import os
import resource
import stat
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import drive_common as DC  # noqa: E402
import helptext  # noqa: E402

P = DC.P


# ---- the task (runs on a worker; pickled by value with this script) -------

def replay_command(sim):
    """`squeal-sim replay` execs squeal-replay from its own folder: run
    that program directly when it is there (one process start per log less)."""
    direct = os.path.join(os.path.dirname(sim), "squeal-replay")
    if os.path.basename(sim) == "squeal-sim" and os.access(direct, os.X_OK):
        return [direct]
    return [sim, "replay"]


def outcome(log, doc):
    """The result of one log from its --each document; never raises."""
    res = {"log": log, "status": "ok", "reason": "", "summary": doc}
    bad = doc.get("first_malformed")
    first = ""
    if bad:
        first = "%s:%d: %s%s" % (log, bad["line"], bad["error"],
                                 " (column %d)" % bad["column"] if bad["column"] else "")
    if doc.get("exit_status", 1) != 0 or not doc.get("started"):
        why = doc.get("error") or "exit status %s" % doc.get("exit_status")
        res.update(status="failed", reason=why + ("; first malformed line: " + first if first else ""))
    elif doc["lines"]["malformed"] > 0:
        res.update(status="partial", reason="%d malformed lines skipped (first: %s)"
                   % (doc["lines"]["malformed"], first))
    return res


def each_command(logs, sim, calib=None):
    """The command line of one `replay --each` over the logs: every log
    from a reset ECU, a JSON document per log on stdout, no frames."""
    cmd = (replay_command(sim) + ["--each"] + logs +
           ["--no-output", "--quiet", "--summary-json", "-"])
    return cmd + ["--calib", calib] if calib else cmd


def replay_each(logs, sim, calib, timeout_s):
    """One `replay --each` process for the logs: ({log: document} of the
    logs it finished, why it stopped before the others, the bytes of those
    documents' text). The reason is read
    from its stderr only for a single log: there every log writes its text
    summary, which its document holds too, and a pipe to this thread would
    wake it for each (replay_batch replays a log that a process of several
    did not finish on its own, and takes the reason from that run)."""
    cmd = each_command(logs, sim, calib)
    keep_err = subprocess.PIPE if len(logs) == 1 else subprocess.DEVNULL
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=keep_err,
                           timeout=timeout_s * len(logs))
        out, err, why = p.stdout, p.stderr, "exit status %d" % p.returncode
    except subprocess.TimeoutExpired as e:
        out, err, why = e.stdout or b"", e.stderr, "replay took longer than %g s" % timeout_s
    except OSError as e:
        return {}, "cannot run %s: %s" % (sim, e.strerror), 0
    docs, nbytes = {}, 0
    for log, line in zip(logs, out.decode("utf-8", "replace").splitlines()):
        try:
            docs[log] = json.loads(line)  # one line per log, in their order
        except ValueError:
            break  # cut short by a crash or the time-out
        nbytes += len(line)
    last = [ln for ln in (err or b"").decode("utf-8", "replace").splitlines()
            if ln.startswith("squeal-sim")]
    return docs, (last[-1] if last else why), nbytes


def add_cells(acc, summary):
    """Adds one log's time per (v0, N) cell and state to acc ({corner:
    {(i, j, state): seconds}}); returns the document's grid."""
    for c in summary["corners"]:
        into = acc.setdefault(c["corner"], {})
        for i, j, s, sec in c["cells"]:
            into[(i, j, s)] = into.get((i, j, s), 0.0) + float(sec)
    return summary["cells_grid"]


def merge_cells(acc, part):
    """Adds one task's cells ({corner: {(i, j, state): seconds}}) to acc."""
    for corner, cells in part.items():
        into = acc.setdefault(corner, {})
        for key, sec in cells.items():
            into[key] = into.get(key, 0.0) + sec


def report_part(summary):
    """What the report reads of a log's document besides its cells: the
    time in each state per corner and the episodes (the rest, a few
    kilobytes per log, is not sent back from the worker)."""
    return {"corners": [{"corner": c["corner"], "state_time_s": c["state_time_s"]}
                        for c in summary["corners"]],
            "episodes": summary["episodes"]}


class TaskResult:
    """What one task sends back: .results (a result per log, in order),
    .cells (the logs' cells added up, add_cells) and .grid. The cells are
    most of a document, and adding them up on the worker sends the client a
    task's worth instead of a log's worth each.
    Dask weighs every task's result with dask.sizeof for its memory
    accounting. A dict or list is weighed by walking it: lists of all its
    keys and values, then a sample of them, recursively; for these results,
    up to a thousand cells and a summary per log, that took 0.5-2 ms per
    task: 15 ms of a job of 200 short logs on two workers, CPU taken from
    the replays on a machine of two CPUs. Any other object is weighed by its
    __sizeof__, here the bytes of the JSON documents it was read from, a
    fair measure of its size that costs nothing (this process's CPU in that
    job: 0.103 -> 0.087 s, medians of 10 runs)."""
    __slots__ = ("results", "cells", "grid", "nbytes")

    def __init__(self, results, cells, grid, nbytes):
        self.results, self.cells, self.grid, self.nbytes = results, cells, grid, nbytes

    def __sizeof__(self):
        return self.nbytes


def replay_batch(logs, sim, calib, timeout_s):
    """One task: its logs in one replay process (a process start per log
    would cost more than the replay of a short log). Logs that process did
    not finish (it crashed or took too long) are replayed one by one, so
    that only the log at fault is failed, with the reason of its own run.
    Returns a TaskResult."""
    docs, why, nbytes = replay_each(logs, sim, calib, timeout_s)
    out, cells, grid = [], {}, None
    for log in logs:
        if log not in docs and len(logs) > 1:
            alone, why, more = replay_each([log], sim, calib, timeout_s)
            docs.update(alone)
            nbytes += more
        if log not in docs:
            out.append({"log": log, "status": "failed", "reason": why, "summary": None})
            continue
        res = outcome(log, docs[log])
        if res["status"] != "failed":
            grid = add_cells(cells, res["summary"])
            res["summary"] = report_part(res["summary"])
        out.append(res)
    return TaskResult(out, cells, grid, nbytes)


def ready(_):
    """The no-op task that starts a cluster's workers up (run_tasks)."""
    return None


# ---- running it ------------------------------------------------------------

# Guided scheduling: each task takes 1/(GUIDE x workers) of the work not yet
# handed out, so the first tasks are large (few process starts and round
# trips) and the last ones small (the workers finish together); no task is
# below 1/(MIN_TASKS_PER_WORKER x workers) of the whole.
GUIDE = 2
MIN_TASKS_PER_WORKER = 16


def log_bytes(path):
    """The size of a regular file (one stat), 0 for anything else."""
    try:
        st = os.stat(path)
    except OSError:
        return 0
    return st.st_size if stat.S_ISREG(st.st_mode) else 0


def log_work(path):
    """A log's work in bytes: its size, and at least one line's worth (an
    empty or unreadable log still costs a replay's start)."""
    return max(log_bytes(path), 64)


def works(logs):
    """{log: log_work(log)}: each log stat-ed once for the tasks and the
    progress line (run_tasks)."""
    return {log: log_work(log) for log in logs}


def batches(logs, nworkers, work_of=None):
    """The logs in tasks by work (bytes, each log at least one line's worth),
    the largest logs first, each task its guided share of the work left
    (GUIDE, MIN_TASKS_PER_WORKER): with equal tasks the last one would let
    one worker run alone for up to a task's time (8 % of a fleet of 10-minute
    drives on two workers). work_of: works(logs), when already known."""
    size = work_of if work_of is not None else works(logs)
    workers = float(max(1, nworkers))
    left = float(sum(size.values()))
    floor = left / (workers * MIN_TASKS_PER_WORKER)
    out, cur, work = [], [], 0
    for log in sorted(logs, key=lambda x: (-size[x], x)):
        cur.append(log)
        work += size[log]
        if work >= max(left / (GUIDE * workers), floor):
            out.append(cur)
            left -= work
            cur, work = [], 0
    if cur:
        out.append(cur)
    return out


class Progress:
    """'fleet: 37/200 logs, 2.1 s left' on a terminal (stderr), nothing
    otherwise; the time left from the bytes still to replay (work_of:
    works(logs), when already known)."""

    def __init__(self, logs, stream=sys.stderr, work_of=None):
        self.on = stream.isatty()
        self.stream = stream
        self.total = len(logs)
        self.work_of = work_of if work_of is not None else works(logs)
        self.work = float(sum(self.work_of.values()))
        self.done = 0
        self.done_work = 0.0
        self.t0 = time.monotonic()

    def update(self, logs):
        self.done += len(logs)
        self.done_work += sum(self.work_of.get(x, 0) for x in logs)
        if not self.on:
            return
        dt = time.monotonic() - self.t0
        left = dt * (self.work - self.done_work) / self.done_work if self.done_work > 0 else 0.0
        self.stream.write("\rfleet: %d/%d logs, %.1f s left   " % (self.done, self.total, left))
        self.stream.flush()

    def close(self):
        if self.on:
            self.stream.write("\r%s\r" % (" " * 40))
            self.stream.flush()


THREADS_PER_PROCESS = 4  # replays one worker process runs at a time


def local_layout(replays):
    """(worker processes, threads each) of a LocalCluster that runs
    `replays` replays at a time. A task's thread only waits for its replay
    process, then reads its documents (about a tenth of a log's cost,
    holding the interpreter), so up to THREADS_PER_PROCESS threads share
    one process; up to that many, the workers are threads of this very
    process, so that no result is pickled and no process but the replays
    competes for the CPUs (on two CPUs, two worker processes made a job
    of 200 short logs a tenth to a fifth slower than two threads)."""
    procs = -(-replays // THREADS_PER_PROCESS)
    return procs, -(-replays // procs)


# The LocalCluster's workers are threads of this process, beside its
# scheduler and client, and on a machine of few CPUs every bit of their
# background work is taken from the replays. No dashboard is served, so the
# workers' statistical profiler (every thread's stack every 10 ms, for the
# dashboard's profile page) has no reader, and the health ticks and system
# and memory monitors need not run 50 times a second on a job of seconds.
# On 200 short logs this process's own CPU time during the job went from
# about 0.17 s to 0.10 s (1 worker) and 0.13 s (2 workers); the replays'
# is 0.7 s.
QUIET_DASK = {"distributed.worker.profile.enabled": False,
              "distributed.admin.tick.interval": "1s",
              "distributed.admin.system-monitor.interval": "1s",
              "distributed.worker.memory.monitor-interval": "1s"}

# With one worker process there is no choice of where a task runs: no
# other worker to steal tasks from, and the scheduler hands that worker
# every task at once (they keep their submission order, the largest first)
# instead of at most 1.1 per thread. A thread that finishes a task then
# starts the next from the worker's own queue, instead of after a round trip
# to the scheduler through the event loop that all of this process's
# threads share: 2-9 ms between a task and the next before, 1-4 ms now.
ONE_PROCESS_DASK = {"distributed.scheduler.work-stealing": False,
                    "distributed.scheduler.worker-saturation": float("inf")}


def cpu_s():
    """CPU seconds (user + sys) of this process so far, its threads included."""
    ru = resource.getrusage(resource.RUSAGE_SELF)
    return ru.ru_utime + ru.ru_stime


def run_tasks(logs, args):
    """Same code path for a LocalCluster and an existing scheduler."""
    import dask
    from dask.distributed import Client, LocalCluster, as_completed
    cluster = None
    t_start = time.monotonic()
    if args.scheduler:
        client = Client(args.scheduler, timeout="30s")
        where = "cluster at %s" % args.scheduler
    else:
        procs, threads = local_layout(args.workers)
        opts = {"host": "127.0.0.1"} if procs > 1 else {}
        dask.config.set(QUIET_DASK)
        if procs == 1:
            dask.config.set(ONE_PROCESS_DASK)
        cluster = LocalCluster(n_workers=procs, threads_per_worker=threads, processes=procs > 1,
                               dashboard_address=None, **opts)
        client = Client(cluster)
        where = "LocalCluster, %d worker process%s x %d thread%s" % (
            procs, "" if procs == 1 else "es", threads, "" if threads == 1 else "s")
    try:
        # a replay at a time per worker thread (a task is one replay process)
        nworkers = sum(w.get("nthreads", 1) for w in client.scheduler_info().get("workers", {}).values())
        # The cluster's first task sets up what Dask makes on first use (the
        # workers' thread pools, the function's serialisation): 10-30 ms,
        # a tenth of a job of 200 short logs on two workers. It is start-up
        # (wall_s), not the job's (job_s).
        client.gather(client.map(ready, range(max(nworkers, 1)), pure=False))
        t_submit, cpu_submit = time.monotonic(), cpu_s()
        work_of = works(logs)
        tasks = batches(logs, nworkers, work_of)
        futures = client.map(replay_batch, tasks, sim=args.sim, calib=args.calib,
                             timeout_s=args.timeout, pure=False)
        task_of = {fut.key: batch for fut, batch in zip(futures, tasks)}
        progress = Progress(logs, work_of=work_of)
        results, cells, grid = [], {}, None
        for fut in as_completed(futures):
            batch = task_of[fut.key]
            try:
                part = fut.result()
                results.extend(part.results)
                merge_cells(cells, part.cells)
                grid = part.grid or grid
            except Exception as e:  # a worker died: still listed logs
                results.extend({"log": log, "status": "failed", "summary": None,
                                "reason": "task failed: %s" % (str(e) or type(e).__name__)}
                               for log in batch)
            progress.update(batch)
        progress.close()
        t_done, cpu_done = time.monotonic(), cpu_s()
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    timing = {"where": where, "workers": nworkers, "tasks": len(tasks), "job_s": t_done - t_submit,
              "own_cpu_s": cpu_done - cpu_submit,
              "wall_s": time.monotonic() - t_start}
    return sorted(results, key=lambda r: r["log"]), cells, grid, timing


# ---- the report ------------------------------------------------------------

def fnum(x):
    return "" if x is None else repr(x) if isinstance(x, float) else str(x)


def write_csvs(out, results):
    ok = [r for r in results if r["status"] != "failed"]
    totals = {}
    with open(os.path.join(out, "state_time.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["log", "corner"] + ["%s_s" % s for s in DC.STATES] + ["total_s"])
        for r in ok:
            for c in r["summary"]["corners"]:
                row = [float(c["state_time_s"][s]) for s in DC.STATES]
                w.writerow([r["log"], c["corner"]] + ["%.6f" % x for x in row] + ["%.6f" % sum(row)])
                acc = totals.setdefault(c["corner"], [0.0] * len(DC.STATES))
                for i, x in enumerate(row):
                    acc[i] += x
        for corner in DC.CORNERS:
            if corner in totals:
                row = totals[corner]
                w.writerow(["ALL", corner] + ["%.6f" % x for x in row] + ["%.6f" % sum(row)])
    keys = ["corner", "state", "start_s", "end_s", "warning_level", "v0_min_mps", "v0_max_mps",
            "force_min_n", "force_max_n", "min_hopf_margin_mps"]
    n_ep = 0
    with open(os.path.join(out, "episodes.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["log"] + keys[:4] + ["duration_s"] + keys[4:])
        for r in ok:
            for e in r["summary"]["episodes"]:
                w.writerow([r["log"]] + [fnum(e[k]) for k in keys[:4]] +
                           ["%.6f" % (e["end_s"] - e["start_s"])] + [fnum(e[k]) for k in keys[4:]])
                n_ep += 1
    with open(os.path.join(out, "problems.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["log", "status", "reason"])
        for r in results:
            if r["status"] != "ok":
                w.writerow([r["log"], r["status"], r["reason"]])
    return totals, n_ep


def write_cells(out, cells, grid):
    with open(os.path.join(out, "cells.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["corner", "v0_lo_mps", "v0_hi_mps", "force_lo_n", "force_hi_n", "state", "time_s"])
        if grid is None:
            return
        dv, dn = float(grid["v0_bin_mps"]), float(grid["force_bin_n"])
        for corner in DC.CORNERS:
            for (i, j, s), sec in sorted(cells.get(corner, {}).items()):
                w.writerow([corner, "%.2f" % (i * dv), "%.2f" % ((i + 1) * dv), "%g" % (j * dn),
                            "%g" % ((j + 1) * dn), s, "%.6f" % sec])


HEAT_ALPHA0 = 0.35   # opacity of the shortest time in a cell (one status period: about 0.7)


def heat_level(seconds):
    """A cell's time on the opacity scale: log(1 + t / 10 ms)."""
    return P.np.log1p(P.np.asarray(seconds, dtype=float) / 0.01)


def heat_rgba(cells, grid):
    """RGBA image (force rows x v0 columns): each cell in the colour of the
    state the monitor reported longest there, opacity growing with log(time)."""
    from matplotlib.colors import to_rgb
    np = P.np
    nv, nf = int(grid["v0_bins"]), int(grid["force_bins"])
    per = np.zeros((len(DC.STATES), nf, nv))
    for (i, j, s), sec in cells.items():
        per[DC.STATES.index(s), j, i] += sec
    total = per.sum(axis=0)
    img = np.zeros((nf, nv, 4))
    if total.max() <= 0:
        return img, total
    dom = per.argmax(axis=0)
    lt = heat_level(total)
    for k, s in enumerate(DC.STATES):
        img[dom == k, :3] = to_rgb(P.PATH_COLORS[s])
    img[..., 3] = np.where(total > 0, HEAT_ALPHA0 + (1 - HEAT_ALPHA0) * lt / lt.max(), 0.0)
    return img, total


def heat_key(fig, ax, t_max):
    """The colour key of a panel: opacity against the time in a cell (the
    hue is the state, in the legend)."""
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import FuncNorm, LinearSegmentedColormap
    grey = P.np.array([0.25, 0.25, 0.25])
    ramp = [tuple(a * grey + (1 - a)) for a in P.np.linspace(HEAT_ALPHA0, 1.0, 64)]
    norm = FuncNorm((heat_level, lambda y: 0.01 * P.np.expm1(y)), vmin=0.0, vmax=t_max)
    cb = fig.colorbar(ScalarMappable(norm, LinearSegmentedColormap.from_list("heat", ramp)),
                      ax=ax, fraction=0.045, pad=0.02)
    ticks = [t for t in (0.01, 0.1, 1.0, 10.0, 100.0, 1000.0, 10000.0) if t <= t_max]
    if not ticks or t_max > 2.0 * ticks[-1]:
        ticks.append(float("%.2g" % t_max))   # the longest cell
    cb.set_ticks(ticks)
    cb.set_ticklabels(["%g" % t for t in ticks])
    cb.set_label("time in the cell [s] (more opaque: longer)", fontsize=8)
    return cb


def heat_figure(cells, grid, setups, title, totals=None):
    """The heat map: a panel per corner over the map of its own brake
    (setups: {corner name: DC.Corner}), each with its colour key; totals
    ({corner: seconds per state}, the report's table) name the time the
    cells cannot hold (no v0 or N reported yet). Returns (figure, {corner: axes})."""
    plt = P.plt
    corners = [c for c in DC.CORNERS if c in cells] or [min(setups, key=DC.CORNERS.index)]
    ncols = min(len(corners), 2)
    nrows = (len(corners) + 1) // 2
    fig, axes = plt.subplots(nrows, ncols, figsize=(9.4 * ncols + 2.6, 5.8 * nrows), squeeze=False)
    for ax in axes.flat[len(corners):]:
        ax.set_visible(False)
    panels = {}
    for n, (ax, corner) in enumerate(zip(axes.flat, corners)):
        panels[corner] = ax
        p, criterion = setups[corner].brake, setups[corner].criterion
        if grid is None:
            DC.draw_map(ax, p, 16.0, 32000.0, criterion, legend=False)
            ax.set_title("%s: no readable logs" % corner, fontsize=10)
            continue
        dv, dn = float(grid["v0_bin_mps"]), float(grid["force_bin_n"])
        img, total = heat_rgba(cells.get(corner, {}), grid)
        used = P.np.argwhere(total > 0)
        v_max = max(2.0, (used[:, 1].max() + 2) * dv) if len(used) else 4.0
        n_max = max(4000.0, (used[:, 0].max() + 2) * dn) if len(used) else 20000.0
        DC.draw_map(ax, p, v_max, n_max, criterion, legend=False, alpha=0.35)
        ax.imshow(img, origin="lower", aspect="auto", interpolation="nearest",
                  extent=(0, grid["v0_bins"] * dv, 0, grid["force_bins"] * dn / 1000.0), zorder=3)
        ax.set_xlim(0, v_max)
        ax.set_ylim(0, n_max / 1000.0)
        in_cells = float(total.sum())
        head = "%s: %.1f s in %d cells of %.1f m/s x %g N" % (corner, in_cells, len(used), dv, dn)
        if totals is not None and corner in totals:
            reported = float(sum(totals[corner]))
            head = ("%s: %.1f s reported (the table's total); %.1f s of it in %d cells of "
                    "%.1f m/s x %g N,\n%.1f s without a reported v0 or N (not drawn)" %
                    (corner, reported, in_cells, len(used), dv, dn, max(reported - in_cells, 0.0)))
        ax.set_title(head, fontsize=9)
        if total.max() > 0:
            heat_key(fig, ax, float(total.max()))
        if n == ncols - 1:  # one legend, right of the first row
            handles, _ = ax.get_legend_handles_labels()
            handles += P.region_handles(alpha=0.35, prefix="map: ")
            handles += P.reported_handles(DC.STATES, "cell: reported ", short=True)
            ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.16, 1.0),
                      framealpha=0.9)
    fig.suptitle(title, fontsize=11)
    return fig, panels


def draw_heatmap(out, cells, grid, setups, title, totals=None):
    fig, _ = heat_figure(cells, grid, setups, title, totals)
    return P.save(fig, out, "heatmap")


def heat_title(results):
    """The heat map's title: the logs it draws, the failed ones apart."""
    failed = sum(r["status"] == "failed" for r in results)
    drawn = len(results) - failed
    return ("%d log%s drawn%s: time per (v0, N) cell by reported state" %
            (drawn, "" if drawn == 1 else "s",
             " (%d failed, not drawn: see the report)" % failed if failed else ""))


def corner_setups(calib_path):
    """{corner name: DC.Corner} of the calibration; a corner a log reports
    that the calibration lacks gets the flat brake at its position."""
    cal = DC.read_calib(calib_path)
    setups = {c.name: c for c in DC.corners({"flat": cal["flat"]})}
    setups.update((c.name, c) for c in DC.corners(cal))
    return setups


def border_note(setups, calib_path, shown):
    """One sentence per shown corner: whose brake its borders are drawn for."""
    parts = []
    for name in shown:
        c = setups[name]
        p = c.brake
        parts.append("%s: %s limit, a = %g s/m, D = %g, w0 = %g rad/s, m = %g kg, dmu = %g"
                     % (name, c.criterion, p["slope"], p["damping"], p["omega0"], p["mass"],
                        p["delta_mu"]))
    return ("Borders: Hopf border and stability limit from the closed forms of docs/model.md "
            "(scipy, tools/plots/plotlib.py) for each corner's brake%s: %s." %
            (" (from %s)" % calib_path if calib_path else " (the paper's)", "; ".join(parts)))


def write_html(out, results, totals, n_ep, timing, border_note):
    bad = [r for r in results if r["status"] != "ok"]
    rows = "".join("<tr><td>%s</td>%s<td>%.1f</td></tr>" % (
        c, "".join("<td>%.1f</td>" % x for x in totals[c]), sum(totals[c]))
        for c in DC.CORNERS if c in totals)
    prob = "".join("<tr><td>%s</td><td>%s</td><td>%s</td></tr>" % (
        html.escape(r["log"]), r["status"], html.escape(r["reason"])) for r in bad)
    page = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>Fleet report</title>
<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}
td,th{border:1px solid #aaa;padding:2px 8px;text-align:right}td:first-child{text-align:left}</style>
</head><body>
<h1>Fleet report</h1>
<p>%d logs: %d ok, %d with malformed lines, %d failed; %d episodes.
Replayed on %s (%d workers) in %.2f s: %.1f logs/s.</p>
<h2>Time in each state per corner [s]</h2>
<table><tr><th>corner</th>%s<th>total</th></tr>%s</table>
<p>Per log: <a href="state_time.csv">state_time.csv</a>; episodes: <a href="episodes.csv">episodes.csv</a>;
cells: <a href="cells.csv">cells.csv</a>.</p>
<h2>Where the brakes operated</h2>
<p>Time in each (v0, N) cell, coloured by the state the monitor reported longest there
(more opaque: more time), over the stability map. %s</p>
<p><img src="heatmap.png" alt="heat map"> (<a href="heatmap.svg">SVG</a>)</p>
<h2>Logs with problems</h2>
<table><tr><th>log</th><th>status</th><th>reason</th></tr>%s</table>
</body></html>
""" % (len(results), sum(r["status"] == "ok" for r in results),
       sum(r["status"] == "partial" for r in results),
       sum(r["status"] == "failed" for r in results), n_ep, html.escape(timing["where"]),
       timing["workers"], timing["job_s"], len(results) / max(timing["job_s"], 1e-9),
       "".join("<th>%s</th>" % s for s in DC.STATES), rows, html.escape(border_note),
       prob or "<tr><td colspan=3>none</td></tr>")
    with open(os.path.join(out, "index.html"), "w", encoding="utf-8") as f:
        f.write(page)


def find_logs(args):
    logs = list(args.logs)
    if args.dir:
        for path in sorted(glob.glob(os.path.join(args.dir, "**", "*.log"), recursive=True)):
            logs.append(path)
    return [os.path.abspath(x) for x in logs]


def main():
    ap = helptext.parser(__doc__, "tools/fleet.py")
    ap.add_argument("logs", nargs="*", metavar="LOG", help="candump log files (-l format), as many as you like")
    ap.add_argument("--dir", metavar="DIR", help="every *.log below DIR (searched recursively)")
    ap.add_argument("--calib", help="calibration text file (replay's --calib and the map's brake)")
    ap.add_argument("--scheduler", help="address of an existing Dask scheduler (tcp://HOST:PORT)")
    ap.add_argument("-o", "--out", default=os.path.join(DC.ROOT, "build", "fleet-report"), metavar="REPORT_DIR",
                    help="folder the report is written to (default build/fleet-report)")
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1,
                    help="replays at a time on the LocalCluster (default: CPUs)")
    ap.add_argument("--sim", default=DC.SIM, help="squeal-sim (default: build/host/squeal-sim)")
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds per log (default 600)")
    args = ap.parse_args()
    if args.dir and not os.path.isdir(args.dir):
        print("fleet: %s: no such folder" % args.dir, file=sys.stderr)
        return 1
    logs = find_logs(args)
    if not logs or args.workers < 1:
        ap.error("give LOG files or --dir DIR with *.log files, and --workers >= 1")
    try:
        setups = corner_setups(args.calib)
    except DC.CalibError as e:
        print("fleet: %s" % e, file=sys.stderr)
        return 2
    args.sim = os.path.abspath(args.sim)
    args.calib = os.path.abspath(args.calib) if args.calib else None
    if args.calib:  # one clear error instead of the same one for every log
        chk = subprocess.run([args.sim, "calib-check", args.calib],
                             stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE)
        if chk.returncode != 0:
            print("fleet: %s" % chk.stderr.decode("utf-8", "replace").strip().splitlines()[0],
                  file=sys.stderr)
            return 2
    try:
        results, cells, grid, timing = run_tasks(logs, args)
    except ImportError as e:
        print("fleet: Dask is missing (%s): apt-get install python3-dask python3-distributed" % e,
              file=sys.stderr)
        return 1
    except (OSError, TimeoutError) as e:
        print("fleet: cannot reach the Dask scheduler %s: %s" % (args.scheduler or "(local)", e),
              file=sys.stderr)
        return 1
    os.makedirs(args.out, exist_ok=True)
    totals, n_ep = write_csvs(args.out, results)
    write_cells(args.out, cells, grid)
    shown = [c for c in DC.CORNERS if c in cells] or [min(setups, key=DC.CORNERS.index)]
    note = border_note(setups, args.calib, shown)
    draw_heatmap(args.out, cells, grid, setups, heat_title(results), totals)
    write_html(args.out, results, totals, n_ep, timing, note)
    counts = {s: sum(r["status"] == s for r in results) for s in ("ok", "partial", "failed")}
    rate = len(results) / max(timing["job_s"], 1e-9)
    with open(os.path.join(args.out, "fleet.json"), "w") as f:
        json.dump(dict(timing, logs=len(results), episodes=n_ep, logs_per_s=rate,
                       borders=note, **counts), f, indent=1)
    print("fleet: %d logs (ok %d, partial %d, failed %d), %d episodes; %s, %d workers: "
          "%.2f s, %.1f logs/s (wall with start-up %.2f s); report in %s" %
          (len(results), counts["ok"], counts["partial"], counts["failed"], n_ep, timing["where"],
           timing["workers"], timing["job_s"], rate, timing["wall_s"], args.out))
    for r in results:
        if r["status"] != "ok":
            print("  %s: %s: %s" % (r["log"], r["status"], r["reason"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
