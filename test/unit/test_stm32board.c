/* test_stm32board.c - the STM32 board file (sim/arm/stm32board.h):
 * boards/bulebule.ini loads with bulebule's wiring (electronics.rst's
 * pinout, src/setup.c), its MCU's memories from the part's name, the
 * encoders' sign derived; boardfile_family tells an STM32 board file from
 * an AVR one; robots/bulebule.ini fits the board and robots/ukmarsbot.ini
 * does not; and each bad file of a table (bulebule.ini with one change)
 * gives its one line FILE:LINE: section.key: reason. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "arm/stm32board.h"
#include "board/board.h"
#include "world/config.h"
#include "world/robot.h"
#include "world/sim.h"

#define BOARD_FILE "boards/bulebule.ini"

static void pin_is(stm32_pin_t p, char port, int bit)
{
    assert_int_equal(p.port, port);
    assert_int_equal(p.bit, bit);
}

static void tch_is(stm32_tch_t t, int timer, int channel)
{
    assert_int_equal(t.timer, timer);
    assert_int_equal(t.channel, channel);
}

static void test_bulebule_loads(void **state)
{
    stm32board_spec_t sp;
    char err[400];
    if (stm32board_load(&sp, BOARD_FILE, err, sizeof err) != 0) fail_msg("%s", err);
    assert_string_equal(sp.mcu, "stm32f103c8");
    assert_int_equal(sp.flash_bytes, 65536);  /* DS5319: 64 KiB (LD: 63K + 1K eeprom page) */
    assert_int_equal(sp.sram_bytes, 20480);
    assert_int_equal(sp.package, 'C');
    assert_int_equal(sp.adc_channels, 10);
    assert_int_equal(sp.hse_hz, 8000000);
    assert_true(sp.vdda_v == 3.3);
    assert_string_equal(sp.default_robot, "bulebule");
    /* TIM3 CH1-4: two channels per motor, IN1 forward */
    tch_is(sp.motor[0].in[0], 3, 1), tch_is(sp.motor[0].in[1], 3, 2);
    tch_is(sp.motor[1].in[0], 3, 3), tch_is(sp.motor[1].in[1], 3, 4);
    pin_is(sp.motor[0].in_pin[0], 'A', 6), pin_is(sp.motor[0].in_pin[1], 'A', 7);
    pin_is(sp.motor[1].in_pin[0], 'B', 0), pin_is(sp.motor[1].in_pin[1], 'B', 1);
    assert_int_equal(sp.motor[0].driver, STM32_DRIVER_DRV8833);
    assert_int_equal(sp.motor[0].forward_in, 0);
    assert_int_equal(sp.motor[1].forward_in, 0);
    /* TIM2 (A on CH1, PA15 remapped) and TIM4 (A on CH2): both count up forward */
    tch_is(sp.enc[0].a, 2, 1), tch_is(sp.enc[0].b, 2, 2);
    pin_is(sp.enc[0].a_pin, 'A', 15), pin_is(sp.enc[0].b_pin, 'B', 3);
    tch_is(sp.enc[1].a, 4, 2), tch_is(sp.enc[1].b, 4, 1);
    pin_is(sp.enc[1].a_pin, 'B', 7), pin_is(sp.enc[1].b_pin, 'B', 6);
    assert_int_equal(sp.enc[0].a_leads, 1);
    assert_int_equal(sp.enc[1].a_leads, 0);
    assert_int_equal(sp.enc[0].ch1_leads, 1);
    assert_int_equal(sp.enc[1].ch1_leads, 1);
    /* emitters by bulebule's sensor ids */
    assert_int_equal(sp.nemitters, 4);
    static const char ports[4] = { 'A', 'B', 'A', 'B' };
    static const int bits[4] = { 9, 8, 8, 9 };
    for (int i = 0; i < 4; i++) {
        assert_int_equal(sp.emitter[i].group, i);
        pin_is(sp.emitter[i].pin, ports[i], bits[i]);
    }
    assert_int_equal(sp.nleds, 3);
    assert_string_equal(sp.led[2].name, "bluepill");
    pin_is(sp.led[2].pin, 'C', 13);
    assert_int_equal(sp.led[2].level, 0);
    assert_int_equal(sp.led[0].level, 1);
    assert_int_equal(sp.nbuttons, 2);
    pin_is(sp.button[1].pin, 'A', 12);
    assert_int_equal(sp.button[1].level, 1);
    tch_is(sp.speaker, 1, 3);
    pin_is(sp.speaker_pin, 'A', 10);
    assert_int_equal(sp.gyro_chip, STM32_GYRO_MPU6500);
    assert_int_equal(sp.gyro_spi, 2);
    pin_is(sp.gyro_cs_pin, 'B', 12);
    pin_is(sp.gyro_sck_pin, 'B', 13), pin_is(sp.gyro_miso_pin, 'B', 14), pin_is(sp.gyro_mosi_pin, 'B', 15);
    assert_int_equal(sp.console_usart, 3);
    pin_is(sp.console_tx_pin, 'B', 10), pin_is(sp.console_rx_pin, 'B', 11);
    assert_int_equal(sp.bat_channel, 0);
    pin_is(sp.bat_pin, 'A', 0);
    assert_true(sp.bat_r_top_ohm / sp.bat_r_bottom_ohm == 1.0); /* VOLT_DIV_FACTOR 2 */
}

