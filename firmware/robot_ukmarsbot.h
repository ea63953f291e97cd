/* robot_ukmarsbot.h - robot_config.h's numbers for UKMARSBOT (ORION: the
 * V1.3 mainboard with the advanced wall sensor board, robots/ukmarsbot.ini).
 * `make firmware-ukmarsbot` and platformio.ini's [env:ukmarsbot] force-include
 * it (-include robot_ukmarsbot.h); it defines ROBOT_CONFIG_H, so
 * robot_config.h (the paper's robot) is then skipped. The basic build
 * (UKB_SENSOR_BOARD=basic) is robots/ukmarsbot-basic-12.ini. Every name
 * robot_config.h defines is defined here too. Sources: robots/ukmarsbot.ini
 * (its `; source:` lines: ORION's published figures, mazerunner-core
 * config-robot-orion.h) and the IR curve measured in mmsim (below). */
#ifndef ROBOT_CONFIG_H
#define ROBOT_CONFIG_H

#ifdef UKB_SENSOR_BOARD_BASIC
/* ---- the basic build: robots/ukmarsbot-basic-12.ini (12-PPR encoders,
 * 19.55:1 gears, 32 mm wheels, the same chassis and sensor positions) ---- */
#define RC_CELL_MM 180.0f            /* classic maze pitch */
#define RC_WALL_MM 12.0f             /* wall thickness */
#define RC_WHEEL_DIAMETER_MM 32.0f   /* wheel_left_d_mm, wheel_right_d_mm */
#define RC_TRACK_MM 75.0f            /* wheel_track_mm */
#define RC_ODOM_TRACK_MM 75.0f
#define RC_COUNTS_PER_REV 234.6f     /* encoder_ppr 12 (both edges of the XOR) x gear_ratio 19.55 */
#define RC_MM_PER_COUNT (3.14159265f * RC_WHEEL_DIAMETER_MM / RC_COUNTS_PER_REV) /* 0.4285 mm */
#define RC_MM_PER_COUNT_LEFT RC_MM_PER_COUNT
#define RC_MM_PER_COUNT_RIGHT RC_MM_PER_COUNT
/* [motor.*] no_load_rpm 1050 at the wheel, 6 V: 1759 mm/s, 293 mm/s per V
 * x 5.865 mV */
#define RC_MM_S_PER_CMD 1.719f
/* no_load_a 0.0140 x (6 V / stall_a 0.736 + driver_r_ohm 0.5 = 8.65 ohm)
 * = 0.121 V = 21 steps */
#define RC_CMD_FRICTION 21.0f
/* no measured time constants: ORION's (0.190 s forward, 0.210 s turning)
 * scaled by (Km / ORION's)^2 = (293 / 475)^2 (the motor's damping grows
 * with its torque per volt, the same chassis): 0.072 s and 0.080 s;
 * 0.072 / 293 = 0.246 mV per mm/s^2 = 0.0419 steps; turning 0.080 / 323
 * (ORION's turning Km over its forward one, 523.5 / 475, times 293) */
#define RC_CMD_PER_MM_S2 0.0419f
#define RC_CMD_PER_ARC_MM_S2 0.0422f
#else
/* ---- ORION: geometry (robots/ukmarsbot.ini [chassis.body], [encoder.*]) ---- */
#define RC_CELL_MM 180.0f            /* classic maze pitch */
#define RC_WALL_MM 12.0f             /* wall thickness */
#define RC_WHEEL_DIAMETER_MM 33.98f  /* the mean of wheel_left_d_mm 34.06 and wheel_right_d_mm 33.90 */
#define RC_TRACK_MM 77.4f            /* wheel_track_mm */
#define RC_ODOM_TRACK_MM 77.4f
#define RC_COUNTS_PER_REV 410.4f     /* encoder_ppr 36 (both edges of the XOR) x gear_ratio 11.4 */
#define RC_MM_PER_COUNT (3.14159265f * RC_WHEEL_DIAMETER_MM / RC_COUNTS_PER_REV) /* 0.2601 mm */
/* each wheel's own: [measured.orion] counts_500mm_left 1918, _right 1927 */
#define RC_MM_PER_COUNT_LEFT (500.0f / 1918.0f)
#define RC_MM_PER_COUNT_RIGHT (500.0f / 1927.0f)
/* ---- motor, for feed-forward (1023 = 6 V: hal/ukmarsbot UKB_MOTOR_REF_MV;
 * one command step is 5.865 mV) ---- */
