/* stm32board_file.c - the STM32 board file (stm32board.h): INI, one section
 * per part, read through the INI reader (world/inifile.h) with its keys in
 * keytab tables (world/keytab.h), as board/board_file.c reads an AVR
 * board's. A bad value is "FILE:LINE: section.key: reason"; a missing key
 * "FILE:LINE: section.key: missing" (the section's line) or "FILE:
 * section.key: missing (no [section] section)"; a check against the MCU
 * (pin, remap, a pin twice) names the section's line.
 *
 * The MCU facts: ST DS5319 (STM32F103x8/xB datasheet) Table 2 (memories,
 * ADC channels per package) and Table 5 (pins per package); RM0008 9.3
 * (AFIO remaps: which pin carries a timer channel, a USART's or an SPI's
 * signal under each MAPR setting) and 11.3 / DS5319 Table 5 (ADC12_INx
 * pins). */
#include "arm/stm32board.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "world/inifile.h"
#include "world/inisec.h"
#include "world/keytab.h"
#include "world/robot.h"
#include "world/sensors/ir.h"

#define N(t) (sizeof t / sizeof t[0])

/* ---- the MCUs ---- */

typedef struct {
    const char *name;
    uint32_t flash_kib, sram_kib;
    char package;
} mcu_t;

/* DS5319 Table 2: medium density, 64 KiB (x8) or 128 KiB (xB) flash, 20 KiB SRAM; C 48, R 64, V 100 pins */
static const mcu_t mcus[] = {
    { "stm32f103c8", 64, 20, 'C' }, { "stm32f103cb", 128, 20, 'C' }, { "stm32f103r8", 64, 20, 'R' },
    { "stm32f103rb", 128, 20, 'R' }, { "stm32f103v8", 64, 20, 'V' }, { "stm32f103vb", 128, 20, 'V' },
};

/* A pin the package has (DS5319 Table 5). LQFP48: PA0-15, PB0-15, PC13-15
 * (PD0/PD1 are OSC_IN/OSC_OUT, the crystal's); LQFP64 adds PC0-12 and PD2;
 * LQFP100 has PA-PE 0-15. */
static int on_package(char package, stm32_pin_t p)
{
    if (p.port == 'A' || p.port == 'B') return 1;
    if (package == 'V') return p.port >= 'C' && p.port <= 'E';
    if (p.port == 'C') return package == 'R' || p.bit >= 13;
    return package == 'R' && p.port == 'D' && p.bit == 2;
}

stm32_pin_t stm32board_adc_pin(const stm32board_spec_t *sp, int ch)
{
    /* DS5319 Table 5: ADC12_IN0-7 on PA0-7, IN8-9 on PB0-1, IN10-15 on PC0-5 (64 and 100 pins only) */
    if (ch < 0 || ch >= sp->adc_channels) return (stm32_pin_t){ 0, 0 };
    if (ch < 8) return (stm32_pin_t){ 'A', (uint8_t)ch };
    if (ch < 10) return (stm32_pin_t){ 'B', (uint8_t)(ch - 8) };
    return (stm32_pin_t){ 'C', (uint8_t)(ch - 10) };
}

/* ---- the AFIO remaps (RM0008 9.3.7-9.3.10) ---- */

/* A signal on a pin under the remap settings in mask (bit r: the MAPR field = r). */
typedef struct {
    uint8_t unit, signal; /* a timer 1-4 and channel 1-4; a USART 1-3 and 0 TX / 1 RX; an SPI 1-2 and 0 SCK / 1 MISO / 2 MOSI */
    char port;
    uint8_t bit, mask;
} afpin_t;

static const afpin_t tim_pins[] = {
    /* TIM1_REMAP (9.3.7): 00/01 PA8-PA11, 11 PE9/PE11/PE13/PE14 */
    { 1, 1, 'A', 8, 0x3 }, { 1, 1, 'E', 9, 0x8 }, { 1, 2, 'A', 9, 0x3 }, { 1, 2, 'E', 11, 0x8 },
    { 1, 3, 'A', 10, 0x3 }, { 1, 3, 'E', 13, 0x8 }, { 1, 4, 'A', 11, 0x3 }, { 1, 4, 'E', 14, 0x8 },
    /* TIM2_REMAP: CH1/CH2 PA0/PA1 (00, 10) or PA15/PB3 (01, 11); CH3/CH4 PA2/PA3 (00, 01) or PB10/PB11 (10, 11) */
    { 2, 1, 'A', 0, 0x5 }, { 2, 1, 'A', 15, 0xA }, { 2, 2, 'A', 1, 0x5 }, { 2, 2, 'B', 3, 0xA },
    { 2, 3, 'A', 2, 0x3 }, { 2, 3, 'B', 10, 0xC }, { 2, 4, 'A', 3, 0x3 }, { 2, 4, 'B', 11, 0xC },
    /* TIM3_REMAP: 00 PA6/PA7/PB0/PB1, 10 (partial) PB4/PB5/PB0/PB1, 11 (full) PC6-PC9 */
    { 3, 1, 'A', 6, 0x1 }, { 3, 1, 'B', 4, 0x4 }, { 3, 1, 'C', 6, 0x8 }, { 3, 2, 'A', 7, 0x1 }, { 3, 2, 'B', 5, 0x4 },
    { 3, 2, 'C', 7, 0x8 }, { 3, 3, 'B', 0, 0x5 }, { 3, 3, 'C', 8, 0x8 }, { 3, 4, 'B', 1, 0x5 }, { 3, 4, 'C', 9, 0x8 },
    /* TIM4_REMAP: 0 PB6-PB9, 1 PD12-PD15 */
    { 4, 1, 'B', 6, 0x1 }, { 4, 1, 'D', 12, 0x2 }, { 4, 2, 'B', 7, 0x1 }, { 4, 2, 'D', 13, 0x2 },
    { 4, 3, 'B', 8, 0x1 }, { 4, 3, 'D', 14, 0x2 }, { 4, 4, 'B', 9, 0x1 }, { 4, 4, 'D', 15, 0x2 },
};

