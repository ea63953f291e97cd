/* f4test.c - our STM32F405 test firmware's scenarios (test_stm32f4_soc.c
 * checks each against RM0090 rev 19). Register level, as a Cube HAL
 * firmware does it where it matters (the clock setup's order, the PLL
 * enabled through the bit-band alias, HAL_Delay on a RAM tick). */
#include "f4test.h"

__attribute__((section(".mailbox"), used)) volatile mailbox_t mb;
static volatile uint32_t uw_tick; /* HAL's uwTick: SysTick's 1 kHz count */
static volatile uint16_t adc_buf[ADC_BUF];
static const char usart_msg[] = USART_MSG;
/* The IR emitter's pattern: BSRR words for PB0 (set, reset, set, reset ...) and PB1 */
static const uint32_t ir_pattern[6] = { 1u << 0, 1u << 16, 1u << 1, 1u << 17, 1u << 0 | 1u << 1, 1u << 16 | 1u << 17 };
__attribute__((section(".sector2"), used)) const uint32_t sector2_data[4] = { 0x5EC70002u, 1, 2, 3 };
__attribute__((section(".sector3"), used)) const uint32_t sector3_data[4] = { 0x5EC70003u, 4, 5, 6 };

static void logev(uint32_t e) { if (mb.nlog < MAILBOX_LOG) mb.log[mb.nlog++] = e; }

void systick_handler(void) { uw_tick++; }

static void hal_delay(uint32_t ms)
{
    uint32_t start = uw_tick, wait = ms + 1u; /* HAL_Delay adds one tick (HAL_MAX_DELAY aside) */
    while (uw_tick - start < wait) {}
}

/* SystemClock_Config as CubeMX writes it for HSE 8 MHz -> 168 MHz (RM0090 6.3.1-6.3.3, 3.5.1 table 10, 5.4.1). */
static void clock_setup(void)
{
    RCC_CR |= 1u << 16;                              /* HSEON */
    while (!(RCC_CR & (1u << 17))) {}                /* HSERDY */
    RCC_APB1ENR |= 1u << 28;                         /* PWREN */
    PWR_CR |= 1u << 14;                              /* VOS scale 1 */
    RCC_PLLCFGR = 8u | 336u << 6 | 0u << 16 | 1u << 22 | 7u << 24; /* M 8, N 336, P 2, HSE, Q 7 */
    BITBAND_PERIPH(RCC + 0x00u, 24) = 1;             /* PLLON through the alias (HAL's __HAL_RCC_PLL_ENABLE) */
    while (!(RCC_CR & (1u << 25))) {}                /* PLLRDY */
    FLASH_ACR = 5u | 1u << 8 | 1u << 9 | 1u << 10;   /* 5 wait states at 168 MHz, 2.7-3.6 V; PRFTEN ICEN DCEN */
    mb.v[0] = FLASH_ACR;                             /* HAL checks LATENCY read back */
    RCC_CFGR = (RCC_CFGR & ~0xFCF0u) | 0u << 4 | 5u << 10 | 4u << 13; /* AHB /1, APB1 /4, APB2 /2 */
    RCC_CFGR = (RCC_CFGR & ~3u) | 2u;                /* SW = PLL */
    while ((RCC_CFGR & 0xCu) != 0x8u) {}             /* SWS = PLL */
    SYST_RVR = 168000u - 1u;                         /* HAL_InitTick: 1 kHz at HCLK */
    SYST_CVR = 0;
    SYST_CSR = 7u;                                   /* CLKSOURCE HCLK, TICKINT, ENABLE */
    SCB_DEMCR |= 1u << 24;                           /* TRCENA */
    DWT_CTRL |= 1u;                                  /* CYCCNTENA */
}

static void sc_clock(void)
{
    uint32_t t0 = DWT_CYCCNT, k0 = uw_tick;
    hal_delay(10);
    mb.v[1] = DWT_CYCCNT - t0;
    mb.v[2] = uw_tick - k0;
    mb.v[3] = RCC_CFGR;
    mb.v[4] = RCC_PLLCFGR;
    mb.v[5] = BITBAND_PERIPH(RCC + 0x00u, 25);       /* PLLRDY read through the alias */
    mb.v[6] = PWR_CSR;                               /* VOSRDY (5.4.2) */
}

