#!/usr/bin/env python3
"""robot_config_check.py - the example firmware's robot constants
(firmware/robot_config.h) against the robot the simulator loads
(robots/paper.ini through mmsim's own loader: --print-robot; the maze's
cell and wall through --print-config), so that neither can change without
the other.

  robot_config_check.py MMSIM [HEADER [ROBOT_INI [CONFIG]]]
      (defaults: firmware/robot_config.h, robots/paper.ini, mmsim's own
      config; CONFIG: the --config file with the maze's cell and wall)

Prints one line per constant, "ok: ..." or "FAILED: ..."; exits 0 if all
agree, 1 if one does not, 2 if a file or a figure is missing.

Tolerances, and why:
- lengths (wheel diameter, track, sensor positions, cell, wall): 0.1 mm.
  Both sides write them in whole or tenth millimetres, so they agree
  exactly; 0.1 mm is below any real change of a part.
- RC_ODOM_TRACK_MM: within 1 mm of the track. It is the track tuned for
  tyre scrub (0.2 mm more, robot_config.h says why), not a copy of it.
- RC_SIDE_WALL_MM (a diagonal sensor's reading of a side wall: along its
  cone's edge nearest the wall's normal, yaw - fov_deg / 2 off it; along
  the axis with fov_deg 0): 0.5 mm; the firmware
  writes it in whole mm.
- the diagonal sensors' yaw: 0.5 degree (the firmware assumes 45).
- counts per wheel turn (encoder_ppr x gear_ratio): 0.05 %; the firmware
  writes 358.32, the exact product.
- the motor and mass figures the firmware derives by hand (RC_MM_S_PER_CMD,
  RC_CMD_FRICTION, RC_CMD_PER_MM_S2, RC_CMD_PER_ARC_MM_S2): 0.5 %. They are
  written to 3-4 significant digits from the same datasheet figures, which
  rounds by less than 0.1 %; the smallest real change (another gearbox,
  wheel or motor winding) moves them by several percent. The formulas are
  the ones robot_config.h's comments give.
"""
import math
import re
import subprocess
import sys


def defines(path):
    """RC_* name: value for the header's plain numeric #defines (the first
    of each name: the host build's when #ifdef __AVR__ gives two)."""
    out = {}
    text = open(path, encoding="utf-8").read()
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    for m in re.finditer(r"(?m)^\s*#\s*define\s+(RC_\w+)\s+([-+0-9.eE]+)f?\s*$", text):
        out.setdefault(m.group(1), float(m.group(2)))
    return out


def printed(cmd):
    """section.key: value of mmsim's --print-robot / --print-config text."""
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        print(f"robot_config_check: {' '.join(cmd)}: exit {r.returncode}: {r.stderr.strip()}")
        sys.exit(2)
    out, section = {}, ""
    for line in r.stdout.splitlines():
        line = line.split(";", 1)[0].strip()
        if line.startswith("["):
            section = line.strip("[]")
        elif "=" in line:
            k, v = (s.strip() for s in line.split("=", 1))
            try:
                out[f"{section}.{k}"] = float(v)
            except ValueError:
                out[f"{section}.{k}"] = v
    return out