static const afpin_t usart_pins[] = {
    /* 9.3.8: USART1_REMAP 0 PA9/PA10, 1 PB6/PB7; USART2_REMAP 0 PA2/PA3, 1 PD5/PD6;
     * USART3_REMAP 00 PB10/PB11, 01 PC10/PC11, 11 PD8/PD9 */
    { 1, 0, 'A', 9, 0x1 }, { 1, 0, 'B', 6, 0x2 }, { 1, 1, 'A', 10, 0x1 }, { 1, 1, 'B', 7, 0x2 },
    { 2, 0, 'A', 2, 0x1 }, { 2, 0, 'D', 5, 0x2 }, { 2, 1, 'A', 3, 0x1 }, { 2, 1, 'D', 6, 0x2 },
    { 3, 0, 'B', 10, 0x1 }, { 3, 0, 'C', 10, 0x2 }, { 3, 0, 'D', 8, 0x8 },
    { 3, 1, 'B', 11, 0x1 }, { 3, 1, 'C', 11, 0x2 }, { 3, 1, 'D', 9, 0x8 },
};

static const afpin_t spi_pins[] = {
    /* 9.3.10: SPI1_REMAP 0 SCK/MISO/MOSI PA5/PA6/PA7, 1 PB3/PB4/PB5; SPI2 (not remappable) PB13/PB14/PB15 */
    { 1, 0, 'A', 5, 0x1 }, { 1, 0, 'B', 3, 0x2 }, { 1, 1, 'A', 6, 0x1 }, { 1, 1, 'B', 4, 0x2 },
    { 1, 2, 'A', 7, 0x1 }, { 1, 2, 'B', 5, 0x2 }, { 2, 0, 'B', 13, 0x1 }, { 2, 1, 'B', 14, 0x1 }, { 2, 2, 'B', 15, 0x1 },
};

/* The remap settings (mask) under which pin carries the signal, 0: none. */
static unsigned af_mask(const afpin_t *t, size_t n, int unit, int signal, stm32_pin_t pin)
{
    unsigned m = 0;
    for (size_t i = 0; i < n; i++)
        if (t[i].unit == unit && t[i].signal == signal && t[i].port == pin.port && t[i].bit == pin.bit) m |= t[i].mask;
    return m;
}

/* "PA6, PB4, PC6": where the signal can be, into buf. */
static const char *af_where(const afpin_t *t, size_t n, int unit, int signal, char *buf, size_t len)
{
    size_t k = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < n && k + 8 < len; i++)
        if (t[i].unit == unit && t[i].signal == signal)
            k += (size_t)snprintf(buf + k, len - k, "%sP%c%d", k ? ", " : "", t[i].port, t[i].bit);
    return buf;
}

/* ---- the keys ---- */

/* "PA0".."PE15" into an stm32_pin_t */
static int parse_pin(const char *v, void *field, char *why, size_t len)
{
    char *end;
    if (v[0] == 'P' && v[1] >= 'A' && v[1] <= 'E' && v[2] >= '0' && v[2] <= '9') {
        long n = strtol(v + 2, &end, 10);
        if (!*end && n <= 15 && (v[3] == '\0' || v[2] != '0')) {
            *(stm32_pin_t *)field = (stm32_pin_t){ v[1], (uint8_t)n };
            return 0;
        }
    }
    snprintf(why, len, "expected a pin PA0-PE15, got '%s'", v);
    return -1;
}

/* "TIM3_CH1" into an stm32_tch_t */
static int parse_tch(const char *v, void *field, char *why, size_t len)
{
    if (!strncmp(v, "TIM", 3) && v[3] >= '1' && v[3] <= '4' && !strncmp(v + 4, "_CH", 3) && v[7] >= '1' && v[7] <= '4' && !v[8]) {
        *(stm32_tch_t *)field = (stm32_tch_t){ (uint8_t)(v[3] - '0'), (uint8_t)(v[7] - '0') };
        return 0;
    }
    snprintf(why, len, "expected a timer channel TIM1_CH1-TIM4_CH4, got '%s'", v);
    return -1;
}

