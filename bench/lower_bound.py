#!/usr/bin/env python3
"""lower_bound.py - physical lower bounds on a maze's speed run: the best orthogonal path, and every path with diagonals and slaloms.

    bench/lower_bound.py [--mmsim build/mmsim] [--mmmaze build/mmmaze]
                         [--config FILE] [--robot FILE] [--radius-mm R]
                         [--v-top-mm-s V] [--turn-mm-s V] [--bins 24]
                         [--slalom firmware/slalom.c] [--no-diagonal] [--json] MAZE...

Two bounds per maze, both with mmsim's robot and motor (`mmsim
--print-config`, `--print-robot`, with --config and --robot as mmsim takes
them), so they follow the config and the robot file. Exit 0, 1 if a goal
is unreachable, 2 on bad input, 3 if a tool fails.

Orthogonal bound ("lower bound"): the path the firmware races today,
`mmmaze solve`'s best path (least cells + quarter turns, sim/maze/solve.h):

- straights: up to the motor's top speed, the no-load wheel speed at the
  battery voltage (450 rpm at 6 V with 32 mm wheels: 754 mm/s);
- speeding up: both motors at the full battery voltage, each wheel's torque
  N*eta*Kt*(V - N*Ke*w)/R less the gearbox friction N*eta*Kt*i0, pushing the
  effective mass (the robot plus each wheel's and rotor's inertia over r^2:
  0.306 kg), and at most the tyres' grip, mu*g;
- braking: the tyres' grip, mu*g (the motors could brake harder);
- turns: each 90-degree turn a circular arc of radius 90 mm (--radius-mm;
  half a cell) from the turn cell's entry edge to its exit edge (the largest arc that
  fits in the cell, so staircases fit too; the firmware's turns are
  smaller), at the lateral friction limit sqrt(mu*g*R) or the speed at
  which the outer wheel turns at the top speed, v_top * R / (R + b),
  whichever is lower; the grip used sideways is taken from the grip for
  braking and speeding up (friction circle);
- timing as the arena's gates (sim/world/race.h): the robot starts at
  rest at the start cell's centre, the run starts when it leaves the start
  cell and ends when it enters the goal cell; an untimed in-place turn at
  the start if the path leaves the start cell sideways.

Optimistic on purpose (so a bound): no controller headroom, no time to
ramp the rotation into and out of a turn, the caster's share of the weight
(6 %) and the load transfer under acceleration ignored, the chassis does
not pitch. Integrated forward (speeding up: on straights in closed form,
as the diagonal bound does) and backward (braking) over the path in steps
of about 1 mm.

Diagonal bound ("diagonal bound"): the least time over EVERY path from the
start to the goal made of the speed run's moves (firmware/slalom.h: whole-
cell straights, diagonal straights of half steps, and the turns S90, F90,
F180, F45, F135, D45, D135, V90, each to either side), so it is a bound on
any run the firmware's planner can choose, whatever its cost function.
Each assumption is the most favourable one, with its reason:

- the moves' geometry is firmware/slalom.c's table, read from the file
  (--slalom): a move may be driven where every side middle it crosses is
  open, as the planner allows (the robot's width is ignored: a point);
- each turn is one circular arc of the largest radius its corner room
  allows, R = min(room before, room after) / tan(A / 2) (S90 90 mm, F90
  270 mm, F180 90 mm, F45 and D45 307 mm, F135 and D135 53 mm, V90 127 mm
  in a 180 mm cell), with straights to fill the room. No curve of a
  smaller curvature fits: leaving a line and joining another at angle A
  moves sideways at least R * (1 - cos A) while turning, which needs room
  R * tan(A / 2) on both sides. A larger radius makes the turn shorter
  (the path's length falls as R grows, since A < 2 tan(A / 2)) and its
  speed limit higher, and the firmware's own arcs are no larger;
- speed limits: straights the motor's top speed; an arc of radius R the
  lower of sqrt(mu*g*R) (the tyres' grip sideways) and v_top * R / (R + b)
  (the outer wheel, b from the centre, at the top speed), as above;
- speeding up by the motors and the tyres as above, on arcs too (the grip
  used sideways is NOT taken from it: more than the friction circle
  allows; the two wheels' torques, linear in their speeds, sum to what they
  give on a straight at the mean speed; no torque spent on yaw); braking
  at mu*g everywhere. Integrated in closed form: a(v) = min(mu*g, alpha -
  beta*v) gives distance and time to each speed exactly (logarithms), the
  top speed taken as reached within 1e-12 of it;
- timing as the orthogonal bound: from rest at the start cell's centre
  (an untimed turn in place to face any open side, an untimed half cell
  speeding up), the run ends where the path first enters a goal cell, in
  the middle of a turn if the turn's arc enters one first;
- the search: A* over (side middle, heading in 45-degree steps, speed bin
  at that node), each move's time the least over every entry speed in its
  bin and every exit speed in the next bin (the highest pair the move
  allows: higher speeds at both ends are never slower), so every real run
  maps to a path in this graph that takes no longer: the graph's least
  time is a lower bound. Bins are --bins equal steps up to the top speed
  plus each limit (every turn's speed limit, the start speed) as a bin's
  top, so a speed held at a limit is exact; more bins give a higher,
  tighter bound (24: within 0.1 % of the found path's own time). A*'s
  estimate is the time at every piece's speed limit, never more than the
  truth, so A* stays exact. A straight never follows a straight of the
  same heading (one longer straight is never slower).

Not modelled (so not a bound against them): a mouse that backs up in the
start cell for a run-up, paths outside the move set (e.g. a curve that is
not one arc per move: the turns above are already the largest arcs), and
parts of the run the firmware does not drive (bumping walls).

The diagonal bound is never above the orthogonal one: its graph holds the
orthogonal path (whole-cell straights and S90s of 90 mm radius), and its
model is at least as favourable on it (test/cli/cli_lower_bound.sh).
"""
import argparse
import json
import heapq
import math
import os
import re
import subprocess
import sys


