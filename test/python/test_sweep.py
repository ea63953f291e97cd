"""test_sweep.py - python/mmsim and tools/mmsweep (run by test/cli/cli_sweep.sh).

A sweep on Dask gives the rows the same runs give one by one with mmsim;
no run is lost or counted twice when a worker dies or the sweep is stopped
and started again; a scheduler and workers started as separate processes
run a sweep; a varied key no file has is one line and exit 2 before any
run; mmsweep plot's numbers are the table's.
"""
import glob
import hashlib
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

import pandas as pd
import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "python"))
import mmsim  # noqa: E402

MMSIM = os.environ.get("MMSIM", os.path.join(REPO, "build", "mmsim"))
MMSWEEP = [sys.executable, os.path.join(REPO, "tools", "mmsweep")]
MAZES = ["mazes/gen-5x5-s1.txt", "mazes/gen-6x6-s1.txt"]
GEARS = [29.0, 30.5]           # motor.left.gear_ratio: a robot-file key
WHEEL_DIFF_M = [0.0, 0.0003]   # asymmetry.wheel_d_diff_m: a config key
VARY = {"motor.left.gear_ratio": GEARS, "asymmetry.wheel_d_diff_m": WHEEL_DIFF_M}
CLOCK_FIELDS = ("wall_time_s", "real_time_factor")  # the host's clock, not the run's
TIME_LIMIT_S = 8


def raw_rows(out):
    """Every row of every part file, repeats kept."""
    return pd.concat([pd.read_parquet(f) for f in sorted(glob.glob(out + "/part-*.parquet"))], ignore_index=True)


def flat(doc, prefix=""):
    out = {}
    for k, v in doc.items():
        out.update(flat(v, prefix + k + ".") if isinstance(v, dict) else {prefix + k: v})
    return out


def set_key(text, section, name, value):
    """The INI text with [section] name's value replaced (written here, not by mmsim.variations)."""
    out, cur = [], None
    for line in text.splitlines():
        m = re.match(r"^\[(.*)\]$", line.strip())
        cur = m.group(1) if m else cur
        if cur == section and re.match(r"^%s\s*=" % re.escape(name), line):
            line = re.sub(r"=\s*[^;]*?(\s*;|$)", "= %.12g\\1" % value, line, count=1)
        out.append(line)
    return "\n".join(out) + "\n"


def by_hand(tmp_path, maze, seed, gear, diff):
    """One run with build/mmsim, its robot file and config edited here."""
    robot = subprocess.run([MMSIM, "--print-robot"], capture_output=True, text=True, check=True).stdout
    config = subprocess.run([MMSIM, "--print-config"], capture_output=True, text=True, check=True).stdout
    text = set_key(robot, "motor.left", "gear_ratio", gear)
    # mmsim's config_hash covers the robot file's path as well as its text:
    # the run by hand reads its file from the path the sweep's copy has (a
    # file named by its content's hash; written here with the text made here).
    folder = tempfile.gettempdir() + "/mmsim-sweep-files"
    os.makedirs(folder, exist_ok=True)
    rpath = "%s/%s.ini" % (folder, hashlib.sha256(text.encode()).hexdigest()[:32])
    with open(rpath, "w") as f:
        f.write(text)
    p = subprocess.run([MMSIM, "--maze", maze, "--json", "--driver", "scripted", "--seed", str(seed),
                        "--time-limit", str(float(TIME_LIMIT_S)), "--robot", str(rpath), "--config", "-"],
                       input=set_key(config, "asymmetry", "wheel_d_diff_m", diff), capture_output=True,
                       text=True, cwd=REPO)
    assert p.returncode in (0, 1), p.stderr
    return flat(json.loads(p.stdout.splitlines()[-1])), rpath


@pytest.fixture(scope="module")
def local2():
    """One LocalCluster of 2 worker processes for the tests that only use it."""
    from distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        yield client