static const char *const drivers[] = { "drv8833" };
static const char *const fwd_in[] = { "in1", "in2" };
static const char *const leads[] = { "b_leads", "a_leads" }; /* the index is a_leads */
static const char *const gyros[] = { "mpu6500" };
static const char *const spis[] = { "SPI1", "SPI2" };
static const char *const usarts[] = { "USART1", "USART2", "USART3" };

#define OFF(f) offsetof(stm32board_spec_t, f)
#define REQ KEYTAB_REQUIRED
#define TEXT(sec, key, f, def, src) { sec, key, OFF(f), def, 0, 0, "text", src, NULL, 0, 0, 0, KEYTAB_TEXT, sizeof ((stm32board_spec_t *)0)->f, NULL }
#define NUM(sec, key, type, f, def, min, max, unit, src) { sec, key, OFF(f), def, min, max, unit, src, NULL, 0, 0, 0, type, 0, NULL }
#define WORD(sec, key, f, def, words, src) { sec, key, OFF(f), def, 0, N(words) - 1, "word", src, words, 1, 0, 0, KEYTAB_INT, 0, NULL }
#define PIN(sec, key, f, src) { sec, key, OFF(f), REQ, 0, 0, "pin", src, NULL, 0, 0, 0, KEYTAB_PARSED, sizeof(stm32_pin_t), parse_pin }
#define TCH(sec, key, f, src) { sec, key, OFF(f), REQ, 0, 0, "TIMn_CHm", src, NULL, 0, 0, 0, KEYTAB_PARSED, sizeof(stm32_tch_t), parse_tch }
#define MOTOR(sec, m) \
    WORD(sec, "driver", motor[m].driver, REQ, drivers, "the motor driver: drv8833 (IN1/IN2 per bridge, both PWM)"), \
    TCH(sec, "in1", motor[m].in[0], "the timer channel driving the bridge's IN1"), \
    PIN(sec, "in1_pin", motor[m].in_pin[0], "that channel's pin, wired to IN1"), \
    TCH(sec, "in2", motor[m].in[1], "the timer channel driving IN2"), \
    PIN(sec, "in2_pin", motor[m].in_pin[1], "that channel's pin, wired to IN2"), \
    WORD(sec, "forward", motor[m].forward_in, REQ, fwd_in, "in1: IN1 high, IN2 low turns the wheel forward; in2: the reverse")
#define ENCODER(sec, e) \
    TCH(sec, "a", enc[e].a, "channel A's timer input (CH1 or CH2)"), \
    PIN(sec, "a_pin", enc[e].a_pin, "channel A's pin"), \
    TCH(sec, "b", enc[e].b, "channel B's timer input, the same timer's other of CH1/CH2"), \
    PIN(sec, "b_pin", enc[e].b_pin, "channel B's pin"), \
    WORD(sec, "forward", enc[e].a_leads, REQ, leads, "which channel leads when the wheel turns forward")

static const keytab_t keys[] = {
    TEXT("board", "name", name, REQ, "the board's name"),
    TEXT("board", "mcu", mcu, REQ, "the MCU: stm32f103c8, cb, r8, rb, v8 or vb"),
    TEXT("board", "default_robot", default_robot, 0, "the robot file a run uses without --robot: robots/NAME.ini"),
    NUM("board", "hse_hz", KEYTAB_U32, hse_hz, REQ, 4e6, 16e6, "Hz", "the crystal on OSC_IN/OSC_OUT (HSE: 4-16 MHz)"),
    NUM("board", "vdda_v", KEYTAB_DOUBLE, vdda_v, REQ, 2.4, 3.6, "V", "VDDA = VREF+: the ADC's full scale"),
    MOTOR("motor.left", 0), MOTOR("motor.right", 1),
    ENCODER("encoder.left", 0), ENCODER("encoder.right", 1),
    TCH("speaker", "channel", speaker, "the timer channel driving the speaker"),
    PIN("speaker", "pin", speaker_pin, "that channel's pin"),
    WORD("gyro", "chip", gyro_chip, REQ, gyros, "the gyro: mpu6500"),
    WORD("gyro", "spi", gyro_spi, REQ, spis, "the SPI bus it is on"),
    PIN("gyro", "cs_pin", gyro_cs_pin, "its chip select (nCS), a GPIO the firmware drives"),
    NUM("gyro", "spi_remap", KEYTAB_INT, gyro_spi_remap, 0, 0, 1, "0/1", "SPI1 only: 1 if its pins are remapped (PB3-PB5)"),
    WORD("console", "usart", console_usart, REQ, usarts, "the USART the firmware talks on"),
    PIN("console", "tx_pin", console_tx_pin, "its TX pin"),
    PIN("console", "rx_pin", console_rx_pin, "its RX pin"),
    NUM("battery", "adc_channel", KEYTAB_INT, bat_channel, REQ, 0, 15, "channel", "ADC12_INn the divider is on"),
    NUM("battery", "r_top_ohm", KEYTAB_DOUBLE, bat_r_top_ohm, REQ, 0, 1e7, "ohm", "battery to the ADC pin"),
    NUM("battery", "r_bottom_ohm", KEYTAB_DOUBLE, bat_r_bottom_ohm, REQ, 1, 1e7, "ohm", "the ADC pin to ground"),
    NUM("battery", "diode_drop_v", KEYTAB_DOUBLE, bat_diode_drop_v, 0, 0, 2, "V", "a series diode's forward drop before the divider (0: none)"),
};
/* the fixed sections; the last three are optional (a part the board may lack) */
static const char *const fixed[] = { "board", "motor.left", "motor.right", "encoder.left", "encoder.right", "battery",
                                     "speaker", "gyro", "console" };