def fail(msg, code=2):
    """One error line and the exit code (2 bad input, 3 a tool or a bug)."""
    print(msg, file=sys.stderr)
    sys.exit(code)


def printed(mmsim, flag, extra):
    """mmsim --print-config or --print-robot (extra: --config FILE and --robot
    FILE, which mmsim checks together) as {section: {key: value}} (INI: key
    = value ; unit; source; numbers as floats, a list of numbers as a list,
    words as strings)."""
    p = subprocess.run([mmsim, flag] + extra, capture_output=True, text=True)
    if p.returncode != 0:
        sys.stderr.write(p.stderr)
        raise SystemExit(p.returncode if p.returncode in (2, 3) else 3)
    out = p.stdout
    sections, cur = {}, None
    for line in out.splitlines():
        line = line.strip()
        if line.startswith("["):
            cur = sections.setdefault(line[1:line.index("]")], {})
        elif "=" in line and not line.startswith(";") and cur is not None:
            k, v = line.split("=", 1)
            v = v.split(";", 1)[0].strip()
            try:
                nums = [float(x) for x in v.split()]
                cur[k.strip()] = nums[0] if len(nums) == 1 else nums
            except ValueError:
                cur[k.strip()] = v
    return sections


def config(mmsim, config_file=None, robot_file=None):
    """The world (mmsim --print-config) and the robot (mmsim --print-robot:
    mm, g, the left motor's figures) as {key: float} in SI units, named as
    Robot reads them."""
    c = {}
    extra = (["--config", config_file] if config_file else []) + (["--robot", robot_file] if robot_file else [])
    for keys in printed(mmsim, "--print-config", extra).values():
        c.update(keys)
    r = printed(mmsim, "--print-robot", extra)
    one = lambda kind: next(v for k, v in r.items() if k.split(".")[0] == kind)
    ch, motor, batt = one("chassis"), r["motor.left"], one("battery")
    c["wheel_d_m"] = (ch["wheel_left_d_mm"] + ch["wheel_right_d_mm"]) / 2 / 1000
    c["wheel_x_m"] = ch["wheel_track_mm"] / 2000
    for k in ("body_mass", "wheel_mass", "caster_mass"):
        c[k + "_kg"] = ch[k + "_g"] / 1000
    c["tyre_mu"] = ch["tyre_mu"]
    for k in ("gear_ratio", "rated_v", "stall_a", "no_load_rpm", "no_load_a", "stall_torque_nm", "rotor_inertia_kgm2"):
        c[k] = motor[k]
    ocv = batt["ocv_v"]
    c["battery_v"] = max(ocv) if isinstance(ocv, list) else ocv  # full charge
    return c


class Robot:
    def __init__(self, c):
        g = 9.81
        self.r = c["wheel_d_m"] / 2
        self.b = c["wheel_x_m"]                        # half track
        self.cell = c["cell_m"]
        self.mass = c["body_mass_kg"] + 2 * c["wheel_mass_kg"] + c["caster_mass_kg"]
        # the datasheet motor (sim/world/motor.c, motor_constants)
        n = c["gear_ratio"]
        self.R = c["rated_v"] / c["stall_a"]
        w_nl = c["no_load_rpm"] * 2 * math.pi / 60 * n
        ke = (c["rated_v"] - self.R * c["no_load_a"]) / w_nl
        eta = c["stall_torque_nm"] / (n * ke * (c["stall_a"] - c["no_load_a"]))
        self.kt_wheel = n * eta * ke                   # N*m/A at the wheel
        self.kn = n * ke                               # V*s/rad at the wheel
        self.t_friction = self.kt_wheel * c["no_load_a"]
        self.v_batt = c["battery_v"]
        j_wheel = 0.5 * c["wheel_mass_kg"] * self.r ** 2 + c["rotor_inertia_kgm2"] * n * n
        self.m_eff = self.mass + 2 * j_wheel / self.r ** 2
        self.grip = c["tyre_mu"] * g                   # m/s^2
        # top speed: no-load at the battery voltage
        self.v_top = (self.v_batt - self.R * c["no_load_a"]) / self.kn * self.r

    def a_motor(self, v):
        """Acceleration both motors give at full voltage at speed v, m/s^2."""
        t = self.kt_wheel * (self.v_batt - self.kn * v / self.r) / self.R - self.t_friction
        return max(0.0, 2 * t / self.r / self.m_eff)


