/* stm32f1_tim.h - the STM32F1's TIM1 (advanced-control, RM0008 section 14)
 * and TIM2-TIM4 (general-purpose, section 15): one model, the advanced
 * timer's extras (repetition counter, BDTR's MOE, its four interrupt lines)
 * enabled for TIM1. The same timer design on the F4 (RM0090 17-20) runs on
 * this model from per-instance descriptions (stm32_tim_desc_t: counter
 * width, channels, registers present, IRQs, DMA requests): stm32f4_tim.h.
 *
 * Modeled (RM0008 15.3, 15.4 registers; 14.3, 14.4 for TIM1):
 *   time base   CR1 (CEN, UDIS, URS, OPM, DIR, CMS edge/center 1-3, ARPE),
 *               PSC and ARR with their preloads (PSC takes effect at the
 *               update event, ARR at once or at the update with ARPE), CNT,
 *               RCR (TIM1), EGR (UG, CCxG, TG, COMG, BG set their flags)
 *   compare     CCMR1/2 output modes (frozen, active/inactive/toggle on
 *               match, forced, PWM1, PWM2) with OCxPE preload, CCRx; CCxIF
 *               and the match modes' OCxREF at each match (center-aligned:
 *               in the CMS's direction)
 *   outputs     CCER (CCxE, CCxP), BDTR MOE (TIM1); the board reads each
 *               channel as a duty and a polarity (stm32f1_tim_output)
 *   encoder     SMCR SMS 1-3: the counter follows the wheel's quadrature
 *               position the board sets (stm32f1_tim_encoder), in edges:
 *               mode 3 counts every edge (4 per line), modes 1 and 2 the
 *               edges of one channel (2 per line); wraps at ARR with an
 *               update event; DIR reads the last count's direction; CC1P
 *               xor CC2P reverses it
 *   interrupts  DIER, SR (rc_w0) -> TIM1_BRK 24, TIM1_UP 25, TIM1_TRG_COM 26,
 *               TIM1_CC 27, TIM2 28, TIM3 29, TIM4 30 (RM0008 table 63)
 *   DMA         update and CCx requests on DMA1's channels (RM0008 table 78),
 *               CCDS moving the CCx requests to the update event; each
 *               request is a pulse (raised then lowered at once)
 *   capture     CCxS 01/10 with CCxE: an edge the board reports on TIx
 *               (stm32f1_tim_input) of the CCxP polarity, every ICxPSC-th,
 *               copies CNT to CCRx with CCxIF (CCxOF if still set); reading
 *               CCRx clears CCxIF. The input filter (ICxF) is not applied.
 *   master      CR2 MMS (RM0090 17.4.2): TRGO on UG (reset), CEN (enable),
 *               the update event, CC1IF (compare pulse), OC1-4REF (match
 *               modes, and PWM modes when edge-aligned); the CCx events,
 *               each a trigger source (stm32_tim_trigger_t) at its cycle
 *   slave       SMCR SMS reset (100), gated (101), trigger (110) from
 *               TI1F_ED, TI1FP1, TI2FP2 (the board's input edges) or ITR0-3
 *               (another timer's TRGO the board routes): TIF, the action;
 *               external clock mode 1 (111) from ITR0-3: each rising edge
 *               one tick of the counter's clock (through PSC)
 * Not modeled (answer MMIO_UNMODELED when a firmware sets them): external
 * clock mode 1 from TIx, mode 2 (ECE), ETRF (TS 111), an unrouted ITRx,
 * a non-reset MMS on a timer without a trigger listener (stm32f1_tim_init),
 * TRGO from OCxREF in PWM mode while center-aligned, TI1S,
 * a capture from TRC (CCxS 11), OCxCE (clear on ETRF),
 * BDTR's break input and dead time, DCR/DMAR (DMA burst); the prescaler in
 * encoder mode (counts are taken undivided); a reserved register (RCR and
 * BDTR on TIM2-4). The pin's waveform edge by edge is not produced: the
 * board reads the duty.
 *
 * Time: the counter counts the timer clock (mmio_clocks_t tim_apb2 for
 * TIM1, tim_apb1 for TIM2-4) divided by PSC+1, converted from core cycles
 * (HCLK) exactly, with the remainder kept; a clock change applies to the
 * whole interval since the last access. */
#ifndef STM32F1_TIM_H
#define STM32F1_TIM_H

#include <stdint.h>

#include "arm/mmio.h"

/* What one timer instance has: the same model serves the F1's TIM1-4 and
 * the F4's TIM1-14 (stm32f4_tim.h) from this description. */
