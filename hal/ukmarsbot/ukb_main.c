/* ukb_main.c - the mouse on UKMARSBOT: main(), the systick, hal_micros and
 * the console's one-letter commands.
 *
 * Systick: Timer2 in CTC mode, clock / 256 (62.5 kHz, 16 us a count),
 * TOP = 62500 / HAL_TICK_HZ - 1 (249 at 250 Hz). Its interrupt masks
 * itself, re-enables the others (encoders and UART keep being served),
 * runs the sensor schedule (ukb_sensors.c) and, while the mouse runs,
 * fw_tick; a tick that is still busy when the next one is due counts as an
 * overrun (command k).
 *
 * At power-on the board waits at its console ("h" lists the commands);
 * the button or "g" starts the mouse: fw_setup, then fw_tick every tick
 * and fw_loop from the main loop. */
#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <util/atomic.h>

#include "hal.h"
#include "ukb_board.h"
#include "ukb_console.h"
#include "ukb_encoders.h"
#include "ukb_motors.h"
#include "ukb_sensors.h"
#include "explore.h"
#include "walls.h"
#include "walls_ir.h"

#define UKB_SYSTICK_CLK_HZ (F_CPU / 256UL) /* Timer2 clock, Hz */
#define UKB_SYSTICK_TOP (UKB_SYSTICK_CLK_HZ / HAL_TICK_HZ - 1UL)
#define UKB_US_PER_COUNT (1000000UL / UKB_SYSTICK_CLK_HZ) /* 16 us */
#if UKB_SYSTICK_CLK_HZ % HAL_TICK_HZ != 0 || UKB_SYSTICK_TOP > 255
#error "HAL_TICK_HZ must divide 62500 Hz into at most 256 Timer2 counts (245..62500 Hz)"
#endif
#define UKB_TEST_CMD 256       /* motor test (m): 256 / 1023 of UKB_MOTOR_REF_MV, 1.5 V */
#define UKB_TEST_TICKS (HAL_TICK_HZ / 2) /* motor test length: 0.5 s */
#define UKB_STACK_PAINT 0xa5   /* byte painted over the free SRAM at start */

static volatile uint32_t ticks;
static volatile uint8_t running;           /* fw_tick on */
static volatile uint16_t motor_test_left;  /* ticks of the motor test still to run */
static volatile uint16_t overruns;
static volatile uint8_t tick_held, tick_due; /* hal_tick_hold: fw_tick left to the release */
/* the longest time from a compare to the end of the sensor schedule and
 * to the end of the whole tick, Timer2 counts (16 us; command k) */
static volatile uint8_t busy_sense_max, busy_tick_max;
static uint8_t test_reported = 1;
extern uint8_t __bss_end; /* avr-libc's linker script: the end of the static RAM */

static void systick_init(void)
{
    TCCR2A = _BV(WGM21);            /* CTC, TOP = OCR2A */
    TCCR2B = _BV(CS22) | _BV(CS21); /* clock / 256 */
    OCR2A = (uint8_t)UKB_SYSTICK_TOP;
    TIMSK2 = _BV(OCIE2A);
}

ISR(TIMER2_COMPA_vect)
{
    ticks++;
    TIMSK2 &= (uint8_t)~_BV(OCIE2A);
    sei();
    ukb_sensors_sample();
    uint8_t t = TCNT2;
    if (t > busy_sense_max) busy_sense_max = t;
    if (running && tick_held) tick_due = 1;
    else if (running) fw_tick();
    else if (motor_test_left && --motor_test_left == 0) hal_motor_set(0, 0);
    static uint8_t blink;
    if (++blink >= HAL_TICK_HZ / 4) { /* heartbeat: the Nano's LED toggles at 4 Hz, a 2 Hz blink */
        blink = 0;
        PORTB ^= _BV(UKB_LED_BUILTIN_BIT);
    }
    cli();
    t = TCNT2;
    if (TIFR2 & _BV(OCF2A)) overruns++;
    else if (t > busy_tick_max) busy_tick_max = t;
    TIMSK2 |= _BV(OCIE2A);
}

/* fw_loop holds the tick: a systick meanwhile runs its sensor pass and
 * leaves fw_tick due, and the release runs it here, in the main loop, until
 * none is due (a systick during that one leaves the next due). */
void hal_tick_hold(void) { tick_held = 1; }

void hal_tick_release(void)
{
    for (;;) {
        cli();
        if (!tick_due) {
            tick_held = 0;
            sei();
            return;
        }
        tick_due = 0;
        sei();
        fw_tick();
    }
}