/* [measured.orion] fwd_km_mm_s_v 475: 475 mm/s per V x 5.865 mV */
#define RC_MM_S_PER_CMD 2.786f
/* the no-load current's voltage, [motor.*] no_load_a 0.02119 x (6 V /
 * stall_a 0.736 + driver_r_ohm 0.5 = 8.65 ohm) = 0.183 V = 31 steps */
#define RC_CMD_FRICTION 31.0f
/* fwd_tm_s 0.190 / fwd_km 475 = 0.400 mV per mm/s^2 = 0.0682 steps */
#define RC_CMD_PER_MM_S2 0.0682f
/* rot_km_deg_s_v 775 deg/s per V = 523.5 mm/s of wheel arc (38.7 mm
 * radius); rot_tm_s 0.210 / 523.5 = 0.401 mV per mm/s^2 = 0.0684 steps */
#define RC_CMD_PER_ARC_MM_S2 0.0684f
#endif

/* the robot starts backed against the start cell's rear wall ([chassis.body]
 * start = back_to_wall): rear 0.5 mm off the wall's face (84 mm behind the
 * centre), body_l_mm 100, axle_y_mm -14 behind the body's centre: the axle
 * 84 - 0.5 - 50 + 14 = 47.5 mm behind the centre */
#define RC_START_BEHIND_MM 47.5f
#define RC_FRICTION_RAMP_MM_S 20.0f /* the friction term ramps in over this speed (robot_config.h) */

#define RC_CMD_MAX 1023
#define RC_CMD_FF_MAX 923.0f         /* as the paper's robot: 100 steps for the controller */

/* ---- wall sensors: IR (firmware/walls.c turns readings into mm) ---- */
#define RC_WALLS_IR 1 /* firmware/walls.h: the IR readings as distances */
/* The front pair ([ir.lfs], [ir.rfs]: x -+20, 46 mm ahead of the body's
 * centre) is 60 mm ahead of the axle; a wall ahead of a cell centre is
 * 84 - 60 = 24 mm from it. */
#define RC_TOF_FRONT_Y_MM 60.0f
/* The diagonal pair ([ir.lds], [ir.rds]: x -+22, 14 mm ahead of the body's
 * centre = 28 ahead of the axle, 45 degrees out, a 3 degree beam): walls.c
 * reports each one's distance to its side wall along that axis, so the
 * "cone's edge" of drive.c's geometry is the axis itself, 45 degrees off
 * the wall's normal */
#define RC_TOF_SIDE_X_MM 22.0f
#define RC_TOF_SIDE_Y_MM 28.0f
#define RC_TOF_FOV_DEG 6.0f          /* [ir.*] half_angle_deg 3, both sides */
#define RC_TOF_RAYS 1                /* one axis: not used (diagref.c is host-only) */
#define RC_DIAG_EDGE_COS 0.7071f     /* cos 45 deg */
#define RC_DIAG_EDGE_SIN 0.7071f     /* sin 45 deg */
#define RC_SIDE_WALL_MM 87.7f        /* (84 - 22) / cos 45 deg, centred */
/* walls.c decides a side wall by the calibration's threshold (no wall:
 * timeout); any distance it reports is a wall */
#define RC_SIDE_THRESHOLD_MM 1000.0f
#define RC_CENTRING_MAX_MM 116.0f    /* 20 mm off the centre line: (62 + 20) / cos 45 deg */
#define RC_CENTRING_MIN_MM_S 100.0f
/* The diagonals' spot lands 62 mm ahead of the sensor, 90 mm ahead of the
 * axle: on the post row at the end of the cell when the axle is near the
 * centre. Their readings within 20 mm of a cell centre are dropped
 * (the 6 mm post plus the 12 degree detector cone at 88 mm, +-9 mm). */
#define RC_SIDE_BLIND_FROM_MM 20.0f
#define RC_SIDE_BLIND_TO_MM 20.0f
#define RC_FRONT_AT_CENTRE_MM (RC_CELL_MM / 2 - RC_WALL_MM / 2 - RC_TOF_FRONT_Y_MM) /* 24 mm */
/* a wall ahead of the cell being sensed: nearer than its far wall plus
 * half a cell (without it the next wall is a cell further: mostly beyond
 * the front curve, a timeout) */
#define RC_FRONT_WALL_MARGIN_MM 90.0f
/* a side reading may be of the cell's entry post (drive.c
 * clear_of_entry_post) up to this beyond the post's half width: the
 * beam's 3 degrees at 88 mm are +-5 mm */
