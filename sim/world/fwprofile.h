/* fwprofile.h - the firmware's robot profile as a robot file holds it: the
 * [firmware] section (every figure and behaviour option of the example
 * firmware, firmware/robot_config.h's RC_* names in lower case without
 * RC_) and [firmware.avr] (the values an AVR image takes where they
 * differ). The robot reader (robot.c) checks the two sections' keys and
 * values with this table; tools/mkprofile.c writes them into the
 * firmware's generated robot_profile.h. A key marked with a `from` takes
 * its value from the robot's own physics keys (wheel diameters, track,
 * encoder and gear, ToF poses) unless [firmware] gives it: docs/ROBOTS.md,
 * "The firmware's side of a robot". */
#ifndef FWPROFILE_H
#define FWPROFILE_H

#include <stddef.h>

typedef enum {
    FW_FLOAT, /* a plain decimal: a float constant (96.2 -> 96.2f) */
    FW_INT,   /* a whole number, may be negative: an int */
    FW_U32,   /* a whole number >= 0: an unsigned constant (400 -> 400u) */
    FW_INTS,  /* 1 to 32 whole numbers, space-separated: an initializer */
    FW_RATIO, /* "MM / COUNTS" (a calibration: mm driven per counts) or 0: the wheel's figure */
} fw_type_t;

/* where a key's value comes from when [firmware] lacks it */
typedef enum {
    FW_OWN = 0,       /* nowhere: [firmware] must give it */
    FW_FROM_WHEELS,   /* [chassis.*] the mean of wheel_left_d_mm and wheel_right_d_mm */
    FW_FROM_TRACK,    /* [chassis.*] wheel_track_mm */
    FW_FROM_COUNTS,   /* [encoder.left] encoder_ppr x [motor.left] gear_ratio */
    FW_FROM_TOF_FRONT_Y, /* [tof.front] y_mm */
    FW_FROM_TOF_SIDE_X,  /* [tof.right] x_mm */
    FW_FROM_TOF_SIDE_Y,  /* [tof.right] y_mm */
    FW_FROM_TOF_FOV,     /* [tof.right] fov_deg */
    FW_FROM_TOF_RAYS,    /* [tof.right] rays */
} fw_from_t;

typedef struct {
    const char *key; /* the robot file's key; the header's name is RC_ and it in upper case */
    fw_type_t type;
    fw_from_t from;
} fw_key_t;

extern const fw_key_t fw_keys[];
extern const size_t fw_nkeys;

/* 1 if section is "firmware" or "firmware.avr", else 0. */
int fw_section(const char *section);
/* The key named key, NULL if none. */
const fw_key_t *fw_key_find(const char *key);
/* val checked for k's type: 0, or -1 with "SECTION.KEY: expected ..., got
 * '...'" in why. */
int fw_value_check(const fw_key_t *k, const char *section, const char *val, char *why, size_t len);
/* The C text of a checked value into out (n bytes): "96.2f", "(-1)",
 * "400u", "{ 22, 32 }", "(500.0f / 1918.0f)", "RC_MM_PER_COUNT". 0, or -1
 * if it does not fit. */
int fw_value_c(const fw_key_t *k, const char *val, char *out, size_t n);

#endif