/* boards/bulebule.ini with up to two substitutions, into a temporary file: its path. */
static char *variant(const char *old1, const char *new1, const char *old2, const char *new2, char **text_out)
{
    FILE *f = fopen(BOARD_FILE, "rb");
    assert_non_null(f);
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    char *text = strdup(buf);
    const char *olds[2] = { old1, old2 }, *news[2] = { new1, new2 };
    for (int i = 0; i < 2 && olds[i]; i++) {
        char *at = strstr(text, olds[i]);
        if (!at) fail_msg("'%s' not in %s", olds[i], BOARD_FILE);
        assert_null(strstr(at + 1, olds[i])); /* unique */
        size_t pre = (size_t)(at - text), lo = strlen(olds[i]), ln = strlen(news[i]);
        char *t = malloc(strlen(text) - lo + ln + 1);
        memcpy(t, text, pre);
        memcpy(t + pre, news[i], ln);
        strcpy(t + pre + ln, at + lo);
        free(text);
        text = t;
    }
    static char path[64];
    strcpy(path, "/tmp/test_stm32board_XXXXXX");
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
    close(fd);
    *text_out = text;
    return path;
}

/* The line of the text's first line that starts with mark. */
static int line_of(const char *text, const char *mark)
{
    int line = 1;
    for (const char *p = text; *p; line++) {
        if (!strncmp(p, mark, strlen(mark))) return line;
        const char *nl = strchr(p, '\n');
        if (!nl) break;
        p = nl + 1;
    }
    fail_msg("no line starts with '%s'", mark);
    return 0;
}

typedef struct {
    const char *old1, *new1, *old2, *new2;
    const char *at;   /* the error's line starts with this */
    const char *want; /* the error after "FILE:LINE: " */
} bad_t;

