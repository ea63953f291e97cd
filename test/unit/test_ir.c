/* test_ir.c - the IR reflectance sensor model: the rays cast in the world
 * against the ideal plane, rho/d^2 in the far field, the near-field peak
 * and fall-off of the offset detector, the angle of a matt and a glossy
 * wall, ambient and noise with the emitter off, the ADC's rails, seeded
 * streams, a beam grazing a wall end, the emitter's skirt and the board's
 * shield. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "world/config.h"
#include "world/rng.h"
#include "world/sensors/ir.h"
#include "world/world.h"

static simcfg_t cfg;
static sim_model_t model; /* of cfg */

static int setup(void **state)
{
    (void)state;
    config_defaults(&cfg);
    sim_model_build(&model, &cfg, 1);
    return 0;
}

/* 4 x 4 cells, only the outer walls (posts everywhere), and optionally the
 * east side of cell (1,1): a wall on x = 2 cells from y = 1 to 2 cells. */
static world_t *arena(int inner_wall)
{
    truemaze_t m;
    truemaze_init(&m, 4, 4);
    for (uint16_t c = 0; c < 16; c++)
        for (uint8_t d = 0; d < 4; d++) truemaze_set_wall(&m, (truemaze_cell_t)c, d, 0);
    if (inner_wall) truemaze_set_wall(&m, truemaze_cell(&m, 1, 1), TRUEMAZE_EAST, 1);
    world_t *w = world_create(&model, &m, 0.09, 0.09, M_PI / 2); /* robot out of the way: rays see only walls and posts */
    assert_non_null(w);
    return w;
}

static double east_face(void) { return 4 * cfg.world.cell_m - cfg.world.wall_thick_m / 2; }

static ir_t quiet(void)
{
    static ir_spec_t s; /* the sensor keeps it by pointer */
    ir_spec_default(&s);
    s.noise_counts = 0;
    ir_t ir;
    ir_init(&ir, &s, cfg.world.wall_reflectivity, 1, 0);
    return ir;
}

/* world_ray_normal: the distance of world_ray, the wall's normal facing
 * the ray, also for a ray tilted up or down. */
static void test_ray_normal(void **state)
{
    (void)state;
    world_t *w = arena(0);
    double p[3] = { east_face() - 0.1, 1.5 * cfg.world.cell_m, cfg.world.wall_height_m / 2 }, n[3];
    double east[3] = { 1, 0, 0 }, west[3] = { -2, 0, 0 }, up[3] = { 1, 0, 0.1 };
    assert_true(fabs(world_ray_normal(w, p, east, 1.0, n) - world_ray(w, p[0], p[1], p[2], 0, 1.0)) < 1e-9);
    assert_true(fabs(n[0] + 1) < 1e-9 && fabs(n[1]) < 1e-9 && fabs(n[2]) < 1e-9);
    assert_true(world_ray_normal(w, p, west, 1.0, n) > 0); /* the west wall, dir not unit length */
    assert_true(fabs(n[0] - 1) < 1e-9);
    assert_true(fabs(world_ray_normal(w, p, up, 1.0, n) - 0.1 * sqrt(1.01)) < 1e-6);
    assert_true(fabs(n[0] + 1) < 1e-9);
    assert_true(world_ray_normal(w, p, east, 0.05, n) < 0); /* out of range */
    assert_true(n[0] == 0 && n[1] == 0 && n[2] == 0);
    world_destroy(w);
}

/* (1) Straight on at the east wall: the rays cast in the world give the
 * model's ideal plane (ir_received_plane), the far field tends to rho/d^2,
 * counts = ambient + gain ref^2 x received. */
static void test_distance(void **state)
{
    (void)state;
    world_t *w = arena(0);
    ir_t ir = quiet();
    const ir_spec_t *s = ir.spec;
    double y = 1.5 * cfg.world.cell_m, z = cfg.world.wall_height_m / 2;
    for (double d = 0.01; d <= 0.2001; d += 0.01) {
        double p[3] = { east_face() - d, y, z };
        double r = ir_received(&ir, w, p, 0), want = ir_received_plane(&ir, d, 0, ir.reflectivity, 0);
        assert_true(fabs(r - want) <= 0.01 * want + 1e-9);
        if (d >= 0.15) assert_true(fabs(r / (ir.reflectivity / (d * d)) - 1) < 0.03);
        double counts = ir_read(&ir, w, p, 0, 1) - s->ambient_counts;
        double want_counts = s->gain_counts * s->ref_m * s->ref_m * want;
        if (want_counts + s->ambient_counts < ir_full_scale(&ir)) /* else the ADC's rail: test_rails */
            assert_true(fabs(counts - want_counts) < 0.02 * want_counts + 0.5);
    }
    world_destroy(w);
}

