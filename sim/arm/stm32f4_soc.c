/* stm32f4_soc.c - an STM32F405 on the Cortex-M4 core (stm32f4_soc.h).
 * Addresses: RM0090 rev 19 2.3 table 1; enable bits: 6.3.10 AHB1ENR,
 * 6.3.13 APB1ENR, 6.3.14 APB2ENR; interrupt lines: table 61 (in each
 * model); DMA requests: tables 42/43 (stm32f4_dma.c); ADC triggers:
 * tables 69/70 (stm32f4_tim.c); the timers' internal trigger connections: 17.4.3, 18.4.3, 19.4.2
 * (stm32f4_tim_itr). */
#include "arm/stm32f4_soc.h"

#include <stddef.h>
#include <stdio.h>
#include <string.h>

enum { AHB1ENR = 0x30, APB1ENR = 0x40, APB2ENR = 0x44 }; /* RCC offsets (RM0090 6.3.10, 6.3.13, 6.3.14) */
#define DMA1EN (1u << 21)
#define DMA2EN (1u << 22)
#define SYSCFGEN (1u << 14)
#define PWREN (1u << 28)
#define VREF_DEFAULT_V 3.3 /* ours: a board's usual VDDA = VREF+ */

/* ---- the clock gate: the registers answer only with the enable bit set ---- */
static stm32f4_gate_t *gate_of(void *self) { return self; }
static bool gate_on(const stm32f4_gate_t *g) { return (*g->enr & g->bit) != 0; }

static mmio_status_t gate_read(void *self, uint32_t off, unsigned size, uint32_t *v)
{
    stm32f4_gate_t *g = gate_of(self);
    if (gate_on(g)) return g->inner->read ? g->inner->read(g->self, off, size, v) : MMIO_UNMODELED;
    g->off_accesses++;
    *v = 0;
    return MMIO_OK;
}

static mmio_status_t gate_write(void *self, uint32_t off, unsigned size, uint32_t v)
{
    stm32f4_gate_t *g = gate_of(self);
    if (gate_on(g)) return g->inner->write ? g->inner->write(g->self, off, size, v) : MMIO_UNMODELED;
    g->off_accesses++;
    return MMIO_OK;
}

static void gate_advance(void *self, uint64_t now)
{
    stm32f4_gate_t *g = gate_of(self);
    if (g->inner->advance) g->inner->advance(g->self, now);
}

static uint64_t gate_next(void *self)
{
    stm32f4_gate_t *g = gate_of(self);
    return g->inner->next_event ? g->inner->next_event(g->self) : MMIO_NEVER;
}

static void gate_reset(void *self)
{
    stm32f4_gate_t *g = gate_of(self);
    g->off_accesses = 0;
    if (g->inner->reset) g->inner->reset(g->self);
}

/* A region on the bus, behind RCC's enable register enr_off bit when bit != 0. */
static void place(stm32f4_soc_t *s, uint32_t base, uint32_t size, const mmio_ops_t *ops, void *self, uint32_t enr_off,
                  uint32_t bit)
{
    if (s->nregions >= STM32F4_SOC_REGIONS || (bit && s->ngates >= STM32F4_SOC_GATES)) { s->overflow = true; return; }
    if (bit) {
        stm32f4_gate_t *g = &s->gate[s->ngates++];
        *g = (stm32f4_gate_t){ .inner = ops, .self = self, .enr = &s->rcc.reg[enr_off / 4], .bit = bit };
        g->ops = (mmio_ops_t){ ops->name, gate_read, gate_write, gate_advance, gate_next, gate_reset };
        ops = &g->ops, self = g;
    }
    s->region[s->nregions++] = (mmio_region_t){ base, size, ops, self };
}

/* ---- the wiring the core's lines go through (the core exists after the models) ---- */
static void soc_irq(void *ctx, unsigned irq, bool level)
{
    stm32f4_soc_t *s = ctx;
    if (!s->core) return; /* the models' power-on reset, before the core */
    mmio_irq_t i = armcore_irq(s->core);
    i.set(i.ctx, irq, level);
}

static bool soc_bus_read(void *ctx, uint32_t addr, unsigned size, uint32_t *v)
{
    stm32f4_soc_t *s = ctx;
    if (!s->core) return false;
    mmio_bus_t b = armcore_bus(s->core);
    return b.read(b.ctx, addr, size, v);
}