static const bad_t bad[] = {
    { "in1_pin = PA6", "in1_pin = PA5", NULL, NULL, "[motor.left]",
      "motor.left.in1_pin: PA5 does not carry TIM3_CH1 (it is on PA6, PB4, PC6: RM0008 9.3.7)" },
    { "mcu = stm32f103c8", "mcu = stm32f407vg", NULL, NULL, "[board]", "board.mcu: 'stm32f407vg': not an STM32 this board file knows" },
    { "hse_hz = 8000000", "hse_hz = 25000000", NULL, NULL, "hse_hz", "board.hse_hz: 2.5e+07 Hz is out of range [4e+06, 1.6e+07]" },
    { "pin = PB8", "pin = PB4", NULL, NULL, "[led.left]", "led.left.pin: PB4 is already wired to emitter.side_right.pin" },
    { "a = TIM2_CH1", "a = TIM2_CH3", NULL, NULL, "[encoder.left]",
      "encoder.left.b: TIM2_CH2 with a = TIM2_CH3: the encoder interface reads CH1 and CH2 of one timer" },
    { "in1 = TIM3_CH3", "in1 = TIM4_CH3", "in1_pin = PB0", "in1_pin = PB8", "[encoder.right]",
      "encoder.right.a: TIM4 also drives a PWM output: a timer in encoder mode counts the wheel and drives no PWM" },
    { "in1_pin = PA6", "in1_pin = PB4", NULL, NULL, "[motor.left]",
      "motor.left.in2_pin: TIM3's channels are on pins that need different AFIO remaps (RM0008 9.3.7)" },
    { "forward = in1\n\n[motor.right]", "fwd = in1\n\n[motor.right]", NULL, NULL, "fwd", "motor.left.fwd: unknown key" },
    { "in2_pin = PA7\n", "", NULL, NULL, "[motor.left]", "motor.left.in2_pin: missing" },
    { "cs_pin = PB12", "cs_pin = PB16", NULL, NULL, "cs_pin", "gyro.cs_pin: expected a pin PA0-PE15, got 'PB16'" },
    { "cs_pin = PB12", "cs_pin = PC0", NULL, NULL, "[gyro]", "gyro.cs_pin: PC0: the stm32f103c8's 48-pin package has no such pin" },
    { "adc_channel = 0", "adc_channel = 12", NULL, NULL, "[battery]", "battery.adc_channel: 12: the stm32f103c8 has ADC12_IN0-9 only" },
    { "tx_pin = PB10", "tx_pin = PA9", NULL, NULL, "[console]", "console.tx_pin: not USART3_TX's pin (it is on PB10, PC10, PD8" },
    { "group = 3", "group = 2", NULL, NULL, "[emitter.front_right]", "emitter.front_right.group: emitter.front_left lights that group" },
    { "spi = SPI2", "spi = SPI3", NULL, NULL, "spi =", "gyro.spi: 'SPI3' is not one of SPI1 SPI2" },
    { "[speaker]", "[lidar]", NULL, NULL, "[lidar]", "[lidar]: unknown section" },
    { "channel = TIM1_CH3\n; source: ELEC l.108; RM0008 9.3.7: TIM1_CH3 on PA10 with no remap\npin = PA10", "channel = TIM1_CH3\npin = PA11",
      NULL, NULL, "[speaker]", "speaker.pin: PA11 does not carry TIM1_CH3" },
    { "in1 = TIM3_CH3", "in1 = TIM3_CH1", "in1_pin = PB0", "in1_pin = PA6", "[motor.right]", "motor.right.in1: TIM3_CH1 is already in use" },
    { "name = bulebule", "name = bulebule\nname = again", NULL, NULL, "name = again", "board.name: given twice (first on line" },
    { "spi = SPI2", "spi = SPI2\nspi_remap = 1", NULL, NULL, "[gyro]", "gyro.spi_remap: SPI2 has no remap" },
    { "pressed_level = 1\n\n[button.right]", "\n[button.right]", NULL, NULL, "[button.left]", "button.left.pressed_level: missing" },
};

static void test_bad_files(void **state)
{
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const bad_t *b = &bad[i];
        char *text, err[400], want[600];
        const char *path = variant(b->old1, b->new1, b->old2, b->new2, &text);
        stm32board_spec_t sp;
        int rc = stm32board_load(&sp, path, err, sizeof err);
        snprintf(want, sizeof want, "%s:%d: %s", path, line_of(text, b->at), b->want);
        unlink(path);
        free(text);
        if (rc != -1) fail_msg("case %zu loaded", i);
        if (strncmp(err, want, strlen(want)) || strchr(err, '\n')) fail_msg("case %zu:\n got  %s\n want %s...", i, err, want);
    }
}

