/* ukb_sensors.c - the ADC's fixed schedule, run from the systick.
 *
 * Each pass, with the emitters off: each wall sensor's detector converted
 * (dark); the enabled emitter groups switched on; one conversion thrown
 * away while the detectors respond; each detector converted again (lit);
 * the emitters off; then the battery (A7) and the switch ladder (A6).
 * hal_ir_raw is lit minus dark (0 if the ambient light changed between
 * them the other way). Conversions are blocking (ADSC polled) at an ADC
 * clock of 16 MHz / 32 = 500 kHz (mazerunner-core adc.h converter_init
 * runs the same: "about 30us" a conversion), 13 ADC clocks = 26 us each;
 * the pass takes 11 of them with the advanced board (README.md has the
 * timeline). The systick runs this with interrupts enabled, so the
 * encoders and the UART are served meanwhile. */
#include "ukb_sensors.h"

#include <avr/io.h>
#include <avr/pgmspace.h>
#include <util/atomic.h>

#include "hal.h"
#include "ukb_board.h"

static const uint8_t ir_channel[UKB_IR_COUNT] PROGMEM = UKB_IR_CHANNELS;
static const uint8_t ir_group[UKB_IR_COUNT] = UKB_IR_GROUPS;
static const uint8_t group_bits[HAL_EMITTER_GROUPS] PROGMEM = UKB_GROUP_BITS;
static const uint16_t switch_level[17] PROGMEM = UKB_SWITCH_LEVELS;

static volatile uint16_t dark[UKB_IR_COUNT], lit[UKB_IR_COUNT];
static volatile uint8_t ir_seq;
static volatile uint16_t battery_adc4; /* four times A7, filtered (below) */
static volatile uint16_t switch_adc;
static uint8_t enabled_bits; /* PORTB bits of the emitter groups switched on */

void ukb_sensors_init(void)
{
    DDRB |= _BV(UKB_EMITTER_A_BIT) | _BV(UKB_EMITTER_B_BIT);
    PORTB &= (uint8_t)~(_BV(UKB_EMITTER_A_BIT) | _BV(UKB_EMITTER_B_BIT));
    ADMUX = _BV(REFS0);                              /* AVCC reference (ukb_board.h) */
    ADCSRA = _BV(ADEN) | _BV(ADPS2) | _BV(ADPS0);   /* enabled, clock / 32 */
    ADCSRB = 0;
    DIDR0 = 0x0f; /* A0-A3: analogue only (their digital input buffers off) */
}

static uint16_t convert(uint8_t channel)
{
    ADMUX = (uint8_t)(_BV(REFS0) | (channel & 0x0f));
    ADCSRA |= _BV(ADSC);
    while (ADCSRA & _BV(ADSC)) {}
    return ADC;
}

void ukb_sensors_sample(void)
{
    uint16_t d[UKB_IR_COUNT], l[UKB_IR_COUNT];
    for (uint8_t i = 0; i < UKB_IR_COUNT; i++) d[i] = convert(pgm_read_byte(&ir_channel[i]));
    PORTB |= enabled_bits;
    (void)convert(pgm_read_byte(&ir_channel[0])); /* the detectors settle: one conversion, 26 us */
    for (uint8_t i = 0; i < UKB_IR_COUNT; i++) l[i] = convert(pgm_read_byte(&ir_channel[i]));
    PORTB &= (uint8_t)~(_BV(UKB_EMITTER_A_BIT) | _BV(UKB_EMITTER_B_BIT));
    uint16_t bat = convert(UKB_BATTERY_CHANNEL), sw = convert(UKB_SWITCH_CHANNEL);
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
        for (uint8_t i = 0; i < UKB_IR_COUNT; i++) {
            dark[i] = d[i];
            lit[i] = l[i];
        }
        ir_seq++;
        /* first-order filter, time constant 4 passes (16 ms at 250 Hz):
         * the divider's ADC noise out, a load step still followed */
        battery_adc4 = battery_adc4 ? (uint16_t)(battery_adc4 - battery_adc4 / 4 + bat) : (uint16_t)(4 * bat);
        switch_adc = sw;
    }
}

uint8_t hal_ir_count(void) { return UKB_IR_COUNT; }

void hal_emitter(uint8_t group, uint8_t on)
{
    if (group >= HAL_EMITTER_GROUPS) return;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
        if (on) enabled_bits |= pgm_read_byte(&group_bits[group]);
        else enabled_bits &= (uint8_t)~pgm_read_byte(&group_bits[group]);
    }
}

uint16_t ukb_ir_dark(uint8_t s)
{
    uint16_t v = 0;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { if (s < UKB_IR_COUNT) v = dark[s]; }
    return v;
}

uint16_t ukb_ir_lit(uint8_t s)
{
    uint16_t v = 0;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { if (s < UKB_IR_COUNT) v = lit[s]; }
    return v;
}

uint16_t hal_ir_raw(uint8_t s)
{
    uint16_t v = 0;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
        if (s < UKB_IR_COUNT && lit[s] > dark[s]) v = (uint16_t)(lit[s] - dark[s]);
    }
    (void)ir_group; /* the groups are lit together (README.md) */
    return v;
}

uint8_t hal_ir_seq(void) { return ir_seq; }

uint16_t hal_battery_mv(void)
{
    uint16_t a4;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { a4 = battery_adc4; }
    /* at the pin, mV = ADC x 5000 / 1023 (to 1 mV); the battery is (R7 + R8) / R8 of that */
    uint32_t pin_mv = (uint32_t)a4 * UKB_ADC_REF_MV / (4UL * UKB_ADC_FULL_SCALE);
    return (uint16_t)(pin_mv * (UKB_BATTERY_R_TOP_OHM + UKB_BATTERY_R_BOTTOM_OHM) / UKB_BATTERY_R_BOTTOM_OHM);
}

uint16_t ukb_switch_adc(void)
{
    uint16_t v;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { v = switch_adc; }
    return v;
}

uint8_t ukb_switches(void)
{
    uint16_t a = ukb_switch_adc();
    if (a > UKB_BUTTON_ADC) return UKB_BUTTON;
    for (uint8_t n = 0; n < 16; n++) {
        uint16_t mid = (uint16_t)((pgm_read_word(&switch_level[n]) + pgm_read_word(&switch_level[n + 1])) / 2);
        if (a > mid) return n;
    }
    return 255;
}

/* UKMARSBOT has no ToF sensors: no reading ever arrives (seq stays 0) */
hal_distance_t hal_distance(uint8_t sensor)
{
    (void)sensor;
    hal_distance_t d = { 0, 1, 0 };
    return d;
}

uint8_t hal_gyro_present(void) { return 0; } /* no IMU on the V1.3 mainboard (PINOUTS l.126-128: an add-on) */
int32_t hal_gyro_mdps(void) { return 0; }
