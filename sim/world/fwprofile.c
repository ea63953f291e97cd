/* fwprofile.c - the [firmware] keys of a robot file: their table, their
 * values' check and C text (fwprofile.h). */
#include "fwprofile.h"

#include <stdio.h>
#include <string.h>

#include "io/number.h"

#define N(a) (sizeof(a) / sizeof((a)[0]))
#define FW_INTS_MAX 32

/* In firmware/robot_config.h's order of subjects: geometry, motor model,
 * wall sensors, speeds and turns, speed runs, sensing, controller, safety,
 * command mode. docs/ROBOTS.md says what each one does. */
const fw_key_t fw_keys[] = {
    { "cell_mm", FW_FLOAT, FW_OWN },
    { "wall_mm", FW_FLOAT, FW_OWN },
    { "wheel_diameter_mm", FW_FLOAT, FW_FROM_WHEELS },
    { "track_mm", FW_FLOAT, FW_FROM_TRACK },
    { "odom_track_mm", FW_FLOAT, FW_OWN },
    { "counts_per_rev", FW_FLOAT, FW_FROM_COUNTS },
    { "mm_per_count_left", FW_RATIO, FW_OWN },
    { "mm_per_count_right", FW_RATIO, FW_OWN },
    { "start_behind_mm", FW_FLOAT, FW_OWN },
    { "mm_s_per_cmd", FW_FLOAT, FW_OWN },
    { "cmd_friction", FW_FLOAT, FW_OWN },
    { "friction_ramp_mm_s", FW_FLOAT, FW_OWN },
    { "cmd_per_mm_s2", FW_FLOAT, FW_OWN },
    { "cmd_per_arc_mm_s2", FW_FLOAT, FW_OWN },
    { "cmd_max", FW_INT, FW_OWN },
    { "cmd_max_v", FW_FLOAT, FW_OWN },
    { "cmd_ff_max", FW_FLOAT, FW_OWN },
    { "tof_front_y_mm", FW_FLOAT, FW_FROM_TOF_FRONT_Y },
    { "tof_side_x_mm", FW_FLOAT, FW_FROM_TOF_SIDE_X },
    { "tof_side_y_mm", FW_FLOAT, FW_FROM_TOF_SIDE_Y },
    { "tof_fov_deg", FW_FLOAT, FW_FROM_TOF_FOV },
    { "tof_rays", FW_INT, FW_FROM_TOF_RAYS },
    { "walls_ir", FW_INT, FW_OWN },
    { "ir_front_curve_ratio64", FW_INTS, FW_OWN },
    { "ir_front_curve_mm", FW_INTS, FW_OWN },
    { "diag_edge_cos", FW_FLOAT, FW_OWN },
    { "diag_edge_sin", FW_FLOAT, FW_OWN },
    { "side_wall_mm", FW_FLOAT, FW_OWN },
    { "side_threshold_mm", FW_FLOAT, FW_OWN },
    { "centring_max_mm", FW_FLOAT, FW_OWN },
    { "centring_min_mm_s", FW_FLOAT, FW_OWN },
    { "side_blind_from_mm", FW_FLOAT, FW_OWN },
    { "side_blind_to_mm", FW_FLOAT, FW_OWN },
    { "search_mm_s", FW_FLOAT, FW_OWN },
    { "run_mm_s", FW_FLOAT, FW_OWN },
    { "accel_mm_s2", FW_FLOAT, FW_OWN },
    { "run_accel_mm_s2", FW_FLOAT, FW_OWN },
    { "run_fast_cmd_ff_max", FW_FLOAT, FW_OWN },
    { "run_fast_mm_s", FW_FLOAT, FW_OWN },
    { "run_fast_accel_mm_s2", FW_FLOAT, FW_OWN },
    { "turn_deg_s", FW_FLOAT, FW_OWN },
    { "turn_accel_deg_s2", FW_FLOAT, FW_OWN },
    { "pivot_max_mm", FW_FLOAT, FW_OWN },
    { "pivot_avg", FW_FLOAT, FW_OWN },
    { "smooth_turns", FW_INT, FW_OWN },
    { "smooth_mm_s", FW_FLOAT, FW_OWN },
    { "smooth_deg_s", FW_FLOAT, FW_OWN },
    { "smooth_accel_deg_s2", FW_FLOAT, FW_OWN },
    { "diag_runs", FW_INT, FW_OWN },
    { "slalom_safe_mm_s", FW_FLOAT, FW_OWN },
    { "slalom_fast_mm_s", FW_FLOAT, FW_OWN },
    { "slalom_f90_safe_mm_s", FW_FLOAT, FW_OWN },
    { "slalom_f90_fast_mm_s", FW_FLOAT, FW_OWN },
    { "slalom_f180_safe_mm_s", FW_FLOAT, FW_OWN },
    { "slalom_f180_fast_mm_s", FW_FLOAT, FW_OWN },
    { "slalom_f45_safe_mm_s", FW_FLOAT, FW_OWN },
    { "slalom_f45_fast_mm_s", FW_FLOAT, FW_OWN },
    { "diag_safe_mm_s", FW_FLOAT, FW_OWN },
    { "diag_fast_mm_s", FW_FLOAT, FW_OWN },
    { "run_clean_mm", FW_FLOAT, FW_OWN },
    { "diag_entry_halves", FW_INT, FW_OWN },
    { "diag_max_halves", FW_INT, FW_OWN },
    { "diag_after_turn_halves", FW_INT, FW_OWN },
    { "diag_all_turns", FW_INT, FW_OWN },
    { "blind_max_halves", FW_INT, FW_OWN },
    { "blind_max_turns", FW_INT, FW_OWN },
    { "diag_tof", FW_INT, FW_OWN },
    { "diag_tof_start_mm", FW_FLOAT, FW_OWN },
    { "diag_tof_drift_mm2", FW_FLOAT, FW_OWN },
    { "tof_cv", FW_FLOAT, FW_OWN },
    { "diag_tof_max_mm", FW_FLOAT, FW_OWN },
    { "diag_tof_margin_mm", FW_FLOAT, FW_OWN },
    { "diag_tof_gate_mm", FW_FLOAT, FW_OWN },
    { "slalom_accel_deg_s2", FW_FLOAT, FW_OWN },
    { "slalom_w_min_deg_s", FW_FLOAT, FW_OWN },
    { "slalom_w_max_deg_s", FW_FLOAT, FW_OWN },
    { "slalom_s90_mm", FW_FLOAT, FW_OWN },
    { "slalom_f90_mm", FW_FLOAT, FW_OWN },
    { "slalom_f45_mm", FW_FLOAT, FW_OWN },
    { "slalom_d45_mm", FW_FLOAT, FW_OWN },
    { "slalom_v90_mm", FW_FLOAT, FW_OWN },
    { "slalom_f135_mm", FW_FLOAT, FW_OWN },
    { "slalom_d135_mm", FW_FLOAT, FW_OWN },
    { "sense_before_mm", FW_FLOAT, FW_OWN },
    { "sense_from_mm", FW_FLOAT, FW_OWN },
    { "post_margin_mm", FW_FLOAT, FW_OWN },
    { "front_wall_margin_mm", FW_FLOAT, FW_OWN },
    { "sense_latest_mm", FW_FLOAT, FW_OWN },
    { "align_from_mm", FW_FLOAT, FW_OWN },
    { "align_gain", FW_FLOAT, FW_OWN },
    { "wall_heading_reads", FW_INT, FW_OWN },
    { "wall_heading_prior", FW_FLOAT, FW_OWN },
    { "wall_heading_near_mm", FW_FLOAT, FW_OWN },
    { "wall_heading_max_rad", FW_FLOAT, FW_OWN },
    { "kp_fwd", FW_FLOAT, FW_OWN },
    { "kp_rot", FW_FLOAT, FW_OWN },
    { "kd_fwd", FW_FLOAT, FW_OWN },
    { "kd_rot", FW_FLOAT, FW_OWN },
    { "kp_lateral", FW_FLOAT, FW_OWN },
    { "ki_lateral", FW_FLOAT, FW_OWN },
    { "lateral_max_rad", FW_FLOAT, FW_OWN },
    { "lateral_ref_mm_s", FW_FLOAT, FW_OWN },
    { "kp_heading", FW_FLOAT, FW_OWN },
    { "settle_mm", FW_FLOAT, FW_OWN },
    { "settle_mm_s", FW_FLOAT, FW_OWN },
    { "stall_mm", FW_FLOAT, FW_OWN },
    { "stall_ms", FW_U32, FW_OWN },
    { "cmd_diag_tof", FW_INT, FW_OWN },
};
const size_t fw_nkeys = N(fw_keys);