/* (1b) Near field: with the detector offset from the emitter the reading
 * rises as the wall comes closer, peaks, and falls as the lit spot leaves
 * the detector's cone; with no offset it keeps rising to the guard. */
static void test_near_field(void **state)
{
    (void)state;
    ir_t ir = quiet();
    double rho = ir.reflectivity, peak = 0, peak_d = 0;
    for (double d = 0.002; d <= 0.1; d += 0.001) {
        double r = ir_received_plane(&ir, d, 0, rho, 0);
        if (r > peak) peak = r, peak_d = d;
    }
    assert_true(peak_d > 0.010 && peak_d < 0.040); /* -5.6 mm, 12 deg: ~22 mm */
    assert_true(ir_received_plane(&ir, 0.005, 0, rho, 0) < 0.1 * peak);
    assert_true(ir_received_plane(&ir, 0.1, 0, rho, 0) < 0.2 * peak);
    static ir_spec_t s0;
    ir_spec_default(&s0);
    s0.det_offset_m = 0;
    ir_t ir0;
    ir_init(&ir0, &s0, rho, 1, 0);
    double prev = 0;
    for (double d = 0.1; d >= s0.near_m; d -= 0.001) {
        double r = ir_received_plane(&ir0, d, 0, rho, 0);
        assert_true(r > prev);
        prev = r;
    }
}

/* (2) The beam turned by a off the wall's normal, its centre ray hitting
 * the wall at the same distance: a matt wall's reading goes about as
 * cos(a) (the detector beside the emitter shifts it a little); a glossy
 * one reads more straight on and falls much faster with the angle (the
 * mirror lobe leaves the detector at twice the tilt). */
static void test_angle(void **state)
{
    (void)state;
    world_t *w = arena(0);
    ir_t ir = quiet(), gl = quiet();
    ir_set_finish(&gl, 0.04, 50);
    double y = 1.5 * cfg.world.cell_m, z = cfg.world.wall_height_m / 2, dist = 0.1, r0 = 0, g0 = 0;
    for (int deg = 0; deg <= 60; deg += 10) {
        double a = deg * M_PI / 180;
        double p[3] = { east_face() - dist * cos(a), y - dist * sin(a), z };
        double r = ir_received(&ir, w, p, a), g = ir_received(&gl, w, p, a);
        if (deg == 0) r0 = r, g0 = g;
        assert_true(fabs(r / r0 - cos(a)) < 0.03 * cos(a));
        assert_true(fabs(g - ir_received_plane(&gl, dist, a, gl.reflectivity, 0.04)) < 0.01 * g);
        if (deg == 0) assert_true(g > 1.5 * r);                  /* the lobe's share straight on */
        if (deg == 10) assert_true(g / g0 < 0.7 * (r / r0));     /* gone at 10 deg */
        if (deg >= 20) assert_true(fabs(g / r - 1) < 0.02);      /* matt beyond */
    }
    world_destroy(w);
}

/* (3) Emitter off: ambient plus noise, whatever is ahead; mean and
 * standard deviation as configured (rounding to counts adds 1/12). */
static void test_dark(void **state)
{
    (void)state;
    world_t *w = arena(0);
    ir_spec_t s;
    ir_spec_default(&s);
    s.ambient_counts = 100;
    s.noise_counts = 5;
    ir_t ir;
    ir_init(&ir, &s, cfg.world.wall_reflectivity, 7, 1);
    double p[3] = { east_face() - 0.03, 1.5 * cfg.world.cell_m, cfg.world.wall_height_m / 2 };
    const int n = 20000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; i++) {
        double v = ir_read(&ir, w, p, 0, 0);
        sum += v;
        sum2 += v * v;
    }
    double mean = sum / n, sd = sqrt(sum2 / n - mean * mean);
    /* dark is dark: the same stream at a wall or in the open reads the same */
    ir_t a, b;
    ir_init(&a, &s, cfg.world.wall_reflectivity, 9, 0);
    ir_init(&b, &s, cfg.world.wall_reflectivity, 9, 0);
    double open_p[3] = { east_face() - 0.6, 1.5 * cfg.world.cell_m, cfg.world.wall_height_m / 2 };
    for (int i = 0; i < 100; i++) assert_int_equal(ir_read(&a, w, p, 0, 0), ir_read(&b, w, open_p, M_PI, 0));
    assert_true(fabs(mean - 100) < 0.15);               /* 5 / sqrt(20000) = 0.035 */
    assert_true(fabs(sd / sqrt(25 + 1.0 / 12) - 1) < 0.03); /* ~0.5 % */
    world_destroy(w);
}

