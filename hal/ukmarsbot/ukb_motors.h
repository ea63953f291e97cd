/* ukb_motors.h - the two motors: Timer1 PWM on D9/D10, direction on D7/D8,
 * the battery's voltage compensated. hal_motor_set (hal.h) is here. */
#ifndef UKB_MOTORS_H
#define UKB_MOTORS_H

/* The voltage a full-scale command (1023) stands for, mV. The firmware's
 * feed-forward counts a command step as this / 1023 (firmware/
 * robot_config.h, the robot file's [firmware]: 6 V / 1023); this backend turns it into the duty that
 * gives that voltage from the battery as it is now, so the robot drives
 * the same on a full and a tired battery. 0: no compensation (the command
 * is a fraction of the battery, as hal.h's default). */
#ifndef UKB_MOTOR_REF_MV
#define UKB_MOTOR_REF_MV 6000UL
#endif
/* Below this battery reading (mV) there is no battery to compensate for
 * (the Nano on USB only): the command is then a fraction of full duty. */
#define UKB_MOTOR_MIN_BATTERY_MV 4000U

void ukb_motors_init(void);

#endif