/* TIM2 TRGO (update, 1 kHz) -> ADC1 scan IN0-IN2 -> DMA2 stream 0 channel 0, circular, HT and TC interrupts */
static void sc_adc_dma(void)
{
    RCC_AHB1ENR |= 1u << 22 | 1u << 0;               /* DMA2, GPIOA */
    RCC_APB1ENR |= 1u << 0;                          /* TIM2 */
    RCC_APB2ENR |= 1u << 8;                          /* ADC1 */
    TIM_PSC(TIM2) = 84u - 1u;                        /* 84 MHz -> 1 MHz (HAL_TIM_Base_Init: PSC, ARR, UG) */
    TIM_ARR(TIM2) = 1000u - 1u;                      /* 1 kHz */
    TIM_EGR(TIM2) = 1u;                              /* UG: PSC takes effect (18.3.1) */
    TIM_SR(TIM2) = 0;
    TIM_CR2(TIM2) = 2u << 4;                         /* MMS update */
    GPIO_MODER(0) |= 0x3Fu;                          /* PA0-PA2 analog */
    DMA_SPAR(2, 0) = ADC_DR_ADDR(ADC1);
    DMA_SM0AR(2, 0) = (uint32_t)adc_buf;
    DMA_SNDTR(2, 0) = ADC_BUF;
    DMA_SCR(2, 0) = 0u << 25 | 1u << 13 | 1u << 11 | 1u << 10 | 1u << 8 | 1u << 4 | 1u << 3; /* ch 0, 16-bit, MINC, CIRC, TCIE, HTIE */
    DMA_SCR(2, 0) |= 1u;
    NVIC_ISER(IRQ_DMA2_S0 / 32) = 1u << (IRQ_DMA2_S0 % 32);
    ADC_CCR = 1u << 16;                              /* ADCPRE /4: 21 MHz */
    ADC_SMPR2(ADC1) = 3u << 0 | 3u << 3 | 3u << 6;   /* 56 cycles */
    ADC_SQR1(ADC1) = 2u << 20;                       /* L = 3 conversions */
    ADC_SQR3(ADC1) = 0u | 1u << 5 | 2u << 10;        /* IN0, IN1, IN2 */
    ADC_CR1(ADC1) = 1u << 8 | 1u << 5;               /* SCAN, EOCIE (EOCS 0: EOC at each sequence's end, 13.9) */
    NVIC_ISER(IRQ_ADC / 32) = 1u << (IRQ_ADC % 32);
    ADC_CR2(ADC1) = 1u << 0 | 1u << 8 | 1u << 9 | 6u << 24 | 1u << 28; /* ADON, DMA, DDS, EXTSEL TIM2_TRGO, rising */
    TIM_CR1(TIM2) = 1u;
    mb.v[0] = DWT_CYCCNT;
    while (mb.step < 4) {}                           /* 4 transfer-complete interrupts */
    TIM_CR1(TIM2) = 0;
    mb.v[1] = ADC_SR(ADC1);
    mb.v[2] = DMA_SNDTR(2, 0);
}

static void dma2_s0_irq(void)
{
    uint32_t isr = DMA_LISR(2);
    if (isr & (1u << 4)) { DMA_LIFCR(2) = 1u << 4; logev(EV('H', adc_buf[0] >> 4)); mb.v[4 + (mb.nlog & 7u)] = DWT_CYCCNT; }
    if (isr & (1u << 5)) {
        DMA_LIFCR(2) = 1u << 5;
        logev(EV('T', adc_buf[5] >> 4));
        for (unsigned i = 0; i < ADC_BUF; i++) mb.v[12 + i] = adc_buf[i];
        mb.step++;
    }
}

static void adc_irq(void)
{
    uint32_t sr = ADC_SR(ADC1);
    mb.v[18]++;
    mb.v[19] |= sr;
    ADC_SR(ADC1) = ~(sr & 0x12u);                    /* EOC, STRT cleared (rc_w0) */
}

