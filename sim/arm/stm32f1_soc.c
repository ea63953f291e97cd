/* stm32f1_soc.c - an STM32F103 as one chip (see stm32f1_soc.h). */
#include "stm32f1_soc.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <unicorn/unicorn.h>

#include "arm/stm32f1_map.h"

/* Enable bits not in stm32f1_map.h (RM0008 7.3.6 AHBENR, 7.3.7 APB2ENR, 7.3.8 APB1ENR) */
#define EN_DMA1 (1u << 0)    /* AHB DMA1EN */
#define EN_ADC1 (1u << 9)    /* APB2 ADC1EN */
#define EN_ADC2 (1u << 10)   /* APB2 ADC2EN */
#define EN_SPI1 (1u << 12)   /* APB2 SPI1EN */
#define EN_USART1 (1u << 14) /* APB2 USART1EN */
#define EN_SPI2 (1u << 14)   /* APB1 SPI2EN */
#define EN_USART2 (1u << 17) /* APB1 USART2EN */
#define EN_USART3 (1u << 18) /* APB1 USART3EN */

/* ---- the wiring: lines into the NVIC, the DMA's bus, the reset ---- */
static const uint32_t tim_base[4] = { STM32F1_TIM1_BASE, STM32F1_TIM2_BASE, STM32F1_TIM3_BASE, STM32F1_TIM4_BASE };

/* The model at base changed through another's doing: the core asks its next event again (armcore_cfg_t.reports_links). */
static void touch(stm32f1_soc_t *s, uint32_t base)
{
    if (s->core) armcore_touch(s->core, base);
}

static void touch_all(stm32f1_soc_t *s)
{
    if (s->core) armcore_touch_all(s->core);
}

static void soc_irq(void *ctx, unsigned irq, bool level)
{
    stm32f1_soc_t *s = ctx;
    if (irq >= CORTEXM_IRQ_MAX) return;
    if (level && !s->irq_level[irq]) s->irq_count[irq]++;
    s->irq_level[irq] = level;
    if (s->core) cortexm_set_irq(armcore_cortexm(s->core), irq, level);
}

/* A peripheral's DMA request: the DMA's next event moves. */
static void soc_dma_request(void *ctx, unsigned channel, bool level)
{
    stm32f1_soc_t *s = ctx;
    stm32_dma_request(&s->dma, channel, level);
    touch(s, STM32_DMA1_BASE);
}

static bool soc_bus_read(void *ctx, uint32_t addr, unsigned size, uint32_t *v)
{
    stm32f1_soc_t *s = ctx;
    mmio_bus_t b = armcore_bus(s->core);
    return b.read(b.ctx, addr, size, v);
}

static bool soc_bus_write(void *ctx, uint32_t addr, unsigned size, uint32_t v)
{
    stm32f1_soc_t *s = ctx;
    mmio_bus_t b = armcore_bus(s->core);
    return b.write(b.ctx, addr, size, v);
}

/* The IWDG's timeout: a system reset with IWDGRSTF (RM0008 19.3.2, 7.3.10). */
static void soc_wdg_reset(void *ctx)
{
    stm32f1_soc_t *s = ctx;
    stm32f1_rcc_reset_cause(&s->rcc, STM32F1_RST_IWDG);
    cortexm_t *cm = armcore_cortexm(s->core);
    cm->reset_request = true, cm->attention = true;
    s->resets++;
    touch_all(s);
}

void stm32f1_soc_reset_pin(stm32f1_soc_t *s)
{
    stm32f1_rcc_reset_cause(&s->rcc, STM32F1_RST_PIN);
    cortexm_t *cm = armcore_cortexm(s->core);
    cm->reset_request = true, cm->attention = true;
    s->resets++;
}

/* ---- timers as trigger sources: the ADCs' EXTSEL/JEXTSEL (RM0008 11.12.3), the ITR links (14.4.3, 15.4.3) ---- */

