/* stm32f4_tim.c - the STM32F4's timer instances (stm32f4_tim.h): bases
 * RM0090 2.3 table 1, enable bits 6.3.13/6.3.14, interrupt lines table 61,
 * DMA requests tables 42/43, ADC trigger sources tables 69/70. */
#include "arm/stm32f4_tim.h"

/* A timer's DMA requests as RM0090 tables 42/43 name them (stm32f4_dreq_t) */
#define UP(n) STM32F4_DREQ_TIM##n##_UP
#define CH(n, k) STM32F4_DREQ_TIM##n##_CH##k
#define CH4(n) { CH(n, 1), CH(n, 2), CH(n, 3), CH(n, 4) }
#define ADV(nm, n, base, en, brk, up, trg, cc, f411) \
    { { nm, n, 16, 4, 1, 2, 1, 1, { brk, up, trg, cc }, UP(n), CH4(n), 0 }, base, en, f411 }

const stm32f4_tim_inst_t stm32f4_tim[STM32F4_TIM_COUNT] = {
    /* TIM1: TIM1_BRK_TIM9 24, TIM1_UP_TIM10 25, TIM1_TRG_COM_TIM11 26, TIM1_CC 27; APB2ENR bit 0 */
    ADV("TIM1", 1, 0x40010000u, 1u << 0, 24, 25, 26, 27, 1),
    /* TIM2-TIM5: APB1ENR bits 0-3; TIM2 and TIM5 32-bit (RM0090 18.1) */
    { { "TIM2", 2, 32, 4, 0, 1, 1, 1, { 28, 28, 28, 28 }, UP(2), CH4(2), 0 },
      0x40000000u, 1u << 0, 1 },
    { { "TIM3", 3, 16, 4, 0, 1, 1, 1, { 29, 29, 29, 29 }, UP(3), CH4(3), 0 },
      0x40000400u, 1u << 1, 1 },
    /* TIM4: no CH4 request in table 42 */
    { { "TIM4", 4, 16, 4, 0, 1, 1, 1, { 30, 30, 30, 30 }, UP(4), { CH(4, 1), CH(4, 2), CH(4, 3), 0 }, 0 },
      0x40000800u, 1u << 2, 1 },
    { { "TIM5", 5, 32, 4, 0, 1, 1, 1, { 50, 50, 50, 50 }, UP(5), CH4(5), 0 },
      0x40000C00u, 1u << 3, 1 },
    /* TIM6 (TIM6_DAC 54), TIM7 (55): basic, no channels, no SMCR; APB1ENR bits 4, 5 */
    { { "TIM6", 6, 16, 0, 0, 1, 1, 0, { 54, 54, 54, 54 }, UP(6), { 0, 0, 0, 0 }, 1 }, 0x40001000u, 1u << 4, 0 },
    { { "TIM7", 7, 16, 0, 0, 1, 1, 0, { 55, 55, 55, 55 }, UP(7), { 0, 0, 0, 0 }, 1 }, 0x40001400u, 1u << 5, 0 },
    /* TIM8: TIM8_BRK_TIM12 43, TIM8_UP_TIM13 44, TIM8_TRG_COM_TIM14 45, TIM8_CC 46; APB2ENR bit 1 */
    ADV("TIM8", 8, 0x40010400u, 1u << 1, 43, 44, 45, 46, 0),
    /* TIM9-11: APB2ENR bits 16-18, on the TIM1 lines; no DMA, no CR2 (RM0090 19.5, 19.6) */
    { { "TIM9", 9, 16, 2, 0, 2, 0, 1, { 24, 24, 24, 24 }, 0, { 0, 0, 0, 0 }, 1 }, 0x40014000u, 1u << 16, 1 },
    { { "TIM10", 10, 16, 1, 0, 2, 0, 0, { 25, 25, 25, 25 }, 0, { 0, 0, 0, 0 }, 1 }, 0x40014400u, 1u << 17, 1 },
    { { "TIM11", 11, 16, 1, 0, 2, 0, 0, { 26, 26, 26, 26 }, 0, { 0, 0, 0, 0 }, 1 }, 0x40014800u, 1u << 18, 1 },
    /* TIM12-14: APB1ENR bits 6-8, on the TIM8 lines */
    { { "TIM12", 12, 16, 2, 0, 1, 0, 1, { 43, 43, 43, 43 }, 0, { 0, 0, 0, 0 }, 1 }, 0x40001800u, 1u << 6, 0 },
    { { "TIM13", 13, 16, 1, 0, 1, 0, 0, { 44, 44, 44, 44 }, 0, { 0, 0, 0, 0 }, 1 }, 0x40001C00u, 1u << 7, 0 },
    { { "TIM14", 14, 16, 1, 0, 1, 0, 0, { 45, 45, 45, 45 }, 0, { 0, 0, 0, 0 }, 1 }, 0x40002000u, 1u << 8, 0 },
};