/* TIM1 CC1 (every 100 us) -> DMA2 stream 1 channel 6 -> GPIOB BSRR: an IR emitter pattern on PB0/PB1 */
static void sc_tim_dma_gpio(void)
{
    RCC_AHB1ENR |= 1u << 22 | 1u << 1;               /* DMA2, GPIOB */
    RCC_APB2ENR |= 1u << 0;                          /* TIM1 */
    GPIO_MODER(1) = (GPIO_MODER(1) & ~0xFu) | 0x5u;  /* PB0, PB1 outputs */
    DMA_SPAR(2, 1) = GPIO_BSRR_ADDR(1);
    DMA_SM0AR(2, 1) = (uint32_t)ir_pattern;
    DMA_SNDTR(2, 1) = 6;
    DMA_SCR(2, 1) = 6u << 25 | 2u << 13 | 2u << 11 | 1u << 10 | 1u << 6 | 1u << 4; /* ch 6, 32-bit, MINC, M2P, TCIE */
    DMA_SCR(2, 1) |= 1u;
    NVIC_ISER(IRQ_DMA2_S1 / 32) = 1u << (IRQ_DMA2_S1 % 32);
    TIM_PSC(TIM1) = 168u - 1u;                       /* 168 MHz -> 1 MHz */
    TIM_ARR(TIM1) = 100u - 1u;                       /* 100 us */
    TIM_CCR1(TIM1) = 50u;
    TIM_DIER(TIM1) = 1u << 9;                        /* CC1DE */
    TIM_EGR(TIM1) = 1u;                              /* UG: PSC loaded */
    TIM_SR(TIM1) = 0;
    mb.v[0] = DWT_CYCCNT;
    TIM_CR1(TIM1) = 1u;
    while (mb.step < 1) {}
    TIM_CR1(TIM1) = 0;
    mb.v[1] = DMA_SNDTR(2, 1);
    mb.v[2] = GPIO_ODR(1);
}

static void dma2_s1_irq(void)
{
    if (DMA_LISR(2) & (1u << 11)) { DMA_LIFCR(2) = 1u << 11; logev(EV('T', 1)); mb.v[3] = DWT_CYCCNT; mb.step++; }
}

/* I2C1 master at 100 kHz (27.3.3): polling as the reference manual's sequences */
static int i2c_wait(uint32_t sr1_bits)
{
    for (uint32_t n = 0; n < 1000000u; n++) if (I2C_SR1(I2C1) & sr1_bits) return 0;
    return -1;
}

static int i2c_start(uint8_t addr_rw)
{
    I2C_CR1(I2C1) |= 1u << 8;                        /* START */
    if (i2c_wait(1u << 0)) return -1;                /* SB */
    I2C_DR(I2C1) = addr_rw;
    if (i2c_wait(1u << 1 | 1u << 10)) return -1;     /* ADDR or AF */
    return (I2C_SR1(I2C1) & (1u << 10)) ? -1 : 0;
}

/* Register reg of the device at addr: n (1 or 2) bytes into out, MSB first (figure 242's sequences). */
static int i2c_read(uint8_t addr, uint8_t reg, uint8_t *out, unsigned n)
{
    if (i2c_start((uint8_t)(addr << 1))) return -1;
    (void)I2C_SR2(I2C1);                             /* ADDR cleared */
    I2C_DR(I2C1) = reg;
    if (i2c_wait(1u << 2)) return -1;                /* BTF */
    if (n == 2) I2C_CR1(I2C1) |= 1u << 10 | 1u << 11; /* ACK, POS */
    if (i2c_start((uint8_t)(addr << 1 | 1u))) return -1;
    if (n == 1) {
        I2C_CR1(I2C1) &= ~(1u << 10);                /* NACK the only byte */
        (void)I2C_SR2(I2C1);
        I2C_CR1(I2C1) |= 1u << 9;                    /* STOP */
        if (i2c_wait(1u << 6)) return -1;            /* RXNE */
        out[0] = (uint8_t)I2C_DR(I2C1);
    } else {
        (void)I2C_SR2(I2C1);
        I2C_CR1(I2C1) &= ~(1u << 10);                /* the second byte NACKed (POS) */
        if (i2c_wait(1u << 2)) return -1;            /* BTF: both bytes in */
        I2C_CR1(I2C1) |= 1u << 9;
        out[0] = (uint8_t)I2C_DR(I2C1);
        out[1] = (uint8_t)I2C_DR(I2C1);
        I2C_CR1(I2C1) &= ~(1u << 11);
    }
    return 0;
}

static int i2c_write(uint8_t addr, uint8_t reg, uint8_t v)
{
    if (i2c_start((uint8_t)(addr << 1))) return -1;
    (void)I2C_SR2(I2C1);
    I2C_DR(I2C1) = reg;
    if (i2c_wait(1u << 7)) return -1;                /* TXE */
    I2C_DR(I2C1) = v;
    if (i2c_wait(1u << 2)) return -1;                /* BTF */
    I2C_CR1(I2C1) |= 1u << 9;
    return 0;
}

