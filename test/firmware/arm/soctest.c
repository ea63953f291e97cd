/* soctest.c - the STM32F103 as one chip (sim/arm/stm32f1_soc.c): our own
 * register-level firmware touching its peripherals through their RM0008
 * addresses, one step after the other, each result in the mailbox
 * (test/test_stm32f1_soc.c checks them): the clock tree to 72 MHz from the
 * 8 MHz crystal, a gated peripheral read with its clock off, GPIO out and
 * in, ADC2's regular conversion of a voltage the host gives, TIM3's PWM,
 * TIM2's update interrupt through the NVIC (vector table moved to SRAM),
 * USART3 sending through DMA1 channel 2, TIM3's update TRGO triggering
 * ADC2 (EXTSEL) and clocking TIM4 through ITR2 (external clock mode 1), the
 * FLASH controller programming and erasing a page. */
#include <stdint.h>

#include "armtest.h"

__attribute__((section(".mailbox"))) mailbox_t mb;

/* RM0008 registers */
#define RCC_CR REG(0x40021000u)
#define RCC_CFGR REG(0x40021004u)
#define RCC_AHBENR REG(0x40021014u)
#define RCC_APB2ENR REG(0x40021018u)
#define RCC_APB1ENR REG(0x4002101Cu)
#define FLASH_ACR REG(0x40022000u)
#define FLASH_KEYR REG(0x40022004u)
#define FLASH_SR REG(0x4002200Cu)
#define FLASH_CR REG(0x40022010u)
#define FLASH_AR REG(0x40022014u)
#define GPIO(p, off) REG(0x40010800u + 0x400u * (p) + (off)) /* CRL 0, CRH 4, IDR 8, ODR C, BSRR 10 */
#define ADC2(off) REG(0x40012800u + (off))                   /* SR 0, CR2 8, SQR3 34, DR 4C */
#define TIM(base, off) REG((base) + (off))
#define TIM2_BASE 0x40000000u
#define TIM3_BASE 0x40000400u
#define TIM4_BASE 0x40000800u
#define USART3(off) REG(0x40004800u + (off))                  /* SR 0, DR 4, BRR 8, CR1 C, CR3 14 */
#define DMA1_CH2(off) REG(0x40020000u + 0x14u + (off))      /* CCR 8, CNDTR C, CPAR 10, CMAR 14, + 20 per channel (RM0008 13.4.7) */
#define DMA1_ISR REG(0x40020000u)
#define FLASH_PAGE 0x0800FC00u                               /* the last 1 KiB page of 64 KiB */

#define NVEC (16 + 43)
static uint32_t ram_vectors[64] __attribute__((aligned(256)));
static volatile uint32_t tim2_irqs;
static const char msg[] = "soc ok\n";

static void tim2_handler(void)
{
    TIM(TIM2_BASE, 0x10) = 0; /* SR: UIF cleared (rc_w0) */
    if (++tim2_irqs == 3) TIM(TIM2_BASE, 0x00) = 0;
}

static void clocks_72mhz(void)
{
    RCC_CR |= 1u << 16;                          /* HSEON */
    while (!(RCC_CR & (1u << 17))) {}            /* HSERDY */
    FLASH_ACR = 0x12;                            /* 2 wait states, prefetch (RM0008 3.3.3) */
    RCC_CFGR = (7u << 18) | (1u << 16) | (4u << 8); /* PLLMUL x9, PLLSRC HSE, PPRE1 /2 */
    RCC_CR |= 1u << 24;                          /* PLLON */
    while (!(RCC_CR & (1u << 25))) {}            /* PLLRDY */
    RCC_CFGR |= 2u;                              /* SW = PLL */
    while (((RCC_CFGR >> 2) & 3u) != 2u) {}      /* SWS */
    mb.v[0] = RCC_CFGR;
}

static void gpio_steps(void)
{
    mb.v[1] = TIM(TIM4_BASE, 0x2C);              /* TIM4 ARR with its clock off: 0 (reset value 0xFFFF) */
    RCC_APB2ENR |= (1u << 2) | (1u << 4);        /* IOPAEN, IOPCEN */
    GPIO(2, 0x04) = (GPIO(2, 0x04) & ~(0xFu << 20)) | (2u << 20); /* PC13 output push-pull 2 MHz */
    GPIO(2, 0x14) = 1u << 13;                    /* BRR: PC13 low */
    GPIO(0, 0x04) = (GPIO(0, 0x04) & ~(0xFu << 16)) | (8u << 16); /* PA12 input pull-up/down */
    GPIO(0, 0x14) = 1u << 12;                    /* ODR 0: pull-down */
    mb.v[2] = GPIO(0, 0x08);                     /* IDR: the host drives PA12 high */
}

static void adc_step(void)
{
    RCC_APB2ENR |= 1u << 10;                     /* ADC2EN */
    ADC2(0x08) = 1u;                             /* ADON */
    for (volatile int i = 0; i < 100; i++) {}    /* tSTAB */
    ADC2(0x08) |= 1u << 2;                       /* CAL */
    while (ADC2(0x08) & (1u << 2)) {}
    ADC2(0x34) = 0;                              /* SQR3: channel 0 first */
    ADC2(0x08) |= (7u << 17) | (1u << 20);       /* EXTSEL SWSTART, EXTTRIG */
    ADC2(0x08) |= 1u << 22;                      /* SWSTART */
    while (!(ADC2(0x00) & 2u)) {}                /* EOC */
    mb.v[3] = ADC2(0x4C);
}

