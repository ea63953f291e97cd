"""planning.py - a sweep's runs: mazes x seeds x varied values x drivers.

Every run is a plain dict of its inputs (a "spec"), keyed by run_key, the
SHA-256 of those inputs: the maze file's content, the seed, the driver,
the robot file's and config's content, the varied values, the time limit
and the extra arguments. Two specs with one key are one run. The varied
keys are checked against `mmsim --print-robot` and `--print-config` and
every varied robot file and config is read by mmsim once, before any run:
a key the files do not have, or a value mmsim rejects, is a SpecError.
"""
import hashlib
import itertools
import json
import os
import subprocess
import tempfile

from . import runner, variations
from .variations import SpecError


def sha256(data):
    return hashlib.sha256(data.encode() if isinstance(data, str) else data).hexdigest()


def maze_files(mazes):
    """A folder (its *.txt maze files, sorted), a file, or a list of either."""
    if isinstance(mazes, (str, os.PathLike)):
        mazes = [mazes]
    out = []
    for m in mazes:
        m = str(m)
        if os.path.isdir(m):
            found = sorted(os.path.join(m, f) for f in os.listdir(m)
                           if f.endswith(".txt") and f.lower() != "readme.txt")
            if not found:
                raise SpecError("%s: no maze files (*.txt) in the folder" % m)
            out += found
        elif os.path.isfile(m):
            out.append(m)
        else:
            raise SpecError("%s: no such maze file or folder" % m)
    return out


MAX_RUNS = 100000  # runs in one sweep: its plan (a dict per run) stays in memory (~0.2 GB)
SEED_MAX = 9007199254740992  # mmsim --seed's range (2^53)


def seed_list(seeds):
    """1-100, 1,5,9, 3-4,10 or a list of ints; counted before it is built, so
    a range of 10^8 seeds is a SpecError, not gigabytes."""
    if isinstance(seeds, int):
        seeds = [seeds]
    if not isinstance(seeds, str):
        seeds = ",".join(str(int(s)) for s in seeds)
    parts = []
    for part in seeds.split(","):
        lo, dash, hi = part.strip().partition("-")
        try:
            a, b = int(lo), int(hi if dash else lo)
        except ValueError:
            raise SpecError("--seeds %r: want N, N-M or a list of them, e.g. 1-100" % seeds) from None
        if not 0 <= a <= b <= SEED_MAX:
            raise SpecError("--seeds %r: want 0 <= N <= M <= %d" % (seeds, SEED_MAX))
        parts.append((a, b))
    n = sum(b - a + 1 for a, b in parts)
    if n == 0:
        raise SpecError("--seeds %r: no seeds" % seeds)
    if n > MAX_RUNS:
        raise SpecError("--seeds %r: %d seeds, more than the %d runs a sweep holds (split it)" % (seeds, n, MAX_RUNS))
    return [s for a, b in parts for s in range(a, b + 1)]


def check_size(mazes, seeds, combos, drivers):
    """The sweep's run count before its plan is built: at most MAX_RUNS."""
    n = len(mazes) * len(seeds) * combos * len(drivers)
    if n > MAX_RUNS:
        raise SpecError("%d mazes x %d seeds x %d combinations x %d drivers = %d runs, more than the %d a sweep holds"
                        " (split it)" % (len(mazes), len(seeds), combos, len(drivers), n, MAX_RUNS))


def check_runs(mmsim, mazes, drivers, time_limit_s, extra_args):
    """Every driver, the time limit and the extra arguments as mmsim reads
    them (mmsim --print-config checks its flags and their combinations:
    an unknown driver, a negative limit), and every maze as mmmaze reads it
    (the mmmaze beside mmsim, when there is one): a SpecError with their
    own error line, before any run."""
    if time_limit_s is not None:
        try:
            ok = 1 <= float(time_limit_s) <= 86400
        except (TypeError, ValueError):
            ok = False
        if not ok:
            raise SpecError("--time-limit %r: want seconds from 1 to 86400 (mmsim --time-limit)" % (time_limit_s,))
    for d in drivers:
        argv = [mmsim, "--print-config"] + runner.driver_args(d) + [str(a) for a in extra_args]
        if time_limit_s is not None:
            argv += ["--time-limit", repr(float(time_limit_s))]
        p = subprocess.run(argv, capture_output=True, text=True)
        if p.returncode != 0:
            why = (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1]
            raise SpecError("--driver %r: %s" % (d, why))
    mmmaze = os.path.join(os.path.dirname(mmsim), "mmmaze")
    if os.access(mmmaze, os.X_OK):
        for i in range(0, len(mazes), 200):
            p = subprocess.run([mmmaze, "check"] + mazes[i:i + 200], capture_output=True, text=True)
            if p.returncode == 2:
                raise SpecError((p.stderr.strip().splitlines() or ["mmmaze check: exit 2"])[0])


