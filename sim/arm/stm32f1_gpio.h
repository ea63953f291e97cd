/* stm32f1_gpio.h - an STM32F1 GPIO port (A-E on the F103): CRL, CRH, IDR,
 * ODR, BSRR, BRR, LCKR (RM0008 9.1 functional description, 9.2
 * registers), one struct per port.
 *
 * The board sees the pins: stm32f1_gpio_drive sets what the outside world
 * drives on a pin (a button, a sensor's output, nothing), stm32f1_gpio_pin
 * reads a pin as the MCU drives it (mode, level), and on_change tells a
 * board part (an LED, an emitter) each time a pin's level changes. A pin's
 * level (RM0008 9.1, figures 13-16):
 *   output push-pull         ODR (alternate function: the peripheral's level)
 *   output open-drain        0 if ODR (or the AF level) is 0, else as an input
 *   input pull-up/down       the outside's drive, else the pull (ODR: 1 up, 0 down)
 *   input floating           the outside's drive, else 0 (an undriven pin
 *                            floats; we read it low)
 *   input analog             the outside's drive; IDR reads 0 (Schmitt trigger off)
 * IDR reads the levels in every mode but analog. Each change of IDR
 * reaches EXTI (stm32f1_exti_pin): an analog pin never triggers it. An alternate function's output level is set by
 * whoever models that peripheral's pin (stm32f1_gpio_af_level). The JTAG
 * pins' reset state (PA13-15, PB3-4 in JTAG mode with pulls) is not
 * modeled: they start as the other pins do. */
#ifndef STM32F1_GPIO_H
#define STM32F1_GPIO_H

#include <stdint.h>

#include "arm/mmio.h"
#include "arm/stm32f1_exti.h"

#define STM32F1_GPIO_PORTS 5 /* A-E (the F103 in 48-100 pin packages) */

typedef enum { STM32F1_DRIVE_FLOAT = -1, STM32F1_DRIVE_LOW = 0, STM32F1_DRIVE_HIGH = 1 } stm32f1_drive_t;

/* A pin as the MCU drives it. */
typedef struct {
    int output;     /* 1: an output mode (MODE != 00) */
    int af;         /* 1: an alternate function output */
    int open_drain; /* 1: open-drain output */
    int analog;     /* 1: analog input */
    int level;      /* the pin's level now (0/1) */
    int driven;     /* 1: the MCU drives the level (push-pull, or open-drain low) */
} stm32f1_pin_t;

typedef void (*stm32f1_pin_cb)(void *ctx, unsigned port, unsigned pin, int level);

typedef struct {
    unsigned port;                 /* 0 = A */
    uint32_t crl, crh, odr;
    uint32_t lckr;                 /* LCK[15:0] and LCKK (bit 16) */
    int lck_step;                  /* the lock key sequence's progress (RM0008 9.2.7) */
    int8_t ext[16];                /* the outside's drive per pin */
    uint8_t af_level[16];          /* the alternate function's output level per pin */
    uint16_t level;                /* the pins' levels as last computed */
    uint16_t idr_seen;             /* the input data (IDR) as last computed: what EXTI sees */
    stm32f1_exti_t *exti;          /* NULL: none */
    stm32f1_pin_cb on_change;      /* NULL: none */
    void *ctx;
} stm32f1_gpio_t;

/* each port's table, by port (0 = GPIOA): the same model under its name */
extern const mmio_ops_t stm32f1_gpio_ops[STM32F1_GPIO_PORTS];

/* Power-on: every pin a floating input, undriven. exti may be NULL. */
void stm32f1_gpio_init(stm32f1_gpio_t *g, unsigned port, stm32f1_exti_t *exti);
/* Call cb(ctx, port, pin, level) on each pin level change. */
void stm32f1_gpio_on_change(stm32f1_gpio_t *g, stm32f1_pin_cb cb, void *ctx);
/* What the outside drives on pin. */
void stm32f1_gpio_drive(stm32f1_gpio_t *g, unsigned pin, stm32f1_drive_t d);
/* A peripheral's alternate-function output level on pin. */
void stm32f1_gpio_af_level(stm32f1_gpio_t *g, unsigned pin, int level);
/* The pin as the MCU drives it now. */
stm32f1_pin_t stm32f1_gpio_pin(const stm32f1_gpio_t *g, unsigned pin);

#endif