static bool soc_bus_write(void *ctx, uint32_t addr, unsigned size, uint32_t v)
{
    stm32f4_soc_t *s = ctx;
    if (!s->core) return false;
    mmio_bus_t b = armcore_bus(s->core);
    return b.write(b.ctx, addr, size, v);
}

/* A request to both controllers: the streams whose CHSEL selects it serve it (tables 42/43). */
static void soc_dreq(void *ctx, unsigned req, bool level)
{
    stm32f4_soc_t *s = ctx;
    stm32f4_dma_request(&s->dma[0], req, level);
    stm32f4_dma_request(&s->dma[1], req, level);
}

/* A timer's TRGO or CCx edge to the ADCs whose EXTSEL (table 69) or JEXTSEL (table 70) codes name it,
 * and a TRGO to the timers whose ITRx it is (stm32f4_tim_itr: their slave mode acts if SMCR TS selects it). */
static void soc_trigger(void *ctx, unsigned source, int rising, uint64_t now)
{
    stm32f4_soc_t *s = ctx;
    int reg = stm32f4_tim_extsel_code(source, 0), inj = stm32f4_tim_extsel_code(source, 1);
    for (int i = 0; i < STM32F4_SOC_ADCS; i++) {
        if (reg >= 0) stm32f4_adc_ext_trigger(&s->adc[i], false, (unsigned)reg, rising != 0, now);
        if (inj >= 0) stm32f4_adc_ext_trigger(&s->adc[i], true, (unsigned)inj, rising != 0, now);
    }
    stm32_tim_links_trgo(&s->links, source, rising, now);
}

/* The timers' compare and update events the ADCs' external triggers take now (EXTEN/JEXTEN on, the
 * EXTSEL/JEXTSEL codes of tables 69/70) and the TRGOs a slave timer takes: only those become the timers'
 * events (the others cost nothing). */
static void trigger_wants(stm32f4_soc_t *s)
{
    uint32_t m[STM32F4_TIM_COUNT] = { 0 };
    for (unsigned i = 0; i < STM32F4_TIM_COUNT; i++) {
        for (unsigned a = 0; a < STM32F4_SOC_ADCS; a++) {
            uint32_t cr2 = s->adc[a].seq.cr2;
            unsigned ext = (cr2 >> 28) & 3u ? (cr2 >> 24) & 0xFu : 15u, jext = (cr2 >> 20) & 3u ? (cr2 >> 16) & 0xFu : 15u;
            m[i] |= stm32f4_tim_adc_wants(stm32f4_tim[i].d.n, ext, jext);
        }
    }
    stm32_tim_links_wants(&s->links, m);
    for (unsigned i = 0; i < STM32F4_TIM_COUNT; i++) stm32_tim_trigger_want(&s->tim[i], m[i]);
}

/* A timer's register write, then the TRGOs the slaves take again (SMCR may have changed); a slave now
 * gated by a TRGO takes its level (MMS enable or OCxREF: a level, not only edges). */
static mmio_status_t soc_tim_write(void *self, uint32_t off, unsigned size, uint32_t v)
{
    stm32f1_tim_t *t = self;
    unsigned i = t->n - 1u;
    stm32f4_soc_t *s = (stm32f4_soc_t *)(void *)((char *)(t - i) - offsetof(stm32f4_soc_t, tim));
    mmio_status_t st = stm32_tim_write(self, off, size, v);
    trigger_wants(s);
    stm32_tim_links_written(&s->links, t);
    return st;
}

/* An ADC's register write, then the timers' wanted events again (CR2's triggers may have changed). */
static mmio_status_t soc_adc_write(void *self, uint32_t off, unsigned size, uint32_t v)
{
    stm32f4_adc_t *a = self;
    stm32f4_soc_t *s = (stm32f4_soc_t *)(void *)((char *)(a - (a->index - 1u)) - offsetof(stm32f4_soc_t, adc));
    mmio_status_t st = stm32f4_adc_ops.write(self, off, size, v);
    trigger_wants(s);
    return st;
}

/* A pin's level to EXTI (SYSCFG's EXTICR picks the port) and to the board. */
static void soc_pin(void *ctx, unsigned port, unsigned pin, int level)
{
    stm32f4_soc_t *s = ctx;
    stm32f4_exti_pin(&s->exti, port, pin, level);
    if (s->io.pin) s->io.pin(s->io.pin_ctx, port, pin, level);
}

