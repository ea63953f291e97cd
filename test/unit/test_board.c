/* test_board.c - the board emulation's API (sim/board/board.h) on
 * boards/ukmarsbot-v1.3.ini: the switch ladder lands in mazerunner-core's
 * decode window for every switch setting and the button; bad board files
 * give FILE:LINE: section.key: reason; and with the NoinitReset sketch
 * (build/clients/board/NoinitReset.elf, `make board-sketches`; skipped
 * without it): power-on SRAM is zero, board_reset keeps SRAM (.noinit
 * survives), board_set_switches and board_button reach the ADC, board_send
 * reaches the UART; with the MotorPwm sketch: the motor part's H-bridge
 * command in both Timer1 modes, stopped, and again after a reset. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "board/board.h"
#include "maze/mazefile.h"
#include "world/robot.h"
#include "world/sim.h"

#define BOARD_FILE "boards/ukmarsbot-v1.3.ini"
#define SKETCH "build/clients/board/NoinitReset.elf"
#define MOTOR_SKETCH "build/clients/board/MotorPwm.elf"

/* mazerunner-core's decode (switches.h read(), config-ukmarsbot.h adc_thesholds) */
static int decode(int adc)
{
    static const int thr[17] = { 660, 647, 630, 614, 590, 570, 545, 522, 461, 429, 385, 343, 271, 212, 128, 44, 0 };
    if (adc > 800) return 16;
    for (int i = 0; i < 16; i++)
        if (adc > (thr[i] + thr[i + 1]) / 2) return i;
    return -1;
}

static int counts(double v, double vcc) { return (int)(v * 1023.0 / vcc); }

static void test_switch_ladder_decodes(void **state)
{
    board_spec_t sp;
    char err[400];
    if (board_load(&sp, BOARD_FILE, err, sizeof err) != 0) fail_msg("%s", err);
    for (unsigned n = 0; n < 16; n++) assert_int_equal(decode(counts(board_switch_volts(&sp, n, 0), sp.vcc_v)), (int)n);
    for (unsigned n = 0; n < 16; n++) assert_int_equal(decode(counts(board_switch_volts(&sp, n, 1), sp.vcc_v)), 16);
    assert_int_equal(sp.motor_oc[0], 0);
    assert_int_equal(sp.motor_oc[1], 1);
    assert_int_equal(sp.nemitters, 2);
    assert_int_equal(sp.nleds, 2);
}

static void bad_file(const char *text, const char *want)
{
    char path[] = "/tmp/test_board_XXXXXX", err[400];
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "w");
    fputs(text, f);
    fclose(f);
    board_spec_t sp;
    assert_int_equal(board_load(&sp, path, err, sizeof err), -1);
    remove(path);
    if (!strstr(err, want)) fail_msg("got '%s', want '%s'", err, want);
    assert_true(!strncmp(err, path, strlen(path)));
    assert_null(strchr(err, '\n'));
}

static void test_bad_files(void **state)
{
    bad_file("[board]\nname = x\nmcu = atmega2560\n", ":1: board.f_cpu_hz: missing"); /* a missing key: its section's line */
    bad_file("[board]\nname = x\nmcu = atmega328p\nf_cpu_hz = 16000000\nvcc_v = 5\n",
             ": motor.left.dir_pin: missing (no [motor.left] section)");
    bad_file("[board]\nname = x\nmcu = atmega328p\nf_cpu_hz = 1\n", ":4: board.f_cpu_hz: 1 Hz is out of range [1e+06, 3.2e+07]");
    bad_file("[board]\nname = x\n[motor.left]\ndir_pin = Q7\n", ":4: motor.left.dir_pin: expected a pin D0-D13, A0-A5 or PB0-PD7, got 'Q7'");
    bad_file("[led.a]\npin = D13\ncolour = red\n", ":3: led.a.colour: unknown key");
    bad_file("[switches]\nr_ohm = 1 2 3\n", ":2: switches.r_ohm: 3 numbers, want 4");
    bad_file("[encoder.left]\nforward = c_leads\n", ":2: encoder.left.forward: 'c_leads' is not one of b_leads a_leads");
    bad_file("[motors]\nx = 1\n", ":1: [motors]: unknown section");
    /* a key twice in one section, the named parts' too (pin = D11 then pin = A0: the last won, the robot never moved) */
    bad_file("[board]\nname = x\nname = y\n", ":3: board.name: given twice (first on line 2)");
    bad_file("[emitter.front]\npin = D11\ngroup = 0\npin = A0\n", ":4: emitter.front.pin: given twice (first on line 2)");
    bad_file("[led.a]\npin = D13\n[led.b]\npin = D6\n[led.a]\npin = D12\n", ":6: led.a.pin: given twice (first on line 2)");
    /* an indented line: libinih would hand it over as the key's value again */
    bad_file("[board]\nname = x\n  y\n", ":3: board.name: an indented line continues its value");
    bad_file("[emitter.front]\npin = D11\n\tA0\n", ":3: emitter.front.pin: an indented line continues its value");
}

