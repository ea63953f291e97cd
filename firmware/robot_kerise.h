/* robot_kerise.h - robot_config.h's numbers for a half-size mouse, KERISE
 * v5 as robots/kerise-v5.ini models it (its `; source:` lines: published
 * figures, and how the rest is estimated), in the half-size maze (90 mm
 * cells, 6 mm walls: NTF's rules). `make $(B)/half/mmsim` force-includes it
 * (-include robot_kerise.h) into the firmware of an in-process mmsim; it
 * defines ROBOT_CONFIG_H, so robot_config.h (the paper's robot) is then
 * skipped. Every name robot_config.h defines is defined here. Where a
 * number is robot_config.h's scaled to the half-size cell, the scaling is
 * said; robot_config.h explains what each one does. */
#ifndef ROBOT_CONFIG_H
#define ROBOT_CONFIG_H

/* ---- geometry (robots/kerise-v5.ini [chassis.body], [encoder.*]) ---- */
#define RC_CELL_MM 90.0f             /* half-size maze pitch */
#define RC_WALL_MM 6.0f              /* half-size wall thickness */
#define RC_WHEEL_DIAMETER_MM 12.72f  /* wheel_left_d_mm, wheel_right_d_mm */
#define RC_TRACK_MM 29.0f            /* wheel_track_mm */
#define RC_ODOM_TRACK_MM 29.0f
#define RC_COUNTS_PER_REV 4096.0f    /* encoder_ppr 970.2 x gear_ratio 4.222 */
#define RC_MM_PER_COUNT (3.14159265f * RC_WHEEL_DIAMETER_MM / RC_COUNTS_PER_REV) /* 0.00976 mm */
#define RC_MM_PER_COUNT_LEFT RC_MM_PER_COUNT  /* wheels of one size */
#define RC_MM_PER_COUNT_RIGHT RC_MM_PER_COUNT
#define RC_START_BEHIND_MM 0.0f      /* mm: on the start cell's centre */

/* ---- motor, for feed-forward (1023 = the battery's 3.7 V) ---- */
/* [motor.*]: R = 3.7 V / stall_a 0.4 + driver_r_ohm 0.305 = 9.56 ohm;
 * the no-load current's voltage 0.03 A x 9.25 ohm = 0.278 V = 77 steps;
 * the rest, 946 steps, drives the wheel at no_load_rpm 6006 = 4000 mm/s */
#define RC_MM_S_PER_CMD 4.227f        /* mm/s per command step */
#define RC_CMD_FRICTION 77.0f         /* command steps */
#define RC_FRICTION_RAMP_MM_S 20.0f   /* mm/s, as robot_config.h */
/* command per mm/s^2 (robot_config.h's formula): each wheel pushes half
 * the robot's 20 g plus its spin (the rotor 1e-9 kg*m^2 x 4.222^2 and the
 * 1 g wheel as a disc, over r^2: 0.94 g), 10.94 g; the torque per amp at
 * the wheel stall_torque / (stall_a - no_load_a) = 5.32 mN*m/A, R = 9.25
 * ohm, a step 3.617 mV: 0.0334 (0.14 s / 4.227 mm/s per step = 0.0331,
 * [KM]'s T1, agrees) */
#define RC_CMD_PER_MM_S2 0.0334f     /* command steps per mm/s^2 */
/* turning: the yaw inertia (the 17.5 g box 29 x 26 mm 2.21e-6 kg*m^2, the
 * skid 0.06e-6, the wheels 0.42e-6) over 2 x (14.5 mm)^2 = 6.40 g per
 * wheel, plus its 0.94 g of spin */
#define RC_CMD_PER_ARC_MM_S2 0.0224f /* command steps per mm/s^2 of wheel arc */
#define RC_CMD_MAX 1023
#define RC_CMD_FF_MAX 923.0f         /* as robot_config.h: 100 steps for the controller */

/* ---- distance sensors (robots/kerise-v5.ini [tof.*]) ---- */
#define RC_TOF_FRONT_Y_MM 12.0f      /* mm ahead of the body centre */
#define RC_TOF_SIDE_X_MM 12.0f       /* mm off the centre line */
#define RC_TOF_SIDE_Y_MM 11.0f       /* mm ahead of the body centre */
#define RC_TOF_FOV_DEG 25.0f         /* deg, full cone */
#define RC_TOF_RAYS 5                 /* rays across the cone, robots/kerise-v5.ini */
/* 0: the wall sensors are ToF (walls.h); no IR front curve (unused) */
#define RC_WALLS_IR 0
#define RC_IR_FRONT_CURVE_RATIO64 { 0 }
#define RC_IR_FRONT_CURVE_MM { 0 }
#define RC_DIAG_EDGE_COS 0.8434f     /* cos(32.5 deg): robot_config.h */
#define RC_DIAG_EDGE_SIN 0.5373f     /* sin(32.5 deg) */
/* a side wall 45 - 3 - 12 = 30 mm out from the sensor: 30 / cos(32.5 deg) */
#define RC_SIDE_WALL_MM 35.6f        /* mm */
/* wall present: up to 16 mm further out than centred ((30 + 16) / cos) */
#define RC_SIDE_THRESHOLD_MM 54.5f   /* mm */
/* centring: within 10 mm of the centre line ((30 + 10) / cos) */
#define RC_CENTRING_MAX_MM 47.4f     /* mm */
#define RC_CENTRING_MIN_MM_S 60.0f    /* mm/s: not from a creep */
/* the blind band about a cell centre, robot_config.h's halved */
#define RC_SIDE_BLIND_FROM_MM 24.0f  /* mm before a cell centre */
#define RC_SIDE_BLIND_TO_MM 2.0f     /* mm past it */
#define RC_FRONT_AT_CENTRE_MM (RC_CELL_MM / 2 - RC_WALL_MM / 2 - RC_TOF_FRONT_Y_MM) /* 30 mm */