def segments(path, cell, radius):
    """The path as (length_m, kind) pieces from the start cell's centre to
    the goal cell's entry edge: 'start' (untimed half cell), 'straight',
    'arc'. Turns at a cell become an arc of `radius` centred on the corner
    (radius <= cell / 2: the rest of the cell is straight)."""
    heads = []
    for (x0, y0), (x1, y1) in zip(path, path[1:]):
        heads.append((x1 - x0, y1 - y0))
    segs = [(cell / 2, "start")]
    # interior cells: entered with heads[i-1], left with heads[i]
    for i in range(1, len(path) - 1):
        if heads[i] == heads[i - 1]:
            segs.append((cell, "straight"))
        elif heads[i] == (-heads[i - 1][0], -heads[i - 1][1]):
            raise ValueError("a U-turn on a best path")
        else:
            leg = cell / 2 - radius
            if leg > 0:
                segs.append((leg, "straight"))
            segs.append((math.pi / 2 * radius, "arc"))
            if leg > 0:
                segs.append((leg, "straight"))
    return segs


def bound(rb, segs, radius, v_top, v_turn):
    ds = 0.001
    lim, kind = [], []
    step = []                                          # each piece in equal steps of about ds
    for length, k in segs:
        n = max(1, int(round(length / ds)))
        for _ in range(n):
            lim.append(v_turn if k == "arc" else v_top)
            kind.append(k)
            step.append(length / n)
    n = len(lim)
    v = [0.0] * (n + 1)                                # speed at the points between steps
    lat = [(lim[i] ** 2 / radius if kind[i] == "arc" else 0.0) for i in range(n)]

    def long_grip(i):
        return math.sqrt(max(0.0, rb.grip ** 2 - lat[i] ** 2))

    dr = Drive(rb)
    for i in range(n):                                 # speeding up
        if kind[i] == "arc":                           # at the step's first speed (the most grip and torque)
            a = min(rb.a_motor(v[i]), long_grip(i))
            v[i + 1] = min(lim[i], math.sqrt(v[i] ** 2 + 2 * a * step[i]))
        else:                                          # in closed form (Drive): exact
            v[i + 1] = dr.up(v[i], step[i], lim[i])
        if i + 1 < n:
            v[i + 1] = min(v[i + 1], lim[i + 1])
    for i in range(n - 1, -1, -1):                     # braking (the end speed is free)
        v[i] = min(v[i], math.sqrt(v[i + 1] ** 2 + 2 * long_grip(i) * step[i]))
    t = {"start": 0.0, "straight": 0.0, "arc": 0.0}
    for i in range(n):
        vm = 0.5 * (v[i] + v[i + 1])
        t[kind[i]] += step[i] / vm if vm > 0 else float("inf")
    return t, max(v)



# ---- the diagonal bound: every path of the speed run's moves (firmware/slalom.h) ----

class Drive:
    """Speeding up and braking on a straight in closed form (m, s): speeding
    up at a(v) = min(mu*g, alpha - beta*v), both motors at full voltage
    (Robot.a_motor: the torque falls linearly with speed and is zero at the
    top speed alpha / beta), braking at mu*g."""

    def __init__(self, rb):
        self.grip = rb.grip
        self.alpha = 2 * (rb.kt_wheel * rb.v_batt / rb.R - rb.t_friction) / rb.r / rb.m_eff   # m/s^2
        self.beta = 2 * rb.kt_wheel * rb.kn / (rb.R * rb.r ** 2 * rb.m_eff)                  # 1/s
        self.v_max = self.alpha / self.beta                                                  # m/s
        # the top speed is only approached: taken as reached within 1e-12 of
        # it (dist and time finite there), which only shortens the times
        self.v_near = self.v_max * (1 - 1e-12)
        self.v_g = min(self.v_max, max(0.0, (self.alpha - self.grip) / self.beta))  # grip-limited below, m/s
        self.s_g = self.v_g ** 2 / (2 * self.grip)

    def _motor_dist(self, u):
        """The integral of u / (alpha - beta*u) du (distance while motor-limited)."""
        a, b = self.alpha, self.beta
        return -u / b - a / b ** 2 * math.log(a - b * u)

    def dist(self, v):
        """Distance to speed up from rest to v (to v_near above it), m."""
        if v <= self.v_g:
            return v * v / (2 * self.grip)
        v = min(v, self.v_near)
        return self.s_g + self._motor_dist(v) - self._motor_dist(self.v_g)

    def time(self, v):
        """Time to speed up from rest to v (to v_near above it), s."""
        if v <= self.v_g:
            return v / self.grip
        v = min(v, self.v_near)
        return self.v_g / self.grip - math.log((self.alpha - self.beta * v) / (self.alpha - self.beta * self.v_g)) / self.beta

    def up(self, v, length, cap):
        """The highest speed after speeding up from v over length, at most cap."""
        if v >= cap:
            return cap
        s = self.dist(v) + length
        if s <= self.s_g:
            return min(cap, math.sqrt(2 * self.grip * s))
        lo, hi = self.v_g, min(cap, self.v_max)
        if self.dist(hi) <= s:
            return hi
        for _ in range(50):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if self.dist(mid) < s else (lo, mid)
        return hi                                      # rounded up: a bound

    def down(self, v, length, cap):
        """The highest speed length before a point passed at v (braking), at most cap."""
        return min(cap, math.sqrt(v * v + 2 * self.grip * length))

    def piece_time(self, a, b, length, cap):
        """The least time over a piece of length at most cap, entered at a and
        left at b (a pair the piece allows): speed up from a, hold cap, brake to b."""
        if length <= 0:
            return 0.0
        g2 = 2 * self.grip
        da = self.dist(a)
        full = self.dist(cap) - da + (cap * cap - b * b) / g2
        if full <= length:
            return self.time(cap) - self.time(a) + (cap - b) / self.grip + (length - full) / cap
        lo, hi = max(a, b), cap                        # the peak speed
        for _ in range(50):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if self.dist(mid) - da + (mid * mid - b * b) / g2 < length else (lo, mid)
        # peak rounded down: a bound; within a rounding of the top speed the
        # distance left (dist's logarithm saturates there) is covered at cap
        rest = length - (self.dist(lo) - da + (lo * lo - b * b) / g2)
        return self.time(lo) - self.time(a) + (lo - b) / self.grip + max(0.0, rest) / cap


