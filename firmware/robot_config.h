/* robot_config.h - every robot-specific number of the firmware, with its
 * unit and where it comes from. Port the firmware to another mouse by
 * changing this file only. Defaults: the paper's robot as simulated by
 * mmsim (robots/paper.ini holds the simulator's side of the same numbers;
 * test/tools/robot_config_check.py checks that the two agree). */
#ifndef ROBOT_CONFIG_H
#define ROBOT_CONFIG_H

/* ---- geometry ---- */
#define RC_CELL_MM 180.0f            /* classic maze pitch */
#define RC_WALL_MM 12.0f             /* wall thickness */
#define RC_WHEEL_DIAMETER_MM 32.0f   /* paper Table 1 */
#define RC_TRACK_MM 96.0f            /* wheel centre planes at +-48 mm */
/* Odometry's track: in-place quarter turns came out 0.2 degrees short of
 * what 96 mm reported (250 turns, japan2018/2019 in mmsim: the tyres'
 * 8 mm contact patches scrub); 96.2 halves that, and of 96.0, 96.2, 96.3
 * and 96.4 it gave the fewest wall contacts over 60 japan seeds. */
#define RC_ODOM_TRACK_MM 96.2f
#define RC_COUNTS_PER_REV 358.32f    /* 12 PPR on the motor x 29.86 gear */
#define RC_MM_PER_COUNT (3.14159265f * RC_WHEEL_DIAMETER_MM / RC_COUNTS_PER_REV) /* 0.2806 mm */
/* each wheel's own mm per count (odom.c): wheels of one size here */
#define RC_MM_PER_COUNT_LEFT RC_MM_PER_COUNT
#define RC_MM_PER_COUNT_RIGHT RC_MM_PER_COUNT
/* The robot stands this far behind the start cell's centre at the start
 * (mm; 0: on the centre; UKMARSBOT starts backed against the rear wall). */
#define RC_START_BEHIND_MM 0.0f

/* ---- motor model, for feed-forward ---- */
/* The Pololu 30:1 LP 6V gearmotor as mmsim's datasheet model has it
 * (sim/world/motor.h; datasheet at 6 V: no load 450 rpm and 0.02 A, stall
 * 0.028439 N*m and 0.36 A, gear N = 29.86): R = 6 V / 0.36 A = 16.67 ohm,
 * Ke = Kt = (6 V - 0.02 A * R) / (N * 47.12 rad/s) = 4.027 mV*s/rad at the
 * motor shaft, gearbox efficiency eta = 0.028439 / (N * Kt * 0.34 A) =
 * 0.696, so N * eta * Kt = 0.0836 N*m/A at the wheel. A command step is
 * 6 V / 1023 = 5.865 mV. Steady state: V = R * (i0 + i_load) + N * Ke * w. */
/* no-load wheel speed per command step, the friction's voltage (below)
 * aside: 5.865 mV / (N * Ke = 0.12025 V*s/rad) = 0.04877 rad/s at the
 * wheel, * 16 mm = 0.7804 mm/s, i.e. 1.2814 command per mm/s. Check:
 * 1023 = 57 + 966 -> 966 * 0.7804 = 754 mm/s, the datasheet's 450 rpm
 * with 32 mm wheels. */
#define RC_MM_S_PER_CMD 0.7804f
/* the gearbox's friction, the no-load current's voltage: i0 * R = 0.02 A *
 * 16.67 ohm = 0.333 V = 56.8 command steps, added in the direction the
 * wheel is meant to turn: its setpoint speed plus the controller's
 * correction as a speed (motion.c wheel_cmd), ramped in over
 * RC_FRICTION_RAMP_MM_S so that a wheel held at rest does not chatter
 * between +-57 (with the P of 30 the ramp ends at 0.85 mm of error) */
#define RC_CMD_FRICTION 56.8f
#define RC_FRICTION_RAMP_MM_S 20.0f
/* command per mm/s^2 of acceleration: each wheel pushes half the effective
 * mass, the robot's 0.157 kg plus each wheel's inertia over r^2 (rotor
 * 2e-8 kg*m^2 * N^2 = 1.783e-5, the 10 g wheel 1.28e-6: 0.0747 kg per
 * wheel), 0.1532 kg; T = F * r, i = T / 0.0836 N*m/A, V = i * R:
 * 0.1532 kg * 0.001 m/s^2 * 0.016 m / 0.08364 * 16.67 ohm * 170.5 / V =
 * 0.0833 per mm/s^2 (the robot accelerates like 0.306 kg) */