static void tim_steps(void)
{
    RCC_APB1ENR |= (1u << 0) | (1u << 1);        /* TIM2EN, TIM3EN */
    TIM(TIM3_BASE, 0x28) = 3;                    /* PSC */
    TIM(TIM3_BASE, 0x2C) = 749;                  /* ARR: 72 MHz / 4 / 750 = 24 kHz */
    TIM(TIM3_BASE, 0x18) = 6u << 4 | 1u << 3;    /* CCMR1: OC1 PWM1, preload */
    TIM(TIM3_BASE, 0x34) = 250;                  /* CCR1: a third */
    TIM(TIM3_BASE, 0x20) = 1u;                   /* CCER: CC1E */
    TIM(TIM3_BASE, 0x14) = 1u;                   /* EGR: UG */
    TIM(TIM3_BASE, 0x00) = 1u;                   /* CEN */
    for (int i = 0; i < NVEC; i++) ram_vectors[i] = ((const uint32_t *)0x08000000u)[i];
    ram_vectors[16 + 28] = (uint32_t)tim2_handler;
    SCB_VTOR = (uint32_t)ram_vectors;
    TIM(TIM2_BASE, 0x28) = 71;                   /* 1 MHz */
    TIM(TIM2_BASE, 0x2C) = 999;                  /* 1 ms */
    TIM(TIM2_BASE, 0x0C) = 1u;                   /* DIER: UIE */
    NVIC_ISER0 = 1u << 28;
    TIM(TIM2_BASE, 0x00) = 1u;
    while (tim2_irqs < 3) __asm volatile("wfi");
    mb.v[4] = tim2_irqs;
}

static void usart_dma_step(void)
{
    RCC_AHBENR |= 1u;                            /* DMA1EN */
    RCC_APB1ENR |= 1u << 18;                     /* USART3EN */
    USART3(0x08) = 39;                           /* BRR: 36 MHz / 39 = 923 kBd (bulebule's 921600) */
    USART3(0x0C) = (1u << 13) | (1u << 3);       /* UE, TE */
    USART3(0x14) = 1u << 7;                      /* CR3: DMAT */
    DMA1_CH2(0x10) = 0x40004804u;                /* CPAR: USART3 DR */
    DMA1_CH2(0x14) = (uint32_t)msg;
    DMA1_CH2(0x0C) = sizeof msg - 1;
    USART3(0x00) &= ~(1u << 6);                  /* TC cleared (RM0008 27.3.13) */
    DMA1_CH2(0x08) = (1u << 7) | (1u << 4) | 1u; /* MINC, DIR from memory, EN */
    while (!(USART3(0x00) & (1u << 6))) {}       /* TC: the last frame sent, the DMA feeding DR on its own (the DMA not polled) */
    mb.v[5] = DMA1_ISR;
}

/* TIM3 (24 kHz) as a master: MMS update (RM0008 15.4.2); its TRGO starts ADC2's regular conversion
 * (EXTSEL 100, 11.12.3) and clocks TIM4 in external clock mode 1 from ITR2 (TIM4_SMCR SMS 111 TS 010,
 * 15.3.14, 15.4.3 table "TIMx internal trigger connection"): one conversion and one count per update */
static void trigger_step(void)
{
    RCC_APB1ENR |= 1u << 2;                      /* TIM4EN */
    TIM(TIM4_BASE, 0x08) = 7u | 2u << 4;         /* SMCR: external clock mode 1, ITR2 = TIM3 */
    TIM(TIM4_BASE, 0x00) = 1u;                   /* CEN */
    ADC2(0x08) = (ADC2(0x08) & ~(7u << 17)) | 4u << 17 | 1u << 20; /* EXTSEL TIM3 TRGO, EXTTRIG */
    (void)ADC2(0x4C);                            /* EOC cleared */
    TIM(TIM3_BASE, 0x04) = 2u << 4;              /* CR2: MMS update */
    uint32_t conversions = 0;
    while (TIM(TIM4_BASE, 0x24) < 10u)
        if (ADC2(0x00) & 2u) { conversions++; mb.v[13] = ADC2(0x4C); }
    TIM(TIM3_BASE, 0x04) = 0;
    mb.v[11] = TIM(TIM4_BASE, 0x24);
    mb.v[12] = conversions;
}

static void flash_wait(void) { while (FLASH_SR & 1u) {} }

static void flash_step(void)
{
    volatile uint16_t *p = (volatile uint16_t *)FLASH_PAGE;
    FLASH_KEYR = 0x45670123u, FLASH_KEYR = 0xCDEF89ABu;
    FLASH_CR = 1u;                               /* PG */
    p[0] = 0x1234;
    flash_wait();
    mb.v[6] = FLASH_SR;                          /* EOP */
    FLASH_SR = 0x34u;                            /* EOP, WRPRTERR, PGERR cleared */
    p[0] = 0x5678;                               /* not erased: PGERR, nothing written */
    flash_wait();
    mb.v[7] = FLASH_SR;
    mb.v[8] = p[0];
    FLASH_SR = 0x34u;
    FLASH_CR = 2u;                               /* PER */
    FLASH_AR = FLASH_PAGE;
    FLASH_CR = 2u | 1u << 6;                     /* STRT */
    flash_wait();
    mb.v[9] = p[0];
    FLASH_CR = 1u;
    p[1] = 0xBEEF;                               /* kept in the flash file */
    flash_wait();
    FLASH_CR = 1u << 7;                          /* LOCK */
    mb.v[10] = p[1];
}

int main(void)
{
    clocks_72mhz();
    gpio_steps();
    adc_step();
    tim_steps();
    usart_dma_step();
    trigger_step();
    flash_step();
    mb.done = 1;
    for (;;) __asm volatile("wfi");
}
