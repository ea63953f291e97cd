/* validate_robot.c - the robot file's own checks (see bench.h): the
 * figures measured on the real robot ([measured.NAME], the IR sensors'
 * measured_centred / measured_backed) reproduced by the simulated robot the
 * way they were measured, and the IR and gyro models against their
 * analytic values. */
#include "bench.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "world/robot.h"
#include "world/sensors/gyro.h"
#include "world/sensors/ir.h"

#define DEG_PER_RAD (180.0 / M_PI)
#define MEASURED "the robot file's [measured] section: the real robot's figure"

/* Names and sources of per-sensor checks (validate_check_t keeps pointers). */
static char names[VALIDATE_MAX_CHECKS][48];

static const char *name_of(int n, const char *fmt, const char *sensor)
{
    snprintf(names[n], sizeof names[n], fmt, sensor);
    return names[n];
}

/* A finer step than the contest's, for one figure reported beside the
 * graded one (how far the contest's step moves it). */
#define FINE_STEP_S 0.0002

/* Two voltages: the slope leaves out the voltage friction takes
 * (mazerunner-core's BIAS_FF); spins at 1 and 2 V: faster, a robot whose
 * mass sits ahead of its axle skids (its centre of mass needs more
 * centripetal force than the tyres give). */
static const double FWD_V1 = 1.5, FWD_V2 = 3.0, ROT_V1 = 1.0, ROT_V2 = 2.0; /* V */

/* The forward (rot 0, mm/s/V) or spin (rot 1, deg/s/V) slope with config
 * c, and the step at the higher voltage. */
static double km_slope(const simcfg_t *c, int rot, bench_step_t *high)
{
    double v1 = rot ? ROT_V1 : FWD_V1, v2 = rot ? ROT_V2 : FWD_V2;
    bench_step_t a = bench_voltage_step(c, v1, rot);
    *high = bench_voltage_step(c, v2, rot);
    return (high->steady - a.steady) / (v2 - v1) * (rot ? DEG_PER_RAD : 1000);
}

#define RATIO_SOURCE                                                                                                    \
    MEASURED " ROT_KM / FWD_KM (deg/s per mm/s): not fitted (no_load_rpm cancels out; the half track is the "         \
             "firmware's MOUSE_RADIUS)"
#define RATIO_FITTED                                                                                                    \
    MEASURED " ROT_KM / FWD_KM (deg/s per mm/s): body_drag_n_s_m, a load on translation alone, is fitted to it "      \
             "(docs/robots/ukmarsbot-sources.md section 7)"

/* The robot's [measured] step responses at the config's step_s (the step a
 * contest runs). tools/mmfit fitted the robot's mass, yaw inertia and motor
 * to ORION's forward KM and TM, rotation KM and TM and BIAS_FF
 * (docs/robots/ukmarsbot-sources.md section 8b): all four are fitted
 * figures. Their ratio is graded unless the robot carries a
 * body_drag_n_s_m, which is fitted to it: then it is a fitted figure too. */