/* (4) The ADC: full scale at 2^10 - 1 when the light is too strong, never
 * below 0 however low the noise takes it. */
static void test_rails(void **state)
{
    (void)state;
    world_t *w = arena(0);
    ir_spec_t s;
    ir_spec_default(&s);
    s.noise_counts = 50;
    s.ambient_counts = 0;
    ir_t ir;
    ir_init(&ir, &s, cfg.world.wall_reflectivity, 3, 2);
    assert_int_equal(ir_full_scale(&ir), 1023);
    double near[3] = { east_face() - 0.02, 1.5 * cfg.world.cell_m, cfg.world.wall_height_m / 2 };
    int zeros = 0;
    for (int i = 0; i < 2000; i++) {
        int lit = ir_read(&ir, w, near, 0, 1), dark = ir_read(&ir, w, near, 0, 0);
        assert_int_equal(lit, 1023); /* gain: 850 (50/20)^2 = 5300 counts */
        assert_true(dark >= 0 && dark <= 1023);
        zeros += dark == 0;
    }
    assert_true(zeros > 800 && zeros < 1200); /* half the noise is below 0 */
    world_destroy(w);
}

/* (5) Same seed and index: the same samples; another index or seed:
 * another stream. */
static void test_streams(void **state)
{
    (void)state;
    world_t *w = arena(0);
    ir_spec_t s;
    ir_spec_default(&s);
    s.noise_counts = 3;
    ir_t a, b, c, d;
    ir_init(&a, &s, cfg.world.wall_reflectivity, 42, 0);
    ir_init(&b, &s, cfg.world.wall_reflectivity, 42, 0);
    ir_init(&c, &s, cfg.world.wall_reflectivity, 42, 1);
    ir_init(&d, &s, cfg.world.wall_reflectivity, 43, 0);
    double p[3] = { east_face() - 0.06, 1.5 * cfg.world.cell_m, cfg.world.wall_height_m / 2 };
    int diff_c = 0, diff_d = 0;
    for (int i = 0; i < 200; i++) {
        int on = i & 1, va = ir_read(&a, w, p, 0, on);
        assert_int_equal(va, ir_read(&b, w, p, 0, on));
        diff_c += va != ir_read(&c, w, p, 0, on);
        diff_d += va != ir_read(&d, w, p, 0, on);
    }
    assert_true(diff_c > 100);
    assert_true(diff_d > 100);
    world_destroy(w);
}

/* (6) A beam whose axis just passes the end of a wall (the post at its
 * end): the half of the cone on the wall's side returns, the rest flies on
 * to the far wall; less than the full wall, more than nothing. */
static void test_graze(void **state)
{
    (void)state;
    world_t *w = arena(1);
    ir_t ir = quiet();
    double c = cfg.world.cell_m, face = 2 * c - cfg.world.wall_thick_m / 2, d = 0.08, z = cfg.world.wall_height_m / 2;
    double full_p[3] = { face - d, 1.5 * c, z };
    double edge_p[3] = { face - d, 2 * c + cfg.world.post_m / 2 + 0.0005, z };
    double past_p[3] = { face - d, 2 * c + cfg.world.post_m / 2 + 0.03, z };
    double full = ir_received(&ir, w, full_p, 0);
    double edge = ir_received(&ir, w, edge_p, 0);
    double past = ir_received(&ir, w, past_p, 0);
    assert_true(fabs(full / ir_received_plane(&ir, d, 0, ir.reflectivity, 0) - 1) < 0.02);
    assert_true(edge > 0.25 * full && edge < 0.6 * full);
    assert_true(past < 0.1 * full);
    world_destroy(w);
}

/* (7) The emitter's skirt (SFH4550 p.5: 0.04 at 10 deg, gone by 45): its
 * rays cast in the world give the ideal plane cut to the wall's height
 * (ir_received_band); with the detector offset it lifts the near field,
 * where the skirt's spots sit near the detector's axis, more than the far,
 * where its upper rays pass over the wall; the far reading falls faster
 * than 1/d^2 as they do. */