#define RC_POST_MARGIN_MM 6.0f
/* The forward pair's sum against the wall ahead, in 1/64 of its sum in the
 * front calibration pose (backed against a rear wall, the wall ahead 71.5 mm
 * from the sensors), and the distance at each (mm, falling readings):
 * measured in mmsim with robots/ukmarsbot.ini, the robot pushed towards a
 * wall in 10 mm steps (sums 859 696 497 355 264 201 159 105 76 49 26 18 at
 * 21.5 ... 251.5 mm, rounded up to whole mm). Nearer than 21.5 mm the sum
 * falls again (the detector's cone leaves the emitter's spot). */
#define RC_IR_FRONT_CURVE_RATIO64 { 273, 222, 158, 113, 84, 64, 51, 33, 24, 16, 8, 6 }
#define RC_IR_FRONT_CURVE_MM { 22, 32, 42, 52, 62, 72, 82, 102, 122, 152, 202, 252 }

/* ---- search and run speeds (config-robot-orion.h: search 400 mm/s,
 * 2000 mm/s^2, smooth turns at 300 mm/s on a 70 mm radius) ---- */
#define RC_SEARCH_MM_S 400.0f
#define RC_RUN_MM_S 600.0f
#define RC_ACCEL_MM_S2 2000.0f
#define RC_RUN_ACCEL_MM_S2 2000.0f
/* in-place turns: the body's corners sweep 72 mm about the axle (32.5 mm
 * out, 64 mm ahead), 12 mm inside the cell's 84 */
#define RC_TURN_DEG_S 360.0f
#define RC_TURN_ACCEL_DEG_S2 3000.0f
#define RC_PIVOT_MAX_MM 4.0f
#define RC_PIVOT_AVG 0.3f
/* turns on the spot only (motion.c): the search stops in each turn cell */
#define RC_SMOOTH_TURNS 0
/* smooth turns: 300 mm/s on 70 mm = 4.29 rad/s */
#define RC_SMOOTH_MM_S 300.0f
#define RC_SMOOTH_DEG_S 245.6f
#define RC_SMOOTH_ACCEL_DEG_S2 3000.0f
#ifdef __AVR__
/* speed runs with diagonals and slaloms: this build does not plan them
 * (PLAN_ENABLED is 0 on the AVR); the names as robot_config.h */
#include "slalom_off.h"
#else
/* ---- speed runs with slaloms and diagonals (host builds: build/ukb/mmsim
 * runs this firmware in-process with plan.c; robot_config.h explains each
 * name). "ours": measured in mmsim with robots/ukmarsbot.ini, seed 1; the
 * turns' clearances by build/test/test_slalom_ukb (UKMARSBOT's body swept
 * along each turn as the control tick drives it). ---- */
#define RC_DIAG_RUNS 1
/* Fast runs (after a clean one): the safe runs' cap (the motor holds 2,485
 * mm/s under it: (923 - 31) x 2.786), cruise 1,500 mm/s, and ORION's
 * acceleration (config-robot-orion.h, 2,000 mm/s^2). Ours: with the fast
 * turns at 350-450 mm/s, cruise 1,000 gave best runs of 22.4 s
 * (japan2018) and 25.0 s (japan2019), 1,500 20.9 and 24.3; at 2,500 and
 * 3,000 mm/s^2 japan2019 crashed in its first fast run (2,000: clean). */
#define RC_RUN_FAST_CMD_FF_MAX RC_CMD_FF_MAX
#define RC_RUN_FAST_MM_S 1500.0f         /* mm/s */
#define RC_RUN_FAST_ACCEL_MM_S2 2000.0f  /* mm/s^2 */
#define RC_RUN_CLEAN_MM 10.0f            /* mm, as robot_config.h */
/* Each turn kind's speed, safe / fast, mm/s (the S90's also the V90's,
 * F135's and D135's; D45 the F45's). Ours: at safe 300 / 400 / 300 / 350
 * and fast 350 / 450 / 350 / 400 (S90, F90, F180, F45) best runs 20.9 s
 * and 24.3 s; with these 19.5 and 22.1 (no diagonal), all within 0.3 g
 * (test_slalom_ukb). The F45 at the S90's speed: at 350 / 450 the
 * first speed run of japan2018 crashed where an S90 leads straight into
 * an F45 (no straight between them to change speed on). Clearances
 * (test_slalom_ukb), safe / fast: S90 34.3 / 33.5 mm, F90 29.5 / 32.0,
 * F180 28.9 / 23.5, F45 and D45 11.5 / 11.5. */
