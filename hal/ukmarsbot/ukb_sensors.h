/* ukb_sensors.h - the ADC: wall sensors with their emitters pulsed, the
 * battery (A7), the function switches and button (A6). hal_ir_*,
 * hal_emitter, hal_battery_mv, hal_distance and hal_gyro_* (hal.h) are
 * here. */
#ifndef UKB_SENSORS_H
#define UKB_SENSORS_H

#include <stdint.h>

#define UKB_BUTTON 16 /* ukb_switches(): the button is pressed */

void ukb_sensors_init(void);
/* One pass of the schedule (README.md): every systick, interrupts enabled. */
void ukb_sensors_sample(void);
/* the detector's last dark and lit ADC readings (0..1023) */
uint16_t ukb_ir_dark(uint8_t sensor);
uint16_t ukb_ir_lit(uint8_t sensor);
/* the DIP switches 0..15 (bit 0 = switch 1), UKB_BUTTON, or 255 if the
 * reading fits no setting */
uint8_t ukb_switches(void);
/* the last raw A6 reading */
uint16_t ukb_switch_adc(void);

#endif