static void test_optional_parts(void **state)
{
    char *text, err[400];
    const char *path = variant("[speaker]\n", "[speaker_gone]\n", NULL, NULL, &text);
    stm32board_spec_t sp;
    assert_int_equal(stm32board_load(&sp, path, err, sizeof err), -1); /* unknown section */
    unlink(path);
    free(text);
    /* without [speaker], [gyro] and [console]: none of their keys */
    FILE *f = fopen(BOARD_FILE, "rb");
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    char *cut = strstr(buf, "[speaker]"), *resume = strstr(buf, "[battery]");
    assert_non_null(cut);
    assert_non_null(resume);
    memmove(cut, resume, strlen(resume) + 1);
    char p2[] = "/tmp/test_stm32board_XXXXXX";
    int fd = mkstemp(p2);
    assert_int_equal(write(fd, buf, strlen(buf)), (ssize_t)strlen(buf));
    close(fd);
    int rc = stm32board_load(&sp, p2, err, sizeof err);
    unlink(p2);
    if (rc) fail_msg("%s", err);
    assert_int_equal(sp.speaker.timer, 0);
    assert_int_equal(sp.gyro_spi, 0);
    assert_int_equal(sp.console_usart, 0);
}

static void test_family(void **state)
{
    char err[400] = "";
    assert_int_equal(boardfile_family(BOARD_FILE, err, sizeof err), BOARDFILE_STM32);
    assert_int_equal(boardfile_family("boards/ukmarsbot-v1.3.ini", err, sizeof err), BOARDFILE_AVR);
    char path[] = "/tmp/test_stm32board_XXXXXX";
    int fd = mkstemp(path);
    const char *t = "[board]\nmcu = pic16f84\n";
    assert_int_equal(write(fd, t, strlen(t)), (ssize_t)strlen(t));
    close(fd);
    assert_int_equal(boardfile_family(path, err, sizeof err), BOARDFILE_UNKNOWN);
    unlink(path);
    char want[200];
    snprintf(want, sizeof want, "%s: board.mcu: 'pic16f84': neither an AVR (atmega...) nor an STM32 (stm32...)", path);
    assert_string_equal(err, want);
    assert_int_equal(boardfile_family("/nonexistent/board.ini", err, sizeof err), BOARDFILE_UNKNOWN);
    assert_non_null(strstr(err, "/nonexistent/board.ini"));
}

/* Mutated copies of bulebule.ini (a character changed, a line dropped or
 * doubled; a fixed seed): each loads, or fails with one line naming the
 * file; never a crash (ASan, UBSan). */
static void test_mutations(void **state)
{
    FILE *f = fopen(BOARD_FILE, "rb");
    static char base[1 << 16], text[1 << 17];
    size_t n = fread(base, 1, sizeof base - 1, f);
    fclose(f);
    base[n] = '\0';
    static const char alphabet[] = "PABCDE0123456789_=[]. ;#\nTIMCHxa-+e";
    unsigned seed = 38, loaded = 0, failed = 0;
    char path[] = "/tmp/test_stm32board_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    for (int round = 0; round < 400; round++) {
        memcpy(text, base, n + 1);
        size_t len = n;
        for (int k = 0, edits = 1 + round % 4; k < edits; k++) {
            size_t at = (size_t)rand_r(&seed) % len;
            int what = rand_r(&seed) % 3;
            char *bol = text + at, *eol;
            while (bol > text && bol[-1] != '\n') bol--;
            eol = strchr(bol, '\n');
            size_t ll = eol ? (size_t)(eol - bol) + 1 : strlen(bol);
            if (what == 0) {
                text[at] = alphabet[rand_r(&seed) % (sizeof alphabet - 1)];
            } else if (what == 1) { /* drop the line */
                memmove(bol, bol + ll, len - (size_t)(bol - text) - ll + 1);
                len -= ll;
            } else if (len + ll < sizeof text - 1) { /* double it */
                memmove(bol + ll, bol, len - (size_t)(bol - text) + 1);
                len += ll;
            }
        }
        f = fopen(path, "wb");
        fwrite(text, 1, len, f);
        fclose(f);
        stm32board_spec_t sp;
        char err[400] = "";
        if (stm32board_load(&sp, path, err, sizeof err) == 0) {
            loaded++;
            continue;
        }
        failed++;
        if (strncmp(err, path, strlen(path)) || err[strlen(path)] != ':' || strchr(err, '\n')) fail_msg("round %d: '%s'", round, err);
    }
    unlink(path);
    printf("mutations: %u loaded, %u refused with one line\n", loaded, failed);
    assert_true(failed > 40 && loaded > 40); /* both kinds happen: the test reaches the checks */
    assert_true(loaded + failed == 400);
}