#define RC_SLALOM_SAFE_MM_S 300.0f
#define RC_SLALOM_FAST_MM_S 400.0f
#define RC_SLALOM_F90_SAFE_MM_S 400.0f
#define RC_SLALOM_F90_FAST_MM_S 500.0f
#define RC_SLALOM_F180_SAFE_MM_S 300.0f
#define RC_SLALOM_F180_FAST_MM_S 400.0f
#define RC_SLALOM_F45_SAFE_MM_S 300.0f
#define RC_SLALOM_F45_FAST_MM_S 400.0f
/* Diagonal straights, mm/s: the wheels pass the posts 11.4 mm off on the
 * diagonal's centre line (posts 63.6 mm from it, minus 43.7 mm of wheel
 * and 8.5 mm of post across the diagonal), held blind on odometry's
 * heading (ours, not tuned further: the runs' diagonals are short). */
#define RC_DIAG_SAFE_MM_S 500.0f
#define RC_DIAG_FAST_MM_S 800.0f
/* Which plans may drive diagonals (slalomrun.c diag_ok): any turn may
 * enter one; from an F45 or F135 to the turn back, at most
 * RC_DIAG_MAX_HALVES half steps of diagonal after an orthogonal straight
 * of at least RC_DIAG_ENTRY_HALVES, RC_DIAG_AFTER_TURN_HALVES after a
 * turn; the turn back leads into such a straight. Ours, every 16th
 * classic maze in name order (31, 30 reachable), the fast figures above:
 * - no rule (up to 12 half steps, from and into any move): 6 of the first
 *   27 touched (Portugal-2024-Final: S90 S90 S90 F45 and 5 half steps;
 *   diag2: 9 half steps after an S90; japan2013eq, higashi-2017 and
 *   uk2011follower: a D45 into a turn; alljapan-010-1989-fin), while
 *   others gained up to 13 % (kw-2 12.84 s against 14.77);
 * - no rule, up to 4 or 6 half steps: at 6 Portugal-2024-Final touched,
 *   at 4 japan2019's plan (6 + 4 half steps about a V90) was dropped;
 * - this rule without its last clause: japan2013eq, higashi-2017 and
 *   uk2011follower touched (japan2019 19.51 s);
 * - this rule: the 30 clean (docs/BENCHMARKS.md); the first speed runs of
 *   higashi-2017, ies90 and portugal-2022 drive diagonals (V90s, F135 and
 *   D135 too), and japan2018's best run does (japan2019's has none). */
#define RC_DIAG_ENTRY_HALVES 2           /* half units */
#define RC_DIAG_MAX_HALVES 12            /* half steps */
#define RC_DIAG_AFTER_TURN_HALVES 2      /* half steps */
#define RC_DIAG_ALL_TURNS 1              /* V90, F135, D135 and lane changes too */
/* Blind straights (slalomrun.c blind_ok): after an orthogonal straight
 * that ends with more than RC_BLIND_MAX_HALVES half units without side
 * walls, at most RC_BLIND_MAX_TURNS turns entered across its line before
 * a wall ahead of one (or centring along that line) measures the offset
 * it drifted; else the run is the orthogonal one. Ours, in
 * alljapan-019-1998-exp-fin's first speed run (seed 1; mmsim's MM_POSE
 * against the plan's nodes): after a staircase of 4 S90s odometry's
 * heading was 0.7-0.9 degrees off the true one, 12 half units (1,080 mm)
 * without side walls drifted 6 -> 29 mm across, the F90 after them
 * carried that on as an error along the way (each S90 entered across the
 * line started 26-33 mm late, none had a wall ahead), and the 7th S90
 * touched (34 mm of clearance). taiwan2017f has 14 such half units
 * drifting 4.5 mm (0.2 degrees off) and an S90 with a wall ahead after
 * them: clean. 8 half units at the 1.2 degrees of the first: 15 mm
 * (not swept further). */
#define RC_BLIND_MAX_HALVES 8            /* half units */
#define RC_BLIND_MAX_TURNS 0             /* turns */
/* No diagonal reference: the IR sensors' distances are calibrated for a
 * side wall square to the corridor (walls.c); diagref.c models ToF cones. */