typedef struct {
    simcfg_t cfg;
    truemaze_t maze;
    sim_state_t sim;
    board_t *b;
} rig_t;

static rig_t rig;

static void steps(int n)
{
    char err[400];
    for (int i = 0; i < n; i++) {
        sim_step(rig.sim.model, &rig.sim);
        if (board_step(rig.b, err, sizeof err) != 0) fail_msg("%s", err);
    }
}

/* the last "SW n" line's n */
static int last_sw(void)
{
    const char *c = board_console(rig.b, NULL), *p = NULL, *q = c;
    while ((q = strstr(q, "SW ")) != NULL) p = q++;
    return p ? atoi(p + 3) : -1;
}

/* the rig with image on the UKMARSBOT board; 0 if the image is not built */
static int rig_open(const char *image)
{
    char err[400];
    FILE *f = fopen(image, "rb");
    if (!f) return 0;
    fclose(f);
    board_spec_t sp;
    config_defaults(&rig.cfg);
    if (board_load(&sp, BOARD_FILE, err, sizeof err) || robot_load(&rig.cfg, "robots/ukmarsbot.ini", err, sizeof err) ||
        mazefile_load(&rig.maze, "mazes/gen-5x5-s1.txt", NULL, err, sizeof err))
        fail_msg("%s", err);
    static sim_model_t rig_sim_model;
    sim_model_build(&rig_sim_model, &rig.cfg, 1);
    assert_int_equal(sim_init(&rig.sim, &rig_sim_model, &rig.maze, 1), 0);
    rig.b = board_open(&sp, image, &rig.sim, err, sizeof err);
    if (!rig.b) fail_msg("%s", err);
    return 1;
}

static void test_reset_switches_button(void **state)
{
    if (!rig_open(SKETCH)) skip();
    steps(200);
    assert_non_null(strstr(board_console(rig.b, NULL), "BOOT 1\r\n")); /* power-on SRAM is zero */
    assert_int_equal(decode(last_sw()), 0);
    board_set_switches(rig.b, 11);
    steps(100);
    assert_int_equal(decode(last_sw()), 11);
    board_button(rig.b, 1);
    steps(100);
    assert_int_equal(decode(last_sw()), 16);
    board_button(rig.b, 0);
    board_reset(rig.b);
    steps(200);
    assert_non_null(strstr(board_console(rig.b, NULL), "BOOT 2\r\n")); /* .noinit kept across the reset */
    assert_int_equal(decode(last_sw()), 11);
    assert_int_equal(board_stats(rig.b)->resets, 1);
    assert_true(board_stats(rig.b)->cycles >= 600u * 16000u);
    assert_int_equal(board_send(rig.b, "hello\n"), 0);
    steps(10);
    assert_int_equal(board_stats(rig.b)->uart_bytes_in, 6);
    board_close(rig.b);
    sim_free(&rig.sim);
}

/* MotorPwm: duty 40/255 forward on both wheels for 400 ms in Timer1's
 * phase correct mode 1, then 400 ms in fast PWM mode 14 (251/1600), then
 * the pins low; the physics step is 1 ms. The H-bridge command is the
 * duty x 1023. */
static void test_motor_part(void **state)
{
    if (!rig_open(MOTOR_SKETCH)) skip();
    steps(200);
    assert_int_equal(rig.sim.cmd[0], 160); /* lround(40 / 255 x 1023) */
    assert_int_equal(rig.sim.cmd[1], 160);
    steps(400);
    assert_int_equal(rig.sim.cmd[0], 160); /* lround(251 / 1600 x 1023) */
    assert_int_equal(rig.sim.cmd[1], 160);
    steps(400);
    assert_int_equal(rig.sim.cmd[0], 0);
    assert_int_equal(rig.sim.cmd[1], 0);
    assert_true(board_stats(rig.b)->duty_max[0] > 0.156 && board_stats(rig.b)->duty_max[0] < 0.158);
    assert_true(board_stats(rig.b)->duty_min[1] == 0.0);
    /* a reset clears the ports and Timer1; the sketch starts again and drives again */
    board_reset(rig.b);
    steps(1);
    assert_int_equal(rig.sim.cmd[0], 160);
    assert_int_equal(rig.sim.cmd[1], 160);
    board_close(rig.b);
    sim_free(&rig.sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_switch_ladder_decodes),
        cmocka_unit_test(test_bad_files),
        cmocka_unit_test(test_reset_switches_button),
        cmocka_unit_test(test_motor_part),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