#define OPS(nm) \
    { .name = nm, .read = stm32_tim_read, .write = stm32_tim_write, .advance = stm32_tim_advance, \
      .next_event = stm32_tim_next_event, .reset = stm32_tim_reset }
const mmio_ops_t stm32f4_tim_ops[STM32F4_TIM_COUNT] = {
    OPS("TIM1"), OPS("TIM2"), OPS("TIM3"), OPS("TIM4"), OPS("TIM5"), OPS("TIM6"), OPS("TIM7"),
    OPS("TIM8"), OPS("TIM9"), OPS("TIM10"), OPS("TIM11"), OPS("TIM12"), OPS("TIM13"), OPS("TIM14"),
};

#define T(n, k) STM32_TIM_TRIG(n, STM32_TIM_##k)
const uint16_t stm32f4_tim_extsel[2][16] = {
    /* regular, RM0090 table 69 (code 15: EXTI line 11) */
    { T(1, CC1), T(1, CC2), T(1, CC3), T(2, CC2), T(2, CC3), T(2, CC4), T(2, TRGO), T(3, CC1),
      T(3, TRGO), T(4, CC4), T(5, CC1), T(5, CC2), T(5, CC3), T(8, CC1), T(8, TRGO), STM32F4_TIM_EXTI },
    /* injected, table 70 (code 15: EXTI line 15) */
    { T(1, CC4), T(1, TRGO), T(2, CC1), T(2, TRGO), T(3, CC2), T(3, CC4), T(4, CC1), T(4, CC2),
      T(4, CC3), T(4, TRGO), T(5, CC4), T(5, TRGO), T(8, CC2), T(8, CC3), T(8, CC4), STM32F4_TIM_EXTI },
};

/* RM0090 17.4.3 (TIM1: TIM5, TIM2, TIM3, TIM4; TIM8: TIM1, TIM2, TIM4, TIM5), 18.4.3 (TIM2: TIM1, TIM8
 * (ITR1 remappable to the OTG SOFs by TIM2_OR, not modeled), TIM3, TIM4; TIM3: TIM1, TIM2, TIM5, TIM4; TIM4:
 * TIM1, TIM2, TIM3, TIM8; TIM5: TIM2, TIM3, TIM4, TIM8), 19.4.2 (TIM9: TIM2, TIM3; TIM12: TIM4, TIM5) */
const uint8_t stm32f4_tim_itr[STM32F4_TIM_COUNT][4] = {
    { 5, 2, 3, 4 }, { 1, 8, 3, 4 }, { 1, 2, 5, 4 }, { 1, 2, 3, 8 }, { 2, 3, 4, 8 }, { 0 }, { 0 },
    { 1, 2, 4, 5 }, { 2, 3, 0, 0 }, { 0 }, { 0 }, { 4, 5, 0, 0 }, { 0 }, { 0 },
};

void stm32f4_tim_init(stm32f1_tim_t *t, unsigned i, const mmio_clocks_t *clk, mmio_irq_t irq, mmio_dma_req_t dma,
                      stm32_tim_trigger_t trig)
{
    stm32_tim_init(t, &stm32f4_tim[i < STM32F4_TIM_COUNT ? i : STM32F4_TIM2].d, clk, irq, dma, trig);
}

uint32_t stm32f4_tim_adc_wants(unsigned n, unsigned ext, unsigned jext)
{
    uint32_t m = 0;
    unsigned src[2] = { stm32f4_tim_extsel[0][ext & 15u], stm32f4_tim_extsel[1][jext & 15u] };
    for (unsigned g = 0; g < 2; g++)
        if (src[g] != STM32F4_TIM_EXTI && src[g] / 8u == n) m |= 1u << (src[g] % 8u);
    return m;
}

int stm32f4_tim_extsel_code(unsigned source, int injected)
{
    for (int c = 0; c < 15; c++)
        if (stm32f4_tim_extsel[injected ? 1 : 0][c] == source) return c;
    return -1;
}