def reach_fwd(dr, pieces, v):
    """The highest exit speed over pieces ((length_m, cap_m_s), ...) from entry speed v."""
    for length, cap in pieces:
        v = dr.up(min(v, cap), length, cap)
    return v


def reach_back(dr, pieces, v):
    """The highest entry speed from which pieces can be left at v."""
    for length, cap in reversed(pieces):
        v = dr.down(min(v, cap), length, cap)
    return v


def pieces_time(dr, pieces, vin, vout):
    """The least time over pieces from vin to vout (a pair they allow): the
    speed everywhere the lower of speeding up from vin and braking to vout."""
    n = len(pieces)
    f = [vin]
    for k, (length, cap) in enumerate(pieces):
        v = dr.up(min(f[-1], cap), length, cap)
        f.append(min(v, pieces[k + 1][1]) if k + 1 < n else v)
    b = [vout]
    for k in range(n - 1, -1, -1):
        length, cap = pieces[k]
        v = dr.down(min(b[0], cap), length, cap)
        b.insert(0, min(v, pieces[k - 1][1]) if k > 0 else v)
    u = [min(x, y) for x, y in zip(f, b)]
    return sum(dr.piece_time(u[k], u[k + 1], length, cap) for k, (length, cap) in enumerate(pieces))


def bin_time(dr, pieces, lo_i, hi_i, lo_j, hi_j):
    """The least time over pieces entered at a speed in [lo_i, hi_i] and left
    at one in [lo_j, hi_j], or None if no such pair is possible. Higher
    entry and exit speeds are never slower, so the best pair is the highest
    one the pieces allow."""
    eps = 1e-9
    vin = min(hi_i, pieces[0][1])
    if vin < lo_i - eps:
        return None
    vout = min(hi_j, reach_fwd(dr, pieces, vin), pieces[-1][1])
    if vout < lo_j - eps:
        return None
    vin = min(vin, reach_back(dr, pieces, vout))
    if vin < lo_i - eps:
        return None
    return pieces_time(dr, pieces, vin, vout)



HEADS = [(0, 1), (1, 1), (1, 0), (1, -1), (0, -1), (-1, -1), (-1, 0), (-1, 1)]   # 45-degree steps clockwise from N


def slalom_table(path):
    """firmware/slalom.c's turns: {name: (exit, turn, from_diag, corner, crossed)}
    in half units for the right-hand turn entered at (0, 0) heading N (NE
    if from_diag), read from its initializer (slalom.h)."""
    turns = {}
    try:
        text = open(path).read()
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    for n, line in enumerate(text.splitlines(), 1):
        m = re.match(r"\s*\[SLALOM_(\w+)\]\s*=\s*\{(.*)\},\s*$", line)
        if not m:
            continue
        v = [int(x) for x in re.findall(r"-?\d+", m.group(2))]
        if v == [0]:
            continue                                   # the straights: their geometry follows from n
        if len(v) < 7 or len(v) != 7 + 2 * v[6]:
            fail(f"{path}:{n}:1: a turn's entry is not {{exit x, y, turn, from_diag, corner x, y, crossed, {{...}}}}")
        turns[m.group(1)] = ((v[0], v[1]), v[2], v[3], (v[4], v[5]), [(v[7 + 2 * k], v[8 + 2 * k]) for k in range(v[6])])
    if not turns:
        fail(f"{path}:1:1: no turns in the slalom_geom table")
    return turns


def turn_shape(exit_, turn, corner):
    """A turn's pieces in half units, [(length, radius or 0 for straight)]:
    the arc of the largest radius that fits its corner room (R * tan(A/2)
    at most the room on either side of the corner); a 180 is a half circle
    about its corner (the arc's centre in slalom.c)."""
    if turn == 4:
        r = math.hypot(*corner)
        return [(math.pi * r, r)]
    a = math.hypot(*corner)
    b = math.hypot(exit_[0] - corner[0], exit_[1] - corner[1])
    ang = turn * math.pi / 4
    t = math.tan(ang / 2)
    r = min(a, b) / t
    return [(max(0.0, a - r * t), 0.0), (r * ang, r), (max(0.0, b - r * t), 0.0)]