static void sc_i2c(void)
{
    uint8_t b[2] = { 0, 0 };
    int err = 0;
    RCC_AHB1ENR |= 1u << 1;                          /* GPIOB */
    RCC_APB1ENR |= 1u << 21;                         /* I2C1 */
    GPIO_MODER(1) = (GPIO_MODER(1) & ~(0xFu << 12)) | 0xAu << 12; /* PB6 SCL, PB7 SDA: AF */
    GPIO_AFRL(1) = (GPIO_AFRL(1) & ~0xFF000000u) | 0x44000000u;   /* AF4 */
    I2C_CR2(I2C1) = 42u;                             /* FREQ: PCLK1 42 MHz */
    I2C_CCR(I2C1) = 210u;                            /* standard mode 100 kHz: 42 MHz / (2 x 100 kHz) */
    I2C_TRISE(I2C1) = 43u;                           /* 1000 ns x 42 MHz + 1 */
    I2C_CR1(I2C1) = 1u;                              /* PE */
    uint32_t t0 = DWT_CYCCNT;
    err |= i2c_read(0x68, 0x75, b, 1);               /* MPU-6050 WHO_AM_I */
    mb.v[0] = b[0];
    mb.v[1] = DWT_CYCCNT - t0;
    err |= i2c_write(0x68, 0x6B, 0x00);              /* PWR_MGMT_1: wake */
    hal_delay(5);
    err |= i2c_read(0x68, 0x47, b, 2);               /* GYRO_ZOUT_H, _L */
    mb.v[2] = (uint32_t)(int32_t)(int16_t)(b[0] << 8 | b[1]);
    err |= i2c_read(0x29, 0xC0, b, 1);               /* VL53L0X IDENTIFICATION_MODEL_ID */
    mb.v[3] = b[0];
    err |= i2c_write(0x29, 0x00, 0x01);              /* SYSRANGE_START: single shot */
    t0 = DWT_CYCCNT;
    do err |= i2c_read(0x29, 0x13, b, 1);            /* RESULT_INTERRUPT_STATUS */
    while (!err && !(b[0] & 0x07u));
    mb.v[4] = DWT_CYCCNT - t0;
    err |= i2c_read(0x29, 0x14 + 10, b, 2);          /* the range, mm */
    mb.v[5] = (uint32_t)(b[0] << 8 | b[1]);
    err |= i2c_write(0x29, 0x0B, 0x01);              /* SYSTEM_INTERRUPT_CLEAR */
    mb.v[6] = (uint32_t)err;
}

/* USART2 at 115200 baud sends USART_MSG by DMA1 stream 6 channel 4; TC interrupt at the end */
static void sc_usart_dma(void)
{
    RCC_AHB1ENR |= 1u << 21;                         /* DMA1 */
    RCC_APB1ENR |= 1u << 17;                         /* USART2 */
    USART_BRR(USART2) = 22u << 4 | 13u;              /* 42 MHz / (16 x 22.8125) = 115068 baud */
    USART_CR3(USART2) = 1u << 7;                     /* DMAT */
    USART_CR1(USART2) = 1u << 13 | 1u << 3;          /* UE, TE */
    DMA_SPAR(1, 6) = USART_DR_ADDR(USART2);
    DMA_SM0AR(1, 6) = (uint32_t)usart_msg;
    DMA_SNDTR(1, 6) = sizeof usart_msg - 1u;
    DMA_SCR(1, 6) = 4u << 25 | 1u << 10 | 1u << 6;   /* ch 4, 8-bit, MINC, M2P */
    USART_SR(USART2) = ~(1u << 6);                   /* TC cleared before the transfer (30.3.13) */
    NVIC_ISER(IRQ_USART2 / 32) = 1u << (IRQ_USART2 % 32);
    USART_CR1(USART2) |= 1u << 6;                    /* TCIE */
    mb.v[0] = DWT_CYCCNT;
    DMA_SCR(1, 6) |= 1u;
    while (mb.step < 1) {}
    mb.v[2] = DMA_HISR(1);
}

static void usart2_irq(void)
{
    if (USART_SR(USART2) & (1u << 6)) {
        mb.v[1] = DWT_CYCCNT;
        USART_CR1(USART2) &= ~(1u << 6);
        logev(EV('U', 'C'));
        mb.step++;
    }
}

/* PC13 falling edge -> EXTI13 (SYSCFG EXTICR4 = port C) -> EXTI15_10 */
static void sc_exti(void)
{
    RCC_AHB1ENR |= 1u << 2;                          /* GPIOC */
    RCC_APB2ENR |= 1u << 14;                         /* SYSCFG */
    GPIO_PUPDR(2) |= 1u << 26;                       /* PC13 pull-up */
    SYSCFG_EXTICR(4) = 2u << 4;                      /* EXTI13 = PC13 */
    EXTI_FTSR |= 1u << 13;
    EXTI_IMR |= 1u << 13;
    NVIC_ISER(IRQ_EXTI15_10 / 32) = 1u << (IRQ_EXTI15_10 % 32);
    mb.step = 1;                                     /* ready: the host drives PC13 */
    while (mb.step < 3) __asm volatile("wfi");
}

