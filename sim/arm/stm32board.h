/* stm32board.h - an STM32F1 board described in a file (boards/NAME.ini
 * whose [board] mcu names an STM32: boards/bulebule.ini has every key with
 * its source, docs/BOARDS.md says how to write one): the MCU and its
 * crystal, and which pin and timer channel of the MCU each part of the
 * robot hangs on. Read by stm32board_load (stm32board_file.c) through the
 * INI path the config, robot and AVR board files share (world/inifile.h,
 * world/keytab.h); every check against the MCU (a pin its package has, a
 * timer channel on a pin the AFIO remaps allow, no pin twice) is done
 * there, so the board that runs the image trusts the spec. */
#ifndef STM32BOARD_H
#define STM32BOARD_H

#include <stddef.h>
#include <stdint.h>

#include "world/sim.h"

#define STM32BOARD_MAX_BYTES (64u << 10) /* bytes of a board file */
#define STM32BOARD_LEDS_MAX 4
#define STM32BOARD_BUTTONS_MAX 4
#define STM32BOARD_NAME_MAX 16           /* a [led.NAME] etc. name, with its NUL */

/* A pin: port 'A'..'E' (0: none) and bit 0..15. */
typedef struct {
    char port;
    uint8_t bit;
} stm32_pin_t;

/* A timer's capture/compare channel: TIM1..TIM4 (timer 0: none), CH1..CH4. */
typedef struct {
    uint8_t timer, channel;
} stm32_tch_t;

typedef enum { STM32_DRIVER_DRV8833 = 0 } stm32_driver_t; /* two inputs per bridge (IN1/IN2), each a PWM */
typedef enum { STM32_GYRO_MPU6500 = 0 } stm32_gyro_t;

/* An H-bridge of the motor driver ([motor.left] / [motor.right]). */
typedef struct {
    int driver;            /* stm32_driver_t */
    stm32_tch_t in[2];     /* IN1, IN2: the timer channels driving them */
    stm32_pin_t in_pin[2];
    int forward_in;        /* 0: IN1 high and IN2 low turn the wheel forward; 1: IN2 high and IN1 low */
} stm32_motor_t;

/* A quadrature encoder on a timer's TI1/TI2 ([encoder.left] / [encoder.right]). */
typedef struct {
    stm32_tch_t a, b;      /* channel A's and B's timer inputs: one timer, CH1 and CH2 */
    stm32_pin_t a_pin, b_pin;
    int a_leads;           /* 1: A leads B when the wheel turns forward */
    int ch1_leads;         /* derived: 1 if the input on CH1 (TI1) leads forward: the sign of
                              stm32f1_tim_encoder's edges for a forward turn (+1), else -1 */
} stm32_encoder_t;

/* A part on one GPIO: an emitter group, an LED, a button. */
typedef struct {
    char name[STM32BOARD_NAME_MAX];
    int line;              /* its section's line */
    stm32_pin_t pin;
    int group;             /* an emitter's: the robot file's [ir.*] emitter */
    int level;             /* an LED's on_level / a button's pressed_level (0/1) */
} stm32_gpio_part_t;

typedef struct stm32board_spec_s {
    char path[256];
    char name[64];
    char mcu[32];              /* "stm32f103c8" */
    char default_robot[64];    /* robots/NAME.ini without --robot ("": none) */
    /* the MCU's, from its name (stm32board_file.c's table, with its datasheet) */
    uint32_t flash_bytes, sram_bytes;
    char package;              /* 'C' 48, 'R' 64, 'V' 100 pins */
    int adc_channels;          /* ADC12_IN0..n-1 on pins */
    uint32_t hse_hz;           /* the crystal */
    double vdda_v;             /* VDDA = VREF+: the ADC's full scale */
    stm32_motor_t motor[2];    /* WORLD_LEFT, WORLD_RIGHT */
    stm32_encoder_t enc[2];
    int nemitters, nleds, nbuttons;
    stm32_gpio_part_t emitter[SIM_EMITTER_GROUPS], led[STM32BOARD_LEDS_MAX], button[STM32BOARD_BUTTONS_MAX];
    /* [speaker] (optional: timer 0 = none) */
    stm32_tch_t speaker;
    stm32_pin_t speaker_pin;
    /* [gyro] (optional: gyro_spi 0 = none) */
    int gyro_chip;             /* stm32_gyro_t */
    int gyro_spi;              /* 1: SPI1, 2: SPI2 */
    int gyro_spi_remap;        /* SPI1 only: 1 if remapped to PB3-PB5 */
    stm32_pin_t gyro_cs_pin;   /* a GPIO the firmware drives (software NSS) */
    stm32_pin_t gyro_sck_pin, gyro_miso_pin, gyro_mosi_pin; /* derived from the SPI and its remap */
    /* [console] (optional: console_usart 0 = none) */
    int console_usart;         /* 1..3 */
    stm32_pin_t console_tx_pin, console_rx_pin;
    /* [battery]: the battery through its divider on an ADC channel */
    int bat_channel;
    stm32_pin_t bat_pin;       /* derived: the channel's pin */
    double bat_r_top_ohm, bat_r_bottom_ohm, bat_diode_drop_v;
} stm32board_spec_t;

/* What a board file's [board] mcu names. */
typedef enum { BOARDFILE_UNKNOWN = -1, BOARDFILE_AVR = 0, BOARDFILE_STM32 = 1 } boardfile_family_t;

/* The family of the board file at path by its [board] mcu key alone
 * ("atmega..." AVR, "stm32..." STM32): which loader reads it (board_load or
 * stm32board_load). BOARDFILE_UNKNOWN with one line in err: unreadable, no
 * [board] mcu, or neither. */
boardfile_family_t boardfile_family(const char *path, char *err, size_t errn);

/* Read an STM32 board file. 0, or -1 with one line "FILE:LINE:
 * section.key: reason" (or "FILE: section.key: missing (no [section]
 * section)") in err. */
int stm32board_load(stm32board_spec_t *spec, const char *path, char *err, size_t errn);

/* 0 if the robot's IR sensors fit the board: each [ir.*] emitter group lit
 * by an [emitter.*], each emitter lighting a sensor, each sensor's
 * adc_channel on a pin of this MCU that no board part uses. Else -1 with
 * one line in err ("ROBOT:LINE: ir.NAME.key: ..." or "BOARD:LINE: ..."). */
int stm32board_fits_robot(const stm32board_spec_t *spec, const simcfg_t *c, char *err, size_t errn);

/* The pin of ADC12_INch on the spec's package (port 0 if none). */
stm32_pin_t stm32board_adc_pin(const stm32board_spec_t *spec, int ch);

#endif