uint32_t hal_micros(void)
{
    uint32_t t;
    uint8_t c, pending;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
        t = ticks;
        c = TCNT2;
        pending = (uint8_t)(TIFR2 & _BV(OCF2A));
    }
    if (pending && c < UKB_SYSTICK_TOP / 2) t++; /* a compare not served yet */
    return t * (1000000UL / HAL_TICK_HZ) + (uint32_t)c * UKB_US_PER_COUNT;
}

void hal_belief(const struct maze_s *map, uint16_t cell, uint8_t heading, uint8_t state)
{
    (void)map; (void)cell; (void)heading; (void)state; /* no telemetry channel on the board */
}

/* Paints the free SRAM between the static data and the stack so that
 * stack_unused can find how deep the stack has been. */
static void stack_paint(void)
{
    uint8_t *p = &__bss_end;
    while (p < (uint8_t *)SP - 16) *p++ = UKB_STACK_PAINT;
}

static uint16_t stack_unused(void)
{
    const uint8_t *p = &__bss_end;
    while (p < (const uint8_t *)SP && *p == UKB_STACK_PAINT) p++;
    return (uint16_t)(p - &__bss_end);
}

static void wait_ticks(uint8_t n)
{
    uint32_t t0;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { t0 = ticks; }
    for (;;) {
        uint32_t t;
        ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { t = ticks; }
        if (t - t0 >= n) return;
    }
}

static void report_ir(void)
{
    uint16_t r[4] = { 0, 0, 0, 0 }, d[4] = { 0, 0, 0, 0 };
    for (uint8_t i = 0; i < UKB_IR_COUNT && i < 4; i++) {
        r[i] = hal_ir_raw(i);
        d[i] = ukb_ir_dark(i);
    }
    ukb_console_printf_P(PSTR("IR %u %u %u %u dark %u %u %u %u"), r[0], r[1], r[2], r[3], d[0], d[1], d[2], d[3]);
}

static void emitters(uint8_t on)
{
    for (uint8_t g = 0; g < HAL_EMITTER_GROUPS; g++) hal_emitter(g, on);
}

static void start_mouse(void)
{
    if (running) return;
    emitters(0); /* hal.h: all emitters start off */
    hal_encoder_reset();
    fw_setup();
    PORTD |= _BV(UKB_LED_USER_BIT);
    running = 1;
    ukb_console_printf_P(PSTR("go"));
}

/* The start gesture, as UKMARSBOT's own firmware waits for it: armed (r,
 * or switches 1 at power-on), the mouse starts when a hand held over the
 * first forward sensor (hal_ir index 0: lfs, or the basic board's front
 * one) is taken away. Held: its reading above UKB_HAND_X times its front
 * calibration (standing in the start cell it reads ~0.1 of it; a hand 20
 * mm away ~5); away: below that calibration. */
#define UKB_HAND_X 3u
static uint8_t armed; /* 0, 1 armed, 2 the hand seen */

static void arm_step(void)
{
    uint16_t r = hal_ir_raw(0), ref = walls_ir_cal()->front_ref[0];
    if (armed == 1 && r > UKB_HAND_X * ref) armed = 2;
    if (armed == 2 && r < ref) {
        armed = 0;
        start_mouse();
    }
}

static void arm(void)
{
    if (running) return;
    emitters(1);
    armed = 1;
    ukb_console_printf_P(PSTR("armed: a hand over the front sensor starts"));
}

static void stop_mouse(void)
{
    running = 0;
    armed = 0;
    hal_motor_set(0, 0);
    emitters(1); /* the console's IR readings (i) light them again */
    PORTD &= (uint8_t)~_BV(UKB_LED_USER_BIT);
    ukb_console_printf_P(PSTR("stopped"));
}

static void motor_test(void)
{
    if (running) return;
    hal_encoder_reset();
    test_reported = 0;
    hal_motor_set(UKB_TEST_CMD, UKB_TEST_CMD);
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { motor_test_left = UKB_TEST_TICKS; }
    ukb_console_printf_P(PSTR("motors %u/1023 for %u ms"), UKB_TEST_CMD, (unsigned)(1000UL * UKB_TEST_TICKS / HAL_TICK_HZ));
}

#define UKB_EEPROM_CAL ((void *)0) /* EEPROM address of the IR calibration (walls_ir_cal_t) */