static void exti_irq(void)
{
    if (EXTI_PR & (1u << 13)) {
        EXTI_PR = 1u << 13;                          /* rc_w1 */
        logev(EV('X', (GPIO_IDR(2) >> 13) & 1u));
        mb.step++;
    }
}

/* Sector 3 erased (3.5.3) at PSIZE x32, sector 2 kept; a word programmed (3.5.4), a byte at the wrong
 * PSIZE and a store without PG refused */
static void sc_flash_erase(void)
{
    mb.v[0] = REG(SECTOR3_ADDR);
    FLASH_KEYR = 0x45670123u;
    FLASH_KEYR = 0xCDEF89ABu;
    mb.v[1] = FLASH_CR;                              /* LOCK cleared */
    FLASH_CR = 2u << 8 | 1u << 1 | 3u << 3;          /* PSIZE x32, SER, SNB 3 */
    uint32_t t0 = DWT_CYCCNT;
    FLASH_CR |= 1u << 16;                            /* STRT */
    while (FLASH_SR & (1u << 16)) {}                 /* BSY */
    mb.v[2] = DWT_CYCCNT - t0;
    mb.v[3] = FLASH_SR;
    FLASH_CR = 2u << 8 | 1u << 0;                    /* PSIZE x32, PG (3.5.4) */
    t0 = DWT_CYCCNT;
    REG(SECTOR3_ADDR + 0x10u) = 0x12345678u;
    while (FLASH_SR & (1u << 16)) {}
    mb.v[8] = DWT_CYCCNT - t0;
    mb.v[9] = REG(SECTOR3_ADDR + 0x10u);
    *(volatile uint8_t *)(SECTOR3_ADDR + 0x20u) = 0x00u; /* a byte at PSIZE x32: PGPERR, no change */
    while (FLASH_SR & (1u << 16)) {}                 /* as HAL's FLASH_WaitForLastOperation */
    mb.v[10] = FLASH_SR;
    FLASH_SR = 1u << 6;                              /* rc_w1 */
    FLASH_CR = 2u << 8;                              /* PG clear: a store is PGSERR */
    REG(SECTOR3_ADDR + 0x24u) = 0u;
    while (FLASH_SR & (1u << 16)) {}
    mb.v[11] = FLASH_SR;
    FLASH_SR = 1u << 7;
    mb.v[12] = REG(SECTOR3_ADDR + 0x20u);
    mb.v[13] = REG(SECTOR3_ADDR + 0x24u);
    FLASH_CR = 1u << 31;                             /* LOCK */
    mb.v[4] = REG(SECTOR3_ADDR);
    mb.v[5] = REG(SECTOR3_ADDR + 0x3FFCu);
    mb.v[6] = REG(SECTOR2_ADDR);
    mb.v[7] = FLASH_CR;
}

/* A peripheral without its RCC clock: writes ignored, reads 0 (6.3.10); then with it */
static void sc_gate(void)
{
    TIM_ARR(TIM2) = 1234u;
    mb.v[0] = TIM_ARR(TIM2);
    RCC_APB1ENR |= 1u << 0;
    mb.v[1] = TIM_ARR(TIM2);                         /* reset value */
    TIM_ARR(TIM2) = 1234u;
    mb.v[2] = TIM_ARR(TIM2);
}

/* SPI1 master (28.3.3) at PCLK2 / 128 (656 kHz, mode 3) to an MPU-6500 with nCS on PA4: WHO_AM_I by polling
 * TXE/RXNE (28.3.5), then GYRO_ZOUT_H/L as HAL_SPI_TransmitReceive_DMA does it: DMA2 stream 2 channel 3
 * (SPI1_RX) enabled, RXDMAEN, stream 3 channel 3 (SPI1_TX) enabled, TXDMAEN (28.3.9, table 43); the RX
 * stream's TC interrupt ends the transfer: BSY waited for, the DMA requests off, nCS high */
static volatile uint8_t spi_tx[3] = { 0x47u | 0x80u, 0, 0 };
static volatile uint8_t spi_rx[3];

static void spi_cs(int high) { REG(GPIO_BSRR_ADDR(0)) = high ? 1u << SPI_CS_PIN : 1u << (SPI_CS_PIN + 16); }