#define FIXED_REQUIRED 6

/* [emitter.NAME], [led.NAME], [button.NAME] */
#define GOFF(f) offsetof(stm32_gpio_part_t, f)
static const keytab_t part_keys[3][2] = {
    { { NULL, "pin", GOFF(pin), REQ, 0, 0, "pin", "lights the emitter group", NULL, 0, 0, 0, KEYTAB_PARSED, sizeof(stm32_pin_t), parse_pin },
      { NULL, "group", GOFF(group), REQ, 0, SIM_EMITTER_GROUPS - 1, "1", "the robot file's [ir.*] emitter number", NULL, 0, 0, 0, KEYTAB_INT, 0, NULL } },
    { { NULL, "pin", GOFF(pin), REQ, 0, 0, "pin", "drives the LED", NULL, 0, 0, 0, KEYTAB_PARSED, sizeof(stm32_pin_t), parse_pin },
      { NULL, "on_level", GOFF(level), 1, 0, 1, "0/1", "the pin's level that lights it", NULL, 0, 0, 0, KEYTAB_INT, 0, NULL } },
    { { NULL, "pin", GOFF(pin), REQ, 0, 0, "pin", "reads the button", NULL, 0, 0, 0, KEYTAB_PARSED, sizeof(stm32_pin_t), parse_pin },
      { NULL, "pressed_level", GOFF(level), REQ, 0, 1, "0/1", "the pin's level while it is pressed", NULL, 0, 0, 0, KEYTAB_INT, 0, NULL } },
};
static const char *const kinds[3] = { "emitter.", "led.", "button." };
static const int kind_max[3] = { SIM_EMITTER_GROUPS, STM32BOARD_LEDS_MAX, STM32BOARD_BUTTONS_MAX };

typedef struct {
    inisec_t ini;               /* the file, its fixed sections' lines, the error */
    stm32board_spec_t work;
    uint64_t seen;              /* keys[] given */
    uint64_t part_seen[3][SIM_EMITTER_GROUPS > STM32BOARD_LEDS_MAX ? SIM_EMITTER_GROUPS : STM32BOARD_LEDS_MAX];
    char *err;
    size_t errn;
} sload_t;

static stm32_gpio_part_t *parts(stm32board_spec_t *sp, int kind) { return kind == 0 ? sp->emitter : kind == 1 ? sp->led : sp->button; }
static int *count(stm32board_spec_t *sp, int kind) { return kind == 0 ? &sp->nemitters : kind == 1 ? &sp->nleds : &sp->nbuttons; }

/* The kind of a named section (-1: none) and its part (NULL: not yet made). */
static stm32_gpio_part_t *named(sload_t *l, const char *section, int *kind)
{
    for (*kind = 0; *kind < 3 && strncmp(section, kinds[*kind], strlen(kinds[*kind])); ++*kind) {}
    if (*kind == 3) {
        *kind = -1;
        return NULL;
    }
    const char *nm = section + strlen(kinds[*kind]);
    stm32_gpio_part_t *p = parts(&l->work, *kind);
    for (int i = 0; i < *count(&l->work, *kind); i++)
        if (!strcmp(p[i].name, nm)) return &p[i];
    return NULL;
}

