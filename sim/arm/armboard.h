/* armboard.h - an STM32F1 board emulated at the register level: the chip
 * (stm32f1_soc.c) running an image in lockstep with the physics, the
 * robot's parts wired to its pins as the board file (stm32board.h,
 * boards/NAME.ini) says:
 *
 *   motors    each DRV8833 bridge's IN1/IN2 from their timer channels
 *             (stm32f1_tim_output) or GPIO levels -> sim_state_t.cmd[]:
 *             DRV8833 datasheet (SLVSAR1) table 1: IN1 high and IN2 low
 *             drive forward, IN2 high and IN1 low reverse, both low coast,
 *             both high brake; table 2: a PWM on one input with the other
 *             held is the same drive for the PWM's fraction. Two PWMs of
 *             one edge-aligned timer start together, so the bridge drives
 *             for high(IN1) - high(IN2) of the period (signed by which is
 *             longer). Stated limit: the decay mode of the rest of the
 *             period (coast or brake) is not told to the motor model.
 *   encoders  the wheel angles -> quadrature edges on the timer in
 *             encoder mode (stm32f1_tim_encoder; the robot file's
 *             encoder_ppr edges per motor turn, the board's ch1_leads
 *             sign), updated ARMBOARD_SLICES times a physics step
 *   IR        ADC channel voltages (the robot file's [ir.*] adc_channel)
 *             from world/analog.h with the emitters as their GPIOs are at
 *             the sample's cycle; the battery through the board's divider
 *   gyro      an MPU-6500 on its SPI, chip select by its GPIO, z rate from
 *             the world's yaw rate
 *   buttons   GPIO inputs driven to pressed_level while held
 *   LEDs      GPIO outputs followed (changes counted)
 *   console   the [console] USART's bytes kept (and echoed live)
 *   flash     kept in a file across runs (--flash FILE)
 *
 * Time: simulated picoseconds; each step runs the core to the step's end
 * time, so the same image and inputs give the same run. */
#ifndef ARMBOARD_H
#define ARMBOARD_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "arm/stm32board.h"
#include "arm/stm32f1_soc.h"
#include "io/console.h"
#include "world/sim.h"

#define ARMBOARD_CONSOLE_MAX CONSOLE_KEEP /* bytes of console output kept (the rest counted; io/console.h) */
/* Encoder updates per physics step. Each is a stop of the core at a time,
 * most often inside a translated block (a split), and unicorn 2.0.1 keeps
 * every dropped translation until its code buffer (1 GiB) fills: measured
 * on bulebule (busy loops, 2 kHz physics) 3.2 MB of RSS per simulated
 * second with 1, 11 MB with 4. At 1 the edges of a step land at its end
 * (0.5 ms); the firmware reads the counters at 1 kHz. */
#define ARMBOARD_SLICES 1

typedef struct {
    uint64_t cycles;
    uint64_t console_bytes, console_dropped;
    uint32_t led_changes[STM32BOARD_LEDS_MAX];
    uint64_t adc_samples[18];           /* per ADC channel (both ADCs) */
    double duty_min[2], duty_max[2];    /* signed bridge duty per motor, -1..1 */
    uint64_t encoder_edges[2];
} armboard_stats_t;

typedef struct armboard armboard_t;

#define ARMBOARD_VERBOSE 1u /* flags: the chip's notes on stderr (registers no model implements ...) */
#define ARMBOARD_NO_SKIP 2u /* flags: armcore_cfg_t.no_idle_skip: WFI slept and wait loops run cycle by cycle */

/* The image on the board described by spec, driving s. flash_path: the
 * flash kept in that file (NULL: erased at power-on); flags: ARMBOARD_*.
 * NULL with one line in err (an image not for the board's MCU, IR sensors
 * that do not fit). */
armboard_t *armboard_open(const stm32board_spec_t *spec, const char *image, const char *flash_path, sim_state_t *s,
                          double step_s, unsigned flags, char *err, size_t errn);
/* --gdb: the core run under the gdb stub (armgdb.h) on 127.0.0.1:port from
 * now on, halted at its first instruction until gdb continues. 0, or -1
 * with the reason in err ("cannot listen on 127.0.0.1:PORT: REASON"). */
int armboard_gdb(armboard_t *b, unsigned port, char *err, size_t errn);
/* One physics step (after sim_step): the core to the step's end, then the
 * motor commands into s->cmd. 0, or -1 if the firmware crashed. */
int armboard_step(armboard_t *b);
/* At the end: a waiting gdb told the run ended, the flash file saved (if given and changed). 0, or -1 with one line in err. */
int armboard_end(armboard_t *b, char *err, size_t errn);
void armboard_close(armboard_t *b);

/* A person's hands: button i (-1: every button) held or released. */
void armboard_button(armboard_t *b, int i, int down);
/* Text typed on the console's USART (its receive queue, one frame apart). 0, or -1 if it lacks a console or the queue is full. */
int armboard_send(armboard_t *b, const char *text);
/* Everything the console received (NUL-terminated) and its length. */
const char *armboard_console(const armboard_t *b, size_t *len);
/* The console as a stream: its live tail and the text --end-on looks for (io/console.h). */
console_t *armboard_console_stream(armboard_t *b);
void armboard_set_echo(armboard_t *b, FILE *f);
const armboard_stats_t *armboard_stats(const armboard_t *b);
stm32f1_soc_t *armboard_soc(armboard_t *b);
const armimage_mcu_t *armboard_mcu(const armboard_t *b); /* the image's MCU (its SRAM for --watch) */
const stm32board_spec_t *armboard_spec(const armboard_t *b);

#endif