#define RC_CMD_PER_MM_S2 0.0833f
/* the same per mm/s^2 of wheel arc in rotation: the chassis' yaw inertia
 * (127 g box 96 x 120 mm 2.50e-4, caster 10 g at 55 mm 3.0e-5, wheels 10 g
 * at 48 mm 4.6e-5: 3.26e-4 kg*m^2) over 2 * (48 mm)^2 = 0.0708 kg per
 * wheel, plus the wheel's 0.0747 kg: 0.1455 kg -> 0.0791 per mm/s^2 */
#define RC_CMD_PER_ARC_MM_S2 0.0791f
#define RC_CMD_MAX 1023
/* Feed-forward may use this much of the command; the rest is for the
 * controller's corrections (at RC_KP_* = 30 per mm, 3 mm of error). Forward
 * moves speed up at most at (RC_CMD_FF_MAX - 57 - 1.2814 * v) / 0.0833
 * mm/s^2: 2,700 at 500 mm/s, 1,200 at 600, none at 676 (the top speed the
 * controller can still hold). Speed runs after a clean one take their own
 * cap, RC_RUN_FAST_CMD_FF_MAX. */
#define RC_CMD_FF_MAX 923.0f

/* ---- ToF sensors (positions as robots/paper.ini's [tof.*]) ---- */
#define RC_TOF_FRONT_Y_MM 55.0f      /* front sensor ahead of the body centre */
#define RC_TOF_SIDE_X_MM 40.0f       /* diagonal sensors' offset from the centre line */
#define RC_TOF_SIDE_Y_MM 50.0f       /* diagonal sensors ahead of the body centre */
/* The VL53L0X reports the nearest surface in its 25 deg field of view
 * (datasheet DocID029104; robots/paper.ini [tof.*] fov_deg). A flat wall
 * 45 degrees off a diagonal sensor's axis (a side wall, or the wall ahead
 * of a cell centre) is therefore read along the cone's edge nearest the
 * wall's normal, 45 - 12.5 = 32.5 degrees off it, not along the axis; the
 * cosine and sine of that angle turn a reading into distances. */
#define RC_TOF_FOV_DEG 25.0f
#define RC_TOF_RAYS 5                /* the cone as robots/paper.ini's rays = 5 models it */
/* 0: the wall sensors are ToF (walls.h); no IR front curve (unused) */
#define RC_WALLS_IR 0
#define RC_IR_FRONT_CURVE_RATIO64 { 0 }
#define RC_IR_FRONT_CURVE_MM { 0 }
#define RC_DIAG_EDGE_COS 0.8434f     /* cos(32.5 deg) */
#define RC_DIAG_EDGE_SIN 0.5373f     /* sin(32.5 deg) */
/* A diagonal sensor sees a side wall 84 - 40 = 44 mm away sideways:
 * 44 / cos(32.5 deg) = 52.2 mm (one ray along the 45 degree axis read 62);
 * 1 mm sideways is 1.19 mm of reading. Without that wall the cone runs on
 * to a wall one cell further out (~200 mm) or to a post. */
#define RC_SIDE_WALL_MM 52.2f
/* nearer = wall present: the side wall up to 32 mm further out than
 * centred ((44 + 32) / cos(32.5 deg) = 90 mm), the reach 110 mm had with
 * the one ray. Kept that short because the cone's inner edge reaches the
 * post or wall ahead of the next cell through its missing side wall at
 * ~110 mm when the walls are read late (RC_SENSE_LATEST_MM: the sensor
 * 10 mm short of the centre). 110 passed the 30 first failing mazes of
 * the classic folder alike (seed 1), once the walls were read with fresh
 * readings (RC_SENSE_FROM_MM). */
#define RC_SIDE_THRESHOLD_MM 90.0f
/* Centring uses a diagonal reading only below this: 20 mm off the centre
 * line ((44 + 20) / cos(32.5 deg) = 76 mm). Between it and
 * RC_SIDE_THRESHOLD_MM the cone has met a post or a wall through a gap (a
 * reading of that kind put a U-turn's pivot 8 mm off on japan2019 seed 6
 * and its corner into the wall). */
#define RC_CENTRING_MAX_MM 76.0f
/* and only while moving faster than this: a creep of more than 4 mm back
 * from a wall ahead took readings of that wall for side walls */