static int motion_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    const robot_measured_t *m = &c->robot.measured;
    int drag = c->robot.body_drag_n_s_m > 0;
    double fkm = 0, rkm = 0;
    bench_step_t hi;
    if (m->fwd_km_mm_s_v > 0 || m->fwd_tm_s > 0) {
        fkm = km_slope(c, 0, &hi);
        if (m->fwd_km_mm_s_v > 0)
            bench_fit(v, &n, "forward_km", m->fwd_km_mm_s_v, fkm, "mm/s/V",
                      drag ? MEASURED " FWD_KM (slope of steady speed at 1.5 and 3 V; no_load_rpm is fitted to it and ROT_KM,"
                                      " body_drag_n_s_m to their ratio)"
                           : MEASURED " FWD_KM (slope of steady speed at 1.5 and 3 V; no_load_rpm is fitted to it and ROT_KM)");
        if (m->fwd_tm_s > 0)
            bench_fit(v, &n, "forward_tm", m->fwd_tm_s, hi.tm_s, "s",
                      MEASURED " FWD_TM (a 3 V step from rest; the mass is fitted to it)");
    }
    if (m->rot_km_deg_s_v > 0 || m->rot_tm_s > 0) {
        rkm = km_slope(c, 1, &hi);
        if (m->rot_km_deg_s_v > 0)
            bench_fit(v, &n, "rotation_km", m->rot_km_deg_s_v, rkm, "deg/s/V",
                      drag ? MEASURED " ROT_KM (motors at -V/+V, slope at 1 and 2 V; no_load_rpm is fitted to it and FWD_KM,"
                                      " body_drag_n_s_m to their ratio)"
                           : MEASURED " ROT_KM (motors at -V/+V, slope at 1 and 2 V; no_load_rpm is fitted to it and FWD_KM)");
        if (m->rot_tm_s > 0)
            bench_fit(v, &n, "rotation_tm", m->rot_tm_s, hi.tm_s, "s",
                      MEASURED " ROT_TM (a 2 V step from rest; the yaw inertia is fitted to it)");
    }
    if (m->fwd_km_mm_s_v <= 0 || m->rot_km_deg_s_v <= 0 || fkm <= 0) return n;
    if (drag)
        bench_fit(v, &n, "rotation_per_forward_km", m->rot_km_deg_s_v / m->fwd_km_mm_s_v, rkm / fkm, "deg/mm", RATIO_FITTED);
    else
        bench_add(v, &n, "rotation_per_forward_km", m->rot_km_deg_s_v / m->fwd_km_mm_s_v, rkm / fkm, "deg/mm", 10,
                  VALIDATE_NEAR, RATIO_SOURCE);
    if (c->sim.step_s > FINE_STEP_S) {
        static simcfg_t fine; /* large */
        fine = *c;
        fine.sim.step_s = FINE_STEP_S;
        double f = km_slope(&fine, 0, &hi), r = km_slope(&fine, 1, &hi);
        bench_add(v, &n, "rotation_per_forward_0.2ms", m->rot_km_deg_s_v / m->fwd_km_mm_s_v, f > 0 ? r / f : 0, "deg/mm",
                  10, VALIDATE_NEAR, "rotation_per_forward_km on a 0.2 ms step (not the contest's), its bar: what the step moves");
    }
    return n;
}

/* 500 mm straight down a long field at about 0.15 m/s, steered on the true
 * heading (a hand pushing it along a ruler): each encoder's counts. */
static void counts_500mm(const simcfg_t *c, double counts[2])
{
    bench_field(&bench.maze, 3, 8, 1);
    sim_state_t *s = &bench.sim;
    counts[0] = counts[1] = 0;
    if (bench_init(c) != 0) return;
    double x0, y0, h0, x, y, h;
    world_pose(s->world, &x0, &y0, &h0);
    int32_t e0[2] = { s->encoder[0].count, s->encoder[1].count };
    for (long i = 0; i < bench_steps(c, 20.0); i++) {
        world_pose(s->world, &x, &y, &h);
        if (hypot(x - x0, y - y0) >= 0.5) break;
        double err = remainder(h - h0, 2 * M_PI), base = 0.6, k = 20.0; /* V, V/rad */
        s->cmd[WORLD_LEFT] = bench_volt_cmd(s, base + k * err);
        s->cmd[WORLD_RIGHT] = bench_volt_cmd(s, base - k * err);
        sim_step(s->model, s);
    }
    world_pose(s->world, &x, &y, &h);
    double scale = 0.5 / hypot(x - x0, y - y0); /* the last step's overshoot, < 0.2 mm */
    for (int i = 0; i < 2; i++) counts[i] = (s->encoder[i].count - e0[i]) * scale;
    sim_free(s);
}

static int count_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    const robot_measured_t *m = &c->robot.measured;
    if (m->counts_500mm_left <= 0 && m->counts_500mm_right <= 0) return n;
    double counts[2];
    counts_500mm(c, counts);
    if (m->counts_500mm_left > 0)
        bench_fit(v, &n, "counts_500mm_left", m->counts_500mm_left, counts[0], "counts",
                  MEASURED " (pushed 500 mm along a straight line; the wheel diameter is fitted to it)");
    if (m->counts_500mm_right > 0)
        bench_fit(v, &n, "counts_500mm_right", m->counts_500mm_right, counts[1], "counts",
                  MEASURED " (pushed 500 mm along a straight line; the wheel diameter is fitted to it)");
    return n;
}

/* The two calibration poses of mazerunner-core's config-robot-*.h:
 * centred: in the middle cell of a corridor 1 cell wide running north,
 *   facing north, side walls left and right, no wall ahead for 2 cells;
 * backed: in the middle cell of a corridor running east, facing north,
 *   the body's rear against the cell's south wall, its north wall ahead. */
