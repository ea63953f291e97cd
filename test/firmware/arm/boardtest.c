/* boardtest.c - our own firmware for the STM32 board (boards/bulebule.ini's
 * wiring) in a maze run (test/cli_board_arm.sh): 72 MHz from the crystal,
 * "boardtest" on USART3, then every 100 ms (SysTick) a line with the
 * encoders (TIM2, TIM4 in encoder mode 3), the front-left IR (ADC2 channel
 * 5, robots/bulebule.ini [ir.fl], with its emitter PA8 lit) and the battery (ADC2 channel 0); the right
 * button (PA12) held starts both motors forward at half duty (TIM3: IN1 at
 * 100 %, IN2 at 50 %, as bulebule's motor.c drives forward); the Blue
 * Pill's LED (PC13) toggles each line. */
#include <stdint.h>

#include "armtest.h"

__attribute__((section(".mailbox"))) mailbox_t mb;

#define RCC_CR REG(0x40021000u)
#define RCC_CFGR REG(0x40021004u)
#define RCC_APB2ENR REG(0x40021018u)
#define RCC_APB1ENR REG(0x4002101Cu)
#define FLASH_ACR REG(0x40022000u)
#define AFIO_MAPR REG(0x40010004u)
#define GPIO(p, off) REG(0x40010800u + 0x400u * (p) + (off))
#define ADC2(off) REG(0x40012800u + (off))
#define TIM(base, off) REG((base) + (off))
#define TIM2_BASE 0x40000000u
#define TIM3_BASE 0x40000400u
#define TIM4_BASE 0x40000800u
#define USART3(off) REG(0x40004800u + (off))

static volatile uint32_t ticks;

void systick_handler(void) { ticks++; }

static void putc3(char c)
{
    while (!(USART3(0x00) & (1u << 7))) {} /* TXE */
    USART3(0x04) = (uint8_t)c;
}

static void puts3(const char *s) { while (*s) putc3(*s++); }

static void putn(int32_t v)
{
    char b[12];
    int n = 0;
    uint32_t u = v < 0 ? (uint32_t)-v : (uint32_t)v;
    if (v < 0) putc3('-');
    do b[n++] = (char)('0' + u % 10u), u /= 10u; while (u);
    while (n) putc3(b[--n]);
}

/* CRL/CRH nibble of pin n of port p */
static void pin_mode(unsigned p, unsigned n, uint32_t nib)
{
    volatile uint32_t *cr = &GPIO(p, n < 8 ? 0x00 : 0x04);
    unsigned sh = 4u * (n & 7u);
    *cr = (*cr & ~(0xFu << sh)) | nib << sh;
}

static void clocks(void)
{
    RCC_CR |= 1u << 16;
    while (!(RCC_CR & (1u << 17))) {}
    FLASH_ACR = 0x12;
    RCC_CFGR = (7u << 18) | (1u << 16) | (4u << 8); /* PLL x9 from HSE, APB1 /2 */
    RCC_CR |= 1u << 24;
    while (!(RCC_CR & (1u << 25))) {}
    RCC_CFGR |= 2u;
    while (((RCC_CFGR >> 2) & 3u) != 2u) {}
    RCC_APB2ENR |= 1u | 0x1Cu | (1u << 10);             /* AFIO, IOPA-C, ADC2 */
    RCC_APB1ENR |= 0x7u | (1u << 18);                   /* TIM2-4, USART3 */
}

static void peripherals(void)
{
    AFIO_MAPR = (2u << 24) | (3u << 8);                 /* JTAG off (SWD on); TIM2 full remap: CH1 PA15, CH2 PB3 */
    pin_mode(1, 10, 0xBu);                              /* PB10 USART3_TX: AF push-pull 50 MHz */
    USART3(0x08) = 39, USART3(0x0C) = (1u << 13) | (1u << 3);
    pin_mode(0, 6, 0xBu), pin_mode(0, 7, 0xBu), pin_mode(1, 0, 0xBu), pin_mode(1, 1, 0xBu); /* TIM3 CH1-4 */
    TIM(TIM3_BASE, 0x2C) = 1023;
    TIM(TIM3_BASE, 0x18) = 0x6868u, TIM(TIM3_BASE, 0x1C) = 0x6868u; /* PWM1 with preload on CH1-4 */
    TIM(TIM3_BASE, 0x20) = 0x1111u;
    TIM(TIM3_BASE, 0x14) = 1u, TIM(TIM3_BASE, 0x00) = 1u;
    for (uint32_t t = TIM2_BASE; t <= TIM4_BASE; t += 0x800u) {
        TIM(t, 0x2C) = 0xFFFFu;
        TIM(t, 0x08) = 3u;                              /* SMS encoder mode 3 */
        TIM(t, 0x18) = 0x0101u;                         /* CC1S = TI1, CC2S = TI2 */
        TIM(t, 0x00) = 1u;
    }
    pin_mode(0, 8, 0x2u);                               /* PA8 emitter front left: output */
    pin_mode(2, 13, 0x2u);                              /* PC13 LED */
    pin_mode(0, 12, 0x8u), GPIO(0, 0x14) = 1u << 12;    /* PA12 button: input pull-down */
    ADC2(0x08) = 1u;
    for (volatile int i = 0; i < 100; i++) {}
    ADC2(0x08) |= 1u << 2;
    while (ADC2(0x08) & (1u << 2)) {}
    ADC2(0x08) |= (7u << 17) | (1u << 20);
}

static uint32_t adc(unsigned ch)
{
    ADC2(0x34) = ch;
    ADC2(0x08) |= 1u << 22;
    while (!(ADC2(0x00) & 2u)) {}
    return ADC2(0x4C);
}

int main(void)
{
    clocks();
    peripherals();
    puts3("boardtest\n");
    SYST_RVR = 72000u - 1u, SYST_CVR = 0, SYST_CSR = 7u; /* 1 ms at HCLK */
    uint32_t next = 100;
    for (;;) {
        __asm volatile("wfi");
        if (ticks < next) continue;
        next += 100;
        int on = (GPIO(0, 0x08) >> 12) & 1u;
        TIM(TIM3_BASE, 0x34) = on ? 1023u : 0u, TIM(TIM3_BASE, 0x38) = on ? 512u : 0u;
        TIM(TIM3_BASE, 0x3C) = on ? 1023u : 0u, TIM(TIM3_BASE, 0x40) = on ? 512u : 0u;
        GPIO(0, 0x10) = 1u << 8;                        /* emitter on */
        for (volatile int i = 0; i < 200; i++) {}
        uint32_t ir = adc(5);
        GPIO(0, 0x14) = 1u << 8;
        GPIO(2, 0x0C) ^= 1u << 13;
        puts3("t "), putn((int32_t)ticks), puts3(" enc "), putn((int16_t)TIM(TIM2_BASE, 0x24)), putc3(' ');
        putn((int16_t)TIM(TIM4_BASE, 0x24)), puts3(" ir "), putn((int32_t)ir), puts3(" bat "), putn((int32_t)adc(0));
        puts3(on ? " run\n" : "\n");
    }
}