/* --board NAME finds boards/NAME.ini as it finds boards/NAME-VERSION.ini; the family then picks the loader */
static void test_find(void **state)
{
    char out[512], err[600];
    if (board_find("bulebule", out, sizeof out, err, sizeof err) != 0) fail_msg("%s", err);
    assert_non_null(strstr(out, "boards/bulebule.ini"));
    assert_int_equal(boardfile_family(out, err, sizeof err), BOARDFILE_STM32);
    if (board_find("ukmarsbot", out, sizeof out, err, sizeof err) != 0) fail_msg("%s", err);
    assert_non_null(strstr(out, "boards/ukmarsbot-v1.3.ini"));
    assert_int_equal(boardfile_family(out, err, sizeof err), BOARDFILE_AVR);
    assert_int_equal(board_find("bulebul", out, sizeof out, err, sizeof err), -1); /* a prefix is no name */
}

static void test_fits_robot(void **state)
{
    stm32board_spec_t sp;
    simcfg_t *c = calloc(1, sizeof *c);
    char err[600];
    if (stm32board_load(&sp, BOARD_FILE, err, sizeof err) != 0) fail_msg("%s", err);
    config_defaults(c);
    if (robot_load(c, "robots/bulebule.ini", err, sizeof err) != 0) fail_msg("%s", err);
    if (stm32board_fits_robot(&sp, c, err, sizeof err) != 0) fail_msg("%s", err);
    /* the robot's figures from bulebule's docs: 15:60 gears, IE2-512 x4, MICROMETERS_PER_COUNT 8.32 */
    for (int m = 0; m < 2; m++) {
        assert_true(c->robot.drive[m].gear_ratio == 4.0);
        assert_true(c->robot.drive[m].encoder_ppr == 2048.0);
        assert_true(c->robot.drive[m].rated_v == 9.0); /* Faulhaber 1524B009SR */
    }
    double um_per_count = 3.14159265358979 * c->robot.wheel_left_d_m * 1e6 / (2048.0 * 4.0);
    assert_true(um_per_count > 8.31 && um_per_count < 8.33);
    assert_int_equal(c->robot.casters, 2); /* the Tetra drive's axles as skids */
    assert_int_equal(robot_count(c, "ir"), 4);
    assert_int_equal(robot_count(c, "gyro"), 1);
    config_defaults(c);
    if (robot_load(c, "robots/ukmarsbot.ini", err, sizeof err) != 0) fail_msg("%s", err);
    assert_int_equal(stm32board_fits_robot(&sp, c, err, sizeof err), -1);
    /* its [ir.rfs] reads ADC channel 0: PA0, bulebule's battery */
    assert_non_null(strstr(err, "ir.rfs.adc_channel 0: its pin PA0 is the board's battery.adc_channel"));
    free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bulebule_loads), cmocka_unit_test(test_bad_files), cmocka_unit_test(test_optional_parts),
        cmocka_unit_test(test_family), cmocka_unit_test(test_find), cmocka_unit_test(test_mutations), cmocka_unit_test(test_fits_robot),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
