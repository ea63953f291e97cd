/* board.h - a whole board emulated at the pin and register level: an AVR
 * image (ELF or Intel HEX) runs in simavr, in lockstep with the physics,
 * with the board's parts wired to the core through simavr's IRQs as a
 * board file (boards/NAME.ini, board_load) describes them. Each part keeps
 * its own state; board.c connects them:
 *
 *   avrhost.c        the core: image read and checked, simavr quiet and
 *                    never sleeping the host, UART0's queues (shared with
 *                    --avr, pil.c)
 *   board_motor.c    H-bridge: direction pins (port IRQs) and Timer1's
 *                    PWM (mode, TOP, OCR1A/B, COM bits) -> sim_state_t.cmd[]
 *   board_encoder.c  quadrature edges from the wheel angle, each at its
 *                    cycle inside the step: A xor B on the interrupt pin,
 *                    B on its own pin
 *   board_adc.c      analogue front end: at each conversion's start the
 *                    channel's voltage (IR detector with the emitters as
 *                    the pins are then, switch ladder, battery divider)
 *   board_switch.c   DIP switches and button on the ladder
 *   board_led.c      LEDs and emitter pins followed by their pin IRQs
 *   board_console.c  UART0's output kept as the console (and echoed live)
 *   board_eeprom.c   the EEPROM kept in a file across runs (--eeprom)
 *   board.c          the core's step: exactly f_cpu x step cycles; counts
 *                    each interrupt vector's services
 *
 * Time is cycles: no wall clock, the same image and inputs give the same
 * run. Power-on SRAM is zero (simavr's calloc); board_reset keeps SRAM as a
 * real reset does (a .noinit variable survives it). */
#ifndef BOARD_H
#define BOARD_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "board/avrhost.h"
#include "io/console.h"
#include "world/sim.h"

#define BOARD_ADC_CHANNELS 8
#define BOARD_LEDS_MAX 4
#define BOARD_VECTORS_MAX 64      /* interrupt vectors counted */
#define BOARD_CONSOLE_MAX CONSOLE_KEEP /* bytes of UART output kept (the rest counted; io/console.h) */
#define BOARD_IN_MAX 4096u        /* bytes waiting for the UART's receive FIFO */
#define BOARD_MAX_BYTES (64u << 10) /* bytes of a board file */

/* A pin of the MCU: port letter 'B'/'C'/'D' (0: none) and bit 0..7. */
typedef struct {
    char port;
    uint8_t bit;
} board_pin_t;

/* What an ADC pin with no other part is wired to ([analog] a4/a5): open
 * (wired 0, the file's `open`: board_adc.c's model of a floating input) or
 * a fixed voltage v (V). */
typedef struct {
    int wired;
    double v;
} board_analog_t;
#define BOARD_ANALOG_FIRST 4 /* [analog] names ADC channels 4 (a4) and 5 (a5): PC4/PC5 of the ATmega328P */
#define BOARD_ANALOG_N 2

/* The board file (see boards/ukmarsbot-v1.3.ini for every key and source). */
typedef struct board_spec_s {
    char path[256];
    char name[64];
    char mcu[32];
    char default_robot[64];       /* the robot a run on this board uses without --robot: robots/NAME.ini ("": none) */
    char mainboard[128];          /* the mainboard's parts file, relative to the board file's folder ("": none) */
    uint32_t f_cpu;               /* Hz */
    double vcc_v;                 /* VCC = AVCC = AREF, V */
    /* motor driver, [motor.left] / [motor.right] (WORLD_LEFT, WORLD_RIGHT) */
    board_pin_t motor_dir[2], motor_pwm[2];
    int motor_oc[2];              /* the PWM pin's Timer1 output: 0 = OC1A, 1 = OC1B */
    int motor_fwd_level[2];       /* the direction pin's level that turns the wheel forward */
    /* encoders, [encoder.left] / [encoder.right] */
    board_pin_t enc_int[2];       /* A xor B: the external-interrupt pin */
    board_pin_t enc_b[2];         /* channel B */
    int enc_a_leads[2];           /* 1: A leads B when the wheel turns forward */
    /* emitters, [emitter.NAME]: the pin that lights sim emitter group g */
    int nemitters;
    board_pin_t emitter_pin[SIM_EMITTER_GROUPS];
    int emitter_group[SIM_EMITTER_GROUPS];
    char emitter_name[SIM_EMITTER_GROUPS][16]; /* [emitter.NAME] */
    int emitter_line[SIM_EMITTER_GROUPS];      /* its section's line */
    /* LEDs, [led.NAME] */
    int nleds;
    board_pin_t led_pin[BOARD_LEDS_MAX];
    char led_name[BOARD_LEDS_MAX][16];
    /* switches and button on a resistor ladder, [switches] */
    int sw_channel;
    double sw_r_top_ohm;          /* VCC to the ADC pin */
    double sw_r_ohm[4];           /* to ground in series, switch bit k shorts sw_r_ohm[k] */
    double sw_r_ground_ohm;       /* what stays in series when every switch is closed */
    /* the battery through its divider, [battery] */
    int bat_channel;
    double bat_r_top_ohm, bat_r_bottom_ohm;
    double bat_diode_drop_v;  /* V: a series (reverse-polarity) diode between the battery and the divider */
    /* A4/A5 when no IR sensor of the robot is on them, [analog] (optional: open) */
    board_analog_t analog[BOARD_ANALOG_N];
} board_spec_t;

