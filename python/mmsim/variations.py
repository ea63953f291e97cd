"""variations.py - robot-file and config keys varied across a sweep.

A key is SECTION.NAME as mmsim --print-robot and --print-config print them
(motor.left.gear_ratio: [motor.left] gear_ratio). A SPEC is:
  a list        29.5,29.86,30.2
  a range       LO:HI:STEP   (LO, LO+STEP, ... up to HI inclusive)
  a distribution [SCALE*]N(MU,SIGMA) or [SCALE*]U(LO,HI), with [xCOUNT]
                (draws, default 8) and [@SEED] (default 1): COUNT values
                drawn once by numpy's default_rng(SEED), e.g.
                29.86*N(1,0.01)x10@7
The values of every varied key are crossed with each other (every
combination), and each combination with the mazes, seeds and drivers.
"""
import re

import numpy as np

DEFAULT_DRAWS = 8
DEFAULT_DIST_SEED = 1
NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
DIST_RE = re.compile(r"^(?:(?P<scale>%s)\*)?(?P<kind>[NU])\((?P<a>%s),(?P<b>%s)\)"
                     r"(?:x(?P<count>\d+))?(?:@(?P<seed>\d+))?$" % (NUM, NUM, NUM))
RANGE_RE = re.compile(r"^(%s):(%s):(%s)$" % (NUM, NUM, NUM))
RANGE_MAX_VALUES = 100000  # a range longer than this is a typing error


class SpecError(ValueError):
    """A --vary KEY=SPEC that cannot be used; its text is the one error line."""


def parse_vary(text):
    """KEY=SPEC (the command line's form) as (key, spec)."""
    key, eq, spec = text.partition("=")
    if not eq or not key.strip() or not spec.strip():
        raise SpecError("--vary %r: want KEY=SPEC (e.g. motor.left.gear_ratio=29.5,30)" % text)
    return key.strip(), spec.strip()


def values(key, spec):
    """The values a SPEC stands for (floats, or strings for words)."""
    if isinstance(spec, (list, tuple, range, np.ndarray)):
        return [num_or_word(v) for v in spec]
    s = str(spec).replace(" ", "")
    m = DIST_RE.match(s)
    if m:
        return draws(key, m)
    m = RANGE_RE.match(s)
    if m:
        return range_values(key, *(float(g) for g in m.groups()))
    if "(" in s:
        raise SpecError("--vary %s=%s: not a distribution: want [SCALE*]N(MU,SIGMA) or U(LO,HI), "
                        "then xCOUNT and @SEED if wanted" % (key, spec))
    return [num_or_word(v) for v in s.split(",") if v != ""]


def draws(key, m):
    scale = float(m.group("scale") or 1.0)
    a, b = float(m.group("a")), float(m.group("b"))
    count = int(m.group("count") or DEFAULT_DRAWS)
    rng = np.random.default_rng(int(m.group("seed") or DEFAULT_DIST_SEED))
    if count < 1:
        raise SpecError("--vary %s: xCOUNT must be at least 1" % key)
    if count > RANGE_MAX_VALUES:
        raise SpecError("--vary %s: x%d draws, more than %d" % (key, count, RANGE_MAX_VALUES))
    x = rng.normal(a, b, count) if m.group("kind") == "N" else rng.uniform(a, b, count)
    return [float("%.12g" % (scale * v)) for v in x]


def range_values(key, lo, hi, step):
    if step <= 0 or hi < lo:
        raise SpecError("--vary %s=%g:%g:%g: want LO:HI:STEP with STEP > 0 and HI >= LO" % (key, lo, hi, step))
    n = int(np.floor((hi - lo) / step + 1e-9)) + 1
    if n > RANGE_MAX_VALUES:
        raise SpecError("--vary %s: %d values in the range, more than %d" % (key, n, RANGE_MAX_VALUES))
    return [float("%.12g" % (lo + i * step)) for i in range(n)]


def num_or_word(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return str(v)


def ini_keys(text):
    """{SECTION.NAME: line index} of an INI text as mmsim prints it."""
    keys, section = {}, None
    for i, line in enumerate(text.splitlines()):
        s = line.strip()
        if s.startswith("[") and s.endswith("]"):
            section = s[1:-1].strip()
        elif section is not None and "=" in s and not s.startswith(";"):
            keys["%s.%s" % (section, s.split("=", 1)[0].strip())] = i
    return keys


def apply(text, settings):
    """text with each SECTION.NAME of settings set to its value (its comment kept)."""
    lines = text.splitlines()
    where = ini_keys(text)
    for key, value in settings.items():
        i = where[key]
        name, rest = lines[i].split("=", 1)
        comment = rest[rest.index(";"):] if ";" in rest else ""
        lines[i] = "%s= %s%s" % (name, fmt(value), (" " + comment) if comment else "")
    return "\n".join(lines) + "\n"


def fmt(value):
    if isinstance(value, float):
        return "%.12g" % value
    return str(value)