static int ir_calibration(const simcfg_t *c, validate_check_t *v, int n)
{
    sim_state_t *s = &bench.sim;
    unsigned nir = robot_count(c, "ir");
    for (int pose = 0; pose < 2; pose++) {
        if (pose == 0) bench_field(&bench.maze, 1, 4, 0);
        else bench_field(&bench.maze, 3, 1, 1);
        if (bench_init(c) != 0) return n;
        double y = pose == 0 ? 1.5 * c->world.cell_m : c->world.wall_thick_m / 2 + c->robot.body_l_m / 2;
        world_place(s->world, pose == 0 ? 0.5 * c->world.cell_m : 1.5 * c->world.cell_m, y, M_PI / 2, NULL);
        for (unsigned i = 0; i < nir; i++) {
            const robot_part_t *p = &c->robot.part[robot_part_of_kind(c, "ir", i)];
            const ir_part_spec_t *sp = (const ir_part_spec_t *)p->spec;
            double want = pose == 0 ? sp->measured_centred : sp->measured_backed;
            if (want < 0) continue;
            bench_fit(v, &n, name_of(n, pose == 0 ? "ir_%s_centred" : "ir_%s_backed", p->name), want, bench_lit_minus_dark(s, i),
                      "counts",
                      pose == 0 ? "the robot file's measured_centred: the real robot centred between side walls, no wall "
                                  "ahead (the sensor's gain is fitted to it)"
                                : "the robot file's measured_backed: the real robot backed against a rear wall, a wall "
                                  "ahead (the sensor's gain is fitted to it)");
        }
        sim_free(s);
    }
    return n;
}

/* The first IR sensor facing a wall straight on at d_m (the robot turned so
 * the sensor's axis is normal to the end wall of a corridor): the rays cast
 * in the world give what the model gives for an ideal plane
 * (ir_received_plane), the dark reading the ambient level. */
static int ir_model_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    int k = robot_part_of_kind(c, "ir", 0);
    if (k < 0) return n;
    const robot_part_t *p = &c->robot.part[k];
    const ir_spec_t *m = &((const ir_part_spec_t *)p->spec)->model;
    sim_state_t *s = &bench.sim;
    bench_corridor(&bench.maze, 4);
    if (bench_init(c) != 0) return n;
    double face = 4 * c->world.cell_m - c->world.wall_thick_m / 2, d = 0.12;
    /* heading so the sensor looks east: its yaw off the robot's forward */
    double h = -p->yaw_deg * M_PI / 180, ch = cos(h - M_PI / 2), sh = sin(h - M_PI / 2);
    double sx = ch * p->x_m - sh * p->y_m, sy = sh * p->x_m + ch * p->y_m; /* the sensor from the body centre */
    world_place(s->world, face - d - sx, 0.5 * c->world.cell_m - sy, h, NULL);
    const ir_t *ir = &((const ir_state_t *)s->part_state[k])->ir;
    double z = p->z_m, want = m->gain_counts * m->ref_m * m->ref_m *
                                ir_received_band(ir, d, 0, ir->reflectivity, ir->gloss, -z, c->world.wall_height_m - z);
    bench_fit(v, &n, "ir_far_field_120mm", want, bench_lit_minus_dark(s, 0), "counts",
              "IR model: the rays cast in the world against the model's ideal plane straight on (ir.h), as tall as a "
              "wall: the model's own formula from the robot file's keys, no outside data");
    double dark = 0;
    unsigned g = (unsigned)((const ir_part_spec_t *)p->spec)->emitter;
    sim_emitter_set(s, g, 0);
    for (int i = 0; i < 256; i++) dark += sim_ir_read(s, 0) / 256.0;
    bench_fit(v, &n, "ir_emitter_off_ambient", m->ambient_counts, dark, "counts",
              "the robot file's ambient_counts: emitter off reads the ambient level (the model's input reproduced)");
    sim_free(s);
    return n;
}

/* The first gyro at rest for 10 s: the spread of its samples is the noise
 * density times sqrt(ODR/2) (the datasheet's figure), and their mean the
 * bias it drew. */