static int on_section(void *user, const char *section, int line, char *why, size_t len)
{
    sload_t *l = user;
    if (inisec_section(&l->ini, section, line) >= 0) return 0;
    int kind;
    if (named(l, section, &kind) || kind < 0) {
        if (kind >= 0) return 0; /* the part's section again */
        snprintf(why, len, "[%s]: unknown section (board, motor.left, motor.right, encoder.left, encoder.right, battery, speaker, "
                 "gyro, console, emitter.NAME, led.NAME, button.NAME)", section);
        return -1;
    }
    const char *nm = section + strlen(kinds[kind]);
    int *n = count(&l->work, kind);
    if (*n >= kind_max[kind] || !*nm || strlen(nm) >= STM32BOARD_NAME_MAX) {
        snprintf(why, len, "[%s]: at most %d %s sections, names of 1-%d characters", section, kind_max[kind], kinds[kind],
                 STM32BOARD_NAME_MAX - 1);
        return -1;
    }
    stm32_gpio_part_t *p = &parts(&l->work, kind)[(*n)++];
    snprintf(p->name, sizeof p->name, "%s", nm);
    p->line = line;
    p->level = 1; /* on_level's default; pressed_level is required */
    return 0;
}

static int on_key(void *user, const char *section, const char *key, const char *val, char *why, size_t len)
{
    sload_t *l = user;
    int kind;
    stm32_gpio_part_t *p = named(l, section, &kind);
    const keytab_t *k = p ? inisec_key(section, key, part_keys[kind], 2, NULL, why, len)
                          : inisec_key(section, key, keys, N(keys), section, why, len);
    if (!k) return -1;
    if (keytab_set(k, p ? (void *)p : (void *)&l->work, section, val, why, len) != 0) return -1;
    if (p) l->part_seen[kind][p - parts(&l->work, kind)] |= 1ull << (k - part_keys[kind]);
    else l->seen |= 1ull << (k - keys);
    return 0;
}

/* Every required key of the sections given (an optional section absent: none of its keys). */
static int missing(sload_t *l)
{
    uint64_t seen = l->seen;
    for (size_t i = 0; i < N(keys); i++)
        for (size_t s = FIXED_REQUIRED; s < N(fixed); s++)
            if (!strcmp(keys[i].section, fixed[s]) && !l->ini.line[s]) seen |= 1ull << i;
    const keytab_t *k = keytab_missing(keys, N(keys), seen);
    if (k && inisec_line(&l->ini, k->section)) return inisec_fail(&l->ini, inisec_line(&l->ini, k->section), "%s.%s: missing", k->section, k->key);
    if (k) return inisec_fail(&l->ini, 0, "%s.%s: missing (no [%s] section)", k->section, k->key, k->section);
    for (int kind = 0; kind < 3; kind++)
        for (int i = 0; i < *count(&l->work, kind); i++) {
            const stm32_gpio_part_t *p = &parts(&l->work, kind)[i];
            if ((k = keytab_missing(part_keys[kind], 2, l->part_seen[kind][i])) != NULL)
                return inisec_fail(&l->ini, p->line, "%s%s.%s: missing", kinds[kind], p->name, k->key);
        }
    return 0;
}

/* ---- the checks against the MCU ---- */

/* The board's pins so far, each with the part it belongs to: no pin twice. */
typedef struct {
    stm32_pin_t pin[64];
    char who[64][40];
    int line[64], n;
} claims_t;

static int claim(sload_t *l, claims_t *c, stm32_pin_t p, int line, const char *fmt, ...) __attribute__((format(printf, 5, 6)));
static int claim(sload_t *l, claims_t *c, stm32_pin_t p, int line, const char *fmt, ...)
{
    char who[40];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(who, sizeof who, fmt, ap);
    va_end(ap);
    if (!on_package(l->work.package, p))
        return inisec_fail(&l->ini, line, "%s: P%c%d: the %s's %d-pin package has no such pin (DS5319 Table 5)", who, p.port, p.bit, l->work.mcu,
                    l->work.package == 'C' ? 48 : l->work.package == 'R' ? 64 : 100);
    for (int i = 0; i < c->n; i++)
        if (c->pin[i].port == p.port && c->pin[i].bit == p.bit)
            return inisec_fail(&l->ini, line, "%s: P%c%d is already wired to %s", who, p.port, p.bit, c->who[i]);
    if (c->n < (int)N(c->pin)) {
        c->pin[c->n] = p;
        snprintf(c->who[c->n], sizeof c->who[0], "%s", who);
        c->line[c->n++] = line;
    }
    return 0;
}

/* The remap settings each timer's channels allow so far (bit r: MAPR = r). */
typedef struct {
    unsigned remap[5];   /* per timer 1-4 */
    int use[5][5];       /* per timer and channel: 1 PWM out, 2 encoder in */
} timers_t;

/* A timer channel on a pin, used as `use`: the pin carries it, the timer's
 * remap stays possible, no channel twice, an encoder's timer drives no PWM. */