def test_localcluster_equals_runs_one_by_one(tmp_path, local2):
    out = str(tmp_path / "r.parquet")
    df = mmsim.sweep(MAZES, "1-3", VARY, ["scripted"], out=out, client=local2, time_limit_s=TIME_LIMIT_S, mmsim=MMSIM)
    assert len(df) == 24 and df["run_key"].is_unique and df["run_error"].isna().all()
    for _, row in df.iterrows():
        gear, diff = row["vary.motor.left.gear_ratio"], row["vary.asymmetry.wheel_d_diff_m"]
        want, rpath = by_hand(tmp_path, row["maze"], row["seed"], gear, diff)
        assert row["robot_sha256"] == hashlib.sha256(open(rpath, 'rb').read()).hexdigest()
        for k, v in want.items():
            if k in CLOCK_FIELDS or k == "robot":
                continue
            got = json.loads(row[k]) if isinstance(v, list) else row[k]
            assert got == v, "%s seed %s gear %g diff %g: %s %r, by hand %r" % (row["maze"], row["seed"], gear, diff, k, got, v)
    assert df.groupby(["vary.motor.left.gear_ratio", "vary.asymmetry.wheel_d_diff_m"]).size().tolist() == [6] * 4


def test_worker_killed_mid_sweep(tmp_path):
    from distributed import Client, LocalCluster
    out = str(tmp_path / "k.parquet")
    killed = []
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        def kill_one(state):
            if state["done"] == 4 and not killed:
                pids = client.run(os.getpid)
                pid = sorted(pids.values())[0]
                os.kill(pid, signal.SIGKILL)
                killed.append(pid)
        df = mmsim.sweep(MAZES, "1-6", {"motor.left.gear_ratio": GEARS}, ["scripted"], out=out,
                         time_limit_s=TIME_LIMIT_S, mmsim=MMSIM, progress=kill_one, client=client)
    assert killed, "no worker was killed"
    raw = raw_rows(out)
    assert len(raw) == 24 and raw["run_key"].is_unique, "rows %d, keys %d" % (len(raw), raw["run_key"].nunique())
    assert len(df) == 24 and df["run_error"].isna().all()


def sweep_cmd(out, seeds="1-8", extra=()):
    return MMSWEEP + ["--mazes"] + MAZES + ["--seeds", seeds, "--driver", "scripted", "--time-limit", "12",
                                          "--vary", "motor.left.gear_ratio=29.5,30", "--out", out,
                                          "--mmsim", MMSIM] + list(extra)


def test_interrupted_and_restarted(tmp_path):
    out = str(tmp_path / "i.parquet")
    p = subprocess.Popen(sweep_cmd(out), cwd=REPO, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 40
    while time.monotonic() < deadline and not glob.glob(out + "/part-*.parquet"):
        time.sleep(0.1)
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=30)
    assert p.returncode == 130, err
    first = raw_rows(out)
    assert 0 < len(first) < 32, "%d rows before the stop" % len(first)
    q = subprocess.run(sweep_cmd(out), cwd=REPO, capture_output=True, text=True, timeout=60)
    assert q.returncode == 0, q.stderr
    assert "(%d skipped: in --out)" % len(first) in q.stderr, q.stderr
    raw = raw_rows(out)
    assert len(raw) == 32 and raw["run_key"].is_unique
    assert set(first["run_key"]) <= set(raw["run_key"])


