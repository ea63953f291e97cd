/* ukb_board.h - the UKMARSBOT V1.3 mainboard on its Arduino Nano
 * (ATmega328P, 16 MHz): every pin, channel and electrical figure this
 * backend uses, each with its source. Nothing else in hal/ukmarsbot names
 * a port bit or a resistor.
 * Short names: MAIN-SCH = ukmarsbot/hardware/mainboard/version-1.3/
 * ukmarsbot-mainboard-V1.3-alpha-schematic.pdf; PINOUTS =
 * ukmarsbot/docs/arduino-pinouts.md; MRC-HW = mazerunner-core/
 * mazerunner-core/config-ukmarsbot.h; ORION = mazerunner-core/
 * mazerunner-core/config-robot-orion.h; BOARD = boards/ukmarsbot-v1.3.ini
 * (the simulator's copy of the same facts). Arduino pin Dn is PORTD bit n
 * for n < 8, PORTB bit n-8 for 8..13 (ATmega328P datasheet, Nano pinout). */
#ifndef UKB_BOARD_H
#define UKB_BOARD_H

#include <avr/io.h>

#ifndef F_CPU
#define F_CPU 16000000UL /* Hz: the Nano's crystal (BOARD [board] f_cpu_hz) */
#endif

/* ---- motors: TB6612FNG (MAIN-SCH U2), direction through the 74HC86 ---- */
/* left: LEFT_DIR on D7 (PD7), PWMA on D9 = OC1A (PB1): MAIN-SCH; MRC-HW l.23, l.25; PINOUTS l.110, l.112 */
#define UKB_LDIR_PORT PORTD
#define UKB_LDIR_DDR DDRD
#define UKB_LDIR_BIT PD7
#define UKB_LPWM_BIT PB1
/* right: RIGHT_DIR on D8 (PB0), PWMB on D10 = OC1B (PB2): MAIN-SCH; MRC-HW l.24, l.26; PINOUTS l.111, l.113 */
#define UKB_RDIR_PORT PORTB
#define UKB_RDIR_DDR DDRB
#define UKB_RDIR_BIT PB0
#define UKB_RPWM_BIT PB2
/* The motors sit back to back: forward is DIR low on the left, DIR high on
 * the right (ORION l.312-313 MOTOR_LEFT_POLARITY 1, MOTOR_RIGHT_POLARITY -1;
 * BOARD [motor.*] forward_level) */
#define UKB_LEFT_FWD_LEVEL 0
#define UKB_RIGHT_FWD_LEVEL 1

/* ---- encoders: 74HC86 "ENCODER PULSE DOUBLER" (MAIN-SCH IC1) ---- */
/* CLK = A xor B on the interrupt pin, B on its own pin (MRC-HW l.18-21):
 * left CLK D2 = INT0 (PD2), left B D4 (PD4); right CLK D3 = INT1 (PD3),
 * right B D5 (PD5). Forward: channel A leads on the left, B on the right
 * (ORION l.307-308 ENCODER_LEFT_POLARITY -1, RIGHT 1 with mazerunner-core's
 * decode; BOARD [encoder.*] forward). */
#define UKB_LCLK_BIT PD2
#define UKB_LB_BIT PD4
#define UKB_RCLK_BIT PD3
#define UKB_RB_BIT PD5

/* ---- wall sensor boards: emitters and detector ADC channels ---- */
/* ADVANCED board (default): two emitter groups; group 0 = the forward pair
 * on EMITTER_A D11 (PB3), group 1 = the diagonal pair on EMITTER_B D12
 * (PB4): ORION l.164-165, MRC-HW l.27-28, PINOUTS l.114. The sensors in
 * robots/ukmarsbot.ini's [ir.*] order (lfs, lds, rds, rfs) on A3, A2, A1,
 * A0 (ORION l.178-181; advanced schematic A3_LF, A2_LD, A1_RD, A0_RF).
 * BASIC board (-DUKB_SENSOR_BOARD_BASIC): one emitter pin for all three
 * pairs, EMITTER_B D12 (ORION l.155-157 "only one emitter pin"; BOARD
 * ukmarsbot-basic-v1.3.ini [emitter.all]); sensors in
 * robots/ukmarsbot-basic-12.ini's order (front, right, left) on A1, A0, A2
 * (that file's adc_channel keys: BASIC-SCH, OSMIUM l.136-139). */
#define UKB_EMITTER_A_BIT PB3
#define UKB_EMITTER_B_BIT PB4
#ifdef UKB_SENSOR_BOARD_BASIC
#define UKB_IR_COUNT 3
#define UKB_IR_CHANNELS { 1, 0, 2 }
#define UKB_IR_GROUPS { 0, 0, 0 }        /* emitter group of each sensor */
#define UKB_GROUP_BITS { _BV(UKB_EMITTER_B_BIT), 0, 0, 0 } /* PORTB bits of group 0..3 */
#define UKB_SENSOR_BOARD_NAME "basic"
#else
#define UKB_IR_COUNT 4
#define UKB_IR_CHANNELS { 3, 2, 1, 0 }
#define UKB_IR_GROUPS { 0, 1, 1, 0 }
#define UKB_GROUP_BITS { _BV(UKB_EMITTER_A_BIT), _BV(UKB_EMITTER_B_BIT), 0, 0 }
#define UKB_SENSOR_BOARD_NAME "advanced"
#endif

/* ---- LEDs ---- */
/* the Nano's LED on D13 (PB5): PINOUTS l.116; the user LED on USER_IO D6 (PD6): MAIN-SCH, ORION l.162 */
#define UKB_LED_BUILTIN_BIT PB5
#define UKB_LED_USER_BIT PD6

/* ---- analogue: function switches, button, battery ---- */
/* FUNCTION_SELECT on A6 (MAIN-SCH; MRC-HW l.37; ORION l.189) */
#define UKB_SWITCH_CHANNEL 6
/* The ladder's readings for switch settings 0..15 and the open end (0):
 * mazerunner-core's measured thresholds (MRC-HW l.48); a reading above the
 * midpoint between entries n and n+1 is setting n (switches.h read()). */
#define UKB_SWITCH_LEVELS { 660, 647, 630, 614, 590, 570, 545, 522, 461, 429, 385, 343, 271, 212, 128, 44, 0 }
/* the push button ties A6 to 5 V: above this ADC reading it is pressed
 * (mazerunner-core switches.h read(): > 800) */
#define UKB_BUTTON_ADC 800
/* BATTERY_VOLTS on A7 (MAIN-SCH POWER; ORION l.190): R7 15k from V_BATT,
 * R8 15k to ground (MAIN-SCH POWER), so A7 = V_BATT x 15/(15+15). V_BATT
 * is the battery after the protection diode D1, which also feeds the
 * motor driver's VM (MAIN-SCH; BOARD [battery] diode_drop_v): the voltage
 * the motors get. */
#define UKB_BATTERY_CHANNEL 7
#define UKB_BATTERY_R_TOP_OHM 15000UL
#define UKB_BATTERY_R_BOTTOM_OHM 15000UL
/* ADC reference: AVCC = the Nano's 5 V regulator (MAIN-SCH; BOARD vcc_v;
 * mazerunner-core adc.h converter_init uses AVCC) */
#define UKB_ADC_REF_MV 5000UL
#define UKB_ADC_FULL_SCALE 1023UL

#endif