static int tch_on(sload_t *l, timers_t *t, const char *sec, const char *key, const char *pin_key, stm32_tch_t ch, stm32_pin_t pin, int use)
{
    int line = inisec_line(&l->ini, sec);
    char where[64];
    unsigned m = af_mask(tim_pins, N(tim_pins), ch.timer, ch.channel, pin);
    if (!m)
        return inisec_fail(&l->ini, line, "%s.%s: P%c%d does not carry TIM%d_CH%d (it is on %s: RM0008 9.3.7)", sec, pin_key, pin.port, pin.bit, ch.timer,
                    ch.channel, af_where(tim_pins, N(tim_pins), ch.timer, ch.channel, where, sizeof where));
    if (!(t->remap[ch.timer] & m))
        return inisec_fail(&l->ini, line, "%s.%s: TIM%d's channels are on pins that need different AFIO remaps (RM0008 9.3.7)", sec, pin_key, ch.timer);
    t->remap[ch.timer] &= m;
    if (t->use[ch.timer][ch.channel])
        return inisec_fail(&l->ini, line, "%s.%s: TIM%d_CH%d is already in use", sec, key, ch.timer, ch.channel);
    for (int c = 1; c <= 4; c++)
        if (t->use[ch.timer][c] && t->use[ch.timer][c] != use)
            return inisec_fail(&l->ini, line, "%s.%s: TIM%d also %s: a timer in encoder mode counts the wheel and drives no PWM", sec, key, ch.timer,
                        use == 2 ? "drives a PWM output" : "reads an encoder");
    t->use[ch.timer][ch.channel] = use;
    return 0;
}

static int check_drive(sload_t *l, timers_t *t, claims_t *c)
{
    static const char *const side[2] = { "left", "right" };
    stm32board_spec_t *sp = &l->work;
    char sec[24];
    for (int m = 0; m < 2; m++) {
        snprintf(sec, sizeof sec, "motor.%s", side[m]);
        for (int i = 0; i < 2; i++) {
            const char *key = i ? "in2" : "in1", *pin_key = i ? "in2_pin" : "in1_pin";
            if (tch_on(l, t, sec, key, pin_key, sp->motor[m].in[i], sp->motor[m].in_pin[i], 1) ||
                claim(l, c, sp->motor[m].in_pin[i], inisec_line(&l->ini, sec), "%s.%s", sec, pin_key))
                return -1;
        }
    }
    for (int e = 0; e < 2; e++) {
        stm32_encoder_t *en = &sp->enc[e];
        snprintf(sec, sizeof sec, "encoder.%s", side[e]);
        if (en->a.timer != en->b.timer || en->a.channel > 2 || en->b.channel > 2 || en->a.channel == en->b.channel)
            return inisec_fail(&l->ini, inisec_line(&l->ini, sec), "%s.b: TIM%d_CH%d with a = TIM%d_CH%d: the encoder interface reads CH1 and CH2 of one timer "
                        "(TI1, TI2: RM0008 15.3.12)", sec, en->b.timer, en->b.channel, en->a.timer, en->a.channel);
        if (tch_on(l, t, sec, "a", "a_pin", en->a, en->a_pin, 2) || tch_on(l, t, sec, "b", "b_pin", en->b, en->b_pin, 2) ||
            claim(l, c, en->a_pin, inisec_line(&l->ini, sec), "%s.a_pin", sec) || claim(l, c, en->b_pin, inisec_line(&l->ini, sec), "%s.b_pin", sec))
            return -1;
        en->ch1_leads = (en->a.channel == 1) == (en->a_leads != 0);
    }
    if (inisec_line(&l->ini, "speaker") &&
        (tch_on(l, t, "speaker", "channel", "pin", sp->speaker, sp->speaker_pin, 1) ||
         claim(l, c, sp->speaker_pin, inisec_line(&l->ini, "speaker"), "speaker.pin")))
        return -1;
    if (!inisec_line(&l->ini, "speaker")) sp->speaker = (stm32_tch_t){ 0, 0 };
    return 0;
}

/* The gyro's SPI pins and chip select, the console's USART pins. */
static int check_buses(sload_t *l, claims_t *c)
{
    stm32board_spec_t *sp = &l->work;
    int line = inisec_line(&l->ini, "gyro");
    if (line) {
        sp->gyro_spi += 1; /* the word's index: SPI1 = 0 */
        if (sp->gyro_spi == 2 && sp->gyro_spi_remap) return inisec_fail(&l->ini, line, "gyro.spi_remap: SPI2 has no remap (RM0008 9.3.10)");
        stm32_pin_t *bus[3] = { &sp->gyro_sck_pin, &sp->gyro_miso_pin, &sp->gyro_mosi_pin };
        static const char *const sig[3] = { "SCK", "MISO", "MOSI" };
        for (int i = 0; i < 3; i++) {
            for (size_t k = 0; k < N(spi_pins); k++)
                if (spi_pins[k].unit == sp->gyro_spi && spi_pins[k].signal == i && (spi_pins[k].mask >> sp->gyro_spi_remap & 1))
                    *bus[i] = (stm32_pin_t){ spi_pins[k].port, spi_pins[k].bit };
            if (claim(l, c, *bus[i], line, "gyro.spi (SPI%d_%s)", sp->gyro_spi, sig[i])) return -1;
        }
        if (claim(l, c, sp->gyro_cs_pin, line, "gyro.cs_pin")) return -1;
    } else {
        sp->gyro_spi = 0;
    }
    if ((line = inisec_line(&l->ini, "console")) == 0) {
        sp->console_usart = 0;
        return 0;
    }
    sp->console_usart += 1;
    char where[64];
    unsigned tx = af_mask(usart_pins, N(usart_pins), sp->console_usart, 0, sp->console_tx_pin);
    unsigned rx = af_mask(usart_pins, N(usart_pins), sp->console_usart, 1, sp->console_rx_pin);
    if (!tx || !rx)
        return inisec_fail(&l->ini, line, "console.%s_pin: not USART%d_%s's pin (it is on %s: RM0008 9.3.8)", tx ? "rx" : "tx", sp->console_usart,
                    tx ? "RX" : "TX", af_where(usart_pins, N(usart_pins), sp->console_usart, tx ? 1 : 0, where, sizeof where));
    if (!(tx & rx)) return inisec_fail(&l->ini, line, "console.rx_pin: TX and RX need different USART%d remaps (RM0008 9.3.8)", sp->console_usart);
    if (claim(l, c, sp->console_tx_pin, line, "console.tx_pin") || claim(l, c, sp->console_rx_pin, line, "console.rx_pin")) return -1;
    return 0;
}