/* A timer's TRGO or CCx edge: a rising one starts the ADC groups whose (J)EXTTRIG and (J)EXTSEL code name it
 * (11.4: the external trigger's rising edge); a TRGO to the timers whose ITRx it is. */
static void soc_trigger(void *ctx, unsigned source, int rising, uint64_t now)
{
    stm32f1_soc_t *s = ctx;
    touch(s, STM32_ADC1_BASE), touch(s, STM32_ADC2_BASE);
    for (unsigned i = 0; i < 4; i++) touch(s, tim_base[i]);
    for (unsigned g = 0; g < 2 && rising; g++)
        for (unsigned code = 0; code < 8; code++)
            if (stm32f1_adc_extsel[g][code] == source)
                for (unsigned a = 0; a < 2; a++) stm32_adc_ext_trigger(&s->adc[a], g == 1, code, now);
    stm32_tim_links_trgo(&s->links, source, rising, now);
}

/* The sources the ADCs' enabled external triggers and the slave timers take now: only those become the
 * timers' events (a timer no one listens to runs as without a listener). */
static void trigger_wants(stm32f1_soc_t *s)
{
    uint32_t m[4] = { 0 };
    for (unsigned a = 0; a < 2; a++) {
        uint32_t cr2 = s->adc[a].seq.cr2;
        unsigned src[2] = { (cr2 & (1u << 20)) ? stm32f1_adc_extsel[0][(cr2 >> 17) & 7u] : STM32F1_ADC_NOT_TIM,
                            (cr2 & (1u << 15)) ? stm32f1_adc_extsel[1][(cr2 >> 12) & 7u] : STM32F1_ADC_NOT_TIM };
        for (unsigned g = 0; g < 2; g++)
            if (src[g] != STM32F1_ADC_NOT_TIM && src[g] / 8u >= 1 && src[g] / 8u <= 4) m[src[g] / 8u - 1u] |= 1u << (src[g] % 8u);
    }
    stm32_tim_links_wants(&s->links, m);
    for (unsigned i = 0; i < 4; i++) {
        uint32_t was = s->tim[i].trig_want;
        stm32_tim_trigger_want(&s->tim[i], m[i]);
        if (s->tim[i].trig_want != was) touch(s, tim_base[i]);
    }
}

static mmio_status_t soc_tim_write(void *self, uint32_t off, unsigned size, uint32_t v)
{
    stm32f1_tim_t *t = self;
    stm32f1_soc_t *s = (stm32f1_soc_t *)(void *)((char *)(t - (t->n - 1u)) - offsetof(stm32f1_soc_t, tim));
    mmio_status_t st = stm32_tim_write(self, off, size, v);
    trigger_wants(s);
    stm32_tim_links_written(&s->links, t);
    return st;
}

static mmio_status_t soc_adc_write(void *self, uint32_t off, unsigned size, uint32_t v)
{
    stm32_adc_t *a = self;
    stm32f1_soc_t *s = (stm32f1_soc_t *)(void *)((char *)(a - (a->index - 1u)) - offsetof(stm32f1_soc_t, adc));
    mmio_status_t st = stm32_adc_ops.write(self, off, size, v);
    trigger_wants(s);
    return st;
}

static void soc_wdg_started(void *ctx)
{
    stm32f1_rcc_lsi_force(&((stm32f1_soc_t *)ctx)->rcc);
    touch(ctx, STM32F1_RCC_BASE);
}

/* RCC's accesses and events switch clocks every model counts with and reset models (APBxRSTR). */
static mmio_status_t soc_rcc_write(void *self, uint32_t off, unsigned size, uint32_t v)
{
    stm32f1_soc_t *s = (stm32f1_soc_t *)(void *)((char *)self - offsetof(stm32f1_soc_t, rcc));
    mmio_status_t st = stm32f1_rcc_ops.write(self, off, size, v);
    touch_all(s);
    return st;
}

