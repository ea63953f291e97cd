#!/usr/bin/env python3
"""fit_ukmarsbot.py - the numbers of robots/ukmarsbot.ini that nobody documents,
fitted to the measurements of mazerunner-core's ORION (config-robot-orion.h).

Standard library only. Run: python3 bench/fit_ukmarsbot.py
Every input names its source; docs/robots/ukmarsbot-sources.md explains the
model and the choices.  The fit is closed-form (each unknown has one equation),
then checked by integrating the same per-wheel model numerically.
"""
import math

# ---------------------------------------------------------------- ORION targets
# config-robot-orion.h l.220-221: 500 mm of travel = 1918 (left) / 1927 (right) counts
COUNTS_500 = {"left": 1918.0, "right": 1927.0}
MOUSE_RADIUS = 38.70e-3   # l.233, m: encoder-calibrated half track
FWD_KM = 0.475            # l.247, m/s per volt (per wheel volts)
FWD_TM = 0.190            # l.248, s
ROT_KM = 775.0            # l.249, deg/s per volt (+V right, -V left: motors.h update_controllers)
ROT_TM = 0.210            # l.250, s
BIAS_FF = 0.340           # l.282, V: the voltage that just overcomes friction
# sensors (lit - dark counts), l.60-65, l.70-71, l.77, l.203, l.356
LFS_CAL, RFS_CAL, LSS_CAL, RSS_CAL = 90.0, 110.0, 152.0, 192.0
FRONT_LINEAR_CONSTANT, FRONT_REFERENCE, TURN_THRESHOLD_SS90E = 861.0, 850.0, 110.0
BACK_WALL_TO_CENTER, LEFT_EDGE_POS = 48.0, 90.0
FRONT_NOMINAL = 100.0     # l.335
# maze: 180 mm cells, 12 mm walls (the brief; the UK/IEEE classic maze)
CELL, WALL = 180.0, 12.0
HALF_IN = CELL / 2 - WALL / 2          # cell centre to a wall face, mm (84)

# ---------------------------------------------------------------- datasheets
V_RATED = 6.0
# pimoroni-gearmotor-20-1.pdf (Kingly Gear JL-12FN20-20): 6 V; no load 1050 rpm,
# 0.08 A; load point 0.05 kg.cm at 826 rpm, 0.220 A; stall 0.19 kg.cm;
# gear train 21/27*16/32*16/32*10/38 = 19.55 (4 stages)
KGCM = 0.0980665          # N.m per kg.cm
N20, N20_STAGES = 19.55, 4
W0_20, I0_20 = 1050.0, 0.08
TL_20, WL_20, IL_20 = 0.05 * KGCM, 826.0, 0.220
TSTALL_20 = 0.19 * KGCM
# pimoroni-gearmotor-11-1.pdf (JL-12FN20-11): 6 V; no load 1950 rpm, 0.08 A;
# gear train 12/36*10/38 -> 11.4 (2 stages); no stall figures
N11, N11_STAGES = 11.4, 2
W0_11, I0_11 = 1950.0, 0.08
# TB6612FNG (mainboard V1.3 schematic U2): 0.5 ohm upper+lower typ (Toshiba datasheet p.1)
R_DRIVER = 0.5

# ---------------------------------------------------------------- ours
CPMR = 36          # 18 magnets = 9 pole pairs x 4 edges (documents/encoders.md l.17-19: 3 poles -> 12)
J_ROTOR = 8e-9     # kg.m^2: N20 armature ~1.5 g, r ~3.25 mm, 0.5 m r^2
M_WHEEL = 0.004    # kg per wheel with tyre
M_CASTER = 0.001   # kg, a skid
R_CASTER = 3e-3
BODY_W, BODY_L = 65e-3, 100e-3   # requirements.md l.31; README "smaller than 100 x 100"
AXLE_Y = -14e-3    # axle ahead of body centre (derived below, printed)
CASTER_Y = 40e-3

rpm = lambda w: w * 2 * math.pi / 60


def motor_from_20_1():
    """R and Ke (motor side) from the 20:1 sheet's no-load and load points:
    V = I R + Ke w_m at both; the speed drop gives R/Ke, iterate for I0 R."""
    wm0, wml = rpm(W0_20) * N20, rpm(WL_20) * N20
    r = 0.0
    for _ in range(50):
        ke = (V_RATED - I0_20 * r) / wm0
        r = (wm0 - wml) * ke / (IL_20 - I0_20)
    ke = (V_RATED - I0_20 * r) / wm0
    i_stall = V_RATED / r
    eta_stall = TSTALL_20 / (N20 * ke * (i_stall - I0_20))
    eta_load = TL_20 / (N20 * ke * (IL_20 - I0_20))
    return r, ke, i_stall, eta_stall, eta_load


