/* ukb_motors.c - Timer1 in phase-correct 9-bit PWM (WGM1 = 2, TOP 511)
 * with no prescaler: 16 MHz / (2 x 511) = 15.66 kHz, above hearing and
 * within the TB6612FNG's 100 kHz PWM input (Toshiba datasheet). OC1A (D9)
 * drives the left motor's PWMA, OC1B (D10) the right's PWMB; a duty of 0
 * holds the output low in this mode (no glitch), so a stopped motor is
 * off. Direction pins as ukb_board.h. */
#include "ukb_motors.h"

#include <avr/io.h>
#include <util/atomic.h>

#include "hal.h"
#include "ukb_board.h"
#include "ukb_sensors.h"

#define UKB_PWM_TOP 511U /* Timer1 TOP in mode 2 */

void ukb_motors_init(void)
{
    UKB_LDIR_DDR |= _BV(UKB_LDIR_BIT);
    UKB_RDIR_DDR |= _BV(UKB_RDIR_BIT);
    DDRB |= _BV(UKB_LPWM_BIT) | _BV(UKB_RPWM_BIT);
    OCR1A = 0;
    OCR1B = 0;
    /* COM1A1/COM1B1: clear on up-count match (non-inverting); WGM11: mode 2; CS10: clk/1 */
    TCCR1A = _BV(COM1A1) | _BV(COM1B1) | _BV(WGM11);
    TCCR1B = _BV(CS10);
}

/* |command| 0..1023 -> duty 0..UKB_PWM_TOP for the battery as it is */
static uint16_t duty_of(uint16_t mag)
{
    uint32_t d = (uint32_t)mag * UKB_PWM_TOP;
    uint16_t bat_mv = hal_battery_mv();
    if (UKB_MOTOR_REF_MV && bat_mv >= UKB_MOTOR_MIN_BATTERY_MV)
        d = d * UKB_MOTOR_REF_MV / bat_mv; /* the reference voltage's share of the battery */
    d /= 1023U;
    return d > UKB_PWM_TOP ? UKB_PWM_TOP : (uint16_t)d;
}

void hal_motor_set(int16_t left, int16_t right)
{
    uint16_t ml = (uint16_t)(left < 0 ? -(int32_t)left : left), mr = (uint16_t)(right < 0 ? -(int32_t)right : right);
    if (ml > 1023) ml = 1023;
    if (mr > 1023) mr = 1023;
    uint16_t dl = duty_of(ml), dr = duty_of(mr);
    uint8_t lfwd = left >= 0, rfwd = right >= 0;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
        if (lfwd == (UKB_LEFT_FWD_LEVEL != 0)) UKB_LDIR_PORT |= _BV(UKB_LDIR_BIT);
        else UKB_LDIR_PORT &= (uint8_t)~_BV(UKB_LDIR_BIT);
        if (rfwd == (UKB_RIGHT_FWD_LEVEL != 0)) UKB_RDIR_PORT |= _BV(UKB_RDIR_BIT);
        else UKB_RDIR_PORT &= (uint8_t)~_BV(UKB_RDIR_BIT);
        OCR1A = dl;
        OCR1B = dr;
    }
}
