# SPDX-License-Identifier: MIT
"""A Dask cluster started separately on 127.0.0.1, as an engineer would:
`dask scheduler` and `dask worker` as their own processes (not LocalCluster),
for the cluster path of tools/fleet.py. Ends only the processes it started
(their process groups, by id)."""
import contextlib
import json
import os
import signal
import subprocess
import time

DASK = "/usr/bin/dask"


def _stop(proc):
    if proc.poll() is None:
        try:
            os.killpg(proc.pid, signal.SIGTERM)
            proc.wait(timeout=20)
        except (ProcessLookupError, subprocess.TimeoutExpired):
            with contextlib.suppress(ProcessLookupError):
                os.killpg(proc.pid, signal.SIGKILL)
            proc.wait(timeout=20)


@contextlib.contextmanager
def separate_cluster(tmpdir, nworkers=1, timeout_s=90):
    """Yields the scheduler's address once nworkers worker processes joined."""
    sfile = os.path.join(tmpdir, "scheduler.json")
    logs = [open(os.path.join(tmpdir, n), "w") for n in ("scheduler.log", "worker.log")]
    procs = []
    try:
        procs.append(subprocess.Popen(
            [DASK, "scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
             "--scheduler-file", sfile], stdout=logs[0], stderr=subprocess.STDOUT,
            start_new_session=True))
        deadline = time.monotonic() + timeout_s
        while not os.path.exists(sfile):
            if time.monotonic() > deadline or procs[0].poll() is not None:
                raise RuntimeError("dask scheduler did not start (see %s)" % logs[0].name)
            time.sleep(0.2)
        time.sleep(0.2)
        with open(sfile) as f:
            address = json.load(f)["address"]
        procs.append(subprocess.Popen(
            [DASK, "worker", address, "--host", "127.0.0.1", "--nworkers", str(nworkers),
             "--nthreads", "1", "--no-dashboard", "--local-directory", tmpdir],
            stdout=logs[1], stderr=subprocess.STDOUT, start_new_session=True))
        from dask.distributed import Client
        with Client(address, timeout="30s") as c:
            c.wait_for_workers(nworkers, timeout=timeout_s)
        yield address
    finally:
        for p in reversed(procs):
            _stop(p)
        for f in logs:
            f.close()