#define RC_CENTRING_MIN_MM_S 100.0f
/* From 48 mm before a cell centre to 4 mm past it the diagonal sensors can
 * reach the post row at the cell's end first (a wall ahead, or the
 * neighbour's end wall where the side wall is missing), which reads like a
 * near side wall. With the cone that happens from 17 mm before the centre
 * (the inner edge meets a wall ahead nearer than 52.2 mm from 10 mm
 * before); the one ray's wider band is kept. */
#define RC_SIDE_BLIND_FROM_MM 48.0f
#define RC_SIDE_BLIND_TO_MM 4.0f
/* distance from the front sensor to the wall ahead when centred in a cell */
#define RC_FRONT_AT_CENTRE_MM (RC_CELL_MM / 2 - RC_WALL_MM / 2 - RC_TOF_FRONT_Y_MM) /* 29 mm */

/* ---- search and run speeds ---- */
/* The motor's top speed is 754 mm/s (no load, 6 V); the controller keeps
 * the feed-forward within RC_CMD_FF_MAX, which caps the speed it can hold
 * at 676 mm/s. Search straights: 600 mm/s (feed-forward 57 + 769 = 826,
 * 100 of the speeding-up budget left at cruise). The turn at the next cell
 * is decided at the sensing point, RC_SENSE_BEFORE_MM before its centre,
 * which leaves 140 - 79 = 61 mm to brake to RC_SMOOTH_MM_S (1,900 mm/s^2
 * from 600 to 350). Search at 500 mm/s with 300 mm/s turns: japan2018's
 * first run 63.7 s; at 600 (sensing 140 mm before the centre) 58.6 s. */
#define RC_SEARCH_MM_S 600.0f
#ifdef __AVR__
/* Over the link the wheel loop lags 5-9 ms; with the old, faster motor
 * speed runs at 1100 and 900 mm/s weaved on japan2019's straights and
 * staircase (docs/BENCHMARKS.md) and 700 held. The true motor's 650 mm/s
 * is below all of those; the AVR keeps 600 (feed-forward 826: ~200 of
 * command for the steering of a loop that lags). */
#define RC_RUN_MM_S 600.0f
#else
/* speed runs: 650 mm/s, feed-forward 57 + 833 = 890 of 1023 at cruise
 * (speeding up slows to ~400 mm/s^2 near it, RC_CMD_FF_MAX). 600: best
 * runs 28.4 s on japan2018 and 27.7 on japan2019, 650: 27.1 and 27.0 */
#define RC_RUN_MM_S 650.0f
#endif
/* ~0.3 g (tyres hold ~1 g at mu 1.0); speeding up, the motor allows it only
 * below 481 mm/s (RC_CMD_FF_MAX), braking always */
#define RC_ACCEL_MM_S2 3000.0f
#define RC_RUN_ACCEL_MM_S2 3000.0f   /* speed runs: 5000 crashed on japan2019 (wheel slip in the stops) */
/* The speed runs climb (slalomrun.c slalomrun_begin): the first, and any after a
 * run whose tracking error reached RC_RUN_CLEAN_MM, at the safe figures
 * (RC_RUN_MM_S, RC_RUN_ACCEL_MM_S2, RC_CMD_FF_MAX, RC_SLALOM_SAFE_MM_S,
 * RC_DIAG_SAFE_MM_S), each after a clean one at these (host builds with
 * the planner; measured in mmsim, paper robot, seed 1):
 * - the feed-forward's cap during the run, command: 990 of 1023 leaves
 *   33 (1.1 mm of error at RC_KP_FWD) for the controller, and the wheels
 *   hold 728 mm/s. japan2018, japan2019 and seven mazes that had touched
 *   at other figures: largest tracking error 3-7 mm per run; at 1000
 *   (cruise 730) 11-18 mm, runs fell back, uk2025-megacon-b touched.
 * - cruise 720 mm/s (feed-forward 57 + 923 = 980): best runs 24.74 s
 *   (japan2018) and 24.65 s (japan2019); at 650 (with 390 mm/s turns)
 *   26.19 and 25.33.
 * - acceleration and braking as the safe runs', 3,000 mm/s^2: 4,000 was
 *   0.15 s faster on both but japan9p touched a wall twice as the third
 *   run stopped at the goal, 0.5 s after its lap ended; at 5,000 japan2001
 *   touched (every 8th classic maze, 61), at 6,000 japan2019 and at 8,000
 *   both crashed in the first fast run (the robot pitches onto its nose
 *   in hard stops: centre of mass 3.5 mm behind the axle, no front skid). */