int fw_section(const char *section)
{
    return !strcmp(section, "firmware") || !strcmp(section, "firmware.avr");
}

const fw_key_t *fw_key_find(const char *key)
{
    for (size_t i = 0; i < fw_nkeys; i++)
        if (!strcmp(fw_keys[i].key, key)) return &fw_keys[i];
    return NULL;
}

/* n bytes at s: a whole number (a '-' first if neg), at most 9 digits */
static int whole(const char *s, size_t n, int neg)
{
    if (neg && n > 1 && *s == '-') s++, n--;
    if (n == 0 || n > 9) return 0;
    for (size_t i = 0; i < n; i++)
        if (s[i] < '0' || s[i] > '9') return 0;
    return 1;
}

/* the space-separated whole numbers of val: how many (0: not that) */
static int ints(const char *val)
{
    int count = 0;
    for (const char *p = val; *p;) {
        if (*p == ' ') { p++; continue; }
        size_t n = strcspn(p, " ");
        if (!whole(p, n, 1) || ++count > FW_INTS_MAX) return 0;
        p += n;
    }
    return count;
}

/* "A / B", two positive plain decimals, into a and b (their spans) */
static int ratio(const char *val, const char **a, size_t *an, const char **b, size_t *bn)
{
    const char *slash = strchr(val, '/');
    if (!slash) return 0;
    *a = val, *an = (size_t)(slash - val);
    while (*an && (*a)[*an - 1] == ' ') (*an)--;
    *b = slash + 1;
    while (**b == ' ') (*b)++;
    *bn = strlen(*b);
    double x, y;
    return io_decimal(*a, *an, &x) == 0 && io_decimal(*b, *bn, &y) == 0 && x > 0 && y > 0;
}

