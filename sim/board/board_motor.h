/* board_motor.h - the motor driver part (a TB6612FNG on UKMARSBOT): each
 * motor's PWM input is a Timer1 output (OC1A or OC1B), its direction a
 * plain pin; the H-bridge applies the PWM's duty of the battery, its sign
 * from the direction pin. */
#ifndef BOARD_MOTOR_H
#define BOARD_MOTOR_H

#include <stddef.h>
#include <stdint.h>

#include "board.h"

struct avr_t;
struct avr_timer_t;

#define BOARD_PORTS 3 /* ports B, C, D of the ATmega48/88/168/328 */

typedef struct {
    struct avr_t *avr;
    const struct avr_timer_t *timer1;
    board_pin_t dir[2], pwm[2];   /* per motor (WORLD_LEFT, WORLD_RIGHT) */
    int oc[2];                    /* the PWM pin's Timer1 output: 0 = OC1A, 1 = OC1B */
    int fwd_level[2];             /* the direction pin's level that turns the wheel forward */
    struct {
        uint8_t ddr, port;        /* DDRx and PORTx as their IRQs last told them */
    } ports[BOARD_PORTS];
    board_stats_t *st;            /* duty_min, duty_max */
} board_motor_t;

/* Wire the part to avr's ports and Timer1 as spec says. 0, or -1 with one
 * line in err (the MCU has no Timer1 in simavr). */
int board_motor_init(board_motor_t *m, struct avr_t *avr, const board_spec_t *spec, board_stats_t *st, char *err, size_t errn);
/* The signed duty of motor i (-1..1) now. */
double board_motor_duty(const board_motor_t *m, int i);
/* Both motors' duty now -> cmd[] (+-1023 full scale), and the duty's range. */
void board_motor_step(board_motor_t *m, int cmd[2]);

#endif
