/* slalom_off.h - robot_config.h's speed-run names for a robot whose
 * firmware drives orthogonal speed runs only (RC_DIAG_RUNS 0: no planner,
 * no slaloms, no diagonals; the turns' room 0 mm = not driven). A robot
 * header includes it after its RC_SMOOTH_* lines. */
#ifndef SLALOM_OFF_H
#define SLALOM_OFF_H

#define RC_DIAG_RUNS 0
#define RC_SLALOM_SAFE_MM_S RC_SMOOTH_MM_S
#define RC_SLALOM_FAST_MM_S RC_SMOOTH_MM_S
#define RC_SLALOM_F90_SAFE_MM_S RC_SMOOTH_MM_S
#define RC_SLALOM_F90_FAST_MM_S RC_SMOOTH_MM_S
#define RC_SLALOM_F180_SAFE_MM_S RC_SMOOTH_MM_S
#define RC_SLALOM_F180_FAST_MM_S RC_SMOOTH_MM_S
#define RC_SLALOM_F45_SAFE_MM_S RC_SMOOTH_MM_S
#define RC_SLALOM_F45_FAST_MM_S RC_SMOOTH_MM_S
#define RC_DIAG_SAFE_MM_S RC_SMOOTH_MM_S
#define RC_DIAG_FAST_MM_S RC_SMOOTH_MM_S
#define RC_RUN_FAST_MM_S RC_RUN_MM_S
#define RC_RUN_FAST_ACCEL_MM_S2 RC_RUN_ACCEL_MM_S2
#define RC_RUN_FAST_CMD_FF_MAX RC_CMD_FF_MAX
#define RC_RUN_CLEAN_MM 10.0f         /* mm */
#define RC_DIAG_ENTRY_HALVES 2        /* half units */
#define RC_DIAG_MAX_HALVES 6          /* half steps */
#define RC_DIAG_AFTER_TURN_HALVES (-1) /* half steps; -1: none */
#define RC_DIAG_ALL_TURNS 0
#define RC_BLIND_MAX_HALVES (-1)      /* half units; -1: no limit */
#define RC_BLIND_MAX_TURNS 0          /* turns */
#define RC_DIAG_TOF 0
#define RC_CMD_DIAG_TOF 0
#define RC_DIAG_TOF_START_MM 1.5f     /* mm, as robot_config.h */
#define RC_DIAG_TOF_DRIFT_MM2 0.02f   /* mm^2 per mm, as robot_config.h */
#define RC_SLALOM_ACCEL_DEG_S2 RC_SMOOTH_ACCEL_DEG_S2
#define RC_SLALOM_W_MIN_DEG_S 57.3f   /* deg/s */
#define RC_SLALOM_W_MAX_DEG_S 859.4f  /* deg/s */
#define RC_SLALOM_S90_MM 0.0f         /* mm: 0, not driven */
#define RC_SLALOM_F90_MM 0.0f         /* mm */
#define RC_SLALOM_F45_MM 0.0f         /* mm */
#define RC_SLALOM_D45_MM 0.0f         /* mm */
#define RC_SLALOM_V90_MM 0.0f         /* mm */
#define RC_SLALOM_F135_MM 0.0f        /* mm */
#define RC_SLALOM_D135_MM 0.0f        /* mm */

#endif