static uint8_t spi_xfer(uint8_t b)
{
    while (!(SPI_SR(SPI1) & 2u)) {}                  /* TXE */
    SPI_DR(SPI1) = b;
    while (!(SPI_SR(SPI1) & 1u)) {}                  /* RXNE */
    return (uint8_t)SPI_DR(SPI1);
}

static void sc_spi_dma(void)
{
    RCC_AHB1ENR |= 1u << 22 | 1u << 0;               /* DMA2, GPIOA */
    RCC_APB2ENR |= 1u << 12;                         /* SPI1 */
    spi_cs(1);
    GPIO_MODER(0) = (GPIO_MODER(0) & ~0xFF00u) | 1u << 8 | 0xA8u << 8; /* PA4 output, PA5-7 AF */
    GPIO_AFRL(0) = (GPIO_AFRL(0) & ~0xFFF00000u) | 0x55500000u;        /* AF5: SPI1 */
    SPI_CR1(SPI1) = 1u << 2 | 6u << 3 | 1u << 9 | 1u << 8 | 3u;         /* MSTR, BR /128, SSM, SSI, CPOL, CPHA */
    SPI_CR1(SPI1) |= 1u << 6;                                          /* SPE */
    uint32_t t0 = DWT_CYCCNT;
    spi_cs(0);
    (void)spi_xfer(0x75u | 0x80u);                   /* WHO_AM_I, read */
    mb.v[0] = spi_xfer(0);
    mb.v[1] = DWT_CYCCNT - t0;
    while (SPI_SR(SPI1) & (1u << 7)) {}              /* BSY */
    spi_cs(1);
    hal_delay(2);
    DMA_SPAR(2, 2) = SPI_DR_ADDR(SPI1);
    DMA_SM0AR(2, 2) = (uint32_t)spi_rx;
    DMA_SNDTR(2, 2) = 3;
    DMA_SCR(2, 2) = 3u << 25 | 1u << 10 | 1u << 4;   /* ch 3, 8-bit, MINC, P2M, TCIE */
    DMA_SPAR(2, 3) = SPI_DR_ADDR(SPI1);
    DMA_SM0AR(2, 3) = (uint32_t)spi_tx;
    DMA_SNDTR(2, 3) = 3;
    DMA_SCR(2, 3) = 3u << 25 | 1u << 10 | 1u << 6;   /* ch 3, 8-bit, MINC, M2P */
    NVIC_ISER(IRQ_DMA2_S2 / 32) = 1u << (IRQ_DMA2_S2 % 32);
    spi_cs(0);
    mb.v[3] = DWT_CYCCNT;
    DMA_SCR(2, 2) |= 1u;
    SPI_CR2(SPI1) |= 1u << 0;                        /* RXDMAEN */
    DMA_SCR(2, 3) |= 1u;
    SPI_CR2(SPI1) |= 1u << 1;                        /* TXDMAEN */
    while (mb.step < 1) {}
    mb.v[2] = (uint32_t)(int32_t)(int16_t)(spi_rx[1] << 8 | spi_rx[2]);
    mb.v[5] = SPI_SR(SPI1);
    mb.v[6] = DMA_SNDTR(2, 3);
}

static void dma2_s2_irq(void)
{
    if (DMA_LISR(2) & (1u << 21)) {                  /* TCIF2 */
        mb.v[4] = DWT_CYCCNT - mb.v[3];
        mb.v[7] = DMA_LISR(2);                       /* both streams' flags at the end */
        DMA_LIFCR(2) = 0x003D0000u;                  /* stream 2's (FEIF2, DMEIF2, TEIF2, HTIF2, TCIF2) */
        while (SPI_SR(SPI1) & (1u << 7)) {}          /* BSY (HAL's SPI_EndRxTxTransaction) */
        SPI_CR2(SPI1) &= ~3u;
        spi_cs(1);
        DMA_LIFCR(2) = 0x0F400000u;                  /* the TX stream 3's flags (FEIF3, TEIF3, HTIF3, TCIF3) */
        logev(EV('S', spi_rx[1]));
        mb.step++;
    }
}

/* USART6 (APB2, 30.6) at 115226 baud receives UART_RX_LEN bytes by DMA2 stream 1 channel 5 (table 43, DMAR)
 * with the idle line's interrupt on USART6's line 71 after them (as HAL_UARTEx_ReceiveToIdle_DMA); then
 * UART4 (APB1) sends them upper-cased and UART5 one byte, polled */
static volatile uint8_t uart_rx[UART_RX_LEN];

static void uart_send(uint32_t u, uint8_t b)
{
    while (!(USART_SR(u) & (1u << 7))) {}            /* TXE */
    USART_DR(u) = b;
}