/* ---- search and run speeds ---- */
/* Search at 250 mm/s, below half robot_config.h's 600: the sensors' 30 ms
 * period covers 7.5 mm of a 90 mm cell. At 300 mm/s (9 mm) two of the 37
 * half-size mazes (japan2010hef, taiwan2018hef, seed 1) mapped a side wall
 * that is not there, missed one ahead and ran into it; at 250 none did. */
#define RC_SEARCH_MM_S 250.0f         /* mm/s */
#define RC_RUN_MM_S 450.0f            /* mm/s, speed runs */
#define RC_ACCEL_MM_S2 2000.0f        /* mm/s^2, 0.2 g */
#define RC_RUN_ACCEL_MM_S2 2000.0f    /* mm/s^2 */
#define RC_TURN_DEG_S 450.0f          /* deg/s on the spot, as robot_config.h */
#define RC_TURN_ACCEL_DEG_S2 2000.0f  /* deg/s^2 */
#define RC_PIVOT_MAX_MM 4.0f          /* mm */
#define RC_PIVOT_AVG 0.3f             /* share per reading */
/* smooth turns at 200 mm/s, 5 rad/s: a ~40 mm radius in a 90 mm cell */
#define RC_SMOOTH_TURNS 1
#define RC_SMOOTH_MM_S 200.0f         /* mm/s */
#define RC_SMOOTH_DEG_S 286.5f       /* 5 rad/s */
#define RC_SMOOTH_ACCEL_DEG_S2 4010.7f /* 70 rad/s^2, as robot_config.h */
/* speed runs with diagonals and slaloms: not for this robot (its turns'
 * clearances in half-size cells are unchecked); the names as robot_config.h */
#include "slalom_off.h"
#define RC_TOF_CV 0.042f              /* per mm of reading, as robot_config.h */
#define RC_DIAG_TOF_MAX_MM 100.0f     /* mm: robot_config.h's halved with the cell */
#define RC_DIAG_TOF_MARGIN_MM 4.0f    /* mm: halved */
#define RC_DIAG_TOF_GATE_MM 8.0f      /* mm: about halved */
/* sense the cell ahead with the diagonal sensors at its entry boundary,
 * as robot_config.h does: 45 + 11 mm before its centre (70 read posts at
 * the entry as side walls: 12 of the 37 half-size mazes mapped a wall
 * that is not there); readings from 5 mm before that */
#define RC_SENSE_BEFORE_MM 56.0f     /* mm */
#define RC_SENSE_FROM_MM 61.0f       /* mm */
/* the rest of robot_config.h's sensing distances, halved with the cell */
#define RC_POST_MARGIN_MM 3.0f        /* mm */
#define RC_FRONT_WALL_MARGIN_MM 25.0f /* mm */
#define RC_SENSE_LATEST_MM 30.0f      /* mm */
#define RC_ALIGN_FROM_MM 45.0f        /* mm */
#define RC_ALIGN_GAIN 0.35f           /* share per reading */
#define RC_WALL_HEADING_READS 3       /* readings per stop */
#define RC_WALL_HEADING_PRIOR 1.0f    /* readings */
#define RC_WALL_HEADING_NEAR_MM 3.0f  /* mm */
#define RC_WALL_HEADING_MAX_RAD 0.09f /* rad, 5 degrees */

/* ---- controller gains ---- */
/* Plant: a command step accelerates by 1 / 0.0334 = 30 mm/s^2 and the
 * back-EMF damps with 0.14 s, much less than the paper robot's 65 ms: a P
 * of 20 (omega 24.6 rad/s) needs a D for a damping ratio of ~0.5:
 * 2 x 0.5 x 24.6 = 24.6 1/s, 7.1 of it the back-EMF's, 17.5 / 30 = 0.6.
 * One encoder count per 1 ms tick is 9.8 mm/s, 6 steps through the D. */
#define RC_KP_FWD 20.0f    /* command per mm of forward position error */
#define RC_KP_ROT 20.0f    /* command per mm of wheel-arc rotation error */
#define RC_KD_FWD 0.6f     /* command per mm/s of forward speed error */
#define RC_KD_ROT 0.4f     /* command per mm/s of wheel-arc rotation rate error */
#define RC_KP_LATERAL 0.01f       /* rad per mm, as robot_config.h */
#define RC_KI_LATERAL 0.01f       /* rad/s per mm */
#define RC_LATERAL_MAX_RAD 0.15f  /* rad */
#define RC_LATERAL_REF_MM_S 0.0f  /* mm/s; 0: the centring P is not scaled */
#define RC_KP_HEADING 10.0f       /* rad/s per rad */

#define RC_SETTLE_MM 1.0f         /* mm: a move is over within this, */
#define RC_SETTLE_MM_S 20.0f      /* and this slow, mm/s */

/* ---- safety ---- */
#define RC_STALL_MM 20.0f         /* mm of forward error that means stuck, */
#define RC_STALL_MS 400u          /* for this long, ms */

#endif