typedef struct {
    const char *name;      /* "TIM1" */
    unsigned n;            /* TIMn */
    uint8_t bits;          /* counter, ARR and CCRx width: 16, or 32 (F4 TIM2/TIM5, RM0090 18.1) */
    uint8_t channels;      /* capture/compare channels: 4, 2 (TIM9/12), 1 (TIM10/11/13/14), 0 (TIM6/7) */
    uint8_t advanced;      /* TIM1/TIM8: RCR, BDTR, complementary bits, four interrupt lines */
    uint8_t apb;           /* 1: counts tim_apb1, 2: tim_apb2 */
    uint8_t has_cr2;       /* CR2 (MMS, CCDS) exists */
    uint8_t has_smcr;      /* SMCR exists (encoder modes when channels == 4) */
    uint16_t irq[4];       /* advanced: BRK, UP, TRG_COM, CC lines; else irq[0] for all */
    uint16_t dma_up, dma_cc[4]; /* the number given to mmio_dma_req_t.request; 0: no request */
    uint8_t up_only;       /* CR1 has no DIR/CMS: counts up only (TIM6/7, TIM9-14) */
} stm32_tim_desc_t;

/* Trigger sources a timer offers other peripherals (an ADC's EXTSEL, another
 * timer's ITR): TRGO (CR2 MMS) and the CCx events, as bits of want masks
 * and as kind in STM32_TIM_TRIG. */
enum { STM32_TIM_TRGO = 0, STM32_TIM_CC1 = 1, STM32_TIM_CC2, STM32_TIM_CC3, STM32_TIM_CC4 };
#define STM32_TIM_TRIG(n, kind) ((unsigned)(n) * 8u + (unsigned)(kind)) /* a source: timer n's kind */

/* An edge on a trigger source at core cycle now (the exact cycle of the
 * compare or the update, whatever the advance's step): a CCx event is a
 * pulse (a rising then a falling edge at the same cycle); TRGO follows MMS. */
typedef struct {
    void (*trigger)(void *ctx, unsigned source, int rising, uint64_t now);
    void *ctx;
} stm32_tim_trigger_t;

typedef struct {
    unsigned n;                 /* TIMn */
    const stm32_tim_desc_t *d;  /* the instance's description */
    uint32_t cr1, cr2, smcr, dier, sr, ccmr[2], ccer, psc, arr, rcr, ccr[4], bdtr;
    uint32_t cnt;               /* the counter, 16 or 32 bits (d->bits) */
    uint32_t psc_sh, arr_sh, rcr_sh, ccr_sh[4]; /* the shadow (active) registers */
    uint32_t pc;                /* the prescaler's counter: timer clocks since the last count */
    uint32_t rep;               /* TIM1's repetition counter */
    int down;                   /* counting down (DIR, the center-aligned phase, the encoder's last count) */
    uint64_t now;               /* core cycle the state is at */
    uint64_t acc;               /* timer clock progress in 1/hclk of a tick */
    int64_t enc;                /* the wheel's quadrature position (edges) as last set */
    const mmio_clocks_t *clk;
    mmio_irq_t irq;
    mmio_dma_req_t dma;
    uint32_t ic_edges[4];       /* input capture: edges since the last capture (ICxPSC) */
    uint32_t ref;               /* OCxREF per channel (bit i) in the modes that hold it: match, toggle, forced */
    uint32_t irq_out;           /* the interrupt lines held high, one bit per line */
    stm32_tim_trigger_t trig;   /* NULL trigger: no listener */
    uint32_t trig_want;         /* the sources (1 << kind) the listener takes: the compares it stops at */
    int trgo;                   /* TRGO's level in the level modes of MMS (enable, OCxREF) */
    int trgi;                   /* the slave mode's trigger input (TRGI) level */
    int itr_routed;             /* bit x: the board routes another timer's TRGO to ITRx (stm32_tim_itr) */
    /* the cycle of an event inside an advance: state at its start */
    int ev_run;                 /* 1 while run_ticks counts */
    uint64_t ev_now0, ev_acc0, ev_done; /* start cycle, its acc, timer clocks before this batch */
    uint32_t ev_pc;             /* the prescaler's counter at this batch's start */
} stm32f1_tim_t;

/* Channel x's output as a board part sees it. */
typedef struct {
    int enabled;     /* CCxE (and MOE on TIM1): the pin is driven by the timer */
    int running;     /* CEN: the counter runs (stopped: the level stays as it was) */
    int pwm;         /* 1: a PWM, forced or toggle mode (toggle: a 50 % square wave), duty valid;
                        0: another mode (duty -1) */
    double duty;     /* fraction of the period OCxREF is active, 0..1 */
    int active_low;  /* CCxP: the pin is high while OCxREF is inactive */
    double high;     /* fraction of the period the pin is high (duty, or 1 - duty if active_low) */
    double freq_hz;  /* the PWM period's frequency: timer clock / ((PSC+1)(ARR+1)), center-aligned / ((PSC+1) 2 ARR);
                        toggle mode half that */
    int ref;         /* OCxREF now (0/1) */
    int level;       /* the pin now: OCxREF xor CCxP if enabled, else -1 */
} stm32f1_tim_out_t;