static void sc_uart_rx_dma(void)
{
    RCC_AHB1ENR |= 1u << 22;                         /* DMA2 */
    RCC_APB2ENR |= 1u << 5;                          /* USART6 */
    RCC_APB1ENR |= 1u << 19 | 1u << 20;              /* UART4, UART5 */
    USART_BRR(USART6) = 45u << 4 | 9u;               /* 84 MHz / (16 x 45.5625) = 115226 baud */
    USART_CR3(USART6) = 1u << 6;                     /* DMAR */
    DMA_SPAR(2, 1) = USART_DR_ADDR(USART6);
    DMA_SM0AR(2, 1) = (uint32_t)uart_rx;
    DMA_SNDTR(2, 1) = UART_RX_LEN;
    DMA_SCR(2, 1) = 5u << 25 | 1u << 10 | 1u << 4;   /* ch 5, 8-bit, MINC, P2M, TCIE */
    DMA_SCR(2, 1) |= 1u;
    NVIC_ISER(IRQ_DMA2_S1 / 32) = 1u << (IRQ_DMA2_S1 % 32);
    NVIC_ISER(IRQ_USART6 / 32) = 1u << (IRQ_USART6 % 32);
    USART_CR1(USART6) = 1u << 13 | 1u << 2 | 1u << 4; /* UE, RE, IDLEIE */
    mb.v[0] = DWT_CYCCNT;
    mb.step = 1;                                     /* ready: the host sends */
    while (mb.step < 3) {}
    USART_BRR(UART4) = 22u << 4 | 13u;               /* 42 MHz / (16 x 22.8125) */
    USART_BRR(UART5) = 22u << 4 | 13u;
    USART_CR1(UART4) = 1u << 13 | 1u << 3;           /* UE, TE */
    USART_CR1(UART5) = 1u << 13 | 1u << 3;
    for (unsigned i = 0; i < UART_RX_LEN; i++) uart_send(UART4, (uint8_t)(uart_rx[i] - 0x20u));
    while (!(USART_SR(UART4) & (1u << 6))) {}        /* TC */
    uart_send(UART5, '5');
    while (!(USART_SR(UART5) & (1u << 6))) {}
    mb.v[3] = DMA_SNDTR(2, 1);
}

static void dma2_s1_uart_irq(void)
{
    if (DMA_LISR(2) & (1u << 11)) { DMA_LIFCR(2) = 1u << 11; mb.v[1] = DWT_CYCCNT; logev(EV('D', uart_rx[0])); mb.step++; }
}

static void usart6_irq(void)
{
    uint32_t sr = USART_SR(USART6);
    if (sr & (1u << 4)) {                            /* IDLE: SR read, then DR read (30.6.1) */
        (void)USART_DR(USART6);
        mb.v[2] = DWT_CYCCNT;
        logev(EV('I', 0));
        mb.step++;
    }
}

/* Timers in master/slave (RM0090 18.3.15, SMCR 18.4.3, ITRx from the internal trigger connection tables):
 * TIM8 gated (SMS 101) by TIM1's enable (MMS 001, ITR0); TIM3's update TRGO (100 us) clocking TIM2 in
 * external clock mode 1 (SMS 111, ITR2), TIM2's update TRGO starting TIM4 (trigger mode 110, ITR1), TIM3's
 * update resetting TIM5 (reset mode 100, ITR1) */
static void wait_us(uint32_t us)
{
    uint32_t t0 = DWT_CYCCNT;
    while (DWT_CYCCNT - t0 < us * 168u) {}
}