static void test_skirt(void **state)
{
    (void)state;
    world_t *w = arena(0);
    static ir_spec_t sk;
    ir_spec_default(&sk);
    sk.noise_counts = 0, sk.skirt_rel = 0.04, sk.skirt_deg = 45;
    ir_t irs, ir0 = quiet();
    ir_init(&irs, &sk, cfg.world.wall_reflectivity, 1, 0);
    assert_int_equal(irs.nrays, ir0.nrays + (int)sk.skirt_rings * 8);
    double y = 1.5 * cfg.world.cell_m, z = 0.036, h = cfg.world.wall_height_m, rho = irs.reflectivity;
    for (double d = 0.02; d <= 0.2001; d += 0.02) {
        double p[3] = { east_face() - d, y, z };
        double r = ir_received(&irs, w, p, 0), want = ir_received_band(&irs, d, 0, rho, 0, -z, h - z);
        assert_true(fabs(r - want) <= 0.01 * want + 1e-9);
    }
    /* the same band as the plane when it spans everything the rays reach */
    assert_true(fabs(ir_received_band(&irs, 0.1, 0, rho, 0, -1, 1) - ir_received_plane(&irs, 0.1, 0, rho, 0)) < 1e-12);
    double near_s = ir_received_band(&irs, 0.024, 0, rho, 0, -z, h - z), near_0 = ir_received_band(&ir0, 0.024, 0, rho, 0, -z, h - z);
    double far_s = ir_received_band(&irs, 0.072, 0, rho, 0, -z, h - z), far_0 = ir_received_band(&ir0, 0.072, 0, rho, 0, -z, h - z);
    double at180_s = ir_received_band(&irs, 0.18, 0, rho, 0, -z, h - z), at180_0 = ir_received_band(&ir0, 0.18, 0, rho, 0, -z, h - z);
    assert_true(near_s / far_s > 1.2 * near_0 / far_0);
    assert_true(at180_s / far_s < 0.97 * at180_0 / far_0);
    world_destroy(w);
}

/* (8) The board's edge in front of the detector hides the spots above it:
 * no shield at setback 0; a setback takes light from the near field (spots
 * high in the detector's view) and little from the far. */
static void test_shield(void **state)
{
    (void)state;
    static ir_spec_t sh;
    ir_spec_default(&sh);
    sh.noise_counts = 0, sh.shield_height_m = 0.0015;
    ir_t ir0 = quiet(), irs;
    double rho = ir0.reflectivity;
    sh.shield_setback_m = 0;
    ir_init(&irs, &sh, rho, 1, 0);
    assert_true(ir_received_plane(&irs, 0.03, 0, rho, 0) == ir_received_plane(&ir0, 0.03, 0, rho, 0));
    sh.shield_setback_m = 0.008;
    ir_init(&irs, &sh, rho, 1, 0);
    double n = ir_received_plane(&irs, 0.024, 0, rho, 0) / ir_received_plane(&ir0, 0.024, 0, rho, 0);
    double f = ir_received_plane(&irs, 0.15, 0, rho, 0) / ir_received_plane(&ir0, 0.15, 0, rho, 0);
    assert_true(n < 0.9 && f > 0.9 && f <= 1);
    assert_true(n < f);
}

/* (9) The detector's directional characteristic from its datasheet: one
 * ray straight on, the spot seen at beta = atan(|offset| / d), its
 * sensitivity interpolated in the table (0 past its last angle), in place
 * of the Gaussian; one point only leaves the Gaussian. */
static void test_detector_table(void **state)
{
    (void)state;
    static ir_spec_t t, t1; /* the sensors keep them by pointer */
    ir_spec_default(&t);
    t.noise_counts = 0, t.rings = 0, t.det_offset_m = -0.0056;
    const double deg[3] = { 0, 40, 50 }, rel[3] = { 1, 0.5, 0.3 };
    for (int i = 0; i < 3; i++) t.det_deg[i] = deg[i], t.det_rel[i] = rel[i];
    t1 = t;
    t.det_deg_n = t.det_rel_n = 3;
    t1.det_deg_n = t1.det_rel_n = 1; /* one point: the Gaussian */
    ir_t a, g;
    ir_init(&a, &t, 1, 1, 0);
    ir_init(&g, &t1, 1, 1, 0);
    double d = 0.0056, r = sqrt(d * d + t.det_offset_m * t.det_offset_m); /* beta = 45 deg */
    double want = (d / r) * 0.4 / (r * r), gauss = (d / r) * exp(-log(2) * (45.0 / 12) * (45.0 / 12)) / (r * r);
    assert_true(fabs(ir_received_plane(&a, d, 0, 1, 0) - want) < 1e-9 * want);
    assert_true(fabs(ir_received_plane(&g, d, 0, 1, 0) - gauss) < 1e-9 * want);
    assert_true(ir_received_plane(&a, 0.0056 * tan(30 * M_PI / 180), 0, 1, 0) == 0); /* beta 60 deg: past the table */
}