/* the IR calibration stored in EEPROM, if there is a good one */
static void calibration_load(void)
{
    walls_ir_cal_t c;
    eeprom_read_block(&c, UKB_EEPROM_CAL, sizeof c);
    uint8_t ok = walls_ir_cal_ok(&c);
    if (ok) *walls_ir_cal() = c;
    ukb_console_printf_P(ok ? PSTR("IR calibration from EEPROM") : PSTR("IR calibration: ORION's (EEPROM blank)"));
}

/* c: the sides (the robot backed against the start cell's rear wall), f:
 * the front (backed, with a wall ahead); kept in EEPROM */
static void calibrate(char which)
{
    if (running) return;
    uint8_t ok = which == 'c' ? walls_ir_calibrate_sides() : walls_ir_calibrate_front();
    const walls_ir_cal_t *c = walls_ir_cal();
    if (ok) eeprom_update_block(c, UKB_EEPROM_CAL, sizeof *c);
    ukb_console_printf_P(PSTR("calibrated %S: sides %u %u, front %u %u"), ok ? PSTR("and saved") : PSTR("NOT (no wall seen)"), c->side_ref[0],
                         c->side_ref[1], c->front_ref[0], c->front_ref[1]);
}

static void report_walls(void)
{
    uint16_t pct[3];
    uint8_t w = walls_around(WALLS_HERE_FRONT_MM);
    walls_ir_levels(pct);
    ukb_console_printf_P(PSTR("walls %c%c%c (%u %u %u %%)"), w & EXPLORE_WALL_LEFT ? 'L' : '-', w & EXPLORE_WALL_FRONT ? 'F' : '-',
                         w & EXPLORE_WALL_RIGHT ? 'R' : '-', pct[0], pct[1], pct[2]);
}

static void command(char c)
{
    switch (c) {
    case 'h': case '?':
        ukb_console_printf_P(PSTR("i IR, w walls, c calibrate the sides, f the front"));
        ukb_console_printf_P(PSTR("b battery, s switches, e encoders, m motor test"));
        ukb_console_printf_P(PSTR("g go, r go at a hand over the front, x stop, k stack"));
        break;
    case 'i': report_ir(); break;
    case 'w': report_walls(); break;
    case 'c': case 'f': calibrate(c); break;
    case 'b': ukb_console_printf_P(PSTR("battery %u mV"), hal_battery_mv()); break;
    case 's': ukb_console_printf_P(PSTR("switches %u adc %u"), ukb_switches(), ukb_switch_adc()); break;
    case 'e': ukb_console_printf_P(PSTR("encoders %ld %ld"), (long)hal_encoder(HAL_LEFT), (long)hal_encoder(HAL_RIGHT)); break;
    case 'm': motor_test(); break;
    case 'g': start_mouse(); break;
    case 'r': arm(); break;
    case 'x': stop_mouse(); break;
    case 'k':
        ukb_console_printf_P(PSTR("stack unused %u B, overruns %u, log lines dropped %u"), stack_unused(), overruns,
                             ukb_console_dropped());
        ukb_console_printf_P(PSTR("tick busy at most: sensors %u us, all %u us of %u"),
                             (unsigned)(busy_sense_max * UKB_US_PER_COUNT), (unsigned)(busy_tick_max * UKB_US_PER_COUNT),
                             (unsigned)(1000000UL / HAL_TICK_HZ));
        break;
    default: break;
    }
}

/* the board has no way to be told the maze: a classic contest */
uint8_t hal_maze(hal_maze_t *m)
{
    (void)m;
    return 0;
}

int main(void)
{
    stack_paint();
    DDRB |= _BV(UKB_LED_BUILTIN_BIT);
    DDRD |= _BV(UKB_LED_USER_BIT);
    ukb_console_init();
    ukb_motors_init();
    ukb_encoders_init();
    ukb_sensors_init();
    systick_init();
    sei();
    emitters(1);
    wait_ticks(8); /* the battery filter settles (4 passes a time constant) */
    ukb_console_printf_P(PSTR("UKMARSBOT mouse (hal/ukmarsbot, %S sensors)"), PSTR(UKB_SENSOR_BOARD_NAME)); /* %S: a string in flash */
    ukb_console_printf_P(PSTR("tick %u Hz, battery %u mV, switches %u; h for help"), (unsigned)HAL_TICK_HZ, hal_battery_mv(),
                         ukb_switches());
    calibration_load();
    if (ukb_switches() == 1) arm();
    for (;;) {
        int c = ukb_console_getc();
        if (c >= 0) command((char)c);
        if (running) fw_loop();
        else if (armed) arm_step();
        else if (ukb_switches() == UKB_BUTTON) start_mouse();
        if (!test_reported && !motor_test_left) {
            test_reported = 1;
            command('e');
        }
    }
}