def printed(mmsim, what, path):
    """mmsim --print-robot/--print-config [FILE]: the text mmsim reads."""
    argv = [mmsim, "--print-" + what] + (["--" + what, str(path)] if path else [])
    p = subprocess.run(argv, capture_output=True, text=True)
    if p.returncode != 0:
        raise SpecError((p.stderr.strip().splitlines() or ["%s failed" % " ".join(argv)])[-1])
    return p.stdout


def checked(mmsim, what, text):
    """text as mmsim reads it (--print-robot/--print-config): its own error line if it rejects it."""
    with tempfile.NamedTemporaryFile("w", suffix=".ini", delete=False) as f:
        f.write(text)
    try:
        printed(mmsim, what, f.name)
    finally:
        os.unlink(f.name)


def split_keys(vary, robot_text, config_text, robot, config):
    """vary's keys as (robot keys, config keys); an unknown key is a SpecError."""
    rk, ck = variations.ini_keys(robot_text), variations.ini_keys(config_text)
    rkeys, ckeys = [], []
    for key in vary:
        if key in rk:
            rkeys.append(key)
        elif key in ck:
            ckeys.append(key)
        else:
            raise SpecError("--vary %s: no such key in the robot file (%s) or the config (%s); "
                            "`mmsim --print-robot` and `mmsim --print-config` list them as SECTION.NAME"
                            % (key, robot or "the default robot", config or "the default config"))
    return rkeys, ckeys


def plan(mazes, seeds, vary=None, drivers=("firmware",), robot=None, config=None,
         time_limit_s=None, extra_args=(), mmsim=None):
    """The list of specs (one per run, repeated keys once), or SpecError."""
    mmsim = os.path.abspath(mmsim or runner.default_mmsim())
    if not os.access(mmsim, os.X_OK):
        raise SpecError("%s: no mmsim binary (make tools, or --mmsim PATH)" % mmsim)
    mazes, seeds = maze_files(mazes), seed_list(seeds)
    vary = {k: variations.values(k, s) for k, s in (vary or {}).items()}
    for k, v in vary.items():
        if not v:
            raise SpecError("--vary %s: no values" % k)
    drivers = list(drivers)
    n_combos = 1
    for v in vary.values():
        n_combos *= len(v)
    check_size(mazes, seeds, n_combos, drivers)
    check_runs(mmsim, mazes, drivers, time_limit_s, extra_args)
    robot_base = printed(mmsim, "robot", robot)
    config_base = printed(mmsim, "config", config)
    rkeys, ckeys = split_keys(vary, robot_base, config_base, robot, config)
    combos = [dict(zip(vary, vals)) for vals in itertools.product(*vary.values())]
    texts = combo_texts(mmsim, combos, rkeys, ckeys, robot_base, config_base)
    common = {"robot": robot, "config": config, "time_limit_s": time_limit_s,
              "extra_args": [str(a) for a in extra_args], "mmsim": mmsim, "cwd": os.getcwd(),
              "robot_file_sha256": file_sha(robot), "config_file_sha256": file_sha(config)}
    return specs_of(mazes, seeds, drivers, combos, texts, common)


def combo_texts(mmsim, combos, rkeys, ckeys, robot_base, config_base):
    """Per combination: (robot text or None, config text or None), each checked by mmsim once."""
    seen, out = set(), []
    for combo in combos:
        r = variations.apply(robot_base, {k: combo[k] for k in rkeys}) if rkeys else None
        c = variations.apply(config_base, {k: combo[k] for k in ckeys}) if ckeys else None
        for what, text in (("robot", r), ("config", c)):
            if text is not None and (what, text) not in seen:
                seen.add((what, text))
                checked(mmsim, what, text)
        out.append((r, c))
    return out


def file_sha(path):
    if path is None:
        return None
    with open(path, "rb") as f:
        return sha256(f.read())


def specs_of(mazes, seeds, drivers, combos, texts, common):
    specs = {}
    for maze in mazes:
        maze_sha = file_sha(maze)
        for (combo, (rtext, ctext)), driver, seed in itertools.product(zip(combos, texts), drivers, seeds):
            s = dict(common, maze=maze, maze_sha256=maze_sha, seed=int(seed), driver=driver,
                     vary=combo, robot_text=rtext, config_text=ctext)
            s["robot_sha256"] = sha256(rtext) if rtext is not None else common["robot_file_sha256"]
            s["config_sha256"] = sha256(ctext) if ctext is not None else common["config_file_sha256"]
            s["run_key"] = run_key(s)
            specs.setdefault(s["run_key"], s)
    return list(specs.values())


def run_key(s):
    """SHA-256 of a run's inputs (paths of mmsim and the folder left out: the
    same run on another machine has the same key)."""
    inputs = {k: s[k] for k in ("maze_sha256", "seed", "driver", "robot_sha256", "config_sha256",
                                "time_limit_s", "extra_args")}
    inputs["maze"] = os.path.basename(s["maze"])
    inputs["vary"] = sorted(s["vary"].items())
    return sha256(json.dumps(inputs, sort_keys=True, default=str))[:32]
