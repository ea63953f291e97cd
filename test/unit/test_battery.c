/* test_battery.c - the battery model (sim/world/battery.h) against its equations. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "world/battery.h"

static void assert_near(double got, double want, double tol)
{
    if (fabs(got - want) > tol) fail_msg("got %.12g, want %.12g (+-%.3g)", got, want, tol);
}

static void test_no_load_is_ocv(void **state)
{
    battery_spec_t s;
    battery_spec_default(&s);
    battery_t b;
    battery_init(&b, &s);
    assert_near(battery_soc(&b), 1.0, 0);
    assert_near(battery_voltage(&b, 0.0), 8.4, 1e-12);
    assert_near(battery_voltage(&b, 0.0), battery_ocv(&b), 0);
}

static void test_sag_is_r_times_i(void **state)
{
    battery_spec_t s;
    battery_spec_default(&s);
    battery_t b;
    battery_init(&b, &s);
    double voc = battery_voltage(&b, 0.0);
    double i_a[] = { 0.1, 0.5, 1.0, 2.5, -0.4 };
    for (unsigned k = 0; k < sizeof i_a / sizeof i_a[0]; k++)
        assert_near(voc - battery_voltage(&b, i_a[k]), s.r_ohm * i_a[k], 1e-12);
    s.r_ohm = 1.7;
    battery_init(&b, &s);
    assert_near(voc - battery_voltage(&b, 2.0), 3.4, 1e-12);
}

/* 0.36 A for 10 s in 1 ms steps = 3.6 C = 1 mAh. */
static void test_charge_is_i_times_t(void **state)
{
    battery_spec_t s;
    battery_spec_default(&s);
    battery_t b;
    battery_init(&b, &s);
    for (int k = 0; k < 10000; k++) battery_draw(&b, 0.36, 0.001);
    assert_near(battery_drawn_mah(&b), 1.0, 1e-9);
    assert_near(battery_soc(&b), 1.0 - 1.0 / 500.0, 1e-12);
    battery_draw(&b, -0.36, 10.0);  /* charging gives it back */
    assert_near(battery_drawn_mah(&b), 0.0, 1e-9);
}

/* The voltage follows the table: at each point its value, halfway between
 * two the mean, falling as charge is drawn; empty = the first point. */
static void test_voltage_falls_with_soc(void **state)
{
    battery_spec_t s;
    battery_spec_default(&s);
    battery_t b;
    battery_init(&b, &s);
    double cap_c = s.capacity_mah * 3.6, last = battery_ocv(&b);
    for (int k = 1; k <= 20; k++) {
        battery_draw(&b, cap_c / 20, 1.0);  /* 5 % of the capacity */
        double soc = 1.0 - k / 20.0, v = battery_ocv(&b);
        int i = (int)floor(soc * 10 + 1e-9);
        double want = k % 2 == 0 ? s.ocv_v[i] : (s.ocv_v[i] + s.ocv_v[i + 1]) / 2;
        assert_near(battery_soc(&b), soc, 1e-12);
        assert_near(v, want, 1e-9);
        assert_true(v < last);
        last = v;
    }
    assert_near(battery_ocv(&b), 6.6, 1e-9);
    battery_draw(&b, 1.0, 100.0);  /* beyond empty: held at the empty voltage */
    assert_near(battery_ocv(&b), 6.6, 1e-9);
    /* a linear spec (two points) and a constant one (one point) */
    s.ocv_n = 2;
    s.ocv_v[0] = 7.0;
    s.ocv_v[1] = 8.0;
    battery_init(&b, &s);
    battery_draw(&b, s.capacity_mah * 3.6 * 0.25, 1.0);
    assert_near(battery_voltage(&b, 0.0), 7.75, 1e-12);
    s.ocv_n = 1;
    battery_init(&b, &s);
    battery_draw(&b, 100.0, 1.0);
    assert_near(battery_voltage(&b, 1.0), 7.0 - s.r_ohm, 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_no_load_is_ocv),
        cmocka_unit_test(test_sag_is_r_times_i),
        cmocka_unit_test(test_charge_is_i_times_t),
        cmocka_unit_test(test_voltage_falls_with_soc),
    };
    return cmocka_run_group_tests_name("battery", tests, NULL, NULL);
}