/* ---- the models and where they sit ---- */
static void init_system(stm32f4_soc_t *s, uint32_t hse_hz, mmio_irq_t irq, mmio_bus_t bus)
{
    stm32f4_rcc_init(&s->rcc, STM32F4_F405, hse_hz);
    const mmio_clocks_t *clk = stm32f4_rcc_clocks(&s->rcc);
    stm32f4_pwr_init(&s->pwr, &s->rcc);
    stm32f4_flash_init(&s->flash, STM32F4_F405, NULL, 1024u << 10, clk, irq); /* the memory: the core's, below */
    stm32f4_syscfg_init(&s->syscfg, 0);
    stm32f4_exti_init(&s->exti, &s->syscfg, irq);
    for (unsigned p = 0; p < STM32F4_SOC_PORTS; p++) stm32f4_gpio_init(&s->gpio[p], p, soc_pin, s);
    stm32f4_dma_init(&s->dma[0], 1, bus, irq);
    stm32f4_dma_init(&s->dma[1], 2, bus, irq);
    place(s, STM32F4_RCC_BASE, STM32F4_RCC_SIZE, &stm32f4_rcc_ops, &s->rcc, 0, 0);
    place(s, STM32F4_PWR_BASE, STM32F4_PWR_SIZE, &stm32f4_pwr_ops, &s->pwr, APB1ENR, PWREN);
    place(s, STM32F4_FLASH_REG_BASE, STM32F4_FLASH_REG_SIZE, &stm32f4_flash_ops, &s->flash, 0, 0);
    place(s, STM32F4_SYSCFG_BASE, STM32F4_SYSCFG_SIZE, &stm32f4_syscfg_ops, &s->syscfg, APB2ENR, SYSCFGEN);
    place(s, STM32F4_EXTI_BASE, STM32F4_SYSCFG_SIZE, &stm32f4_exti_ops, &s->exti, 0, 0);
    for (unsigned p = 0; p < STM32F4_SOC_PORTS; p++)
        place(s, STM32F4_GPIO_BASE(p), STM32F4_GPIO_SIZE, &stm32f4_gpio_ops, &s->gpio[p], AHB1ENR, 1u << p);
    place(s, STM32F4_DMA1_BASE, STM32F4_DMA_SIZE, &stm32f4_dma_ops, &s->dma[0], AHB1ENR, DMA1EN);
    place(s, STM32F4_DMA2_BASE, STM32F4_DMA_SIZE, &stm32f4_dma_ops, &s->dma[1], AHB1ENR, DMA2EN);
}

static void init_analog_timers(stm32f4_soc_t *s, mmio_irq_t irq, mmio_dma_req_t dreq)
{
    const mmio_clocks_t *clk = stm32f4_rcc_clocks(&s->rcc);
    static const unsigned adc_dreq[STM32F4_SOC_ADCS] = { STM32F4_DREQ_ADC1, STM32F4_DREQ_ADC2, STM32F4_DREQ_ADC3 };
    double vref = s->io.vref_v > 0 ? s->io.vref_v : VREF_DEFAULT_V;
    stm32f4_adc_common_init(&s->adc_common, clk, irq);
    s->adc_ops = stm32f4_adc_ops;
    s->adc_ops.write = soc_adc_write;
    for (unsigned i = 0; i < STM32F4_SOC_ADCS; i++) {
        stm32f4_adc_init(&s->adc[i], &s->adc_common, i + 1, dreq, adc_dreq[i], s->io.volts, s->io.volts_ctx, vref);
        place(s, STM32F4_ADC_BASE(i + 1), STM32F4_ADC_SIZE, &s->adc_ops, &s->adc[i], APB2ENR, 1u << (8 + i));
    }
    place(s, STM32F4_ADC_COMMON_BASE, STM32F4_ADC_SIZE, &stm32f4_adc_common_ops, &s->adc_common, 0, 0);
    stm32_tim_trigger_t trig = { soc_trigger, s };
    for (unsigned i = 0; i < STM32F4_TIM_COUNT; i++) {
        const stm32f4_tim_inst_t *t = &stm32f4_tim[i];
        stm32f4_tim_init(&s->tim[i], i, clk, irq, dreq, trig);
        s->tim_ops[i] = stm32f4_tim_ops[i];
        s->tim_ops[i].write = soc_tim_write;
        place(s, t->base, STM32F4_TIM_SIZE, &s->tim_ops[i], &s->tim[i], t->d.apb == 2 ? APB2ENR : APB1ENR, t->enable);
    }
    s->links = (stm32_tim_links_t){ s->tim, STM32F4_TIM_COUNT, stm32f4_tim_itr };
    stm32_tim_links_init(&s->links);
    trigger_wants(s);
}

