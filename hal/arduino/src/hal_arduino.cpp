/* hal_arduino.cpp - hal/hal.h on an Arduino, over mmLink (see MMMouse.h). */
#include "MMMouse.h"

#include <stdio.h>
#include <util/atomic.h>

#include "hal.h"
extern "C" { /* the firmware's headers are plain C */
#include "mouse.h"
}

static volatile int16_t cmd[2];          /* latest motor command */
static volatile int32_t enc_zero[2];
/* Log lines are cut to MM_LOG_TEXT_MAX characters on the MCU (the
 * firmware's longest is 49): 24 B less SRAM and stack than HAL_LOG_MAX */
#define MM_LOG_TEXT_MAX 56
static char log_line[MM_LOG_TEXT_MAX + 1];
static volatile uint8_t log_state;       /* 0 free, 1 being filled, 2 waits to be sent */
static volatile uint16_t log_dropped, overruns;
static volatile uint8_t busy;
static volatile uint8_t tick_held, tick_due; /* hal_tick_hold: the tick left to the release */
static uint8_t stop_sent;                /* RUN stop sent: the contest is over */
static uint8_t done_ticks;               /* ticks since the mouse finished (26: report queued) */
static volatile uint16_t worst_tick_half_us; /* longest tick, Timer1 counts (0.5 us at 16 MHz) */

uint32_t hal_micros(void) { return micros(); }

void hal_motor_set(int16_t left, int16_t right)
{
    if (left > WIRE_MOTOR_MAX) left = WIRE_MOTOR_MAX;
    if (left < -WIRE_MOTOR_MAX) left = -WIRE_MOTOR_MAX;
    if (right > WIRE_MOTOR_MAX) right = WIRE_MOTOR_MAX;
    if (right < -WIRE_MOTOR_MAX) right = -WIRE_MOTOR_MAX;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE)
    {
        cmd[0] = left;
        cmd[1] = right;
    }
}

int32_t hal_encoder(uint8_t side)
{
    int32_t c;
    side &= 1;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { c = mmLink.enc[side] - enc_zero[side]; }
    return c;
}

void hal_encoder_reset(void)
{
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE)
    {
        enc_zero[0] = mmLink.enc[0];
        enc_zero[1] = mmLink.enc[1];
    }
}

hal_distance_t hal_distance(uint8_t sensor)
{
    hal_distance_t d = { WIRE_TOF_RANGE_MM, 1, 0 }; /* a bad index reads as a timeout */
    if (sensor >= HAL_TOF_COUNT) return d;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE)
    {
        d.mm = mmLink.tof_mm[sensor];
        d.timeout = mmLink.tof_timeout[sensor];
        d.seq = mmLink.tof_seq[sensor];
    }
    return d;
}

/* Queue one line (text in SRAM, or in flash with from_flash): one line
 * waits at a time, the next tick sends it. */
static void queue_log(const char *line, uint8_t from_flash)
{
    uint8_t mine = 0;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) /* fw_loop and fw_tick may both log */
    {
        if (log_state == 0) {
            log_state = 1;
            mine = 1;
        } else {
            log_dropped++; /* one line in flight: drop, never block */
        }
    }
    if (!mine) return;
    if (from_flash) strncpy_P(log_line, line, MM_LOG_TEXT_MAX);
    else strncpy(log_line, line, MM_LOG_TEXT_MAX);
    log_line[MM_LOG_TEXT_MAX] = '\0';
    log_state = 2;
}

void hal_log(const char *line) { queue_log(line, 0); }
void hal_log_P(const char *line) { queue_log(line, 1); }

void hal_belief(const struct maze_s *map, uint16_t cell, uint8_t heading, uint8_t state)
{
    (void)map; (void)cell; (void)heading; (void)state; /* no telemetry over the link */
}

/* the wire protocol carries no maze announcement: a classic contest */
uint8_t hal_maze(hal_maze_t *m)
{
    (void)m;
    return 0;
}