def shape_points(shape, diag, step):
    """Points every `step` half units along a right-hand turn's shape (from
    (0, 0) heading N, or NE if diag), with their distances from the entry."""
    ux, uy = HEADS[1 if diag else 0]
    norm = math.hypot(ux, uy)
    ux, uy = ux / norm, uy / norm
    x = y = s = 0.0
    pts = [(1e-6 * ux, 1e-6 * uy, 0.0)]
    for length, r in shape:
        n = max(1, int(math.ceil(length / step)))
        if r == 0.0:
            for k in range(1, n + 1):
                pts.append((x + ux * length * k / n, y + uy * length * k / n, s + length * k / n))
            x, y = x + ux * length, y + uy * length
        else:
            cx, cy = x + r * uy, y - r * ux            # centre on the right
            phi = length / r
            for k in range(1, n + 1):
                p = phi * k / n                        # clockwise about the centre
                dx, dy = x - cx, y - cy
                pts.append((cx + dx * math.cos(p) + dy * math.sin(p), cy - dx * math.sin(p) + dy * math.cos(p), s + length * k / n))
            dx, dy = x - cx, y - cy
            x, y = cx + dx * math.cos(phi) + dy * math.sin(phi), cy - dx * math.sin(phi) + dy * math.cos(phi)
            ux, uy = ux * math.cos(phi) + uy * math.sin(phi), -ux * math.sin(phi) + uy * math.cos(phi)
        s += length
    return pts