#define RC_DIAG_TOF 0
#define RC_CMD_DIAG_TOF 0
#define RC_DIAG_TOF_START_MM 1.5f        /* mm, as robot_config.h (RC_DIAG_TOF 0: unused) */
#define RC_DIAG_TOF_DRIFT_MM2 0.02f      /* mm^2 per mm, as robot_config.h (unused) */
/* the slaloms' rotation: robot_config.h's (70 rad/s^2 is 2.7 m/s^2 of
 * wheel arc on the 38.7 mm half track) */
#define RC_SLALOM_ACCEL_DEG_S2 4010.7f   /* deg/s^2 */
#define RC_SLALOM_W_MIN_DEG_S 57.3f      /* deg/s */
#define RC_SLALOM_W_MAX_DEG_S 859.4f     /* deg/s */
/* From each turn's start to its corner, mm: the paper robot's S90, F90,
 * F45 and D45 (robot_config.h; clearances above). V90 80 (of 127): 9.6 mm
 * from the posts at 300 mm/s, 10.9 at 400; at 100 it fails
 * test_slalom_ukb at 300 mm/s, at 120 it touches. F135 and D135 120 (of 127): 8.3 and 8.4 mm at 300 mm/s; at
 * 400 they do not fit (the fast runs plan without them); at 60-100 no
 * rate the motor allows fits them. */
#define RC_SLALOM_S90_MM 85.0f
#define RC_SLALOM_F90_MM 120.0f
#define RC_SLALOM_F45_MM 60.0f
#define RC_SLALOM_D45_MM 60.0f
#define RC_SLALOM_V90_MM 80.0f
#define RC_SLALOM_F135_MM 120.0f
#define RC_SLALOM_D135_MM 120.0f
#endif
#define RC_TOF_CV 0.042f              /* per mm of reading */
#define RC_DIAG_TOF_MAX_MM 200.0f     /* mm */
#define RC_DIAG_TOF_MARGIN_MM 8.0f    /* mm */
#define RC_DIAG_TOF_GATE_MM 15.0f     /* mm */
/* the walls of the cell ahead are read 120 mm before its centre: the
 * diagonals' spots 30 mm inside it, the front pair 144 mm from its far wall */
#define RC_SENSE_BEFORE_MM 120.0f
#define RC_SENSE_FROM_MM 125.0f      /* a fresh IR pass every tick: 1.6 mm at 400 mm/s */
#define RC_SENSE_LATEST_MM 60.0f
#define RC_ALIGN_FROM_MM 90.0f
#define RC_ALIGN_GAIN 0.35f
/* no heading from the wall ahead: standing at a centre the diagonals look
 * at the post row, not at the wall ahead (NEAR_MM < 0 never holds) */
#define RC_WALL_HEADING_READS 1
#define RC_WALL_HEADING_PRIOR 1.0f
#define RC_WALL_HEADING_NEAR_MM -1.0f
#define RC_WALL_HEADING_MAX_RAD 0.09f

/* ---- controller (the loop runs on the Nano: one 4 ms tick of lag) ---- */
/* Plant: one command step accelerates the robot by 1 / 0.0682 = 14.7 mm/s^2
 * and the motor damps it with ORION's 0.19-0.21 s time constant (the
 * paper's robot: 65 ms). P alone (30: 21 rad/s) is damped at zeta 0.11:
 * the heading swung +-14 degrees on gen-16x16-s1 and the robot stopped 10
 * mm past a centre and pushed into the wall. D 1.0 adds 14.7 / s of
 * damping (zeta ~0.47); one encoder count in a 4 ms tick is 65 mm/s, 65
 * steps of command. */
#define RC_KP_FWD 30.0f    /* command per mm of forward position error */
#define RC_KP_ROT 30.0f    /* command per mm of wheel-arc rotation error */
#define RC_KD_FWD 1.0f     /* command per mm/s of forward speed error */
#define RC_KD_ROT 1.0f     /* command per mm/s of wheel-arc rotation rate error */
#define RC_KP_LATERAL 0.01f   /* rad per mm */
#define RC_KI_LATERAL 0.01f   /* rad/s per mm */
#define RC_LATERAL_MAX_RAD 0.15f
#define RC_LATERAL_REF_MM_S 500.0f
#define RC_KP_HEADING 10.0f
#define RC_SETTLE_MM 1.5f
#define RC_SETTLE_MM_S 25.0f
#define RC_STALL_MM 40.0f
#define RC_STALL_MS 400u

#endif