static void init_i2c(stm32f4_soc_t *s, mmio_irq_t irq, mmio_dma_req_t dreq)
{
    const mmio_clocks_t *clk = stm32f4_rcc_clocks(&s->rcc);
    static const unsigned i2c_dreq[STM32F4_SOC_I2CS][2] = {
        { STM32F4_DREQ_I2C1_TX, STM32F4_DREQ_I2C1_RX }, { STM32F4_DREQ_I2C2_TX, STM32F4_DREQ_I2C2_RX },
        { STM32F4_DREQ_I2C3_TX, STM32F4_DREQ_I2C3_RX } };
    for (unsigned n = 1; n <= STM32F4_SOC_I2CS; n++) {
        stm32_i2c_init(&s->i2c[n - 1], n, clk, irq, dreq, i2c_dreq[n - 1][0], i2c_dreq[n - 1][1]);
        place(s, STM32F4_I2C_BASE(n), STM32_I2C_SIZE, &stm32_i2c_ops, &s->i2c[n - 1], APB1ENR, 1u << (20 + n));
    }
}

/* USART1-3, UART4/5, USART6 (the F1 USART model: the same registers, RM0090 30.6): bases table 1,
 * enable bits 6.3.13 APB1ENR (USART2/3, UART4/5: bits 17-20) and 6.3.14 APB2ENR (USART1 bit 4, USART6
 * bit 5), NVIC lines table 61, DMA requests tables 42/43 */
static void init_usart(stm32f4_soc_t *s, mmio_irq_t irq, mmio_dma_req_t dreq)
{
    static const struct { uint32_t base, enr, bit; unsigned irq, apb, tx, rx; } u6[STM32F4_SOC_USARTS] = {
        { STM32F4_USART1_BASE, APB2ENR, 1u << 4, 37, 2, STM32F4_DREQ_USART1_TX, STM32F4_DREQ_USART1_RX },
        { STM32_USART2_BASE, APB1ENR, 1u << 17, 38, 1, STM32F4_DREQ_USART2_TX, STM32F4_DREQ_USART2_RX },
        { STM32_USART3_BASE, APB1ENR, 1u << 18, 39, 1, STM32F4_DREQ_USART3_TX, STM32F4_DREQ_USART3_RX },
        { STM32F4_UART4_BASE, APB1ENR, 1u << 19, 52, 1, STM32F4_DREQ_UART4_TX, STM32F4_DREQ_UART4_RX },
        { STM32F4_UART5_BASE, APB1ENR, 1u << 20, 53, 1, STM32F4_DREQ_UART5_TX, STM32F4_DREQ_UART5_RX },
        { STM32F4_USART6_BASE, APB2ENR, 1u << 5, 71, 2, STM32F4_DREQ_USART6_TX, STM32F4_DREQ_USART6_RX },
    };
    for (unsigned i = 0; i < STM32F4_SOC_USARTS; i++) {
        stm32_usart_t *u = &s->usart[i];
        stm32_usart_init(u, i + 1, stm32f4_rcc_clocks(&s->rcc), irq, dreq, s->io.usart_sink, s->io.usart_ctx);
        u->irq_n = u6[i].irq, u->apb = u6[i].apb, u->dma_tx = u6[i].tx, u->dma_rx = u6[i].rx;
        place(s, u6[i].base, STM32_USART_SIZE, &stm32_usart_ops, u, u6[i].enr, u6[i].bit);
    }
}

/* SPI1-3 (the F1 SPI model: the same registers in SPI mode, RM0090 28.5): bases table 1, SPI1 APB2ENR
 * bit 12 on PCLK2, SPI2/3 APB1ENR bits 14/15 on PCLK1 (6.3.13-6.3.14), NVIC lines 35, 36, 51 (table 61),
 * DMA requests tables 42/43 (SPI1 on DMA2, SPI2/3 on DMA1); slaves attached by the board */