def test_scheduler_and_workers_as_processes(tmp_path):
    py = sys.executable
    sched_file = str(tmp_path / "scheduler.json")
    env = dict(os.environ, PYTHONPATH=os.path.join(REPO, "python"))
    procs = [subprocess.Popen([py, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", "0",
                               "--no-dashboard", "--scheduler-file", sched_file], env=env,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    try:
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and not os.path.exists(sched_file):
            time.sleep(0.1)
        addr = json.load(open(sched_file))["address"]
        assert addr.startswith("tcp://127.0.0.1:")
        for _ in range(2):
            procs.append(subprocess.Popen([py, "-m", "distributed.cli.dask_worker", "--scheduler-file", sched_file,
                                           "--host", "127.0.0.1", "--nworkers", "1", "--nthreads", "1",
                                           "--no-dashboard"], env=env, cwd=REPO,
                                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        out = str(tmp_path / "s.parquet")
        from distributed import Client
        with Client(addr, timeout="20s") as c:
            c.wait_for_workers(2, timeout=30)
        q = subprocess.run(sweep_cmd(out, "1-3", ["--scheduler", addr]), cwd=REPO, capture_output=True, text=True, timeout=60)
        assert q.returncode == 0, q.stderr
        raw = raw_rows(out)
        assert len(raw) == 12 and raw["run_key"].is_unique and raw["run_error"].isna().all()
    finally:
        for p in procs:
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()


@pytest.mark.parametrize("vary", ["motor.left.no_such_key=1,2", "nosection.gear_ratio=3",
                                  "motor.left.gear_ratio=N(1,2", "motor.left.gear_ratio"])
def test_bad_vary_is_one_line_before_any_run(tmp_path, vary):
    out = str(tmp_path / "bad.parquet")
    q = subprocess.run(MMSWEEP + ["--mazes", MAZES[0], "--seeds", "1-2", "--driver", "scripted", "--vary", vary,
                                  "--out", out, "--mmsim", MMSIM], cwd=REPO, capture_output=True, text=True, timeout=30)
    assert q.returncode == 2
    assert len(q.stderr.splitlines()) == 1 and q.stderr.startswith("mmsweep: "), q.stderr
    assert "Traceback" not in q.stderr and not os.path.exists(out)


def test_plot_rates_equal_the_table(tmp_path, local2):
    out = str(tmp_path / "p.parquet")
    # a robot too long for its turns touches walls: contact rates that are not all 0
    df = mmsim.sweep(MAZES, "1-2", {"chassis.body.body_l_mm": [120, 150]}, ["firmware"], out=out, client=local2,
                     time_limit_s=6, mmsim=MMSIM)
    for ext in ("png", "svg"):
        q = subprocess.run(MMSWEEP + ["plot", out, "-o", str(tmp_path / ("p." + ext)), "--dump-data",
                                      str(tmp_path / "p.json")], capture_output=True, text=True, timeout=60)
        assert q.returncode == 0, q.stderr
    doc = json.load(open(tmp_path / "p.json"))
    assert (tmp_path / "p.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert b"<svg" in (tmp_path / "p.svg").read_bytes()[:2000]
    for col, plotted in (("maze", doc["per_maze"]), ("vary.chassis.body.body_l_mm", doc["per_value"]["chassis.body.body_l_mm"])):
        want = {}
        for value in sorted(set(df[col])):
            g = [r for _, r in df.iterrows() if r[col] == value]
            want[str(value)] = {"runs": len(g), "success_rate": sum(bool(r["reached_goal"]) for r in g) / len(g),
                                "contact_rate": sum(r["collisions"] > 0 for r in g) / len(g)}
        assert plotted == want
    assert any(v["contact_rate"] > 0 for v in doc["per_value"]["chassis.body.body_l_mm"].values())
    for m, times in doc["best_run_s"].items():
        assert sorted(times) == sorted(df[(df["maze"] == m) & (df["reached_goal"] == True)]["best_run_s"].dropna())  # noqa: E712


def test_folder_reads_whole_when_a_part_has_only_nulls(tmp_path):
    """A first part whose runs all missed the goal (best_run_s null) and had
    no error, a later one with numbers and an error: pandas.read_parquet on
    the folder (the dataset's schema from its first part) reads every row."""
    out = str(tmp_path / "r.parquet")
    w = mmsim.store.Writer(out, flush_rows=2)
    w.add({"run_key": "a", "best_run_s": None, "run_error": None, "laps": []})
    w.add({"run_key": "b", "best_run_s": None, "run_error": None, "laps": []})
    time.sleep(0.01)
    w.add({"run_key": "c", "best_run_s": 12.5, "run_error": "exit 3", "laps": [{"run_s": 12.5}]})
    w.add({"run_key": "d", "best_run_s": 11.0, "run_error": None, "laps": []})
    w.flush()
    assert len(glob.glob(out + "/part-*.parquet")) == 2
    df = pd.read_parquet(out).sort_values("run_key").reset_index(drop=True)
    assert df["best_run_s"].tolist()[2:] == [12.5, 11.0] and df["best_run_s"].isna().tolist()[:2] == [True, True]
    assert df["run_error"].tolist()[2] == "exit 3"
    pd.testing.assert_frame_equal(df, mmsim.store.read(out).sort_values("run_key").reset_index(drop=True), check_dtype=False)


def quick(out, extra=(), mazes=(MAZES[0],), timeout=60):
    """mmsweep with a small plan: (CompletedProcess, seconds it took)."""
    t0 = time.monotonic()
    q = subprocess.run(MMSWEEP + ["--mazes"] + list(mazes) + ["--seeds", "1-2", "--driver", "scripted", "--out", out,
                                                              "--mmsim", MMSIM] + list(extra),
                       cwd=REPO, capture_output=True, text=True, timeout=timeout)
    return q, time.monotonic() - t0


def one_line(q, rc):
    assert q.returncode == rc, q.stderr
    assert len(q.stderr.splitlines()) == 1 and q.stderr.startswith("mmsweep: "), q.stderr
    assert "Traceback" not in q.stderr


@pytest.mark.parametrize("extra,says", [
    (["--driver", "bogus"], "--driver 'bogus': mmsim: --driver: expected firmware or scripted"),
    (["--time-limit", "-5"], "--time-limit -5.0: want seconds from 1 to 86400"),
    (["--time-limit", "0"], "--time-limit 0.0: want seconds from 1 to 86400"),
    (["--", "--bogus-flag"], "unknown option: '--bogus-flag'"),
    (["--seeds", "1-100000000"], "100000000 seeds, more than the 100000 runs a sweep holds"),
    (["--vary", "motor.left.gear_ratio=29.86*N(1,0.01)x100000000"], "x100000000 draws, more than 100000"),
])
def test_bad_input_is_one_line_before_any_run(tmp_path, extra, says):
    out = str(tmp_path / "bad.parquet")
    q, took = quick(out, extra)
    one_line(q, 2)
    assert says in q.stderr and not os.path.exists(out), q.stderr
    assert took < 30, "%.1f s before the refusal" % took  # 10^8 seeds refused up front, not built


def test_junk_maze_is_one_line_before_any_run(tmp_path):
    junk = tmp_path / "junk.txt"
    junk.write_text("not a maze\n")
    out = str(tmp_path / "bad.parquet")
    q, _ = quick(out, mazes=[MAZES[0], str(junk)])
    one_line(q, 2)
    assert "junk.txt:1:1: " in q.stderr and not os.path.exists(out), q.stderr


def test_outputs_that_cannot_be(tmp_path):
    (tmp_path / "file.parquet").write_text("not parquet\n")
    (tmp_path / "junkdir").mkdir()
    (tmp_path / "junkdir" / "part-1-1-000001.parquet").write_text("junk")
    for out, rc, says in (("/proc/mmsweep-test.parquet", 3, "cannot write"),
                          (str(tmp_path / "file.parquet"), 2, "a file; --out is a folder"),
                          (str(tmp_path / "junkdir"), 2, "not a Parquet results folder")):
        q, _ = quick(out)
        one_line(q, rc)
        assert says in q.stderr, q.stderr
    q = subprocess.run(MMSWEEP + ["plot", str(tmp_path / "file.parquet"), "-o", str(tmp_path / "x.png")],
                       capture_output=True, text=True, timeout=60)
    one_line(q, 2)


def test_unreachable_scheduler_is_exit_3_in_bounded_time(tmp_path):
    q, took = quick(str(tmp_path / "u.parquet"), ["--scheduler", "tcp://127.0.0.1:1"])
    one_line(q, 3)
    assert "not reached in 10 s" in q.stderr and took < 30, (took, q.stderr)


def test_interrupted_before_any_run_says_nothing_written(tmp_path):
    out = str(tmp_path / "n.parquet")
    p = subprocess.Popen(MMSWEEP + ["--mazes", MAZES[0], "--seeds", "1-2", "--driver", "scripted", "--time-limit", "60",
                                    "--out", out, "--mmsim", MMSIM, "--", "--realtime"],
                         cwd=REPO, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(6)  # the plan made, the runs under way (60 s each, in real time)
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=60)
    assert p.returncode == 130, err
    assert not glob.glob(out + "/part-*.parquet")
    assert "nothing written" in err and "the runs done are in" not in err, err


NO_GUARD = """
import sys
sys.path.insert(0, %r)
import mmsim
df = mmsim.sweep([%r], "1-3", drivers=["scripted"], time_limit_s=5, mmsim=%r)
print("rows", len(df), "errors", int(df["run_error"].notna().sum()))
"""


@pytest.mark.parametrize("how", ["script", "stdin"])
def test_sweep_from_a_script_without_the_main_guard(tmp_path, how):
    """No `if __name__ == "__main__"` guard, or the script on stdin: the local
    workers are threads (each run is a process of its own), so nothing
    re-imports the script."""
    text = NO_GUARD % (os.path.join(REPO, "python"), os.path.join(REPO, MAZES[0]), MMSIM)
    script = tmp_path / "noguard.py"
    script.write_text(text)
    argv, stdin = ([sys.executable, str(script)], None) if how == "script" else ([sys.executable, "-"], text)
    q = subprocess.run(argv, input=stdin, cwd=str(tmp_path), capture_output=True, text=True, timeout=90)
    assert q.returncode == 0 and "rows 3 errors 0" in q.stdout, q.stderr[-2000:]
    assert "RuntimeError" not in q.stderr and "leaked semaphore" not in q.stderr, q.stderr[-2000:]