#define RC_RUN_FAST_CMD_FF_MAX 990.0f
#define RC_RUN_FAST_MM_S 720.0f
#define RC_RUN_FAST_ACCEL_MM_S2 3000.0f
/* in-place turns: a quarter turn peaks at 424 deg/s (wheels 355 mm/s),
 * feed-forward 57 + 455 + 133 (35 rad/s^2 of wheel arc) = 645. At 600
 * deg/s and 3,000 deg/s^2 (peak 520 deg/s) with the contacts as springs
 * and the load-dependent gearbox friction, 12 of the 479 reachable classic
 * mazes (seed 1) touched a wall, every time a body corner in a turn on the
 * spot; with this and RC_PIVOT_MAX_MM 4, none of those 12 and none of 30
 * clean others did (each change alone left 1 of the 12). A U-turn takes
 * ~0.15 s longer. */
#define RC_TURN_DEG_S 450.0f
#define RC_TURN_ACCEL_DEG_S2 2000.0f
/* On the spot the body's corners sweep 77 mm about the pivot and the cell
 * leaves 84 mm: 7 mm off the centre line touches a wall. Off-centre stops
 * turn about a point up to this far towards the cell's centre. Turning
 * about a point p to the side puts the outer corners sqrt(60^2 + (48 +
 * p)^2) mm from it: 82.3 at 8 mm (1.7 mm for the stop's error along the
 * heading and the offset estimate's), 79.6 at 4 mm (4.4 mm); an offset
 * beyond 4 mm is left partly, which touches only past 8.6 mm. */
#define RC_PIVOT_MAX_MM 4.0f
/* The offset for that is a running average of the straight's centring
 * estimates (each new reading moves it by this share): a single one has
 * ~2 mm of noise, and a pivot set from a wrong one moves the robot off
 * the centre instead. */
#define RC_PIVOT_AVG 0.3f
/* Smooth 90-degree turns while moving at RC_SMOOTH_MM_S: the rotation
 * profile speeds up at 70 rad/s^2 towards 5.5 rad/s, and no faster than
 * the outer wheel's feed-forward leaves within RC_CMD_FF_MAX (motion.c
 * ff_spare): at 350 mm/s that limit takes over at ~4.5 rad/s, so the
 * outer wheel reaches 614 mm/s (feed-forward 57 + 787 = 844 at cruise, at
 * most ~930 with the acceleration term) and the turn peaks at 0.20 g
 * sideways. The turn starts ~79 mm before the turn cell's centre and ends
 * ~79 mm past it on the new heading (computed at start-up,
 * motion_smooth_geometry, with the same limit); its body (96 x 120 mm,
 * wheels to +-52 mm) keeps >= 21 mm from the cell's walls and 32 mm from
 * the inner post (checked numerically). The motor sets the speed: with a
 * trapezoidal rotation the feed-forward of the outer wheel peaks where the
 * ramp ends (speed and acceleration at once), so 300 mm/s, 5 rad/s and
 * 40 rad/s^2 were the fastest it allowed, and japan2018's first run took
 * 58.6 s; this turn takes 0.36 s instead of 0.44. At 100 rad/s^2 (370
 * mm/s, 6.25 rad/s: 4.8 m/s^2 at each wheel as the turn begins) the
 * search of japan2019 lost its heading in a staircase of turns, mapped
 * wrong walls and crashed. Before the motor was faithful (1210 mm/s
 * no-load) the turns ran at 500 mm/s, 8 rad/s, 120 rad/s^2; 160 rad/s^2
 * had slipped ~0.5 degrees per turn pair in staircases (7.7 m/s^2). A
 * shorter offset leaves the 30 ms ToF sensors time to deliver a fresh
 * reading of the next cell before its own turn must start. */
/* 1: smooth turns (0: on the spot only, motion.c) */
#define RC_SMOOTH_TURNS 1
#define RC_SMOOTH_MM_S 350.0f
#define RC_SMOOTH_DEG_S 315.1f       /* 5.5 rad/s */
#define RC_SMOOTH_ACCEL_DEG_S2 4010.7f /* 70 rad/s^2 */
/* ---- speed runs with diagonals and slaloms (host builds: PLAN_ENABLED;
 * firmware/slalom.c sizes each turn, plan.c picks the moves) ---- */