static void soc_rcc_advance(void *self, uint64_t now)
{
    stm32f1_rcc_ops.advance(self, now);
    touch_all((stm32f1_soc_t *)(void *)((char *)self - offsetof(stm32f1_soc_t, rcc)));
}

static mmio_status_t soc_flash_write(void *ctx, uint32_t off, unsigned size, uint32_t value, uint64_t now)
{
    stm32f1_soc_t *s = ctx;
    stm32f1_flash_ops.advance(&s->flash, now);
    return stm32f1_flash_mem_write(&s->flash, off, size, value);
}

/* ---- placing the models ---- */
static void place(stm32f1_soc_t *s, uint32_t base, uint32_t size, const mmio_ops_t *ops, void *self)
{
    s->region[s->nregions++] = (mmio_region_t){ base, size, ops, self };
}

static void place_gated(stm32f1_soc_t *s, uint32_t base, uint32_t size, stm32f1_bus_t bus, uint32_t bit,
                        const mmio_ops_t *ops, void *self)
{
    stm32f1_gate_t *g = &s->gate[s->ngates++];
    stm32f1_gate_init(g, &s->rcc, bus, bit, ops, self);
    place(s, base, size, &g->bus_ops, g);
}

static void init_models(stm32f1_soc_t *s, const stm32f1_soc_cfg_t *cfg)
{
    mmio_irq_t irq = { soc_irq, s };
    mmio_dma_req_t dma = { soc_dma_request, s };
    stm32f1_rcc_init(&s->rcc, cfg->hse_hz, irq);
    const mmio_clocks_t *clk = stm32f1_rcc_clocks(&s->rcc);
    stm32f1_afio_init(&s->afio);
    stm32f1_exti_init(&s->exti, &s->afio, irq);
    for (unsigned p = 0; p < STM32F1_GPIO_PORTS; p++) {
        stm32f1_gpio_init(&s->gpio[p], p, &s->exti);
        if (cfg->pin_cb) stm32f1_gpio_on_change(&s->gpio[p], cfg->pin_cb, cfg->pin_ctx);
    }
    for (unsigned n = 1; n <= 4; n++) {
        stm32f1_tim_init_trig(&s->tim[n - 1], n, clk, irq, dma, (stm32_tim_trigger_t){ soc_trigger, s });
        s->tim_ops[n - 1] = stm32f1_tim_ops[n - 1];
        s->tim_ops[n - 1].write = soc_tim_write;
    }
    s->links = (stm32_tim_links_t){ s->tim, 4, stm32f1_tim_itr };
    stm32_tim_links_init(&s->links);
    stm32f1_iwdg_init(&s->iwdg, clk, (stm32f1_iwdg_hooks_t){ soc_wdg_reset, soc_wdg_started, s });
    stm32_adc_init(&s->adc[0], 1, clk, irq, dma, cfg->volts, cfg->volts_ctx, cfg->vdda_v);
    stm32_adc_init(&s->adc[1], 2, clk, irq, (mmio_dma_req_t){ NULL, NULL }, cfg->volts, cfg->volts_ctx, cfg->vdda_v);
    stm32_adc_share_irq(&s->adc[0], &s->adc[1]);
    s->adc_ops = stm32_adc_ops;
    s->adc_ops.write = soc_adc_write;
    s->rcc_ops = stm32f1_rcc_ops;
    s->rcc_ops.write = soc_rcc_write, s->rcc_ops.advance = soc_rcc_advance;
    trigger_wants(s);
    stm32_dma_init(&s->dma, (mmio_bus_t){ soc_bus_read, soc_bus_write, s }, irq);
    for (unsigned u = 0; u < 3; u++) stm32_usart_init(&s->usart[u], u + 1, clk, irq, dma, cfg->sink[u], cfg->sink_ctx[u]);
    for (unsigned i = 0; i < 2; i++) stm32_spi_init(&s->spi[i], i + 1, clk, irq, dma, cfg->spi_slave[i]);
}