def main():
    if len(sys.argv) < 2:
        print("usage: robot_config_check.py MMSIM [HEADER [ROBOT_INI [CONFIG]]]")
        return 2
    mmsim = sys.argv[1]
    header = sys.argv[2] if len(sys.argv) > 2 else "firmware/robot_config.h"
    ini = sys.argv[3] if len(sys.argv) > 3 else "robots/paper.ini"
    rc = defines(header)
    rob = printed([mmsim, "--print-robot", "--robot", ini])
    cfg = printed([mmsim, "--print-config", "--robot", ini] + (["--config", sys.argv[4]] if len(sys.argv) > 4 else []))
    fails = []

    def get(d, key, where):
        if key not in d:
            print(f"robot_config_check: {where}: no {key}")
            sys.exit(2)
        return d[key]

    def check(name, model, tol, unit, why):
        fw = get(rc, name, header)
        bad = abs(fw - model) > (tol if unit != "%" else tol / 100 * abs(model))
        word = "FAILED" if bad else "ok"
        print(f"{word}: {name} = {fw:g}, {why} = {model:.6g} (tolerance {tol:g} {unit})")
        if bad:
            fails.append(name)

    R = lambda k: get(rob, k, ini)
    body = "chassis.body."
    for side in ("left", "right"):
        check("RC_WHEEL_DIAMETER_MM", R(f"{body}wheel_{side}_d_mm"), 0.1, "mm", f"wheel_{side}_d_mm")
    check("RC_TRACK_MM", R(body + "wheel_track_mm"), 0.1, "mm", "wheel_track_mm")
    check("RC_ODOM_TRACK_MM", R(body + "wheel_track_mm"), 1.0, "mm", "wheel_track_mm")
    cell_mm, wall_mm = get(cfg, "world.cell_m", "--print-config") * 1000, get(cfg, "world.wall_thick_m", "--print-config") * 1000
    check("RC_CELL_MM", cell_mm, 0.1, "mm", "[world] cell_m")
    check("RC_WALL_MM", wall_mm, 0.1, "mm", "[world] wall_thick_m")
    check("RC_TOF_FRONT_Y_MM", R("tof.front.y_mm"), 0.1, "mm", "tof.front y_mm")
    check("RC_TOF_SIDE_X_MM", -R("tof.left.x_mm"), 0.1, "mm", "-tof.left x_mm")
    check("RC_TOF_SIDE_X_MM", R("tof.right.x_mm"), 0.1, "mm", "tof.right x_mm")
    check("RC_TOF_SIDE_Y_MM", R("tof.left.y_mm"), 0.1, "mm", "tof.left y_mm")
    check("RC_TOF_SIDE_Y_MM", R("tof.right.y_mm"), 0.1, "mm", "tof.right y_mm")
    for side, sign in (("left", 1), ("right", -1)):  # the firmware's rays at 45 degrees
        yaw = sign * R(f"tof.{side}.yaw_deg")
        bad = abs(yaw - 45) > 0.5
        print(f"{'FAILED' if bad else 'ok'}: diagonal rays at 45 deg, tof.{side} yaw_deg = {yaw * sign:g} (tolerance 0.5 deg)")
        if bad:
            fails.append(f"tof.{side}.yaw_deg")
    check("RC_TOF_FOV_DEG", R("tof.left.fov_deg"), 0.1, "deg", "tof.left fov_deg")
    check("RC_TOF_FOV_DEG", R("tof.right.fov_deg"), 0.1, "deg", "tof.right fov_deg")
    edge = math.radians(R("tof.left.yaw_deg") - R("tof.left.fov_deg") / 2)
    check("RC_DIAG_EDGE_COS", math.cos(edge), 0.0005, "", "cos(yaw_deg - fov_deg / 2)")
    check("RC_DIAG_EDGE_SIN", math.sin(edge), 0.0005, "", "sin(yaw_deg - fov_deg / 2)")
    side_wall = (cell_mm / 2 - wall_mm / 2 - (-R("tof.left.x_mm"))) / math.cos(edge)
    check("RC_SIDE_WALL_MM", side_wall, 0.5, "mm", "the left cone's edge to the side wall")

    for side in ("left", "right"):
        m, e = f"motor.{side}.", f"encoder.{side}."
        n = R(m + "gear_ratio")
        check("RC_COUNTS_PER_REV", R(e + "encoder_ppr") * n, 0.05, "%", f"{side} encoder_ppr x gear_ratio")
        if R(m + "model") != "datasheet":
            print(f"FAILED: motor.{side} model is {R(m + 'model')}: the firmware's figures assume datasheet")
            fails.append(m + "model")
            continue
        v, i0, ist, tst = R(m + "rated_v"), R(m + "no_load_a"), R(m + "stall_a"), R(m + "stall_torque_nm")
        ohm = v / ist                                      # R = V / stall current
        n_ke = (v - i0 * ohm) / (R(m + "no_load_rpm") * 2 * math.pi / 60)  # V*s/rad at the wheel
        n_eta_kt = tst / (ist - i0)                        # N*m/A at the wheel
        step_v = R("battery.main.ocv_v") / get(rc, "RC_CMD_MAX", header)  # one command step, V
        r_m = R(f"{body}wheel_{side}_d_mm") / 2000
        wheel_kg = R(body + "wheel_mass_g") / 1000
        mass_kg = (R(body + "body_mass_g") + 2 * R(body + "wheel_mass_g")
                   + R(body + "casters") * R(body + "caster_mass_g")) / 1000
        spin_kg = (R(m + "rotor_inertia_kgm2") * n * n + 0.5 * wheel_kg * r_m * r_m) / (r_m * r_m)
        per_kg = 0.001 * r_m / n_eta_kt * ohm / step_v     # command per kg at 1 mm/s^2
        half_track_m = R(body + "wheel_track_mm") / 2000
        yaw_kgm2 = R(body + "body_yaw_inertia_kgm2") or \
            R(body + "body_mass_g") / 1000 * ((R(body + "body_w_mm") / 1000) ** 2 + (R(body + "body_l_mm") / 1000) ** 2) / 12
        yaw_kgm2 += R(body + "caster_mass_g") / 1000 * (R(body + "caster_y_mm") / 1000) ** 2 + 2 * wheel_kg * half_track_m ** 2
        check("RC_MM_S_PER_CMD", step_v / n_ke * r_m * 1000, 0.5, "%", f"motor.{side}: step / (N Ke) x r")
        check("RC_CMD_FRICTION", i0 * ohm / step_v, 0.5, "%", f"motor.{side}: no_load_a x R / step")
        check("RC_CMD_PER_MM_S2", (mass_kg / 2 + spin_kg) * per_kg, 0.5, "%", f"motor.{side}: half the mass and the wheel's spin")
        check("RC_CMD_PER_ARC_MM_S2", (yaw_kgm2 / (2 * half_track_m ** 2) + spin_kg) * per_kg, 0.5, "%",
              f"motor.{side}: the yaw inertia per wheel and the wheel's spin")
    if fails:
        print(f"robot_config_check: {len(set(fails))} constant(s) of {header} disagree with {ini}: {' '.join(sorted(set(fails)))}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