static int gyro_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    int k = robot_part_of_kind(c, "gyro", 0);
    if (k < 0) return n;
    const gyro_spec_t *g = (const gyro_spec_t *)c->robot.part[k].spec;
    bench_field(&bench.maze, 3, 3, 1);
    sim_state_t *s = &bench.sim;
    if (bench_init(c) != 0) return n;
    double sum = 0, sum2 = 0, prev = NAN;
    long m = 0;
    for (long i = 0; i < bench_steps(c, 10.0); i++) {
        sim_step(s->model, s);
        double r = sim_gyro_rad_s(s) * DEG_PER_RAD;
        if (r == prev) continue; /* a held sample */
        prev = r;
        sum += r, sum2 += r * r, m++;
    }
    double mean = sum / m, sd = sqrt(fmax(0, sum2 / m - mean * mean));
    const gyro_t *st = s->part_state[k];
    double q = g->lsb_dps * g->lsb_dps / 12; /* quantisation adds LSB^2/12 */
    bench_fit(v, &n, "gyro_noise_sd", sqrt(gyro_sigma_dps(g) * gyro_sigma_dps(g) + q), sd, "deg/s",
              "the robot file's noise density * sqrt(ODR/2) (LSM6DS3 Table 3), with the LSB's quantisation (the model's "
              "input reproduced)");
    bench_fit(v, &n, "gyro_bias_at_rest", st->bias0_dps + st->walk_dps / 2, mean, "deg/s",
              "the gyro model's drawn zero-rate level (plus the walk): the mean at rest (the model's input reproduced)");
    sim_free(s);
    return n;
}

static int ir_front_sum_checks(const simcfg_t *c, validate_check_t *v, int n);
static int ir_ratio_checks(const simcfg_t *c, validate_check_t *v, int n);

int validate_robot_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    n = motion_checks(c, v, n); /* at c's own step, the contest's */
    n = count_checks(c, v, n);
    n = ir_calibration(c, v, n);
    n = ir_model_checks(c, v, n);
    n = gyro_checks(c, v, n);
    n = ir_front_sum_checks(c, v, n);
    return ir_ratio_checks(c, v, n);
}

/* The forward pair's normalised sum (mazerunner-core's get_front_sum: each
 * sensor's lit minus dark x 100 / its measured_backed) with the robot
 * heading east along row `row` of bench.maze (four cells long), its axle
 * axle_to_wall_m from the east wall's face. */
static double front_sum_at(const simcfg_t *c, double axle_to_wall_m, unsigned row)
{
    sim_state_t *s = &bench.sim;
    double face = 4 * c->world.cell_m - c->world.wall_thick_m / 2, sum = 0;
    world_place(s->world, face - axle_to_wall_m - c->robot.axle_y_m, (row + 0.5) * c->world.cell_m, 0, NULL);
    for (unsigned i = 0; i < robot_count(c, "ir"); i++) {
        const ir_part_spec_t *sp = (const ir_part_spec_t *)c->robot.part[robot_part_of_kind(c, "ir", i)].spec;
        if (sp->measured_backed > 0 && sp->measured_facing_sum > 0) sum += 100 * bench_lit_minus_dark(s, i) / sp->measured_backed;
    }
    return sum;
}

/* The forward pair against the published front sums of mazerunner-core's
 * config-robot-*.h (the robot file's measured_facing_sum,
 * measured_turn_sum and measured_turn_wall_adjust on the pair), all
 * predicted: the fit used only the backed-up and centred readings (at
 * 132 mm and of the side walls), never a front sum:
 * - facing: FRONT_REFERENCE, centred in a cell facing its wall, the axle
 *   half a cell less half a wall from it (84 mm), side walls there: the
 *   near field, set by the detector's offset from the emitter;
 * - turn in a corridor: TURN_THRESHOLD_SS90E, "set for when the robot is
 *   20mm past the cell boundary" (the wall ahead a cell less half a wall
 *   less 20 mm from the axle: 154 mm; ORION l.73-76), plus
 *   EXTRA_WALL_ADJUST for each of the two side walls, as mouse.h's
 *   turn_smooth raises its trigger when it sees them: the far field as
 *   the firmware meets it between walls;
 * - turn in the open: the threshold alone, no side walls. Reported, not
 *   graded: the model's front sensors see nothing of a side wall (their
 *   emitters' +-6 deg cone stays off it), where the real pair gains
 *   EXTRA_WALL_ADJUST a wall, so the open pose reads what the corridor
 *   does (sim/world/sensors/README.md). */
