"""runner.py - one simulation through the built mmsim binary.

run() starts `mmsim --maze MAZE --json ...` and returns the run's JSON line
as a dict, with "exit_code" added. A run that fails as a contest (goal not
reached, time limit: exit 1) is a result like any other. A run that gives
no JSON (bad input, exit 2; an external failure, exit 3; a crash) returns
{"exit_code": N, "run_error": the last lines of its stderr}; run() never
raises for a run's own failure.
"""
import json
import os
import shlex
import shutil
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
STDERR_TAIL_LINES = 5  # lines of a failed run's stderr kept in its row


def default_mmsim():
    """The binary: $MMSIM, else this repository's build/mmsim, else mmsim on PATH."""
    env = os.environ.get("MMSIM")
    if env:
        return env
    built = os.path.join(REPO, "build", "mmsim")
    if os.access(built, os.X_OK):
        return built
    return shutil.which("mmsim") or built


def driver_args(driver):
    """A driver name (firmware, scripted) as --driver NAME; a string starting
    with "--" (e.g. "--mms ./solver", "--board ukmarsbot-basic --avr x.elf")
    is split as a shell would and passed as it is."""
    if driver is None:
        return []
    if driver.startswith("--"):
        return shlex.split(driver)
    return ["--driver", driver]


def command(maze, driver=None, seed=None, robot=None, config=None,
            extra_args=(), mmsim=None, time_limit_s=None):
    """The argument vector of one run; config "-" reads the config on stdin."""
    argv = [mmsim or default_mmsim(), "--maze", str(maze), "--json"]
    argv += driver_args(driver)
    if seed is not None:
        argv += ["--seed", str(int(seed))]
    if robot is not None:
        argv += ["--robot", str(robot)]
    if config is not None:
        argv += ["--config", str(config)]
    if time_limit_s is not None:
        argv += ["--time-limit", repr(float(time_limit_s))]
    return argv + [str(a) for a in extra_args]


def run(maze, driver=None, seed=None, robot=None, config=None, extra_args=(),
        mmsim=None, time_limit_s=None, config_text=None, cwd=None, timeout_s=None):
    """One run; returns its JSON dict with "exit_code" (see the module's text).
    config_text: a config's text, given to mmsim on stdin (--config -)."""
    if config_text is not None:
        config = "-"
    argv = command(maze, driver, seed, robot, config, extra_args, mmsim, time_limit_s)
    try:
        p = subprocess.run(argv, input=config_text, capture_output=True, text=True,
                           cwd=cwd, timeout=timeout_s)
    except subprocess.TimeoutExpired as e:
        return {"exit_code": -1, "run_error": "no result within %g s (timeout_s)" % e.timeout}
    except OSError as e:
        return {"exit_code": -1, "run_error": "%s: %s" % (argv[0], e.strerror)}
    return parse_result(p.returncode, p.stdout, p.stderr)


def parse_result(rc, stdout, stderr):
    """The last JSON line of stdout with "exit_code"; without one, the error."""
    for line in reversed(stdout.splitlines()):
        line = line.strip()
        if line.startswith("{"):
            try:
                doc = json.loads(line)
            except ValueError:
                break
            doc["exit_code"] = rc
            return doc
    tail = stderr.strip().splitlines()[-STDERR_TAIL_LINES:]
    return {"exit_code": rc, "run_error": "\n".join(tail) or "no JSON and no stderr"}