static int check(sload_t *l)
{
    stm32board_spec_t *sp = &l->work;
    claims_t *c = calloc(1, sizeof *c);
    timers_t t;
    if (!c) return inisec_fail(&l->ini, 0, "out of memory");
    for (int i = 1; i <= 4; i++) t.remap[i] = 0xF;
    memset(t.use, 0, sizeof t.use);
    int rc = check_drive(l, &t, c) || check_buses(l, c) ? -1 : 0;
    sp->bat_pin = stm32board_adc_pin(sp, sp->bat_channel);
    if (!rc && !sp->bat_pin.port)
        rc = inisec_fail(&l->ini, inisec_line(&l->ini, "battery"), "battery.adc_channel: %d: the %s has ADC12_IN0-%d only (DS5319 Table 2)", sp->bat_channel, sp->mcu,
                  sp->adc_channels - 1);
    if (!rc) rc = claim(l, c, sp->bat_pin, inisec_line(&l->ini, "battery"), "battery.adc_channel (ADC12_IN%d)", sp->bat_channel);
    for (int kind = 0; kind < 3 && !rc; kind++)
        for (int i = 0; i < *count(sp, kind) && !rc; i++) {
            const stm32_gpio_part_t *p = &parts(sp, kind)[i];
            rc = claim(l, c, p->pin, p->line, "%s%s.pin", kinds[kind], p->name);
            for (int j = 0; j < i && !rc && kind == 0; j++)
                if (sp->emitter[j].group == p->group) rc = inisec_fail(&l->ini, p->line, "emitter.%s.group: emitter.%s lights that group", p->name, sp->emitter[j].name);
        }
    free(c);
    return rc;
}

/* Ahead of the keys' checks: the MCU by name, its memories and package. */
static int check_mcu(sload_t *l)
{
    stm32board_spec_t *sp = &l->work;
    for (size_t i = 0; i < N(mcus); i++)
        if (!strcmp(sp->mcu, mcus[i].name)) {
            sp->flash_bytes = mcus[i].flash_kib * 1024u;
            sp->sram_bytes = mcus[i].sram_kib * 1024u;
            sp->package = mcus[i].package;
            sp->adc_channels = mcus[i].package == 'C' ? 10 : 16; /* DS5319 Table 2 */
            return 0;
        }
    return inisec_fail(&l->ini, inisec_line(&l->ini, "board"), "board.mcu: '%s': not an STM32 this board file knows (stm32f103c8, stm32f103cb, "
                "stm32f103r8, stm32f103rb, stm32f103v8, stm32f103vb)", sp->mcu);
}

int stm32board_load(stm32board_spec_t *spec, const char *path, char *err, size_t errn)
{
    sload_t *l = calloc(1, sizeof *l);
    if (!l) {
        snprintf(err, errn, "%s: out of memory", path);
        return -1;
    }
    inisec_init(&l->ini, path, err, errn, fixed, N(fixed));
    keytab_defaults(keys, N(keys), &l->work);
    const inifile_t r = { on_section, on_key, l, "want key = value or [section]" };
    int rc = inifile_load(&r, path, STM32BOARD_MAX_BYTES, err, errn);
    if (rc == 0 && missing(l) == 0 && check_mcu(l) == 0 && check(l) == 0) {
        snprintf(l->work.path, sizeof l->work.path, "%s", path);
        *spec = l->work;
    } else {
        rc = -1;
    }
    free(l);
    return rc;
}

/* ---- which loader ---- */

typedef struct {
    char mcu[32];
    int found;
} peek_t;