static void sc_tim_itr(void)
{
    RCC_APB1ENR |= 0xFu;                             /* TIM2-5 */
    RCC_APB2ENR |= 3u;                               /* TIM1, TIM8 */
    TIM_CR2(TIM1) = 1u << 4;                         /* MMS enable: TRGO = CEN */
    TIM_PSC(TIM8) = 168u - 1u;                       /* 1 MHz */
    TIM_ARR(TIM8) = 0xFFFFu;
    TIM_EGR(TIM8) = 1u;
    TIM_SMCR(TIM8) = 5u | 0u << 4;                   /* gated, ITR0 = TIM1 */
    TIM_CR1(TIM8) = 1u;
    wait_us(200);
    mb.v[0] = TIM_CNT(TIM8);                         /* TIM1 off: no count */
    TIM_CR1(TIM1) = 1u;
    wait_us(1000);
    TIM_CR1(TIM1) = 0;
    mb.v[1] = TIM_CNT(TIM8);
    wait_us(500);
    mb.v[2] = TIM_CNT(TIM8);
    mb.v[3] = TIM_SR(TIM8);
    TIM_PSC(TIM3) = 84u - 1u;                        /* 84 MHz -> 1 MHz */
    TIM_ARR(TIM3) = 100u - 1u;                       /* 100 us */
    TIM_EGR(TIM3) = 1u;
    TIM_SR(TIM3) = 0;
    TIM_CR2(TIM3) = 2u << 4;                         /* MMS update */
    TIM_ARR(TIM2) = 10u - 1u;                        /* 10 TIM3 updates: 1 ms */
    TIM_CR2(TIM2) = 2u << 4;
    TIM_SMCR(TIM2) = 7u | 2u << 4;                   /* external clock mode 1, ITR2 = TIM3 */
    TIM_DIER(TIM2) = 1u;                             /* UIE */
    TIM_CR1(TIM2) = 1u;
    TIM_PSC(TIM4) = 84u - 1u;
    TIM_ARR(TIM4) = 0xFFFFu;
    TIM_EGR(TIM4) = 1u;
    TIM_SR(TIM4) = 0;
    TIM_SMCR(TIM4) = 6u | 1u << 4;                   /* trigger mode, ITR1 = TIM2 */
    TIM_ARR(TIM5) = 0xFFFFFFFFu;
    TIM_SMCR(TIM5) = 4u | 1u << 4;                   /* reset mode, ITR1 = TIM3 */
    TIM_CR1(TIM5) = 1u;
    NVIC_ISER(IRQ_TIM2 / 32) = 1u << (IRQ_TIM2 % 32);
    mb.v[4] = DWT_CYCCNT;
    TIM_CR1(TIM3) = 1u;
    while (mb.step < 3) {}
    TIM_CR1(TIM3) = 0;
    mb.v[14] = TIM_CR1(TIM4);
    mb.v[15] = TIM_CNT(TIM2);
}

static void tim2_irq(void)
{
    if (TIM_SR(TIM2) & 1u) {
        uint32_t now = DWT_CYCCNT, t4 = TIM_CNT(TIM4), t5 = TIM_CNT(TIM5);
        TIM_SR(TIM2) = ~1u;
        if (mb.step < 3) mb.v[5 + mb.step] = now, mb.v[8 + mb.step] = t4, mb.v[11 + mb.step] = t5;
        logev(EV('T', 2));
        mb.step++;
    }
}

void irq_handler(void)
{
    uint32_t ipsr;
    __asm volatile("mrs %0, ipsr" : "=r"(ipsr));
    switch (ipsr - 16u) {
    case IRQ_DMA2_S0: dma2_s0_irq(); break;
    case IRQ_DMA2_S1: if (mb.scenario == SC_UART_RX_DMA) dma2_s1_uart_irq(); else dma2_s1_irq(); break;
    case IRQ_DMA2_S2: dma2_s2_irq(); break;
    case IRQ_USART6: usart6_irq(); break;
    case IRQ_TIM2: tim2_irq(); break;
    case IRQ_USART2: usart2_irq(); break;
    case IRQ_ADC: adc_irq(); break;
    case IRQ_EXTI15_10: exti_irq(); break;
    default: logev(0xDEAD0000u | ipsr); for (;;) __asm volatile("wfi");
    }
}

int main(void)
{
    RCC_AHB1ENR |= 1u << 4;                          /* GPIOE: the scenario pins */
    mb.scenario = GPIO_IDR(4) & 0xFu;
    if (mb.scenario != SC_FLASH_ERASE && mb.scenario != SC_GATE) clock_setup();
    else { SCB_DEMCR |= 1u << 24; DWT_CTRL |= 1u; }
    switch (mb.scenario) {
    case SC_CLOCK: sc_clock(); break;
    case SC_ADC_DMA: sc_adc_dma(); break;
    case SC_TIM_DMA_GPIO: sc_tim_dma_gpio(); break;
    case SC_I2C: sc_i2c(); break;
    case SC_USART_DMA: sc_usart_dma(); break;
    case SC_EXTI: sc_exti(); break;
    case SC_FLASH_ERASE: sc_flash_erase(); break;
    case SC_GATE: sc_gate(); break;
    case SC_SPI_DMA: sc_spi_dma(); break;
    case SC_UART_RX_DMA: sc_uart_rx_dma(); break;
    case SC_TIM_ITR: sc_tim_itr(); break;
    default: break;
    }
    mb.done = 1;
    for (;;) __asm volatile("wfi");
}