def main():
    out = []
    p = out.append
    r_m, ke20, i_stall, eta_s, eta_l = motor_from_20_1()
    eta20 = 0.5 * (eta_s + eta_l)
    eta_stage = eta20 ** (1.0 / N20_STAGES)
    eta11 = eta_stage ** N11_STAGES
    p("== motor from the pimoroni 20:1 sheet (same N20 6 V motor, JL-12FN20)")
    p(f"R = {r_m:.2f} ohm, Ke = {ke20*1e3:.3f} mV.s/rad (motor), stall {i_stall:.3f} A at 6 V")
    p(f"gearbox efficiency: {eta_s:.2f} (stall point), {eta_l:.2f} (load point); mean {eta20:.2f}"
      f" -> {eta_stage:.3f} a stage -> 11.4:1 (2 stages) {eta11:.2f}")
    ke11 = (V_RATED - I0_11 * r_m) / (rpm(W0_11) * N11)
    p(f"11:1 sheet: Ke = (6 - 0.08 R)/w0 = {ke11*1e3:.3f} mV.s/rad (motor); motor-side no-load"
      f" {W0_11*N11:.0f} rpm vs 20:1 {W0_20*N20:.0f} rpm")

    # ---- wheels from the counts: counts/mm = CPMR N / (pi D)
    p("\n== encoder counts -> wheel diameters (N = 11.4, 36 counts per motor turn)")
    d = {s: CPMR * N11 * 500.0 / (math.pi * c) for s, c in COUNTS_500.items()}
    for s in d:
        p(f"{s}: D = {d[s]:.3f} mm  ({COUNTS_500[s]:.0f} counts / 500 mm)")
    for cp in (12, 24, 36, 72):
        p(f"   (with {cp:2d} counts per motor turn D would be {cp*N11*500/(math.pi*1922.5):6.1f} mm)")
    r_mean = 0.25e-3 * (d["left"] + d["right"])   # m
    d_over_n = 0.5 * (d["left"] + d["right"]) / N11
    p(f"D/N = {d_over_n:.4f} mm: KM = (D/2)/(N Ke) = CPMR*500/(2 pi counts Ke) does not depend on N,")
    p("and neither does the reflected rotor inertia N^2 Jr / r^2: the gear ratio is not identifiable;"
      " 11.4 (datasheet gear train) is used.")

    # ---- KM -> Ke
    km_ds = r_mean / (N11 * ke11)
    p(f"\n== forward KM: datasheet 11:1 motor (1950 rpm) would give {km_ds*1e3:.0f} mm/s/V"
      f" ({km_ds*1e3*0.9:.0f} at -10% speed); 20:1 with these wheels scaled to 32 mm: "
      f"{16e-3/(N20*ke20)*1e3:.0f} mm/s/V")
    # config-robot-osmium.h l.20, l.172-173, l.199-202: 20:1, 6 magnets (12 counts), 1175/1166 counts
    # per 500 mm, and the very same KM/TM numbers as ORION
    d_os = 12 * N20 * 500.0 / (math.pi * 0.5 * (1175 + 1166))
    p(f"OSMIUM (20:1, 12 counts/turn): D = {d_os:.1f} mm, sheet KM {d_os/2/(N20*ke20):.0f} mm/s/V: its"
      f" FWD_KM 475 (the same as ORION's) is {475/(d_os/2/(N20*ke20))*100-100:.0f}% above its no-load speed, so the KM/TM set can only be ORION's (or neither's)")
    nke = r_mean / FWD_KM          # N*Ke at the output, V.s/rad
    ke = nke / N11
    p(f"ORION KM 475 -> N Ke = {nke*1e3:.2f} mV.s/rad at the wheel, Ke = {ke*1e3:.3f} mV.s/rad (motor),"
      f" {ke/ke11:.3f} x the 11:1 sheet's")

    # ---- bias -> the friction current (the sim's only drive-train friction is no_load_a)
    r_c = r_m + R_DRIVER
    i0 = BIAS_FF / r_c
    p(f"BIAS_FF 0.340 V over R_m + R_driver = {r_c:.2f} ohm -> no_load_a = {i0:.4f} A (sheet: 0.08 at 1950 rpm)")

    # ---- TMs -> mass and yaw inertia
    # per wheel, forward:  (m/2 r^2 + Jw + N^2 Jr) dw/dt = eta N Ke (V - N Ke w)/Rc - friction
    #   TM_fwd = (m/2 r^2 + Jw + N^2 Jr) Rc / (eta (N Ke)^2)
    # per wheel, rotation (wheel at +-b):  J dOmega/dt = 2 F b, v = b Omega
    #   -> each wheel carries J/(2 b^2):   TM_rot = (J r^2/(2 b^2) + Jw + N^2 Jr) Rc / (eta (N Ke)^2)
    b = MOUSE_RADIUS
    jw = 0.5 * M_WHEEL * r_mean ** 2
    jr = N11 ** 2 * J_ROTOR
    res = {}
    p("\n== time constants -> mass m and yaw inertia J (about the axle midpoint)")
    for label, eta in (("A: ORION's motors slower than the sheet (Ke as fitted, eta from the gear train)", eta11),
                       ("B: sheet Ke, the shortfall a speed-proportional loss (eta_eff = eta Ke_sheet/Ke)", eta11 * ke11 / ke)):
        g = eta * nke ** 2 / r_c       # damping at the wheel, N.m.s/rad
        jt_f = FWD_TM * g
        jt_r = ROT_TM * g
        m = 2 * (jt_f - jw - jr) / r_mean ** 2
        jyaw = (jt_r - jw - jr) * 2 * b ** 2 / r_mean ** 2
        res[label[0]] = (eta, m, jyaw)
        p(f"{label}\n   eta = {eta:.3f}: m = {m*1e3:.1f} g, J = {jyaw*1e7:.0f} g.cm^2 (= {jyaw:.3e} kg.m^2),"
          f" radius of gyration {math.sqrt(jyaw/m)*1e3:.1f} mm")
    eta, m, jyaw = res["A"]
    p(f"chosen: A (the sim has no speed-proportional loss to put B's in); a parts estimate (2 N20 ~20 g, PP3"
      f" NiMH ~45 g, PCB ~19 g, Nano 7 g, sensor board ~8 g, wheels 8 g, driver, encoders, parts ~15 g)"
      f" is ~125 g: A {m*1e3:.0f} g is {(m/0.125-1)*100:+.0f}%, B {res['B'][1]*1e3:.0f} g is"
      f" {(res['B'][1]/0.125-1)*100:+.0f}%")

    # ---- rotation KM check
    rot_km_pred = FWD_KM / b * 180 / math.pi
    p(f"\n== rotation KM: FWD_KM / MOUSE_RADIUS = {rot_km_pred:.0f} deg/s/V vs ORION {ROT_KM:.0f}"
      f" ({(rot_km_pred/ROT_KM-1)*100:+.1f}%)")
    p(f"   775 would need a half-track of {FWD_KM/(ROT_KM*math.pi/180)*1e3:.1f} mm, or a per-wheel KM in"
      f" rotation of {ROT_KM*math.pi/180*b*1e3:.0f} mm/s/V")

    # ---- numeric check: integrate the same model (Coulomb friction included)
    def run(v, rot, t_end=1.5, dt=1e-4):
        jt = (jyaw * r_mean ** 2 / (2 * b ** 2) if rot else m / 2 * r_mean ** 2) + jw + jr
        w, t, hist = 0.0, 0.0, []
        tq_f = eta * N11 * ke * i0
        while t < t_end:
            i = (v - nke * w) / r_c
            tq = eta * N11 * ke * i - (tq_f if w > 0 or eta * N11 * ke * i > tq_f else eta * N11 * ke * i)
            w += tq / jt * dt
            t += dt
            hist.append((t, w))
        return hist

    def km_tm(rot):
        speeds = []
        for v in (1.0, 2.0, 3.0, 4.0, 5.0):
            h = run(v, rot)
            speeds.append(h[-1][1] * r_mean)
        slope = (speeds[-1] - speeds[0]) / 4.0
        h = run(3.0, rot)
        wss = h[-1][1]
        t63 = next(t for t, w in h if w >= (1 - math.exp(-1)) * wss)
        return slope, t63, speeds

    fk, ft, _ = km_tm(False)
    rk, rt, _ = km_tm(True)
    rk_deg = rk / b * 180 / math.pi
    p("\n== achieved (numeric, same model, friction included)")
    p(f"forward KM {fk*1e3:.1f} mm/s/V (target 475, {(fk/FWD_KM-1)*100:+.1f}%), TM {ft:.3f} s (target 0.190,"
      f" {(ft/FWD_TM-1)*100:+.1f}%)")
    p(f"rotation KM {rk_deg:.0f} deg/s/V (target 775, {(rk_deg/ROT_KM-1)*100:+.1f}%), TM {rt:.3f} s (target 0.210,"
      f" {(rt/ROT_TM-1)*100:+.1f}%)")
    for s in d:
        got = 500.0 / (math.pi * d[s]) * CPMR * N11
        p(f"{s} counts per 500 mm: {got:.1f} (target {COUNTS_500[s]:.0f})")
    p(f"half track: wheel_track_mm = {2*b*1e3:.1f} (MOUSE_RADIUS 38.70 exactly)")
    p(f"bias: {i0*r_c:.3f} V (BIAS_FF 0.340)")

    # ---- datasheet-form numbers for the .ini (the sim's motor_constants inverted)
    stall_a = V_RATED / r_m
    no_load_rpm = (V_RATED - r_m * i0) / (ke * N11) * 60 / (2 * math.pi)
    stall_t = eta * N11 * ke * (stall_a - i0)
    p("\n== [motor] in the sim's datasheet form (R = V/stall_a, Ke = (V - R I0)/w0, eta = T/(N Ke (Is - I0)))")
    p(f"rated_v = 6.0, no_load_rpm = {no_load_rpm:.0f}, no_load_a = {i0:.3f}, stall_torque_nm = {stall_t:.5f},"
      f" stall_a = {stall_a:.3f}, gear_ratio = {N11}, rotor_inertia_kgm2 = {J_ROTOR:.1e}, driver_r_ohm = {R_DRIVER}")

    # ---- what the sim's geometry gives for J (box + caster + wheels about the axle midpoint)
    m_body = m - 2 * M_WHEEL - M_CASTER
    j_box = m_body * (BODY_W ** 2 + BODY_L ** 2) / 12 + m_body * AXLE_Y ** 2
    j_cas = M_CASTER * (CASTER_Y - AXLE_Y) ** 2 + 0.4 * M_CASTER * R_CASTER ** 2
    j_whl = 2 * (M_WHEEL * b ** 2 + M_WHEEL * (3 * r_mean ** 2 + (8e-3) ** 2) / 12)
    j_geo = j_box + j_cas + j_whl
    p(f"\n== the sim's own yaw inertia from the file's geometry: box {BODY_W*1e3:.0f} x {BODY_L*1e3:.0f} mm,"
      f" {m_body*1e3:.0f} g, axle {AXLE_Y*1e3:.0f} mm: J = {j_geo:.3e} kg.m^2 ({(j_geo/jyaw-1)*100:+.0f}% vs fitted)")
    g = eta * nke ** 2 / r_c
    tm_rot_geo = (j_geo * r_mean ** 2 / (2 * b ** 2) + jw + jr) / g
    p(f"   -> rotation TM with that J: {tm_rot_geo:.3f} s (target 0.210)")

    # ---------------------------------------------------------------- sensors
    p("\n== sensor geometry (mm, relative to the axle midpoint; y forward, x right)")
    rear_to_axle = HALF_IN - BACK_WALL_TO_CENTER             # backed up: rear on the wall face -> 36
    face_to_face = CELL - WALL                               # rear wall face to front wall face, 168
    nose_y = (CELL - WALL / 2) - 92.0 - 20.0                 # SS90E comment: axle 20 past the boundary, nose 92 from the wall
    p(f"rear -> axle {rear_to_axle:.0f} (BACK_WALL_TO_CENTER); nose axle+{nose_y:.0f} (SS90E comment); length"
      f" {rear_to_axle+nose_y:.0f}; body 100 used, centre at axle+{50-rear_to_axle:.0f}")
    p(f"backed up, the NOSE is {face_to_face-rear_to_axle-nose_y:.0f} mm from the wall ahead: the '68' of the"
      f" FRONT_LINEAR_CONSTANT comment is the nose; 861/sqrt(200) = {FRONT_LINEAR_CONSTANT/math.sqrt(200):.1f}"
      f" (68 would need {68*math.sqrt(200):.0f})")
    # front pair: the reading goes as 1/d^2 (sim far field); backed up (d_b) it is the calibration
    # (normalised 100 each), centred with a wall ahead (d_c) it is FRONT_REFERENCE/2 each:
    # (d_b/d_c)^2 = 850/200 -> the pair's effective y
    k = math.sqrt(FRONT_REFERENCE / (2 * FRONT_NOMINAL))
    db_wall = face_to_face - rear_to_axle                    # axle to the wall ahead, backed up: 132
    fs_y = (k * HALF_IN - db_wall) / (k - 1)
    d_back, d_centre = db_wall - fs_y, HALF_IN - fs_y
    turn_wall = (CELL - WALL / 2) - 20.0                     # axle to the wall face at the SS90E trigger
    d_turn = turn_wall - fs_y
    p(f"front pair, fitted to FRONT_REFERENCE: y = axle+{fs_y:.1f} ({nose_y-fs_y:.0f} mm behind the nose);"
      f" d backed up {d_back:.1f}, centred {d_centre:.1f}")
    p(f"   SS90E check: sensors {d_turn:.0f} mm from the wall -> normalised sum"
      f" {2*FRONT_NOMINAL*(d_back/d_turn)**2:.0f} (TURN_THRESHOLD_SS90E {TURN_THRESHOLD_SS90E:.0f});"
      f" reached {d_back*math.sqrt(2*FRONT_NOMINAL/TURN_THRESHOLD_SS90E)-d_turn:.0f} mm early")
    p("   the alternative, the pair at the nose (axle+62 .. +64):")
    for y in (50.0, 56.0, 62.0, 64.0):
        b_, c_, t_ = db_wall - y, HALF_IN - y, turn_wall - y
        p(f"     y = axle+{y:.0f}: centred sum {2*FRONT_NOMINAL*(b_/c_)**2:.0f} (850 reached"
          f" {b_/k - c_:.0f} mm short of the centre), SS90E sum {2*FRONT_NOMINAL*(b_/t_)**2:.0f}")
    fs_x = 20.0                                              # ours
    ds_x = 22.0                                              # ours
    aim = (HALF_IN, 90.0)                                    # documents/sensors.md l.3: at the posts when centred
    ds_y = aim[1] - (aim[0] - ds_x)                          # ... and "about 45 degrees"
    dx, dy = aim[0] - ds_x, aim[1] - ds_y
    yaw = math.degrees(math.atan2(dx, dy))
    dist_ds = math.hypot(dx, dy)
    cos_ds = dx / dist_ds
    p(f"diagonal pair at (+-{ds_x:.0f}, axle+{ds_y:.0f}), yaw {yaw:.1f} deg: aimed at the post face centre"
      f" ({aim[0]:.0f}, {aim[1]:.0f}) when centred; it leaves the post's far edge {WALL/2:.0f} mm later")
    p("\n== calibration poses (gain for reflectivity 1 at ref 50 mm; the sim's wall reflectivity 0.85)")
    rho, ref = 0.85, 50.0
    g_lfs = LFS_CAL / (rho * (ref / d_back) ** 2)
    g_rfs = RFS_CAL / (rho * (ref / d_back) ** 2)
    p(f"front, backed up: d = {d_back:.1f} mm, incidence 0 deg -> gain lfs {g_lfs:.0f}, rfs {g_rfs:.0f}")
    g_lds = LSS_CAL / (rho * cos_ds * (ref / dist_ds) ** 2)
    g_rds = RSS_CAL / (rho * cos_ds * (ref / dist_ds) ** 2)
    p(f"side, centred: d = {dist_ds:.1f} mm along the axis, incidence {math.degrees(math.acos(cos_ds)):.1f} deg"
      f" (cos {cos_ds:.3f}) -> gain lds {g_lds:.0f}, rds {g_rds:.0f}")
    p(f"centred, wall ahead: raw lfs {g_lfs*rho*(ref/d_centre)**2:.0f}, rfs {g_rfs*rho*(ref/d_centre)**2:.0f};"
      f" normalised sum {FRONT_NOMINAL*(g_lfs*rho*(ref/d_centre)**2/LFS_CAL + g_rfs*rho*(ref/d_centre)**2/RFS_CAL):.0f}"
      f" (FRONT_REFERENCE 850)")
    d_fw = (HALF_IN - ds_y) / math.cos(math.radians(yaw))
    p(f"   there the diagonal beams meet the wall ahead at {d_fw:.1f} mm (x = {ds_x + (HALF_IN-ds_y):.0f}, inside the"
      f" post at {HALF_IN:.0f}): lds {g_lds*rho*math.cos(math.radians(yaw))*(ref/d_fw)**2:.0f} counts"
      f" (documents/sensors.md l.14: side sensors see a wall ahead)")
    body = lambda y: y - (50 - rear_to_axle)
    p(f"\nbody frame (origin body centre = axle+{50-rear_to_axle:.0f}): lfs ({-fs_x:.0f}, {body(fs_y):.1f}),"
      f" rfs ({fs_x:.0f}, {body(fs_y):.1f}), lds ({-ds_x:.0f}, {body(ds_y):.0f}, yaw {yaw:+.0f}),"
      f" rds ({ds_x:.0f}, {body(ds_y):.0f}, yaw {-yaw:+.0f}); axle_y {AXLE_Y*1e3:.0f}, caster_y {CASTER_Y*1e3:.0f}")
    print("\n".join(out))


if __name__ == "__main__":
    main()
