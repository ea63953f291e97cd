#!/usr/bin/env python3
"""lower_bound.py - a physical lower bound on a speed run of a maze's best path.

    bench/lower_bound.py [--mmsim build/mmsim] [--mmmaze build/mmmaze]
                         [--radius-mm 90] [--v-top-mm-s V] [--turn-mm-s V] MAZE...

The path is the one the firmware races: `mmmaze solve`'s best path (least
cells + quarter turns, sim/maze/solve.h). The robot and the motor are
mmsim's (`mmsim --print-config`, `--print-robot`), so the bound follows the
config and the robot file:

- straights: up to the motor's top speed, the no-load wheel speed at the
  battery voltage (450 rpm at 6 V with 32 mm wheels: 754 mm/s);
- speeding up: both motors at the full battery voltage, each wheel's torque
  N*eta*Kt*(V - N*Ke*w)/R less the gearbox friction N*eta*Kt*i0, pushing the
  effective mass (the robot plus each wheel's and rotor's inertia over r^2:
  0.306 kg), and at most the tyres' grip, mu*g;
- braking: the tyres' grip, mu*g (the motors could brake harder);
- turns: each 90-degree turn a circular arc of radius 90 mm (--radius-mm)
  from the turn cell's entry edge to its exit edge (the largest arc that
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
not pitch. Integrated forward (speeding up) and backward (braking) over the
path in 1 mm steps.
"""
import argparse
import json
import math
import subprocess
import sys


def printed(mmsim, flag):
    """mmsim --print-config or --print-robot as {section: {key: value}}
    (INI: key = value ; unit; source; numbers as floats, a list of numbers
    as a list, words as strings)."""
    out = subprocess.run([mmsim, flag], check=True, capture_output=True, text=True).stdout
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


def config(mmsim):
    """The world (mmsim --print-config) and the robot (mmsim --print-robot:
    mm, g, the left motor's figures) as {key: float} in SI units, named as
    Robot reads them."""
    c = {}
    for keys in printed(mmsim, "--print-config").values():
        c.update(keys)
    r = printed(mmsim, "--print-robot")
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

    for i in range(n):                                 # speeding up
        a = min(rb.a_motor(v[i]), long_grip(i))
        v[i + 1] = min(lim[i], math.sqrt(v[i] ** 2 + 2 * a * step[i]))
        if i + 1 < n:
            v[i + 1] = min(v[i + 1], lim[i + 1])
    for i in range(n - 1, -1, -1):                     # braking (the end speed is free)
        v[i] = min(v[i], math.sqrt(v[i + 1] ** 2 + 2 * long_grip(i) * step[i]))
    t = {"start": 0.0, "straight": 0.0, "arc": 0.0}
    for i in range(n):
        vm = 0.5 * (v[i] + v[i + 1])
        t[kind[i]] += step[i] / vm if vm > 0 else float("inf")
    return t, max(v)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--mmsim", default="build/mmsim")
    ap.add_argument("--mmmaze", default="build/mmmaze")
    ap.add_argument("--radius-mm", type=float, default=90.0)
    ap.add_argument("--v-top-mm-s", type=float, help="straights' speed limit (default: the motor's no-load speed)")
    ap.add_argument("--turn-mm-s", type=float, help="turns' speed limit (default: friction and outer wheel)")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("mazes", nargs="+")
    a = ap.parse_args()
    rb = Robot(config(a.mmsim))
    radius = a.radius_mm / 1000
    v_top = a.v_top_mm_s / 1000 if a.v_top_mm_s else rb.v_top
    v_friction = math.sqrt(rb.grip * radius)
    v_wheel = v_top * radius / (radius + rb.b)
    v_turn = a.turn_mm_s / 1000 if a.turn_mm_s else min(v_friction, v_wheel)
    if not a.json:
        print(f"robot: {rb.mass * 1000:.0f} g, effective {rb.m_eff * 1000:.0f} g; motor top speed "
              f"{rb.v_top * 1000:.0f} mm/s (straights at {v_top * 1000:.0f}); speeding up from rest at "
              f"min({rb.a_motor(0):.2f} motor, {rb.grip:.2f} tyres) m/s^2, {rb.a_motor(0.5):.2f} at 0.5 m/s; braking "
              f"{rb.grip:.2f} m/s^2")
        print(f"turns: R {radius * 1000:.0f} mm, friction limit {v_friction * 1000:.0f} mm/s, outer wheel at top "
              f"speed {v_wheel * 1000:.0f} mm/s -> {v_turn * 1000:.0f} mm/s "
              f"({v_turn ** 2 / radius / 9.81:.2f} g sideways)")
    rc = 0
    for m in a.mazes:
        out = subprocess.run([a.mmmaze, "solve", m, "--json"], capture_output=True, text=True)
        d = json.loads(out.stdout) if out.stdout.strip() else {}
        if not d.get("goal_reachable"):
            print(f"{m}: goal unreachable", file=sys.stderr)
            rc = 1
            continue
        segs = segments(d["path"], rb.cell, radius)
        t, vmax = bound(rb, segs, radius, v_top, v_turn)
        total = t["straight"] + t["arc"]
        length = sum(s for s, k in segs if k != "start")
        res = {"maze": m, "cells": d["cells"], "turns": d["turns"], "timed_length_m": round(length, 3),
               "bound_s": round(total, 2), "straights_s": round(t["straight"], 2), "turns_s": round(t["arc"], 2),
               "top_speed_reached_m_s": round(vmax, 3)}
        if a.json:
            print(json.dumps(res))
        else:
            print(f"{m}: {d['cells']} cells, {d['turns']} turns, {length:.2f} m timed: lower bound "
                  f"{total:.2f} s ({t['straight']:.2f} s straights, {t['arc']:.2f} s in turns; "
                  f"fastest {vmax * 1000:.0f} mm/s)")
    return rc


if __name__ == "__main__":
    sys.exit(main())