/* 1: speed runs follow plan_run's moves; 0: orthogonal straights joined
 * by smooth turns (run_plan) */
#define RC_DIAG_RUNS 1
/* Each turn kind at its own speed (plan.h: the straights between turns
 * speed up or brake from one turn's speed to the next's). The S90 (a 90
 * inside one cell) at 350 mm/s, the smooth 90's speed: it fits its
 * RC_SLALOM_S90_MM of room up to ~375 mm/s under RC_CMD_FF_MAX (above it
 * the outer wheel runs into the feed-forward's cap); at 300 the zigzags
 * of staircases took longer (japan2019 seed 1: best run 30.0 s against
 * 27.0). The fast runs' 390 fits it under RC_RUN_FAST_CMD_FF_MAX (up to
 * ~395). At 400 the S90 needs 88 mm of room, and at 88 five of 61
 * classic mazes (every 8th) touched, taiwan2017f in its first run at 350.
 * F135, D135 and V90 (not driven, RC_SLALOM_*_MM 0) take the S90's. */
#define RC_SLALOM_SAFE_MM_S 350.0f
#define RC_SLALOM_FAST_MM_S 390.0f
/* F90, F180, F45 and D45 (D45 the F45's speed), each checked by
 * test_slalom (the body 10 mm clear of posts and walls, 3 mm for turns to
 * or from a diagonal; within 0.3 g and the wheels' top speed). The F90:
 * the fastest in steps of 10 mm/s that slalom_fit_kinds fits in its room under
 * the run's cap (at 450 and 480 no rate the outer wheel's feed-forward
 * allows turns it within RC_SLALOM_F90_MM). The F180: 400 under the fast
 * cap (10.8 mm from its post; 410: 9.9), 350 on the safe runs (14.0 mm;
 * at 390, 10.5 mm, taiwan2017f crashed in its first speed run, seed 1).
 * The F45 and D45 at the S90's speeds: they fit up to 430 and 460, but at
 * a fast 460 uk2003f and uk2024-megacon-a touched (a lane change F45 D45
 * after a staircase, 3.2 mm of clearance), at 430 uk2003f. */
#define RC_SLALOM_F90_SAFE_MM_S 440.0f
#define RC_SLALOM_F90_FAST_MM_S 470.0f
#define RC_SLALOM_F180_SAFE_MM_S 350.0f
#define RC_SLALOM_F180_FAST_MM_S 400.0f
#define RC_SLALOM_F45_SAFE_MM_S 350.0f
#define RC_SLALOM_F45_FAST_MM_S 390.0f
/* Diagonal straights: the wheels pass the posts 3.1 mm off on the
 * diagonal's centre line (posts 63.6 mm from it, minus 52 mm of wheel and
 * 8.5 mm of post across the diagonal); held on odometry's heading, nothing
 * to centre on. The speed runs climb: the first at _SAFE, each later one
 * at _FAST if the run before it ended with the wheels' tracking error
 * under RC_RUN_CLEAN_MM (a bump into a post or wall shows there; the
 * firmware has no other word on a contact). On this robot both are 400:
 * with 500 after a clean run, 6 of the 479 reachable classic mazes (seed
 * 1) touched a post, each in a later run on a plan with a short diagonal;
 * at 400 the planner finds no diagonal worth driving (it costs more than
 * it saves at that speed) and none of the 479 touched a wall. */
#define RC_DIAG_SAFE_MM_S 400.0f
#define RC_DIAG_FAST_MM_S 400.0f
#define RC_RUN_CLEAN_MM 10.0f
/* Diagonals only where the robot knows where it is (slalomrun.c
 * diag_ok), else the run is planned without them: entered from an
 * orthogonal straight of at least RC_DIAG_ENTRY_HALVES (centred on its
 * side walls) and at most RC_DIAG_MAX_HALVES long. Measured in mmsim
 * (seed 1, the true pose against the plan's): a diagonal starts with the
 * held heading 0.2-0.6 degrees off the maze's and 1-2 mm off its line,
 * which puts the wheels into a post within 3-4 half steps. Every 8th
 * classic maze (61): diagonals of any length entered from anywhere, 18
 * touched; from a centred straight of 2, up to 6 half steps: uk1990f; of
 * 4, up to 4: japan2013eq; of 2, up to 2: none. With each turn kind at
 * its own speed the planner takes short diagonals (F45, 1-2 half steps,
 * D45) where they save time, and 6 of the 479 reachable classic mazes
 * touched a post on them (5 crashed); with none (0: every plan with a
 * diagonal straight or a D45 is planned again without), those 6 are
 * clean and japan2018 and japan2019 are as fast (no diagonal pays in
 * their plans). */