static void place_models(stm32f1_soc_t *s)
{
    const uint32_t sz = STM32F1_PERIPH_SIZE;
    place(s, STM32F1_RCC_BASE, sz, &s->rcc_ops, &s->rcc);
    place(s, STM32F1_FLASHIF_BASE, sz, &stm32f1_flash_ops, &s->flash);
    place(s, STM32F1_EXTI_BASE, sz, &stm32f1_exti_ops, &s->exti);
    place(s, STM32F1_IWDG_BASE, sz, &stm32f1_iwdg_ops, &s->iwdg);
    place_gated(s, STM32_DMA1_BASE, STM32_DMA_SIZE, STM32F1_AHB, EN_DMA1, &stm32_dma_ops, &s->dma);
    place_gated(s, STM32F1_AFIO_BASE, sz, STM32F1_APB2, STM32F1_EN_AFIO, &stm32f1_afio_ops, &s->afio);
    for (unsigned p = 0; p < STM32F1_GPIO_PORTS; p++)
        place_gated(s, STM32F1_GPIOA_BASE + sz * p, sz, STM32F1_APB2, STM32F1_EN_GPIO(p), &stm32f1_gpio_ops[p], &s->gpio[p]);
    place_gated(s, STM32_ADC1_BASE, STM32_ADC_SIZE, STM32F1_APB2, EN_ADC1, &s->adc_ops, &s->adc[0]);
    place_gated(s, STM32_ADC2_BASE, STM32_ADC_SIZE, STM32F1_APB2, EN_ADC2, &s->adc_ops, &s->adc[1]);
    place_gated(s, STM32F1_TIM1_BASE, sz, STM32F1_APB2, STM32F1_EN_TIM1, &s->tim_ops[0], &s->tim[0]);
    place_gated(s, STM32F1_TIM2_BASE, sz, STM32F1_APB1, STM32F1_EN_TIM2, &s->tim_ops[1], &s->tim[1]);
    place_gated(s, STM32F1_TIM3_BASE, sz, STM32F1_APB1, STM32F1_EN_TIM3, &s->tim_ops[2], &s->tim[2]);
    place_gated(s, STM32F1_TIM4_BASE, sz, STM32F1_APB1, STM32F1_EN_TIM4, &s->tim_ops[3], &s->tim[3]);
    place_gated(s, STM32_SPI1_BASE, STM32_SPI_SIZE, STM32F1_APB2, EN_SPI1, &stm32_spi_ops, &s->spi[0]);
    place_gated(s, STM32_SPI2_BASE, STM32_SPI_SIZE, STM32F1_APB1, EN_SPI2, &stm32_spi_ops, &s->spi[1]);
    place_gated(s, STM32_USART1_BASE, STM32_USART_SIZE, STM32F1_APB2, EN_USART1, &stm32_usart_ops, &s->usart[0]);
    place_gated(s, STM32_USART2_BASE, STM32_USART_SIZE, STM32F1_APB1, EN_USART2, &stm32_usart_ops, &s->usart[1]);
    place_gated(s, STM32_USART3_BASE, STM32_USART_SIZE, STM32F1_APB1, EN_USART3, &stm32_usart_ops, &s->usart[2]);
}

/* The flash at power-on: the file's bytes (erased if none) under the image's. */
static uint8_t *flash_at_power_on(stm32f1_soc_t *s, const stm32f1_soc_cfg_t *cfg, char *err, size_t errn)
{
    const armimage_t *img = cfg->image;
    uint32_t bytes = img->mcu->flash_bytes;
    uint8_t *mem = malloc(bytes);
    if (!mem) return snprintf(err, errn, "mmsim: out of memory"), NULL;
    memset(mem, 0xFF, bytes);
    s->flash.mem = mem;
    if (cfg->flash_path) {
        char what[64];
        snprintf(what, sizeof what, "%s's flash", img->mcu->name);
        if (stm32f1_flash_load(&s->flash, cfg->flash_path, what, err, errn) != 0) return free(mem), NULL;
    }
    memcpy(mem, img->flash, img->flash_end);
    return mem;
}