/* (10) An emitter lying on its board: the board takes its skirt's lower
 * half (skirt_below 0), not its beam; that takes light from the near field,
 * where the lower skirt's spots sit on the detector's axis below, far more
 * than from the far field. */
static void test_skirt_below(void **state)
{
    (void)state;
    static ir_spec_t full, half;
    ir_spec_default(&full);
    full.noise_counts = 0, full.skirt_rel = 0.04;
    half = full;
    half.skirt_below = 0;
    ir_t f, h;
    ir_init(&f, &full, 0.85, 1, 0);
    ir_init(&h, &half, 0.85, 1, 0);
    int cut = 0;
    for (int i = 0; i < f.nrays; i++) {
        int skirt = acos(f.off[i][0]) * 180 / M_PI > full.cone_deg + 1e-9, below = f.off[i][2] < 0;
        if (skirt && below) assert_true(h.weight[i] == 0 && f.weight[i] > 0), cut++;
        else assert_true(h.weight[i] > 0 && f.weight[i] > 0);
    }
    assert_true(cut > 0);
    double z = 0.036, top = 0.05 - z;
    double nf = ir_received_band(&f, 0.024, 0, 0.85, 0, -z, top) / ir_received_band(&f, 0.072, 0, 0.85, 0, -z, top);
    double nh = ir_received_band(&h, 0.024, 0, 0.85, 0, -z, top) / ir_received_band(&h, 0.072, 0, 0.85, 0, -z, top);
    assert_true(nh < 0.9 * nf);
}

/* (11) A reading flows one way: the world casts the sensor's rays
 * (world_cast) and the model turns the hits into light (ir_received_hits)
 * and counts (ir_counts), with no world: the same as ir_received and
 * ir_read. */
static void test_hits(void **state)
{
    (void)state;
    world_t *w = arena(1);
    ir_t a = quiet(), b = quiet();
    sim_pose_t at = { { east_face() - 0.05, 1.5 * cfg.world.cell_m, 0.036 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    world_hit_t hit[IR_MAX_RAYS];
    world_cast(w, &at, a.nrays, (const double (*)[3])a.off, a.spec->max_m, hit);
    double r = ir_received_hits(&a, &at, hit);
    assert_true(r > 0 && r == ir_received(&a, w, at.pos_m, 0));
    assert_int_equal(ir_counts(&a, r), ir_read(&b, w, at.pos_m, 0, 1));
    assert_int_equal(ir_counts(&a, 0), ir_read(&b, w, at.pos_m, 0, 0));
    world_destroy(w);
}

/* (12) A diagonal sensor's return from a wall ahead (mazerunner-core
 * documents/sensors.md): centred in cell (1,1) facing north, ORION's left
 * diagonal (22 mm left, 28 mm ahead, 45 deg) aims at the post face by the
 * corner; a wall ahead meets its beam first and lifts its reading. */
static void test_wall_ahead(void **state)
{
    (void)state;
    ir_t ir = quiet();
    double r[2];
    for (int ahead = 0; ahead < 2; ahead++) {
        truemaze_t m;
        truemaze_init(&m, 4, 4);
        for (uint16_t c = 0; c < 16; c++)
            for (uint8_t d = 0; d < 4; d++) truemaze_set_wall(&m, (truemaze_cell_t)c, d, 0);
        for (int y = 0; y < 4; y++) truemaze_set_wall(&m, truemaze_cell(&m, 1, (uint8_t)y), TRUEMAZE_WEST, 1);
        if (ahead) truemaze_set_wall(&m, truemaze_cell(&m, 1, 1), TRUEMAZE_NORTH, 1);
        world_t *w = world_create(&model, &m, 3.5 * cfg.world.cell_m, 3.5 * cfg.world.cell_m, 0);
        assert_non_null(w);
        double p[3] = { 1.5 * cfg.world.cell_m - 0.022, 1.5 * cfg.world.cell_m + 0.028, 0.036 };
        r[ahead] = ir_received(&ir, w, p, 0.75 * M_PI);
        world_destroy(w);
    }
    assert_true(r[0] > 0 && r[1] > 1.1 * r[0]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ray_normal),
        cmocka_unit_test(test_distance),
        cmocka_unit_test(test_near_field),
        cmocka_unit_test(test_angle),
        cmocka_unit_test(test_dark),
        cmocka_unit_test(test_rails),
        cmocka_unit_test(test_streams),
        cmocka_unit_test(test_graze),
        cmocka_unit_test(test_skirt),
        cmocka_unit_test(test_shield),
        cmocka_unit_test(test_detector_table),
        cmocka_unit_test(test_skirt_below),
        cmocka_unit_test(test_hits),
        cmocka_unit_test(test_wall_ahead),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
