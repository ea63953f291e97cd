/* steplog.c - `mmsim --bench-log`: a voltage step or an IR reading of the
 * configured robot as a CSV log (steplog.h), on the benches of bench.h. */
#include "validate/steplog.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "validate/bench.h"
#include "world/robot.h"
#include "world/sensors/ir.h"

#define STEP_LOG_S 1.2   /* s: as validate_robot.c's voltage_step, motorlab's step length */
#define OFF_MAZE_M 4.0   /* m west of the maze: more than a 12 V step covers in 1.2 s (~3 m) */
#define ROW_EVERY_S 1e-3 /* s: one row a millisecond, a firmware's control tick */

/* On a converged integration, as --validate measures the robot's figures
 * (validate_robot.c: FINE_STEP_S). */
#define FINE_STEP_S 0.0002

static int step_log(const simcfg_t *run, double v_volt, int rot, FILE *out)
{
    static simcfg_t fine; /* large */
    fine = *run;
    if (fine.sim.step_s > FINE_STEP_S) fine.sim.step_s = FINE_STEP_S;
    const simcfg_t *c = &fine;
    /* on open floor: a field's posts stand at every cell corner, and a robot with
     * unequal wheels veers into them; the floor is an infinite plane, so the robot
     * starts west of a one-cell maze, facing further west */
    bench_field(&bench.maze, 1, 1, 0);
    sim_state_t *s = &bench.sim;
    if (bench_init(c) != 0) return -1;
    world_place(s->world, -OFF_MAZE_M, 0.5 * c->world.cell_m, M_PI, NULL);
    long n = bench_steps(c, STEP_LOG_S), every = lround(ROW_EVERY_S / c->sim.step_s);
    if (every < 1) every = 1;
    int32_t e0[2] = { s->encoder[0].count, s->encoder[1].count };
    fprintf(out, "t_s,volts,left_counts,right_counts\n0,%g,0,0\n", v_volt);
    for (long i = 1; i <= n; i++) {
        s->cmd[WORLD_LEFT] = bench_volt_cmd(s, rot ? -v_volt : v_volt);
        s->cmd[WORLD_RIGHT] = bench_volt_cmd(s, v_volt);
        sim_step(s->model, s);
        if (i % every == 0)
            fprintf(out, "%.4f,%g,%ld,%ld\n", i * c->sim.step_s, v_volt, (long)(s->encoder[0].count - e0[0]),
                    (long)(s->encoder[1].count - e0[1]));
    }
    sim_free(s);
    return 0;
}

/* Sensor `name` looking east at the end wall of a corridor, d_m from the
 * wall along its axis, its axis angle_rad off the wall's normal. */
static int ir_log(const simcfg_t *c, const char *name, double d_m, double angle_rad, FILE *out)
{
    unsigned nir = robot_count(c, "ir"), i;
    int k = -1;
    for (i = 0; i < nir; i++) {
        k = robot_part_of_kind(c, "ir", i);
        if (strcmp(c->robot.part[k].name, name) == 0) break;
    }
    if (i == nir) {
        fprintf(stderr, "mmsim: --bench-log: no [ir.%s] in the robot file\n", name);
        return -1;
    }
    const robot_part_t *p = &c->robot.part[k];
    bench_corridor(&bench.maze, 4);
    sim_state_t *s = &bench.sim;
    if (bench_init(c) != 0) return -1;
    double face = 4 * c->world.cell_m - c->world.wall_thick_m / 2;
    /* heading so the sensor's axis points angle_rad off east; the sensor d along it from the wall */
    double h = angle_rad - p->yaw_deg * M_PI / 180, ch = cos(h - M_PI / 2), sh = sin(h - M_PI / 2);
    double sx = ch * p->x_m - sh * p->y_m, sy = sh * p->x_m + ch * p->y_m; /* the sensor from the body centre */
    double ax = d_m * cos(angle_rad); /* the axis meets the wall d_m away: east offset */
    world_place(s->world, face - ax - sx, 0.5 * c->world.cell_m - sy, h, NULL);
    fprintf(out, "sensor,distance_mm,angle_deg,counts\n%s,%g,%g,%.3f\n", name, d_m * 1000, angle_rad * 180 / M_PI,
            bench_lit_minus_dark(s, i));
    sim_free(s);
    return 0;
}

int steplog_run(const simcfg_t *c, const char *spec, FILE *out)
{
    char buf[128], *end;
    if (strlen(spec) >= sizeof buf) goto bad;
    strcpy(buf, spec);
    char *kind = strtok(buf, ":"), *a = strtok(NULL, ":"), *b = strtok(NULL, ":"), *d = strtok(NULL, ":");
    if (!kind || !a) goto bad;
    if ((!strcmp(kind, "fwd") || !strcmp(kind, "rot")) && !b) {
        double v = strtod(a, &end);
        if (*end || !(fabs(v) <= 12)) goto bad;
        return step_log(c, v, kind[0] == 'r', out);
    }
    if (!strcmp(kind, "ir") && b && d) {
        double mm = strtod(b, &end);
        if (*end || !(mm > 0 && mm < 1000)) goto bad;
        double deg = strtod(d, &end);
        if (*end || !(fabs(deg) < 80)) goto bad;
        return ir_log(c, a, mm / 1000, deg * M_PI / 180, out);
    }
bad:
    fprintf(stderr, "mmsim: --bench-log: expected fwd:VOLTS, rot:VOLTS (|V| <= 12) or ir:NAME:D_MM:ANGLE_DEG, got '%s'\n", spec);
    return -1;
}