static void init_spi(stm32f4_soc_t *s, mmio_irq_t irq, mmio_dma_req_t dreq)
{
    static const struct { uint32_t base, enr, bit; unsigned irq, tx, rx; } sp[STM32F4_SOC_SPIS] = {
        { STM32_SPI1_BASE, APB2ENR, 1u << 12, 35, STM32F4_DREQ_SPI1_TX, STM32F4_DREQ_SPI1_RX },
        { STM32_SPI2_BASE, APB1ENR, 1u << 14, 36, STM32F4_DREQ_SPI2_TX, STM32F4_DREQ_SPI2_RX },
        { STM32F4_SPI3_BASE, APB1ENR, 1u << 15, 51, STM32F4_DREQ_SPI3_TX, STM32F4_DREQ_SPI3_RX },
    };
    for (unsigned i = 0; i < STM32F4_SOC_SPIS; i++) {
        stm32_spi_t *p = &s->spi[i];
        stm32_spi_init(p, i + 1, stm32f4_rcc_clocks(&s->rcc), irq, dreq, (stm32_spi_slave_t){ NULL, NULL });
        p->irq_n = sp[i].irq, p->dma_tx = sp[i].tx, p->dma_rx = sp[i].rx;
        place(s, sp[i].base, STM32_SPI_SIZE, &stm32_spi_ops, p, sp[i].enr, sp[i].bit);
    }
}

/* The firmware's store into flash, to the FLASH interface (RM0090 3.5.4) at its cycle. */
static mmio_status_t soc_flash_write(void *ctx, uint32_t off, unsigned size, uint32_t value, uint64_t now)
{
    stm32f4_soc_t *s = ctx;
    stm32f4_flash_ops.advance(&s->flash, now);
    return stm32f4_flash_mem_write(&s->flash, off, size, value);
}

int stm32f4_soc_init(stm32f4_soc_t *soc, armcore_t **core, const armcore_cfg_t *cfg, uint32_t hse_hz,
                     const stm32f4_soc_io_t *io, char *err, size_t errn)
{
    memset(soc, 0, sizeof *soc);
    if (io) soc->io = *io;
    mmio_irq_t irq = { soc_irq, soc };
    mmio_bus_t bus = { soc_bus_read, soc_bus_write, soc };
    mmio_dma_req_t dreq = { soc_dreq, soc };
    init_system(soc, hse_hz, irq, bus);
    init_analog_timers(soc, irq, dreq);
    init_i2c(soc, irq, dreq);
    init_usart(soc, irq, dreq);
    init_spi(soc, irq, dreq);
    if (cfg->image->mcu->flash_bytes != soc->flash.size || cfg->image->mcu->core != ARMCORE_M4)
        return snprintf(err, errn, "mmsim: the STM32F405 SoC runs stm32f405xg images only"), -1;
    if (soc->overflow) return snprintf(err, errn, "mmsim: the STM32F405 SoC has more regions than its table"), -1;
    armcore_cfg_t c = *cfg;
    c.regions = soc->region, c.nregions = soc->nregions;
    c.clocks = stm32f4_rcc_clocks(&soc->rcc), c.hclk_hz = STM32F4_HSI_HZ;
    c.flash_write = soc_flash_write, c.flash_ctx = soc;
    soc->core = armcore_new(&c, err, errn);
    if (!soc->core) return -1;
    soc->flash.mem = armcore_flash(soc->core);
    if (core) *core = soc->core;
    return 0;
}

void stm32f4_soc_free(stm32f4_soc_t *soc)
{
    armcore_free(soc->core);
    soc->core = NULL;
}

stm32f4_gpio_t *stm32f4_soc_gpio(stm32f4_soc_t *soc, unsigned port) { return port < STM32F4_SOC_PORTS ? &soc->gpio[port] : NULL; }
stm32_i2c_t *stm32f4_soc_i2c(stm32f4_soc_t *soc, unsigned n) { return n >= 1 && n <= STM32F4_SOC_I2CS ? &soc->i2c[n - 1] : NULL; }
stm32_usart_t *stm32f4_soc_usart(stm32f4_soc_t *soc, unsigned n) { return n >= 1 && n <= STM32F4_SOC_USARTS ? &soc->usart[n - 1] : NULL; }
stm32_spi_t *stm32f4_soc_spi(stm32f4_soc_t *soc, unsigned n) { return n >= 1 && n <= STM32F4_SOC_SPIS ? &soc->spi[n - 1] : NULL; }
stm32f1_tim_t *stm32f4_soc_tim(stm32f4_soc_t *soc, unsigned i) { return i < STM32F4_TIM_COUNT ? &soc->tim[i] : NULL; }
const mmio_clocks_t *stm32f4_soc_clocks(const stm32f4_soc_t *soc) { return stm32f4_rcc_clocks(&soc->rcc); }

unsigned long stm32f4_soc_gated_accesses(const stm32f4_soc_t *soc)
{
    unsigned long n = 0;
    for (unsigned i = 0; i < soc->ngates; i++) n += soc->gate[i].off_accesses;
    return n;
}