#define RC_DIAG_ENTRY_HALVES 2
#define RC_DIAG_MAX_HALVES 0
/* -1: no diagonal entered from a turn (slalomrun.c diag_ok), half steps */
#define RC_DIAG_AFTER_TURN_HALVES (-1)
/* 0: no V90, F135, D135 or lane change (slalomrun.c diag_ok) */
#define RC_DIAG_ALL_TURNS 0
/* blind straights (slalomrun.c blind_ok, robot_ukmarsbot.h): -1, no limit */
#define RC_BLIND_MAX_HALVES (-1)
#define RC_BLIND_MAX_TURNS 0             /* turns */
/* 1: a position reference on diagonal straights from the diagonal ToF
 * sensors (diagref.c diagref_centring): each reading of a known wall
 * face square to the sensor's axis is compared with the one the map
 * predicts from the estimated pose, a Kalman filter per maze axis moves the
 * estimate, and its offset from the diagonal's line steers as wall
 * centring does. Readings used: expected within RC_DIAG_TOF_MAX_MM, every
 * other surface (or unknown wall) at least RC_DIAG_TOF_MARGIN_MM further,
 * measured within RC_DIAG_TOF_GATE_MM of expected. Measured in mmsim (seed
 * 1, every 8th classic maze, 61): with it, diagonals of up to 12 half
 * steps at 500 mm/s touched no post (without it, of up to 6: uk1990f and
 * uk2011follower did); at 600 two mazes touched. On all 479 reachable
 * classic mazes at 500 and up to 12, four still touched (taiwan2011f and
 * br2024-robochallenge-day3 on the first speed run, also with up to 6;
 * ies90f, uk2024-hazlemere). Off (0) for that, and because it gains
 * little: the planner takes a diagonal in 9 of the 61 mazes (none on
 * japan2019, even at 1000 mm/s), so the median best run does not move
 * (all 479: 63 faster, 1 slower, mean -0.46 %; uk2011follower 22.78 s
 * against 23.51 s). To try it: 1 here,
 * RC_DIAG_MAX_HALVES 12, RC_DIAG_SAFE_MM_S and _FAST_MM_S 500. */
#define RC_DIAG_TOF 0
#define RC_DIAG_TOF_START_MM 1.5f    /* the estimate's standard deviation at the start: the entry's 1-2 mm */
#define RC_DIAG_TOF_DRIFT_MM2 0.02f  /* its variance's growth per mm driven, mm^2 (ours: tuned in mmsim) */
#define RC_TOF_CV 0.042f             /* a reading's standard deviation per mm of it (robots/paper.ini [tof.*]: 4.2 %) */
#define RC_DIAG_TOF_MAX_MM 200.0f     /* mm: 8.4 mm of noise there */
#define RC_DIAG_TOF_MARGIN_MM 8.0f    /* mm */
#define RC_DIAG_TOF_GATE_MM 15.0f     /* mm */
/* Each slalom's rotation speeds up at the smooth 90's 70 rad/s^2 (the
 * outer wheel's acceleration budget, RC_CMD_FF_MAX) up to a peak rate
 * slalom.c chooses between these bounds (deg/s: 1 and 15 rad/s; the
 * motor's cap on the outer wheel takes over below 15 at these speeds). */
#define RC_SLALOM_ACCEL_DEG_S2 4010.7f
#define RC_SLALOM_W_MIN_DEG_S 57.3f
#define RC_SLALOM_W_MAX_DEG_S 859.4f
/* From each turn's start to its corner, mm (slalom.c sizes the peak rate
 * to it). Larger cuts the corner more (a shorter, faster path) and brings
 * the body nearer the inner post. Checked at 300 and 350 mm/s by
 * sweeping the body (96 x 120 mm, wheels to +-52 mm) along the integrated
 * path against 12 mm posts and every wall the turn does not cross
 * (test/unit/test_slalom.c; at 350): S90 85 (of 90: 22 mm from the wall
 * ahead), F90 120 (of 270: 20 mm from the inner post; 160: 2.4 mm), F45
 * and D45 60 (of 127: 3.2 mm, as on the diagonal itself; 100: 0.3 mm),
 * V90 70 (of 127: 3.1 mm; 85: 0.2 mm). V90 is not driven (0): it joins
 * two diagonals, and a diagonal starts only from a centred straight
 * (RC_DIAG_ENTRY_HALVES). F135 and D135: 0, not driven: at 250-350 mm/s
 * no rate the motor allows fits them (the body overlaps the post). F180
 * has none: it is sized to end RC_CELL_MM to the side (14 mm from the
 * post it turns about). */
