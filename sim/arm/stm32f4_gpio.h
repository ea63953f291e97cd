/* stm32f4_gpio.h - an STM32F4 GPIO port at register level (RM0090 rev 19
 * section 8, RM0383 rev 3 section 8): MODER, OTYPER, OSPEEDR, PUPDR, IDR,
 * ODR, BSRR, LCKR, AFRL, AFRH. The board tells the port the level the
 * outside drives on a pin (stm32f4_gpio_input) and is told when a pin's
 * level as the port sees it changes (the callback: LEDs, emitters, chip
 * selects; EXTI through SYSCFG's routing). */
#ifndef ARM_STM32F4_GPIO_H
#define ARM_STM32F4_GPIO_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

#define STM32F4_GPIO_BASE(port) (0x40020000u + 0x400u * (port)) /* A = 0 .. I = 8 (RM0090 2.3 table 1) */
#define STM32F4_GPIO_SIZE 0x400u

/* Pin pin of port port now at level (0/1), as the port's input sees it. */
typedef void (*stm32f4_gpio_pin_fn)(void *ctx, unsigned port, unsigned pin, int level);

typedef enum { STM32F4_PIN_INPUT = 0, STM32F4_PIN_OUTPUT = 1, STM32F4_PIN_AF = 2, STM32F4_PIN_ANALOG = 3 } stm32f4_pin_mode_t;

typedef struct {
    unsigned port;                     /* 0 = A */
    uint32_t moder, otyper, ospeedr, pupdr, odr, afr[2];
    uint32_t lckr;                     /* LCKK and the locked pins */
    int lock_step;                     /* the LCKR write sequence's progress (RM0090 8.4.8) */
    uint16_t ext_level, ext_driven;    /* what the outside drives on each pin, and which pins it drives */
    uint16_t idr;                      /* the input data as last computed */
    stm32f4_gpio_pin_fn changed;
    void *ctx;
} stm32f4_gpio_t;

extern const mmio_ops_t stm32f4_gpio_ops;

/* Power-on; changed is told the pins that read 1 at reset (from 0), so an
 * EXTI fed by it starts from the ports' levels. */
void stm32f4_gpio_init(stm32f4_gpio_t *g, unsigned port, stm32f4_gpio_pin_fn changed, void *ctx);
/* The outside drives pin at level (0/1), or lets it float (driven false). */
void stm32f4_gpio_input(stm32f4_gpio_t *g, unsigned pin, bool driven, int level);
/* A pin's configured mode and alternate function (0..15). */
stm32f4_pin_mode_t stm32f4_gpio_mode(const stm32f4_gpio_t *g, unsigned pin);
unsigned stm32f4_gpio_af(const stm32f4_gpio_t *g, unsigned pin);
/* The pin's level as the port sees it (IDR's bit). */
int stm32f4_gpio_level(const stm32f4_gpio_t *g, unsigned pin);

#endif
