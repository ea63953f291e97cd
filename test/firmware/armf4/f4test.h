/* f4test.h - our register-level STM32F405 test firmware (test/firmware/armf4,
 * test/unit/test_stm32f4_soc.c): the registers it uses (RM0090 rev 19; the
 * core's: PM0214 rev 10), the scenarios and the mailbox the host reads.
 * The host picks the scenario with pins PE0-PE3 (read at reset). */
#ifndef F4TEST_H
#define F4TEST_H

#include <stdint.h>

#define REG(a) (*(volatile uint32_t *)(a))
/* core (PM0214 4.3-4.5, ARMv7-M C1.8) */
#define SYST_CSR REG(0xE000E010u)
#define SYST_RVR REG(0xE000E014u)
#define SYST_CVR REG(0xE000E018u)
#define NVIC_ISER(n) REG(0xE000E100u + 4u * (n))
#define SCB_DEMCR REG(0xE000EDFCu)
#define DWT_CTRL REG(0xE0001000u)
#define DWT_CYCCNT REG(0xE0001004u)
/* RCC (6.3) */
#define RCC 0x40023800u
#define RCC_CR REG(RCC + 0x00u)
#define RCC_PLLCFGR REG(RCC + 0x04u)
#define RCC_CFGR REG(RCC + 0x08u)
#define RCC_AHB1ENR REG(RCC + 0x30u)
#define RCC_APB1ENR REG(RCC + 0x40u)
#define RCC_APB2ENR REG(RCC + 0x44u)
#define BITBAND_PERIPH(addr, bit) REG(0x42000000u + ((addr) - 0x40000000u) * 32u + (bit) * 4u) /* 2.3.2 */
/* PWR (5.4), FLASH (3.8) */
#define PWR_CR REG(0x40007000u)
#define PWR_CSR REG(0x40007004u)
#define FLASH_ACR REG(0x40023C00u)
#define FLASH_KEYR REG(0x40023C04u)
#define FLASH_SR REG(0x40023C0Cu)
#define FLASH_CR REG(0x40023C10u)
/* GPIO (8.4): port p = 0 (A) .. 8 (I) */
#define GPIO(p) (0x40020000u + 0x400u * (p))
#define GPIO_MODER(p) REG(GPIO(p) + 0x00u)
#define GPIO_PUPDR(p) REG(GPIO(p) + 0x0Cu)
#define GPIO_IDR(p) REG(GPIO(p) + 0x10u)
#define GPIO_ODR(p) REG(GPIO(p) + 0x14u)
#define GPIO_BSRR_ADDR(p) (GPIO(p) + 0x18u)
#define GPIO_AFRL(p) REG(GPIO(p) + 0x20u)
/* SYSCFG (9.2), EXTI (12.3) */
#define SYSCFG_EXTICR(n) REG(0x40013808u + 4u * ((n) - 1u))
#define EXTI_IMR REG(0x40013C00u)
#define EXTI_RTSR REG(0x40013C08u)
#define EXTI_FTSR REG(0x40013C0Cu)
#define EXTI_PR REG(0x40013C14u)
/* DMA (10.5): controller d 1/2, stream s */
#define DMA(d) ((d) == 1 ? 0x40026000u : 0x40026400u)
#define DMA_LISR(d) REG(DMA(d) + 0x00u)
#define DMA_HISR(d) REG(DMA(d) + 0x04u)
#define DMA_LIFCR(d) REG(DMA(d) + 0x08u)
#define DMA_HIFCR(d) REG(DMA(d) + 0x0Cu)
#define DMA_SCR(d, s) REG(DMA(d) + 0x10u + 0x18u * (s))
#define DMA_SNDTR(d, s) REG(DMA(d) + 0x14u + 0x18u * (s))
#define DMA_SPAR(d, s) REG(DMA(d) + 0x18u + 0x18u * (s))
#define DMA_SM0AR(d, s) REG(DMA(d) + 0x1Cu + 0x18u * (s))
/* ADC (13.13) */
#define ADC1 0x40012000u
#define ADC_SR(a) REG((a) + 0x00u)
#define ADC_CR1(a) REG((a) + 0x04u)
#define ADC_CR2(a) REG((a) + 0x08u)
#define ADC_SMPR2(a) REG((a) + 0x10u)
#define ADC_SQR1(a) REG((a) + 0x2Cu)
#define ADC_SQR3(a) REG((a) + 0x34u)
#define ADC_DR_ADDR(a) ((a) + 0x4Cu)
#define ADC_CCR REG(0x40012304u)
/* TIM (17.4, 18.4) */
#define TIM1 0x40010000u
#define TIM2 0x40000000u
#define TIM3 0x40000400u
#define TIM4 0x40000800u
#define TIM5 0x40000C00u
#define TIM8 0x40010400u
#define TIM_CR1(t) REG((t) + 0x00u)
#define TIM_CR2(t) REG((t) + 0x04u)
#define TIM_SMCR(t) REG((t) + 0x08u)
#define TIM_DIER(t) REG((t) + 0x0Cu)
#define TIM_SR(t) REG((t) + 0x10u)
#define TIM_EGR(t) REG((t) + 0x14u)
#define TIM_CCMR1(t) REG((t) + 0x18u)
#define TIM_CNT(t) REG((t) + 0x24u)
#define TIM_PSC(t) REG((t) + 0x28u)
#define TIM_ARR(t) REG((t) + 0x2Cu)
#define TIM_CCR1(t) REG((t) + 0x34u)
/* I2C (27.6) */
#define I2C1 0x40005400u
#define I2C_CR1(i) REG((i) + 0x00u)
#define I2C_CR2(i) REG((i) + 0x04u)
#define I2C_DR(i) REG((i) + 0x10u)
#define I2C_SR1(i) REG((i) + 0x14u)
#define I2C_SR2(i) REG((i) + 0x18u)
#define I2C_CCR(i) REG((i) + 0x1Cu)
#define I2C_TRISE(i) REG((i) + 0x20u)
/* USART (30.6) */
#define USART2 0x40004400u
#define UART4 0x40004C00u
#define UART5 0x40005000u
#define USART6 0x40011400u
#define USART_DR(u) REG((u) + 0x04u)
#define USART_SR(u) REG((u) + 0x00u)
#define USART_DR_ADDR(u) ((u) + 0x04u)
#define USART_BRR(u) REG((u) + 0x08u)
#define USART_CR1(u) REG((u) + 0x0Cu)
#define USART_CR3(u) REG((u) + 0x14u)

