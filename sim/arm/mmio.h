/* mmio.h - the seam between the Cortex-M core (armcore.c) and the models of
 * an MCU's memory-mapped peripherals (stm32f1_*.c, and the core's own NVIC,
 * SysTick, SCB and DWT). Each peripheral owns its struct (self) and is
 * reached only through this table, as simavr's parts are reached through
 * their IRQs; the board connects them (armboard.c), never the reverse.
 *
 * Time is core clock cycles (HCLK, the clock the firmware configures through
 * RCC): nothing here reads a wall clock. A peripheral that changes on its own
 * (a timer's counter, a conversion ending, a byte shifted out) is brought to
 * cycle `now` by advance() before any access and before the core runs past
 * next_event(); so an access sees the state of the cycle it happens in,
 * whatever the core's chunking, and a run is the same at any chunk size.
 *
 * A register a model does not implement answers MMIO_UNMODELED: the bus
 * counts each such address and lists it in the run's JSON ("board".
 * "unmodeled"), and prints one line the first time with --verbose. It is
 * never silently read as 0 or dropped. */
#ifndef ARM_MMIO_H
#define ARM_MMIO_H

#include <stdbool.h>
#include <stdint.h>

#define MMIO_NEVER UINT64_MAX /* next_event(): nothing due */

typedef enum {
    MMIO_OK = 0,
    MMIO_UNMODELED,   /* a register (or a bit field's write) this model does not implement */
    MMIO_BUS_FAULT,   /* an access the hardware answers with a bus error (reserved space) */
} mmio_status_t;

/* A peripheral as the bus sees it. off: the byte offset from its base;
 * size: 1, 2 or 4 bytes (RM0008: most registers take 16/32-bit accesses). */
typedef struct {
    const char *name; /* "RCC", "TIM2", ... as the reference manual names it */
    mmio_status_t (*read)(void *self, uint32_t off, unsigned size, uint32_t *value);
    mmio_status_t (*write)(void *self, uint32_t off, unsigned size, uint32_t value);
    /* State brought to core cycle now (never called with a smaller now). NULL: static. */
    void (*advance)(void *self, uint64_t now);
    /* The next core cycle at which it changes on its own, MMIO_NEVER if none. NULL: never. */
    uint64_t (*next_event)(void *self);
    /* Power-on / system reset state. */
    void (*reset)(void *self);
} mmio_ops_t;

/* A peripheral placed on the bus at [base, base + size). */
typedef struct {
    uint32_t base, size;
    const mmio_ops_t *ops;
    void *self;
} mmio_region_t;

/* An interrupt line into the NVIC, level-sensitive as on the Cortex-M: while
 * a peripheral holds it high the interrupt is (re-)pended; the model lowers
 * it when the firmware clears the flag. irq: the external interrupt number
 * (IRQn >= 0, the vector table's entry 16 + irq). */
typedef struct {
    void (*set)(void *ctx, unsigned irq, bool level);
    void *ctx;
} mmio_irq_t;

/* The bus as a DMA controller sees it: memory and peripherals alike, at the
 * cycle of the transfer. false: the access faults (a DMA transfer error). */
typedef struct {
    bool (*read)(void *ctx, uint32_t addr, unsigned size, uint32_t *value);
    bool (*write)(void *ctx, uint32_t addr, unsigned size, uint32_t value);
    void *ctx;
} mmio_bus_t;

/* A peripheral's DMA request line (ADC EOC, USART TXE/RXNE, SPI, TIM
 * update/compare): the DMA model is told when a request rises; the
 * peripheral's model then sees the transfer's read or write through its own
 * registers as a core access would. */
typedef struct {
    void (*request)(void *ctx, unsigned channel, bool level);
    void *ctx;
} mmio_dma_req_t;

/* The clocks RCC derives and the peripherals count with, Hz. RCC owns it;
 * every other model holds a const pointer and reads it when it needs it
 * (a clock change takes effect at the next access or event). */
typedef struct {
    uint32_t sysclk, hclk, pclk1, pclk2;
    uint32_t tim_apb1, tim_apb2; /* x2 when the APB prescaler is not 1 (RM0008 7.2) */
    uint32_t adcclk;
} mmio_clocks_t;

#endif