#define RC_SLALOM_S90_MM 85.0f
#define RC_SLALOM_F90_MM 120.0f
#define RC_SLALOM_F45_MM 60.0f
#define RC_SLALOM_D45_MM 60.0f
#define RC_SLALOM_V90_MM 0.0f
#define RC_SLALOM_F135_MM 0.0f
#define RC_SLALOM_D135_MM 0.0f
/* sense the next cell's walls this far before its centre: the diagonal
 * sensors (50 mm ahead of the body's centre) are then at its entry
 * boundary, and their cones (32.5 to 57.5 degrees off the heading) meet
 * its side wall 28 to 69 mm past that boundary, clear of the posts (+-6 mm
 * about it). 110 before left only 31 mm to brake into a smooth turn. */
#define RC_SENSE_BEFORE_MM 140.0f
/* and only with readings taken within this of the cell's centre (the
 * diagonal sensors then at most 10 mm short of its entry boundary): the
 * cone's outer edge, 57.5 degrees off the heading, meets the post at that
 * boundary from 22 mm short of it (17 mm turned 5 degrees towards it),
 * and a post there reads like a side wall (52 mm) where the cell has none.
 * Readings up to 30 ms old at the sensing point (18 mm at 600 mm/s) put
 * side walls that are not there into 13ye (seed 1: a post read 50 mm)
 * and 87us1; with this both are mapped right. The first
 * reading after this point arrives at most 18 mm later: 132 - 79 = 53 mm
 * to brake into a smooth turn (2,200 mm/s^2). */
#define RC_SENSE_FROM_MM 150.0f
/* A side reading counts for the cell ahead only when its cone's outer edge
 * (57.5 degrees off the heading, 44 mm from the side wall's line square
 * and centred: it meets that line 28 mm ahead of the sensor) runs past the
 * post at the cell's entry (+-6 mm about the boundary) by this much; the
 * robot's turn towards the wall moves the sensor back and turns the edge
 * towards the post (drive.c clear_of_entry_post). Square, every reading
 * after RC_SENSE_FROM_MM is clear by 12 mm; turned 4.4 degrees left (a
 * centring that took the turn for an offset weaved +-6 degrees), at 148.4
 * mm before the centre of (15,0) by odometry (152.4 true), hk90's left
 * sensor read that post at 43 mm, a wall where there is none (seed 1).
 * 6 mm: that run's 4 mm of odometry along the heading and 2 mm of reach
 * for 3 mm off the centre line. */
#define RC_POST_MARGIN_MM 6.0f
/* The wall ahead of the cell ahead reads RC_FRONT_AT_CENTRE_MM beyond its
 * centre, up to 18 mm more from a reading 30 ms old at search speed; with
 * four sigmas of the sensor's noise (4.2 % of the ~165 mm at the sensing
 * point: 7 mm) nearer than this beyond that is a wall. Without that wall
 * the nearest surface the front cone (12.5 degrees either side) can meet
 * is a side wall beyond the cell, 84 mm off the centre line: 84 / sin(12.5
 * deg) = 388 mm square, 233 mm turned 8.6 degrees (RC_LATERAL_MAX_RAD).
 * With 90 mm, on eastjapan-016-1998 (seed 1) the robot turned 5 degrees
 * right (the same weave) took such a wall 251 mm away, 255 allowed, for a
 * wall ahead of (9,15). */
#define RC_FRONT_WALL_MARGIN_MM 50.0f
/* without a fresh reading by this distance before a cell's centre, sense
 * with the last one (at most 30 ms = 18 mm old at search speed) */
#define RC_SENSE_LATEST_MM 60.0f
/* front-wall alignment works in the last part of a move towards a wall */
#define RC_ALIGN_FROM_MM 90.0f
#define RC_ALIGN_GAIN 0.35f /* share of the sensor's correction taken per reading */
/* Heading from the wall ahead, standing at a cell centre (drive.c
 * wall_heading): the diagonal rays meet it ~48 mm out, 10 mm from the side
 * walls; one pair of readings (5 % noise each) gives the angle to ~0.9
 * degrees. */