/* SPI (28.5) */
#define SPI1 0x40013000u
#define SPI_CR1(s) REG((s) + 0x00u)
#define SPI_CR2(s) REG((s) + 0x04u)
#define SPI_SR(s) REG((s) + 0x08u)
#define SPI_DR(s) REG((s) + 0x0Cu)
#define SPI_DR_ADDR(s) ((s) + 0x0Cu)

/* Interrupt numbers (table 61) */
enum { IRQ_DMA1_S6 = 17, IRQ_ADC = 18, IRQ_TIM2 = 28, IRQ_USART2 = 38, IRQ_EXTI15_10 = 40, IRQ_DMA2_S0 = 56,
       IRQ_DMA2_S1 = 57, IRQ_DMA2_S2 = 58, IRQ_USART6 = 71 };

enum { SC_NONE, SC_CLOCK, SC_ADC_DMA, SC_TIM_DMA_GPIO, SC_I2C, SC_USART_DMA, SC_EXTI, SC_FLASH_ERASE, SC_GATE,
       SC_SPI_DMA, SC_UART_RX_DMA, SC_TIM_ITR };

#define SECTOR2_ADDR 0x08008000u
#define SECTOR3_ADDR 0x0800C000u
#define ADC_BUF 6                   /* two scans of three channels */
#define USART_MSG "F405 DMA\r\n"
#define SPI_CS_PIN 4                /* PA4: the MPU-6500's nCS */
#define UART_RX_LEN 4               /* bytes USART6 receives by DMA */

#define MAILBOX_LOG 64
typedef struct {
    uint32_t scenario, done, step;
    uint32_t nlog;
    uint32_t log[MAILBOX_LOG];      /* events in order, one word each */
    uint32_t v[24];                 /* figures the scenario measured */
} mailbox_t;
#ifdef __arm__
extern volatile mailbox_t mb; /* the firmware's (f4test.c) */
#endif

#define EV(a, b) ((uint32_t)(a) << 8 | (uint32_t)(b))

#endif