static void tick()
{
    mmLink.poll();
    fw_tick();
    wire_msg_t m;
    memset(&m, 0, sizeof m);
    m.type = WIRE_MOTOR;
    m.u.motor.t_us = micros();
    m.u.motor.left = cmd[0];
    m.u.motor.right = cmd[1];
    mmLink.send(m);
    if (hal_wire_extra && hal_wire_extra(NULL, &m)) mmLink.send(m); /* a queued EMITTER (hal_arduino_sensors.cpp, if linked in) */
    if (log_state == 2) {
        memset(&m, 0, sizeof m);
        m.type = WIRE_LOG;
        m.u.log.len = (uint8_t)strlen(log_line);
        m.u.log.text = log_line;
        mmLink.send(m);
        log_state = 0;
    }
    /* done, no goal or crashed: tell the sim, after 25 ticks and an empty log
     * queue so the mouse's last lines arrive first */
    if (mouse_status()->mode >= MOUSE_DONE && done_ticks < 25) done_ticks++;
    if (done_ticks == 25 && log_state == 0) { /* the runner's own report, once */
        snprintf_P(log_line, sizeof log_line, PSTR("runner: %u Hz tick, %u overruns, worst %u us, %u lost"),
                 (unsigned)HAL_TICK_HZ, (unsigned)overruns, (unsigned)(worst_tick_half_us / 2u), (unsigned)log_dropped);
        log_state = 2;
        done_ticks = 26;
    }
    if (!stop_sent && done_ticks > 25 && log_state == 0) {
        memset(&m, 0, sizeof m);
        m.type = WIRE_RUN;
        m.u.flag.on = 0;
        mmLink.send(m);
        stop_sent = 1;
    }
}

ISR(TIMER1_COMPA_vect, ISR_NOBLOCK)
{
    if (busy) { /* the previous tick still runs: skip, counted */
        overruns++;
        return;
    }
    if (tick_held) { /* fw_loop holds it: hal_tick_release runs it */
        tick_due = 1;
        return;
    }
    busy = 1;
    tick();
    uint16_t t = TCNT1; /* counts since this tick's compare match */
    if (t > worst_tick_half_us) worst_tick_half_us = t;
    busy = 0;
}

void mm_mouse_begin(Stream &s, uint8_t protocol)
{
    mmLink.begin(s, protocol, HAL_TICK_HZ);
    if (protocol == MM_COMPAT) { /* the paper's sim sends nothing before this */
        wire_msg_t m;
        memset(&m, 0, sizeof m);
        m.type = WIRE_SENSORS;
        m.u.flag.on = 1;
        mmLink.send(m);
    }
    fw_setup();
    /* Timer1, CTC, prescaler 8: 2 MHz at 16 MHz */
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE)
    {
        TCCR1A = 0;
        TCCR1B = (1 << WGM12) | (1 << CS11);
        TCNT1 = 0;
        OCR1A = (uint16_t)(F_CPU / 8u / HAL_TICK_HZ - 1u);
        TIMSK1 |= 1 << OCIE1A;
    }
}

void mm_mouse_loop() { fw_loop(); }

/* fw_loop holds the tick: a tick interrupt meanwhile leaves the tick due,
 * and the release runs it here, in loop(), until none is due (busy: a tick
 * interrupt during one counts as an overrun, as in the interrupt) */
void hal_tick_hold(void) { tick_held = 1; }

void hal_tick_release(void)
{
    for (;;) {
        noInterrupts();
        if (!tick_due) {
            tick_held = 0;
            interrupts();
            return;
        }
        tick_due = 0;
        busy = 1;
        interrupts();
        tick();
        busy = 0;
    }
}

uint16_t mm_mouse_worst_tick_us()
{
    uint16_t n;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { n = worst_tick_half_us; }
    return (uint16_t)(n / 2u);
}

uint16_t mm_mouse_overruns()
{
    uint16_t n;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { n = overruns; }
    return n;
}
