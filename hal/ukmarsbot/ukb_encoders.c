/* ukb_encoders.c - the wheel encoders through the board's XOR doubler.
 *
 * Each interrupt pin carries CLK = A xor B and toggles on every edge of
 * either channel (ukb_board.h), so INT0/INT1 on any change see all four
 * quadrature edges of a cycle: 36 counts per motor turn on UKMARSBOT's
 * 9-pole-pair discs (robots/ukmarsbot.ini [encoder.left] encoder_ppr).
 * In the interrupt, B is read from its pin and A recovered as CLK xor B;
 * the step from the previous (A, B) to the new one is looked up in a
 * Gray-code table: +1 where A leads B. A step that skips a state (both
 * changed: an edge missed) counts 0. */
#include "ukb_encoders.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <util/atomic.h>

#include "hal.h"
#include "ukb_board.h"

/* index (old A, old B, new A, new B) as bits 3..0: +1 for the A-leads
 * order 00 -> 10 -> 11 -> 01 -> 00, -1 for the reverse, 0 otherwise */
static const int8_t step_a_leads[16] PROGMEM = {
    0, -1, +1, 0,  /* from 00: to 01 is B first (-1), to 10 is A first (+1) */
    +1, 0, 0, -1,  /* from 01: to 00 (+1), to 11 (-1) */
    -1, 0, 0, +1,  /* from 10: to 00 (-1), to 11 (+1) */
    0, +1, -1, 0,  /* from 11: to 01 (+1), to 10 (-1) */
};

static volatile int32_t count[2];
static uint8_t state[2]; /* (A << 1) | B as last seen */

/* the wheel's (A << 1) | B from PIND */
static uint8_t ab(uint8_t pins, uint8_t clk_bit, uint8_t b_bit)
{
    uint8_t b = (uint8_t)((pins >> b_bit) & 1), a = (uint8_t)(((pins >> clk_bit) & 1) ^ b);
    return (uint8_t)((a << 1) | b);
}

void ukb_encoders_init(void)
{
    DDRD &= (uint8_t)~(_BV(UKB_LCLK_BIT) | _BV(UKB_LB_BIT) | _BV(UKB_RCLK_BIT) | _BV(UKB_RB_BIT));
    uint8_t pins = PIND;
    state[HAL_LEFT] = ab(pins, UKB_LCLK_BIT, UKB_LB_BIT);
    state[HAL_RIGHT] = ab(pins, UKB_RCLK_BIT, UKB_RB_BIT);
    EICRA = _BV(ISC00) | _BV(ISC10); /* INT0, INT1: any logical change */
    EIFR = _BV(INTF0) | _BV(INTF1);
    EIMSK = _BV(INT0) | _BV(INT1);
}

ISR(INT0_vect) /* left: forward = A leads */
{
    uint8_t s = ab(PIND, UKB_LCLK_BIT, UKB_LB_BIT);
    count[HAL_LEFT] += (int8_t)pgm_read_byte(&step_a_leads[(state[HAL_LEFT] << 2) | s]);
    state[HAL_LEFT] = s;
}

ISR(INT1_vect) /* right: forward = B leads */
{
    uint8_t s = ab(PIND, UKB_RCLK_BIT, UKB_RB_BIT);
    count[HAL_RIGHT] -= (int8_t)pgm_read_byte(&step_a_leads[(state[HAL_RIGHT] << 2) | s]);
    state[HAL_RIGHT] = s;
}

int32_t hal_encoder(uint8_t side)
{
    int32_t c;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { c = count[side & 1]; }
    return c;
}

void hal_encoder_reset(void)
{
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { count[0] = count[1] = 0; }
}