/* TIM1..TIM4's tables (index n-1): the same model under each name */
extern const mmio_ops_t stm32f1_tim_ops[4];

/* Power-on for TIMn (1-4): every register 0 (RM0008 15.4) but ARR 0xFFFF
 * (see tim_reset). dma may have a NULL request (no DMA controller). */
void stm32f1_tim_init(stm32f1_tim_t *t, unsigned n, const mmio_clocks_t *clk, mmio_irq_t irq, mmio_dma_req_t dma);
/* The same with a trigger listener (the F1 SoC's: the ADCs' EXTSEL, the ITR links). */
void stm32f1_tim_init_trig(stm32f1_tim_t *t, unsigned n, const mmio_clocks_t *clk, mmio_irq_t irq, mmio_dma_req_t dma,
                           stm32_tim_trigger_t trig);
/* The F1's internal trigger connections (stm32_tim_links_t.itr) and the
 * ADC1/2 trigger sources of EXTSEL (row 0) and JEXTSEL (row 1) codes 0-7
 * (STM32_TIM_TRIG; STM32F1_ADC_NOT_TIM: EXTI or the software start). */
extern const uint8_t stm32f1_tim_itr[4][4];
#define STM32F1_ADC_NOT_TIM 0xFFFFu
extern const uint16_t stm32f1_adc_extsel[2][8];

/* Power-on for the instance desc (which outlives t) with a trigger
 * listener (trig.trigger may be NULL); the listener takes every source
 * until stm32_tim_trigger_want narrows it. */
void stm32_tim_init(stm32f1_tim_t *t, const stm32_tim_desc_t *desc, const mmio_clocks_t *clk, mmio_irq_t irq,
                    mmio_dma_req_t dma, stm32_tim_trigger_t trig);
/* The sources (bits 1 << STM32_TIM_TRGO / _CCx) the listener takes now
 * (an ADC's EXTSEL): only their compares become next_event()s. */
void stm32_tim_trigger_want(stm32f1_tim_t *t, uint32_t kinds);
/* Another timer's TRGO, routed to this one's input ITRitr (0-3; which
 * timer is which ITR: RM0090 table 93/94, the board's data), is now at
 * level rising (an edge) at core cycle now: the slave mode acts if SMCR
 * TS selects it. stm32_tim_route_itr tells the model the board routes
 * ITR0-3, stm32_tim_route_itr_mask the ITRs of mask's bits (else a slave
 * mode on that ITRx is reported unmodeled). */
void stm32_tim_itr(stm32f1_tim_t *t, unsigned itr, int rising, uint64_t now);
void stm32_tim_route_itr(stm32f1_tim_t *t);
void stm32_tim_route_itr_mask(stm32f1_tim_t *t, unsigned mask);
/* A chip's timers linked master to slave (its reference manual's "TIMx
 * internal trigger connection" tables): tim[i] is TIM(i+1), itr[i][x] the
 * timer n whose TRGO reaches TIM(i+1)'s ITRx (0: none there). The SoC
 * calls _init once the timers exist (each told the ITRs routed to it),
 * _trgo from its trigger listener (a TRGO edge to the slaves whose SMCR
 * TS selects it), _wants to add the TRGOs the slaves take now to the
 * want masks (want[i] for TIM(i+1)), and _written after a timer register
 * write (a slave gated by a level TRGO takes its current level). */
typedef struct {
    stm32f1_tim_t *tim;
    unsigned count;
    const uint8_t (*itr)[4];
} stm32_tim_links_t;
void stm32_tim_links_init(const stm32_tim_links_t *l);
void stm32_tim_links_trgo(const stm32_tim_links_t *l, unsigned source, int rising, uint64_t now);
void stm32_tim_links_wants(const stm32_tim_links_t *l, uint32_t *want);
void stm32_tim_links_written(const stm32_tim_links_t *l, stm32f1_tim_t *t);

/* The model's bus functions, for another family's ops tables. */
mmio_status_t stm32_tim_read(void *self, uint32_t off, unsigned size, uint32_t *value);
mmio_status_t stm32_tim_write(void *self, uint32_t off, unsigned size, uint32_t value);
void stm32_tim_advance(void *self, uint64_t now);
uint64_t stm32_tim_next_event(void *self);
void stm32_tim_reset(void *self);

/* The wheel's quadrature position, edges (4 per encoder line; positive
 * forward: channel 1 leads), from core cycle now (>= the last access).
 * In an encoder mode with CEN the counter follows it. */
void stm32f1_tim_encoder(stm32f1_tim_t *t, uint64_t now, int64_t edges);
/* An edge on input TIti (1-4), rising or falling, at core cycle now:
 * captured by the channels that select it (input capture). */
void stm32f1_tim_input(stm32f1_tim_t *t, uint64_t now, unsigned ti, int rising);
/* Channel ch (1-4) now. */
stm32f1_tim_out_t stm32f1_tim_output(const stm32f1_tim_t *t, unsigned ch);

#endif