/* readings per stop, one per 35 ms: over 160 japan contests 1, 2 and 3
 * gave contacts in 8, 3 and 2; each costs ~0.5 s of japan2018's first run */
#define RC_WALL_HEADING_READS 3
#define RC_WALL_HEADING_PRIOR 1.0f   /* weight of the held heading, in readings */
/* only this near the centre (front reading, mm): 10 mm short of it the rays
 * reach the side walls first */
#define RC_WALL_HEADING_NEAR_MM 6.0f
#define RC_WALL_HEADING_MAX_RAD 0.09f /* 5 degrees: more is a post or a missing wall, not drift */

/* ---- controller gains (tuned in mmsim on japan2018) ---- */
/* Plant: one command step accelerates the robot by 1 / 0.0833 = 12 mm/s^2,
 * and the motor's back-EMF damps it with a 0.0833 * 0.7804 = 65 ms time
 * constant, so the loop needs a stiff P and no D (a 1 ms encoder
 * difference is 280 mm/s per count). With the gearbox's friction (57) the
 * P alone left the wheels at rest up to 57 / 30 = 1.9 mm off, more than
 * RC_SETTLE_MM: motion.c wheel_cmd compensates it. */
#ifdef __AVR__
/* On an Arduino over the serial link (HIL, and PIL in simavr) the loop runs
 * at 250 Hz and lags 5-9 ms (encoder frames up to 4 ms old, ~1.8 ms of
 * tick, the motor frame on the wire; in process: one 4 ms tick). At 30 the
 * robot's heading swung +-3 degrees at rest and in-place turns ended up to
 * 11 degrees off (japan2018 in simavr); 20 holds (docs/BENCHMARKS.md). */
#define RC_KP_FWD 20.0f    /* command per mm of forward position error */
#define RC_KP_ROT 20.0f    /* command per mm of wheel-arc rotation error */
#else
#define RC_KP_FWD 30.0f    /* command per mm of forward position error */
#define RC_KP_ROT 30.0f    /* command per mm of wheel-arc rotation error */
#endif
#define RC_KD_FWD 0.0f     /* command per mm/s of forward speed error */
#define RC_KD_ROT 0.0f     /* command per mm/s of wheel-arc rotation rate error */
/* Wall centring: heading offset per mm off the centre line (P: 10 mm ->
 * 5.7 degrees; with the heading loop's 0.1 s lag the lateral loop is
 * damped at zeta ~0.7 at 500 mm/s, ~0.6 at 650 mm/s) and the rate at
 * which the held heading itself follows (I, a fifth of P per second). */
#define RC_KP_LATERAL 0.01f   /* rad per mm */
#define RC_KI_LATERAL 0.01f  /* rad/s per mm */
#define RC_LATERAL_MAX_RAD 0.15f /* at most 8.6 degrees off the held heading */
#ifdef __AVR__
/* Over the link the heading loop lags more, and the lateral loop's
 * damping falls with speed (its stiffness is v * RC_KP_LATERAL): at 900
 * mm/s the robot weaved +-6 degrees at ~1.7 Hz on japan2019's straights and
 * entered turns up to 10 degrees off. Above this speed the centring P is
 * scaled by RC_LATERAL_REF_MM_S / v, which keeps the loop as at 500 mm/s. */
#define RC_LATERAL_REF_MM_S 500.0f
#else
#define RC_LATERAL_REF_MM_S 0.0f /* mm/s; 0: the centring P is not scaled */
#endif
#define RC_KP_HEADING 10.0f /* rad/s of steering per rad of heading error */

/* a move is over when the robot is within this of its setpoint, this slow */
#define RC_SETTLE_MM 1.5f
#define RC_SETTLE_MM_S 25.0f

/* ---- safety ---- */
#define RC_STALL_MM 40.0f       /* forward error that means we are stuck... */
#define RC_STALL_MS 400u        /* ...for this long: crash stop */

/* ---- command mode (mmsim --mms) ---- */
/* 1: command mode's diagonals (cmd.c diagonal) steer on the speed
 * runs' diagonal reference (RC_DIAG_TOF's, with its RC_DIAG_TOF_* figures),
 * anchored at the middle of the boundary each starts from; 0: held blind
 * on odometry's heading. Host builds only (diagref.c is PLAN_ENABLED code). */
#define RC_CMD_DIAG_TOF 1

#endif