int fw_value_check(const fw_key_t *k, const char *section, const char *val, char *why, size_t len)
{
    const char *a, *b;
    size_t an, bn;
    static const char *const want[] = { "a plain decimal number", "a whole number", "a whole number >= 0",
                                        "1 to 32 whole numbers separated by spaces", "0 or MM / COUNTS" };
    int ok = k->type == FW_FLOAT   ? io_plain_decimal(val, strlen(val))
             : k->type == FW_INT   ? whole(val, strlen(val), 1)
             : k->type == FW_U32   ? whole(val, strlen(val), 0)
             : k->type == FW_INTS  ? ints(val) > 0
                                   : !strcmp(val, "0") || ratio(val, &a, &an, &b, &bn);
    if (ok) return 0;
    snprintf(why, len, "%s.%s: expected %s, got '%s'", section, k->key, want[k->type], val);
    return -1;
}

/* a float constant of n bytes at s: 96 -> 96.0f, -1.5 -> (-1.5f) */
static int float_c(const char *s, size_t n, char *out, size_t len)
{
    int neg = *s == '-';
    int m = snprintf(out, len, "%s%.*s%sf%s", neg ? "(" : "", (int)n, s, memchr(s, '.', n) ? "" : ".0", neg ? ")" : "");
    return m > 0 && (size_t)m < len ? 0 : -1;
}

int fw_value_c(const fw_key_t *k, const char *val, char *out, size_t n)
{
    int m = 0;
    if (k->type == FW_FLOAT) return float_c(val, strlen(val), out, n);
    if (k->type == FW_INT) m = snprintf(out, n, *val == '-' ? "(%s)" : "%s", val);
    if (k->type == FW_U32) m = snprintf(out, n, "%su", val);
    if (k->type == FW_INTS) {
        m = snprintf(out, n, "{");
        for (const char *p = val; *p && m > 0 && (size_t)m < n;) {
            if (*p == ' ') { p++; continue; }
            size_t w = strcspn(p, " ");
            m += snprintf(out + m, n - (size_t)m, "%s %.*s", m > 1 ? "," : "", (int)w, p);
            p += w;
        }
        if (m > 0 && (size_t)m < n) m += snprintf(out + m, n - (size_t)m, " }");
    }
    if (k->type == FW_RATIO) {
        const char *a, *b;
        size_t an, bn;
        if (!strcmp(val, "0") || !ratio(val, &a, &an, &b, &bn)) {
            m = snprintf(out, n, "RC_MM_PER_COUNT");
        } else {
            char x[64], y[64];
            if (float_c(a, an, x, sizeof x) || float_c(b, bn, y, sizeof y)) return -1;
            m = snprintf(out, n, "(%s / %s)", x, y);
        }
    }
    return m > 0 && (size_t)m < n ? 0 : -1;
}