stm32f1_soc_t *stm32f1_soc_new(const stm32f1_soc_cfg_t *cfg, char *err, size_t errn)
{
    const armimage_mcu_t *m = cfg->image->mcu;
    if (m->core != ARMCORE_M3 || strncmp(m->name, "stm32f103", 9) != 0)
        return snprintf(err, errn, "mmsim: %s is not an STM32F103", m->name), NULL;
    stm32f1_soc_t *s = calloc(1, sizeof *s);
    if (!s) return snprintf(err, errn, "mmsim: out of memory"), NULL;
    init_models(s, cfg);
    uint32_t page = m->flash_bytes > (128u << 10) ? STM32F1_FLASH_PAGE_HD : STM32F1_FLASH_PAGE_MD;
    stm32f1_flash_init(&s->flash, NULL, m->flash_bytes, page, stm32f1_rcc_clocks(&s->rcc), (mmio_irq_t){ soc_irq, s });
    place_models(s);
    uint8_t *mem = flash_at_power_on(s, cfg, err, errn);
    if (!mem) return free(s), NULL;
    armimage_t img = *cfg->image;
    img.flash = mem;
    armcore_cfg_t cc = { .image = &img, .regions = s->region, .nregions = s->nregions, .clocks = stm32f1_rcc_clocks(&s->rcc),
                         .hclk_hz = STM32F1_HSI_HZ, .verbose = cfg->verbose, .no_idle_skip = cfg->no_idle_skip,
                         .flash_write = soc_flash_write, .flash_ctx = s, .reports_links = true };
    s->core = armcore_new(&cc, err, errn);
    free(mem);
    if (!s->core) return free(s), NULL;
    s->flash.mem = armcore_flash(s->core);
    s->flash.changed = 0;
    if (cfg->flash_path) snprintf(s->flash_path, sizeof s->flash_path, "%s", cfg->flash_path);
    return s;
}

int stm32f1_soc_save(stm32f1_soc_t *s, char *err, size_t errn)
{
    if (!s->flash_path[0] || !s->flash.changed) return 0;
    return stm32f1_flash_save(&s->flash, s->flash_path, err, errn);
}

void stm32f1_soc_free(stm32f1_soc_t *s)
{
    if (!s) return;
    armcore_free(s->core);
    free(s);
}

uint32_t stm32f1_soc_pc(stm32f1_soc_t *s) { return armcore_reg(s->core, UC_ARM_REG_PC); }

const char *stm32f1_irq_name(unsigned irq)
{
    static const char *const names[] = { /* RM0008 rev 21 table 63, positions 0-42 */
        "WWDG", "PVD", "TAMPER", "RTC", "FLASH", "RCC", "EXTI0", "EXTI1", "EXTI2", "EXTI3", "EXTI4",
        "DMA1_Channel1", "DMA1_Channel2", "DMA1_Channel3", "DMA1_Channel4", "DMA1_Channel5", "DMA1_Channel6",
        "DMA1_Channel7", "ADC1_2", "USB_HP_CAN_TX", "USB_LP_CAN_RX0", "CAN_RX1", "CAN_SCE", "EXTI9_5", "TIM1_BRK",
        "TIM1_UP", "TIM1_TRG_COM", "TIM1_CC", "TIM2", "TIM3", "TIM4", "I2C1_EV", "I2C1_ER", "I2C2_EV", "I2C2_ER",
        "SPI1", "SPI2", "USART1", "USART2", "USART3", "EXTI15_10", "RTCAlarm", "USBWakeup",
    };
    return irq < sizeof names / sizeof names[0] ? names[irq] : NULL;
}