/* What the board saw during the run (the JSON's "board"). */
typedef struct {
    uint64_t cycles;
    uint32_t led_changes[BOARD_LEDS_MAX];
    uint64_t interrupts[BOARD_VECTORS_MAX]; /* serviced, per vector number */
    uint64_t adc_conversions[BOARD_ADC_CHANNELS];
    double duty_min[2], duty_max[2];       /* signed H-bridge duty per motor, -1..1 */
    uint64_t encoder_edges[2];
    uint64_t uart_bytes_out, uart_bytes_in;
    uint64_t uart_bytes_dropped;           /* typed before the firmware enabled its receiver: lost */
    uint64_t console_dropped;              /* sent after the console held BOARD_CONSOLE_MAX bytes: not kept */
    uint32_t resets;
} board_stats_t;

typedef struct board_s board_t;

/* NAME (boards/NAME.ini, the file's own name; else boards/NAME-VERSION.ini,
 * VERSION without '-': the first in sorted order) or a path into out.
 * 0, or -1 with one line in err naming the boards there. */
int board_find(const char *name, char *out, size_t outn, char *err, size_t errn);
/* Read a board file. 0, or -1 with one line "FILE:LINE: section.key:
 * reason" (or "FILE: section.key: missing") in err. */
int board_load(board_spec_t *spec, const char *path, char *err, size_t errn);
/* 0 if the board's emitters and the robot's IR sensors match: each [ir.*]
 * emitter group lit by an emitter pin, each emitter's group lighting a
 * sensor of the robot. Else -1 with one line in err ("BOARD:LINE:
 * emitter.NAME.group ..." or "ROBOT:LINE: ir.NAME.emitter ..."). */
int board_fits_robot(const board_spec_t *spec, const simcfg_t *c, char *err, size_t errn);
/* The vector name of the spec's MCU ("INT0", "ADC", ...; NULL: unnamed). */
const char *board_vector_name(const board_t *b, unsigned vector);

/* The image (ELF, or Intel HEX by its .hex name) on the board, driving s
 * (its motors, read from its wheels, IR sensors and battery). step_s: the
 * physics step. NULL with one line in err: an unreadable image, one for
 * another MCU, a robot whose IR channel the board lacks, a board whose
 * emitters and the robot's IR sensors do not match (board_fits_robot). */
board_t *board_open(const board_spec_t *spec, const char *image, sim_state_t *s, char *err, size_t errn);
/* One physics step of AVR time (call after sim_step): encoder edges at
 * their cycles, ADC conversions as the firmware starts them, then the
 * motor commands into s->cmd. 0, or -1 with the reason in err (the AVR
 * crashed or halted, an ADC auto-trigger simavr lacks). */
int board_step(board_t *b, char *err, size_t errn);
/* Stop the AVR (simavr cannot free a core: b stays allocated, its stats
 * and console readable; keep the pointer until the process ends). */
void board_close(board_t *b);

/* A person's hands (take effect at once, between steps). */
void board_set_switches(board_t *b, unsigned n); /* DIP switches 0..15 */
void board_button(board_t *b, int down);
void board_reset(board_t *b);                     /* the reset button: SRAM kept */
/* What a person sees on the board and set on it now (the viewer's panel). */
typedef struct {
    unsigned switches;              /* 0..15 */
    int button;                     /* 1: held down */
    int nleds;
    int led[BOARD_LEDS_MAX];        /* 1: lit (its pin high) */
    const char *led_name[BOARD_LEDS_MAX]; /* the board file's [led.NAME] */
} board_panel_t;
void board_panel(const board_t *b, board_panel_t *out);
/* Type text on UART0 (no newline added). 0, or -1 if the input queue is full. */
int board_send(board_t *b, const char *text);

/* Everything the firmware printed so far (NUL-terminated) and its length. */
const char *board_console(const board_t *b, size_t *len);
/* The console as a stream: its live tail and the text --end-on looks for (io/console.h). */
console_t *board_console_stream(board_t *b);
/* Echo UART output to f as it comes (NULL: off), for --verbose. */
void board_set_echo(board_t *b, FILE *f);
/* Keep the MCU's EEPROM in the file at path (board_eeprom.h): loaded now
 * (call right after board_open: power-on), saved by board_eeprom_end.
 * 0, or -1 with one line in err (a file of the wrong size, not writable). */
int board_eeprom_keep(board_t *b, const char *path, char *err, size_t errn);
/* At the end of the run: *written 1 if the firmware wrote the EEPROM,
 * *changed 1 if its contents differ from power-on; then the file saved
 * (if board_eeprom_keep gave one). 0, or -1 with one line in err. */
int board_eeprom_end(board_t *b, int *written, int *changed, char *err, size_t errn);
const board_stats_t *board_stats(const board_t *b);
/* The board file it was opened with (board_open's copy: resolved once). */
const board_spec_t *board_spec(const board_t *b);
/* The AVR core (read only): its crash (h->crash) and watchdog resets. */
const avrhost_t *board_host(const board_t *b);
/* --gdb: simavr's gdb stub on 127.0.0.1:port, the firmware halted until
 * gdb continues (avrhost_gdb). 0, or -1 with the reason in err. */
int board_gdb(board_t *b, unsigned port, char *err, size_t errn);
/* The A6-style ladder's voltage for switches n and the button, V. */
double board_switch_volts(const board_spec_t *spec, unsigned n, int button);

#endif