static int peek_key(void *user, const char *section, const char *key, const char *val, char *why, size_t len)
{
    peek_t *p = user;
    if (!strcmp(section, "board") && !strcmp(key, "mcu")) {
        snprintf(p->mcu, sizeof p->mcu, "%s", val);
        p->found = 1;
    }
    return 0;
}

boardfile_family_t boardfile_family(const char *path, char *err, size_t errn)
{
    peek_t p = { "", 0 };
    const inifile_t r = { NULL, peek_key, &p, "want key = value or [section]" };
    if (inifile_load(&r, path, STM32BOARD_MAX_BYTES, err, errn) != 0) return BOARDFILE_UNKNOWN;
    if (!strncmp(p.mcu, "atmega", 6)) return BOARDFILE_AVR;
    if (!strncmp(p.mcu, "stm32", 5)) return BOARDFILE_STM32;
    if (!p.found) snprintf(err, errn, "%s: board.mcu: missing (the MCU says which board emulation reads the file)", path);
    else snprintf(err, errn, "%s: board.mcu: '%s': neither an AVR (atmega...) nor an STM32 (stm32...)", path, p.mcu);
    return BOARDFILE_UNKNOWN;
}

/* ---- the robot on the board ---- */

/* The board part wired to pin p, NULL if none. */
static const char *pin_user(const stm32board_spec_t *sp, stm32_pin_t p)
{
    const stm32_pin_t pins[] = { sp->motor[0].in_pin[0], sp->motor[0].in_pin[1], sp->motor[1].in_pin[0], sp->motor[1].in_pin[1],
                                 sp->enc[0].a_pin, sp->enc[0].b_pin, sp->enc[1].a_pin, sp->enc[1].b_pin, sp->speaker_pin,
                                 sp->gyro_cs_pin, sp->gyro_sck_pin, sp->gyro_miso_pin, sp->gyro_mosi_pin, sp->console_tx_pin,
                                 sp->console_rx_pin, sp->bat_pin };
    static const char *const who[] = { "motor.left.in1_pin", "motor.left.in2_pin", "motor.right.in1_pin", "motor.right.in2_pin",
                                       "encoder.left.a_pin", "encoder.left.b_pin", "encoder.right.a_pin", "encoder.right.b_pin",
                                       "speaker.pin", "gyro.cs_pin", "gyro.spi", "gyro.spi", "gyro.spi", "console.tx_pin",
                                       "console.rx_pin", "battery.adc_channel" };
    for (size_t i = 0; i < N(pins); i++)
        if (pins[i].port && pins[i].port == p.port && pins[i].bit == p.bit) return who[i];
    const stm32_gpio_part_t *g[3] = { sp->emitter, sp->led, sp->button };
    const int n[3] = { sp->nemitters, sp->nleds, sp->nbuttons };
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < n[k]; i++)
            if (g[k][i].pin.port == p.port && g[k][i].pin.bit == p.bit) return kinds[k];
    return NULL;
}

int stm32board_fits_robot(const stm32board_spec_t *sp, const simcfg_t *c, char *err, size_t errn)
{
    int lights[SIM_EMITTER_GROUPS] = { 0 };
    for (unsigned i = 0, n = robot_count(c, "ir"); i < n; i++) {
        const robot_part_t *p = &c->robot.part[robot_part_of_kind(c, "ir", i)];
        const ir_part_spec_t *ir = (const ir_part_spec_t *)(const void *)p->spec;
        int g = (int)ir->emitter, e = 0, ch = (int)ir->adc_channel;
        while (e < sp->nemitters && sp->emitter[e].group != g) e++;
        stm32_pin_t pin = stm32board_adc_pin(sp, ch);
        const char *user = pin.port ? pin_user(sp, pin) : NULL;
        if (e == sp->nemitters)
            snprintf(err, errn, "%s:%d: ir.%s.emitter %d: the board %s (%s) has no [emitter.*] for group %d", c->robot.path, p->line,
                     p->name, g, sp->name, sp->path, g);
        else if (!pin.port)
            snprintf(err, errn, "%s:%d: ir.%s.adc_channel %d: the board %s (%s, %s) has ADC12_IN0-%d", c->robot.path, p->line, p->name, ch,
                     sp->name, sp->path, sp->mcu, sp->adc_channels - 1);
        else if (user)
            snprintf(err, errn, "%s:%d: ir.%s.adc_channel %d: its pin P%c%d is the board's %s (%s)", c->robot.path, p->line, p->name, ch,
                     pin.port, pin.bit, user, sp->path);
        if (e == sp->nemitters || !pin.port || user) return -1;
        lights[g]++;
    }
    for (int e = 0; e < sp->nemitters; e++)
        if (!lights[sp->emitter[e].group]) {
            snprintf(err, errn, "%s:%d: emitter.%s.group %d: the robot %s has no [ir.*] sensor with emitter = %d", sp->path,
                     sp->emitter[e].line, sp->emitter[e].name, sp->emitter[e].group, c->robot.path, sp->emitter[e].group);
            return -1;
        }
    return 0;
}