def place(x, y, diag, left, h):
    """A right-hand turn's point (table frame) for entry heading h, turning left if `left`."""
    if left:
        x, y = (y, x) if diag else (-x, y)
    for _ in range(h // 2):
        x, y = y, -x                                   # 90 degrees clockwise
    return x, y



class Maze:
    """A maze's walls, start and goal from `mmmaze show` (the text format
    with 'S' in the start cell and 'G' in every goal cell), in the
    half-cell grid of firmware/slalom.h: cell (x, y) centred at (2x, 2y)."""

    def __init__(self, text, name):
        rows = text.rstrip("\n").split("\n")
        self.h = (len(rows) - 1) // 2
        self.w = (max(len(r) for r in rows) - 1) // 4
        if self.w < 1 or self.h < 1 or not rows[0].startswith(("o", "+")):
            fail(f"{name}:1:1: not a maze in the text format")
        rows = [r.ljust(4 * self.w + 1) for r in rows]
        line = lambda y: 2 * (self.h - 1 - y) + 1      # the text line of cell row y
        self.east = {(x, y) for x in range(self.w) for y in range(self.h) if rows[line(y)][4 * x + 4] == "|"}
        self.north = {(x, y) for x in range(self.w) for y in range(self.h) if rows[line(y) - 1][4 * x + 2] == "-"}
        letter = {(x, y): rows[line(y)][4 * x + 2] for x in range(self.w) for y in range(self.h)}
        self.goal = {c for c, k in letter.items() if k == "G"}
        starts = [c for c, k in letter.items() if k == "S"]
        self.start = starts[0] if starts else (0, 0)

    def inside(self, c):
        return 0 <= c[0] < self.w and 0 <= c[1] < self.h

    def open(self, X, Y):
        """Whether the side middle (X, Y) is open (no wall, both cells in the maze)."""
        if X % 2 == 1 and Y % 2 == 0:
            a, b = ((X - 1) // 2, Y // 2), ((X + 1) // 2, Y // 2)
            return self.inside(a) and self.inside(b) and a not in self.east
        if X % 2 == 0 and Y % 2 == 1:
            a, b = (X // 2, (Y - 1) // 2), (X // 2, (Y + 1) // 2)
            return self.inside(a) and self.inside(b) and a not in self.north
        return False

    def crossing(self, X, Y, h):
        """(cell left, cell entered) crossing the side middle (X, Y) heading h."""
        dx, dy = HEADS[h]
        if X % 2 == 1:
            return ((X - dx) // 2, Y // 2), ((X + dx) // 2, Y // 2)
        return (X // 2, (Y - dy) // 2), (X // 2, (Y + dy) // 2)


def valid_state(mz, X, Y, h):
    """A node and heading a run can pass: an open side middle, crossed (an
    orthogonal heading crosses its side; a diagonal one may pass either kind)."""
    if not mz.open(X, Y):
        return False
    return h % 2 == 1 or (h % 4 == 0) == (Y % 2 == 1)


def truncate(pieces, dist):
    """The pieces' first dist metres."""
    out = []
    for length, cap in pieces:
        if dist <= 0:
            break
        out.append((min(length, dist), cap))
        dist -= length
    return out



class DiagBound:
    """The least time over every path of the speed run's moves from the
    start to the goal (the module's docstring, "Diagonal bound"): A* over
    (node, heading, speed bin) in the half-cell grid."""

    def __init__(self, rb, slalom_c, v_top, bins):
        self.dr = Drive(rb)
        self.half = rb.cell / 2                        # m
        self.v_top = v_top
        self.turn_cap = lambda r: min(math.sqrt(rb.grip * r), v_top * r / (r + rb.b))   # m/s at radius r m
        self.turns = slalom_table(slalom_c)
        self.types, self.type_id = [], {}              # edge kinds: pieces ((length m, cap m/s), ...)
        self.shapes = {k: turn_shape(e, t, c) for k, (e, t, d, c, x) in self.turns.items()}
        # each turn's shape sampled every 0.5 mm (in half units), for the goal cells it enters
        self.points = {k: shape_points(self.shapes[k], self.turns[k][2], 0.5e-3 / self.half) for k in self.turns}
        self.v_start = self.dr.up(0.0, self.half, v_top)   # leaving the start cell from rest at its centre
        caps = {v_top, self.v_start} | {self.turn_cap(r * self.half) for s in self.shapes.values() for _, r in s if r}
        grid = sorted({v_top * k / bins for k in range(bins + 1)} | {c for c in caps if c <= v_top})
        self.grid = [g for k, g in enumerate(grid) if k + 1 == len(grid) or grid[k + 1] - g > 1e-9]   # speed bins' tops, m/s
        self.exits, self.free = {}, {}                 # per (kind, bin): [(bin, s)], s to the goal
        self.entered = {}

    def kind(self, key, pieces):
        if key not in self.type_id:
            self.type_id[key] = len(self.types)
            self.types.append(tuple(pieces))
        return self.type_id[key]

    def turn_pieces(self, name):
        return [(length * self.half, self.turn_cap(r * self.half) if r else self.v_top) for length, r in self.shapes[name]]

    def bounds(self, j):
        return (self.grid[j - 1] if j else 0.0), self.grid[j]

    def exits_of(self, t, i):
        """[(exit bin, least time)] over edge kind t entered in bin i."""
        key = (t, i)
        if key not in self.exits:
            lo_i, hi_i = self.bounds(i)
            out = []
            for j in range(len(self.grid)):
                s = bin_time(self.dr, self.types[t], lo_i, hi_i, *self.bounds(j))
                if s is not None:
                    out.append((j, s))
            self.exits[key] = out
        return self.exits[key]

    def free_of(self, t, i):
        """The least time over edge kind t entered in bin i, any exit speed (it ends the run)."""
        key = (t, i)
        if key not in self.free:
            s = bin_time(self.dr, self.types[t], *self.bounds(i), 0.0, math.inf)
            self.free[key] = math.inf if s is None else s
        return self.free[key]

    def cells_entered(self, name, left, h, px, py):
        """[(dx, dy, distance m)]: the cells a turn's shape enters, in order,
        relative to the entry node's (X // 2, Y // 2); px, py the node's parities."""
        key = (name, left, h, px, py)
        if key not in self.entered:
            out, last = [], None
            prev_s = 0.0
            for x, y, s in self.points[name]:
                x, y = place(x, y, self.turns[name][2], left, h)
                c = (math.floor((px + x + 1) / 2), math.floor((py + y + 1) / 2))
                if last is not None and c != last:
                    out.append((c[0], c[1], prev_s * self.half))   # the sample before: never late
                last, prev_s = c, s
            self.entered[key] = out
        return self.entered[key]


    def straights(self, mz, X, Y, h):
        """[(target, kind)]: orthogonal straights of whole cells, diagonal ones of half steps."""
        dx, dy = HEADS[h]
        step, unit = (1, math.sqrt(2)) if h % 2 else (2, 2.0)
        out, n = [], step
        while mz.open(X + n * dx, Y + n * dy):
            length = n // step * unit * self.half
            out.append(((X + n * dx, Y + n * dy, h), self.kind(("S", h % 2, n), [(length, self.v_top)])))
            n += step
        return out

    def turns_from(self, mz, X, Y, h):
        """[(target or None for the goal, kind)]: the table's turns that fit
        here (every side middle crossed open, the exit a valid state); a turn
        that enters a goal cell before its exit ends there."""
        out = []
        for name, (ex, turn, diag, _corner, crossed) in self.turns.items():
            if diag != h % 2:
                continue
            for left in (False, True):
                if not all(mz.open(X + a, Y + b) for a, b in (place(p[0], p[1], diag, left, h) for p in crossed)):
                    continue
                h2 = (h - turn) % 8 if left else (h + turn) % 8
                ax, ay = place(ex[0], ex[1], diag, left, h)
                if not valid_state(mz, X + ax, Y + ay, h2):
                    continue
                pieces = self.turn_pieces(name)
                total = sum(p[0] for p in pieces)
                end = (X + ax, Y + ay, h2)
                for cx, cy, s in self.cells_entered(name, left, h, X % 2, Y % 2):
                    if (X // 2 + cx, Y // 2 + cy) in mz.goal and s < total - 1e-3:
                        end = None
                        pieces = truncate(pieces, s)
                        break
                key = ("T", name) if end else ("G", name, round(s, 9))
                out.append((end, self.kind(key, pieces)))
        return out

    @staticmethod
    def at_goal(mz, s):
        """Whether passing state s enters a goal cell (and so ends the run)."""
        left, entered = mz.crossing(*s)
        return entered in mz.goal and left not in mz.goal

    def graph(self, mz):
        """{state: [(target state or None, kind)]} over the maze's states;
        states that enter a goal cell end the run and have no edges."""
        adj = {}
        for X in range(-1, 2 * mz.w):
            for Y in range(-1, 2 * mz.h):
                for h in range(8):
                    if not valid_state(mz, X, Y, h):
                        continue
                    if self.at_goal(mz, (X, Y, h)):
                        adj[(X, Y, h)] = []
                    else:
                        adj[(X, Y, h)] = self.straights(mz, X, Y, h) + self.turns_from(mz, X, Y, h)
        return adj

    def heuristic(self, mz, adj):
        """Each state's least time to the goal at every piece's speed cap
        (no speeding up or braking): never more than the true time, so A*
        stays exact."""
        rev = {s: [] for s in adj}
        goal_cost = {}
        for s, edges in adj.items():
            if self.at_goal(mz, s):
                goal_cost[s] = 0.0
            for t, k in edges:
                c = sum(length / cap for length, cap in self.types[k])
                if t is None:
                    goal_cost[s] = min(goal_cost.get(s, math.inf), c)
                else:
                    rev[t].append((s, c))
        best = dict(goal_cost)
        heap = [(c, s) for s, c in goal_cost.items()]
        heapq.heapify(heap)
        while heap:
            c, s = heapq.heappop(heap)
            if c > best.get(s, math.inf):
                continue
            for p, e in rev[s]:
                if c + e < best.get(p, math.inf):
                    best[p] = c + e
                    heapq.heappush(heap, (c + e, p))
        return best


    def search(self, mz):
        """The least time from leaving the start cell to entering a goal cell,
        s, and the path's moves (route). A label is (state, 2 * speed bin +
        1 if it came by a straight): a straight never follows a straight
        (the two are one longer straight, and one is never slower)."""
        adj = self.graph(mz)
        hx = self.heuristic(mz, adj)
        straight = {k for key, k in self.type_id.items() if key[0] == "S"}
        sx, sy = mz.start
        j_start = next(j for j, g in enumerate(self.grid) if g >= self.v_start - 1e-12)
        best, came, heap = {}, {}, []
        for dx, dy, h in ((0, 1, 0), (1, 0, 2), (0, -1, 4), (-1, 0, 6)):   # an untimed turn in place first
            s = (2 * sx + dx, 2 * sy + dy, h)
            if s in adj and s in hx:
                for j in range(j_start + 1):
                    best[(s, 2 * j)] = 0.0
                    heapq.heappush(heap, (hx[s], 0.0, s, 2 * j))
        while heap:
            f, d, s, i = heapq.heappop(heap)
            if s == ():                                # the goal
                return d, self.route(came, i)
            if d > best.get((s, i), math.inf):
                continue
            if self.at_goal(mz, s):
                heapq.heappush(heap, (d, d, (), (s, i)))
                continue
            for t, k in adj[s]:
                if i % 2 and k in straight:
                    continue
                if t is None:
                    nd = d + self.free_of(k, i // 2)
                    heapq.heappush(heap, (nd, nd, (), (s, i, k)))
                    continue
                if t not in hx:
                    continue
                for j, e in self.exits_of(k, i // 2):
                    nd, key = d + e, (t, 2 * j + (k in straight))
                    if nd < best.get(key, math.inf):
                        best[key] = nd
                        came[key] = (s, i, k)
                        heapq.heappush(heap, (nd + hx[t], nd, t, key[1]))
        return math.inf, []

    def route(self, came, end):
        """The path's moves: [(kind key, state it starts from, speed bin there)]."""
        keys = {v: k for k, v in self.type_id.items()}
        out, node = [], end
        if len(node) == 3:                             # a turn that ends the run inside it
            out.append((keys[node[2]], node[0], node[1] // 2))
            node = node[:2]
        while node in came:
            s, i, k = came[node]
            out.append((keys[k], s, i // 2))
            node = (s, i)
        return out[::-1]



def maze_text(mmmaze, m):
    """`mmmaze show m`: the maze normalised, with its start and goal letters."""
    out = subprocess.run([mmmaze, "show", m], capture_output=True, text=True)
    if out.returncode != 0:
        sys.stderr.write(out.stderr)
        raise SystemExit(out.returncode if out.returncode in (2, 3) else 3)
    return out.stdout


def ortho_result(a, rb, m, radius, v_top, v_turn):
    """The orthogonal bound on m's best path as a dict, or None if the goal is unreachable."""
    out = subprocess.run([a.mmmaze, "solve", m, "--json"], capture_output=True, text=True)
    if out.returncode not in (0, 1):
        sys.stderr.write(out.stderr)
        raise SystemExit(out.returncode if out.returncode in (2, 3) else 3)
    d = json.loads(out.stdout) if out.stdout.strip() else {}
    if not d.get("goal_reachable"):
        return None
    segs = segments(d["path"], rb.cell, radius)
    t, vmax = bound(rb, segs, radius, v_top, v_turn)
    total = t["straight"] + t["arc"]
    length = sum(s for s, k in segs if k != "start")
    return {"maze": m, "cells": d["cells"], "turns": d["turns"], "timed_length_m": round(length, 3),
            "bound_s": round(total, 2), "straights_s": round(t["straight"], 2), "turns_s": round(t["arc"], 2),
            "top_speed_reached_m_s": round(vmax, 3)}


def diag_result(db, mmmaze, m):
    """The diagonal bound on m as a dict: the bound, its path's moves and
    length, and that path's own time at the model's limits without speed
    bins (the bound is at most this; the least time over all paths lies
    between the two)."""
    t, route = db.search(Maze(maze_text(mmmaze, m), m))
    pieces = [p for key, _s, _i in route for p in db.types[db.type_id[key]]]
    vin = min(db.v_start, pieces[0][1]) if pieces else 0.0
    path_s = pieces_time(db.dr, pieces, vin, reach_fwd(db.dr, pieces, vin)) if pieces else 0.0
    if math.isnan(t) or math.isnan(path_s):
        fail(f"lower_bound: {m}: a time is not a number (a bug)", 3)
    names = [key[1] if key[0] in ("T", "G") else ("diag" if key[1] else "straight") for key, _s, _i in route]
    return {"diag_bound_s": round(t, 2), "diag_path_s": round(path_s, 2),
            "diag_length_m": round(sum(p[0] for p in pieces), 3), "diag_moves": len(route),
            "diag_turns": {n: names.count(n) for n in sorted(set(names)) if n not in ("straight", "diag")}}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.error = lambda msg: fail(f"lower_bound: {msg}")
    ap.add_argument("--mmsim", default="build/mmsim")
    ap.add_argument("--mmmaze", default="build/mmmaze")
    ap.add_argument("--config", help="mmsim --config: the world (default: mmsim's)")
    ap.add_argument("--robot", help="mmsim --robot: the robot file (default: mmsim's)")
    ap.add_argument("--radius-mm", type=float, help="the orthogonal bound's turn radius (default: half a cell)")
    ap.add_argument("--v-top-mm-s", type=float, help="straights' speed limit (default: the motor's no-load speed)")
    ap.add_argument("--turn-mm-s", type=float, help="the orthogonal bound's turn speed (default: friction and outer wheel)")
    ap.add_argument("--bins", type=int, default=24, help="the diagonal bound's speed bins (more: tighter, slower)")
    ap.add_argument("--slalom", default=os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                                     "firmware", "slalom.c"), help="the moves' geometry table")
    ap.add_argument("--no-diagonal", action="store_true", help="the orthogonal bound only")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("mazes", nargs="+")
    a = ap.parse_args()
    if a.bins < 1:
        fail("lower_bound: --bins must be at least 1")
    rb = Robot(config(a.mmsim, a.config, a.robot))
    radius = a.radius_mm / 1000 if a.radius_mm else rb.cell / 2
    v_top = a.v_top_mm_s / 1000 if a.v_top_mm_s else rb.v_top
    v_friction = math.sqrt(rb.grip * radius)
    v_wheel = v_top * radius / (radius + rb.b)
    v_turn = a.turn_mm_s / 1000 if a.turn_mm_s else min(v_friction, v_wheel)
    db = None if a.no_diagonal else DiagBound(rb, a.slalom, v_top, a.bins)
    if not a.json:
        header(rb, db, radius, v_top, v_friction, v_wheel, v_turn)
    rc = 0
    for m in a.mazes:
        res = ortho_result(a, rb, m, radius, v_top, v_turn)
        if res is None:
            print(f"{m}: goal unreachable", file=sys.stderr)
            rc = 1
            continue
        if db:
            res.update(diag_result(db, a.mmmaze, m))
        print(json.dumps(res) if a.json else line(res))
    return rc


def header(rb, db, radius, v_top, v_friction, v_wheel, v_turn):
    print(f"robot: {rb.mass * 1000:.0f} g, effective {rb.m_eff * 1000:.0f} g; motor top speed "
          f"{rb.v_top * 1000:.0f} mm/s (straights at {v_top * 1000:.0f}); speeding up from rest at "
          f"min({rb.a_motor(0):.2f} motor, {rb.grip:.2f} tyres) m/s^2, {rb.a_motor(0.5):.2f} at 0.5 m/s; braking "
          f"{rb.grip:.2f} m/s^2")
    print(f"turns: R {radius * 1000:.0f} mm, friction limit {v_friction * 1000:.0f} mm/s, outer wheel at top "
          f"speed {v_wheel * 1000:.0f} mm/s -> {v_turn * 1000:.0f} mm/s "
          f"({v_turn ** 2 / radius / 9.81:.2f} g sideways)")
    if db:
        arcs = ", ".join(f"{k} R {r * db.half * 1000:.0f} mm {db.turn_cap(r * db.half) * 1000:.0f} mm/s"
                         for k, s in db.shapes.items() for _, r in s if r)
        print(f"diagonal: {len(db.grid) - 1} speed bins; turns at their largest arcs: {arcs}")


def line(res):
    s = (f"{res['maze']}: {res['cells']} cells, {res['turns']} turns, {res['timed_length_m']:.2f} m timed: lower bound "
         f"{res['bound_s']:.2f} s ({res['straights_s']:.2f} s straights, {res['turns_s']:.2f} s in turns; "
         f"fastest {res['top_speed_reached_m_s'] * 1000:.0f} mm/s)")
    if "diag_bound_s" in res:
        turns = ", ".join(f"{n} {c}" for n, c in res["diag_turns"].items())
        s += (f"; diagonal bound {res['diag_bound_s']:.2f} s ({res['diag_moves']} moves, {res['diag_length_m']:.2f} m: "
              f"{turns}; that path {res['diag_path_s']:.2f} s without speed bins)")
    return s


if __name__ == "__main__":
    sys.exit(main())