static int ir_front_sum_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    const ir_part_spec_t *pair = NULL;
    for (unsigned i = 0; i < robot_count(c, "ir"); i++) {
        const ir_part_spec_t *sp = (const ir_part_spec_t *)c->robot.part[robot_part_of_kind(c, "ir", i)].spec;
        if (sp->measured_backed > 0 && sp->measured_facing_sum > 0) pair = sp;
    }
    if (pair == NULL) return n;
    double cell = c->world.cell_m, wall = c->world.wall_thick_m, turn_m = cell - wall / 2 - 0.020;
    bench_corridor(&bench.maze, 4);
    if (bench_init(c) != 0) return n;
    bench_add(v, &n, "ir_front_sum_facing", pair->measured_facing_sum, front_sum_at(c, cell / 2 - wall / 2, 0), "1", 10,
              VALIDATE_NEAR, "the robot file's measured_facing_sum (FRONT_REFERENCE), centred facing a wall: not used by the fit");
    if (pair->measured_turn_sum > 0)
        bench_add(v, &n, "ir_front_sum_turn_walls", pair->measured_turn_sum + 2 * pair->measured_turn_wall_adjust,
                  front_sum_at(c, turn_m, 0), "1", 10, VALIDATE_NEAR,
                  "the robot file's measured_turn_sum + 2 x measured_turn_wall_adjust (TURN_THRESHOLD_SS90E + 2 x EXTRA_WALL_ADJUST, "
                  "the trigger between two side walls), wall 154 mm from the axle: not used by the fit");
    sim_free(&bench.sim);
    if (pair->measured_turn_sum <= 0) return n;
    bench_field(&bench.maze, 4, 3, 0);
    if (bench_init(c) != 0) return n;
    bench_add(v, &n, "ir_front_sum_turn_open", pair->measured_turn_sum, front_sum_at(c, turn_m, 1), "1", 10, VALIDATE_NEAR,
              "the robot file's measured_turn_sum (TURN_THRESHOLD_SS90E), no side walls, wall 154 mm from the axle: not used by "
              "the fit (sim/world/sensors/README.md: the far field)");
    sim_free(&bench.sim);
    return n;
}

/* Each sensor's lit minus dark with the robot in pose `pose` (0: backed
 * against a cell's rear wall, its wall ahead, as ir_calibration's backed
 * pose; 1: centred in a corridor's end cell facing its end wall, as
 * FRONT_REFERENCE's pose), into lmd[] (robot_count "ir" of them). */
static int ir_pose_readings(const simcfg_t *c, int pose, double *lmd)
{
    sim_state_t *s = &bench.sim;
    if (pose == 0) bench_field(&bench.maze, 3, 1, 1);
    else bench_corridor(&bench.maze, 4);
    if (bench_init(c) != 0) return -1;
    double cell = c->world.cell_m, wall = c->world.wall_thick_m;
    if (pose == 0) world_place(s->world, 1.5 * cell, wall / 2 + c->robot.body_l_m / 2, M_PI / 2, NULL);
    else world_place(s->world, 4 * cell - wall / 2 - (cell / 2 - wall / 2) - c->robot.axle_y_m, 0.5 * cell, 0, NULL);
    for (unsigned i = 0; i < robot_count(c, "ir"); i++) lmd[i] = bench_lit_minus_dark(s, i);
    sim_free(s);
    return 0;
}

/* The forward sensors' rise from backed against the rear wall to centred
 * facing the wall ahead (the robot file's measured_facing_ratio, a real
 * robot's own two readings' ratio, so no gain enters it): the near field
 * against the far, predicted: the fit used only the backed or centred
 * reading. */
static int ir_ratio_checks(const simcfg_t *c, validate_check_t *v, int n)
{
    unsigned nir = robot_count(c, "ir"), any = 0;
    for (unsigned i = 0; i < nir; i++)
        any |= ((const ir_part_spec_t *)c->robot.part[robot_part_of_kind(c, "ir", i)].spec)->measured_facing_ratio > 0;
    double backed[ROBOT_MAX_PARTS], facing[ROBOT_MAX_PARTS];
    if (!any || nir > ROBOT_MAX_PARTS || ir_pose_readings(c, 0, backed) != 0 || ir_pose_readings(c, 1, facing) != 0) return n;
    for (unsigned i = 0; i < nir; i++) {
        const robot_part_t *p = &c->robot.part[robot_part_of_kind(c, "ir", i)];
        double want = ((const ir_part_spec_t *)p->spec)->measured_facing_ratio;
        if (want <= 0) continue;
        bench_add(v, &n, name_of(n, "ir_%s_facing_over_backed", p->name), want, backed[i] > 0 ? facing[i] / backed[i] : 0, "1",
                  10, VALIDATE_NEAR,
                  "the robot file's measured_facing_ratio: the real robot's reading centred facing a wall over its reading "
                  "backed against the rear wall (132 mm from the axle to the wall ahead): not used by the fit");
    }
    return n;
}
