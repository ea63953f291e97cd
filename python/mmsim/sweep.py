"""sweep.py - a sweep's runs scheduled by Dask distributed.

Each run is one task, execute(spec), keyed "mmsim-run-" + its run_key: a
pure function of its inputs, so a task the scheduler runs again (its worker
died; Dask reschedules the tasks of a lost worker) gives the same row, and
the client takes each key's result once. Rows are appended to out as they
come back (store.Writer); runs out already holds are not submitted.
"""
import os
import tempfile
import time

from . import planning as planner
from . import runner, store

KEY_PREFIX = "mmsim-run-"
INPUT_COLUMNS = ("run_key", "maze", "maze_sha256", "seed", "driver", "robot", "robot_sha256",
                 "config", "config_sha256", "time_limit_s", "extra_args")


def flatten(doc, prefix=""):
    """Nested dicts as one level, keys joined with "." (final_pose.x_m)."""
    out = {}
    for k, v in doc.items():
        if isinstance(v, dict):
            out.update(flatten(v, prefix + k + "."))
        else:
            out[prefix + k] = v
    return out


def materialise(text, suffix):
    """A file holding text, named by its hash, in this machine's temp folder."""
    folder = os.path.join(tempfile.gettempdir(), "mmsim-sweep-files")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, planner.sha256(text)[:32] + suffix)
    if not os.path.exists(path):
        tmp = "%s.%d.tmp" % (path, os.getpid())
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, path)
    return path


def execute(spec):
    """One run of a spec as a row: its inputs, then every field of its JSON.
    The JSON's "robot" (the path of a varied copy) gives way to the input's
    robot file; robot_sha256 names the copy's content."""
    robot = materialise(spec["robot_text"], ".ini") if spec["robot_text"] is not None else spec["robot"]
    cwd = spec["cwd"] if os.path.isdir(spec["cwd"]) else None
    config = spec["config"] if spec["config_text"] is None else None
    doc = runner.run(spec["maze"], spec["driver"], spec["seed"], robot, config, spec["extra_args"],
                     spec["mmsim"], spec["time_limit_s"], spec["config_text"], cwd)
    row = flatten(doc)
    row.update({k: spec[k] for k in INPUT_COLUMNS})
    row.update({"vary." + k: v for k, v in spec["vary"].items()})
    row.setdefault("run_error", None)
    return row


class ExternalError(Exception):
    """A failure outside the sweep's inputs (a scheduler not reached, an
    output that cannot be written): one line, exit 3."""


SCHEDULER_TIMEOUT_S = 10  # a scheduler not reached within this is an external failure


def connect(scheduler=None, workers=2):
    """A Dask client: on a LocalCluster of `workers` workers in this process
    (one thread each: every run is a process of its own, so the workers need
    no process of their own, and a script without the `if __name__ ==
    "__main__"` guard, a notebook or a script on stdin works), or on the
    scheduler at the address given (ExternalError if it is not reached in
    SCHEDULER_TIMEOUT_S). Returns (client, cluster or None)."""
    from distributed import Client, LocalCluster
    if scheduler:
        try:
            return Client(scheduler, timeout="%ds" % SCHEDULER_TIMEOUT_S), None
        except (OSError, TimeoutError, ValueError) as e:
            raise ExternalError("--scheduler %s: not reached in %d s: %s" % (
                scheduler, SCHEDULER_TIMEOUT_S, (str(e).splitlines() or [type(e).__name__])[0])) from None
    import logging
    import dask
    # A run is a child process the worker waits for: Dask's statistical
    # profiler (a stack sample every 10 ms in each worker), work stealing
    # (equal tasks, nothing to balance) and the 20 ms event-loop health
    # tick only cost CPU the runs need (measured on 481 scripted runs:
    # the workers' own CPU 9.8 -> 2.8 s, the client's 8.6 -> 4.7 s).
    dask.config.set({"distributed.worker.profile.enabled": False,
                     "distributed.scheduler.work-stealing": False,
                     "distributed.admin.tick.interval": "1s"})
    cluster = LocalCluster(n_workers=int(workers), threads_per_worker=1, processes=False,
                           dashboard_address=None, silence_logs=logging.ERROR)
    return Client(cluster), cluster


def failed_row(spec, why):
    """The row of a run Dask gave up on (its workers kept dying)."""
    row = {k: spec[k] for k in INPUT_COLUMNS}
    row.update({"vary." + k: v for k, v in spec["vary"].items()})
    row.update({"exit_code": -1, "run_error": why})
    return row


def sweep(mazes, seeds, vary=None, drivers=("firmware",), robot=None, config=None, out=None,
          scheduler=None, workers=2, time_limit_s=None, extra_args=(), mmsim=None,
          progress=None, client=None):
    """mazes x seeds x vary x drivers as a pandas DataFrame, one row per run.
    A SpecError (bad key, value, maze or seed list) is raised before any run."""
    specs = planner.plan(mazes, seeds, vary, drivers, robot, config, time_limit_s, extra_args, mmsim)
    store.check_out(out)
    have = store.done_keys(out)
    todo = [s for s in specs if s["run_key"] not in have]
    state = {"total": len(specs), "skipped": len(specs) - len(todo), "done": 0, "failed": 0,
             "not_reached": 0, "start": time.monotonic()}
    writer, rows = store.Writer(out), []
    try:
        if todo:
            run_all(todo, scheduler, workers, client, writer, rows, state, progress)
    finally:
        writer.flush()
    order = {s["run_key"]: i for i, s in enumerate(specs)}  # the plan's order: maze, combination, driver, seed
    df = store.to_frame(rows) if out is None else store.read(out)
    if df.empty:
        return df
    df = df[df["run_key"].isin(order)]
    return df.sort_values("run_key", key=lambda k: k.map(order)).reset_index(drop=True)


def run_all(todo, scheduler, workers, client, writer, rows, state, progress):
    from distributed import as_completed
    own = client is None
    cluster = None
    if own:
        client, cluster = connect(scheduler, workers)
    try:
        by_key = {KEY_PREFIX + s["run_key"]: s for s in todo}
        futures = [client.submit(execute, s, key=k, pure=False) for k, s in by_key.items()]
        for fut in as_completed(futures):
            if fut.status == "finished":
                row = fut.result()
            else:
                row = failed_row(by_key[fut.key], "dask: %r" % (fut.exception(),))
            fut.release()
            rows.append(row)
            writer.add(row)
            count(state, row)
            if progress:
                progress(state)
    finally:
        if own:
            client.close()
            if cluster is not None:
                cluster.close()


def count(state, row):
    state["done"] += 1
    if row.get("run_error"):
        state["failed"] += 1
    elif row.get("reached_goal") is False:
        state["not_reached"] += 1
