/* board_int.h - inside the board emulation (board.h): the state the core
 * (board.c) and its peripherals (board_motor.c, board_encoder.c,
 * board_adc.c, board_console.c) share. Not for use outside sim/board. */
#ifndef BOARD_INT_H
#define BOARD_INT_H

#include "board.h"

struct avr_t;
struct avr_irq_t;

#define BOARD_EDGES_MAX 512 /* encoder edges in one step, both wheels (~1.5 at full speed) */

typedef struct {
    uint64_t cycle; /* when, AVR cycles */
    int wheel;
    long q;         /* the edge index after it */
} board_edge_t;

struct board_s {
    board_spec_t spec;
    sim_t *sim;
    struct avr_t *avr;
    uint64_t cycles_per_step, target;
    board_stats_t st;
    /* switches and button, as a person set them */
    unsigned switches;
    int button;
    /* output levels of the pins the board listens to (emitters, LEDs) */
    int emitter_level[SIM_EMITTER_GROUPS];
    int led_level[BOARD_LEDS_MAX];
    /* encoders: the wheel's position in edges (continuous) and the edge index shown on the pins */
    double enc_per_rad[2], enc_last_rad[2], enc_pos[2];
    long enc_q[2];
    board_edge_t edges[BOARD_EDGES_MAX];
    int nedges;
    /* ADC: the IR sensor on each channel (-1: none) */
    int ir_of_channel[BOARD_ADC_CHANNELS];
    struct avr_irq_t *adc_in[BOARD_ADC_CHANNELS];
    /* UART0 */
    struct avr_irq_t *uart_in;
    int xoff;
    uint8_t in[BOARD_IN_MAX];
    size_t in_head, in_len;
    char *con;
    size_t con_len;
    FILE *echo;
    char adc_err[200]; /* an ADC mode simavr cannot emulate, seen during the step */
};

/* a pin's IRQ in simavr's ioport */
struct avr_irq_t *board_pin_irq(board_t *b, board_pin_t p);

/* board_motor.c: Timer1 and the direction pins -> sim_t.cmd */
void board_motor_step(board_t *b);
/* The signed duty of motor m (-1..1) from the registers now. */
double board_motor_duty(board_t *b, int m);

/* board_encoder.c */
void board_encoder_init(board_t *b);
/* the edges of this step (wheel angles after sim_step) into b->edges, sorted by cycle */
void board_encoder_plan(board_t *b, uint64_t start_cycle);
/* put an edge's pin levels on the pins */
void board_encoder_apply(board_t *b, const board_edge_t *e);
/* raise both wheels' current levels again (after a reset cleared the PIN registers) */
void board_encoder_restore(board_t *b);

/* board_adc.c */
int board_adc_init(board_t *b, char *err, size_t errn);
/* 0, or -1 with a line in err: the firmware chose an auto-trigger simavr lacks */
int board_adc_check(board_t *b, char *err, size_t errn);

/* board_console.c: UART0, LEDs, interrupts */
int board_console_init(board_t *b, char *err, size_t errn);
void board_console_feed(board_t *b);
void board_uart_flags(board_t *b);

#endif
