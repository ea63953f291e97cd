/* stm32_adcseq.h - the conversion engine the STM32F1's ADC (RM0008 rev 21
 * section 11, stm32f1_adc.c) and the STM32F4's (RM0090 rev 19 section 13,
 * stm32f4_adc.c) share: one register file at the same offsets (RM0008
 * 11.12.15 and RM0090 13.13.18 register maps: SR, CR1, CR2, SMPR1/2,
 * JOFR1-4, HTR, LTR, SQR1-3, JSQR, JDR1-4, DR), the regular and injected
 * groups' sequencing (SCAN, CONT, an injected group interrupting a regular
 * one, which resumes after it), the sampling instant and the end of each
 * conversion, the results aligned into DR/JDRx, the analog watchdog, the
 * EOC/JEOC flags, the overrun, the regular DMA request and the interrupt
 * level. What differs between the families is data (stm32_adcseq_family_t:
 * bit positions, the sample-time and resolution tables, the trigger
 * latencies) and a few hooks (the clock, the analog inputs, the IRQ line,
 * CR2's write, a narrow write's lanes), each beside its manual's section in
 * the family's file.
 * A family's model struct holds its stm32_adcseq_t as its FIRST member, so
 * the engine's mmio operations take the model itself as `self`. */
#ifndef ARM_STM32_ADCSEQ_H
#define ARM_STM32_ADCSEQ_H

#include <stdbool.h>
#include <stdint.h>

#include "arm/mmio.h"

typedef struct stm32_adcseq stm32_adcseq_t;

/* Register offsets, the same on both families (RM0008 11.12, RM0090 13.13). */
enum {
    STM32_ADCSEQ_SR = 0x00, STM32_ADCSEQ_CR1 = 0x04, STM32_ADCSEQ_CR2 = 0x08, STM32_ADCSEQ_SMPR1 = 0x0C,
    STM32_ADCSEQ_SMPR2 = 0x10, STM32_ADCSEQ_JOFR1 = 0x14, STM32_ADCSEQ_HTR = 0x24, STM32_ADCSEQ_LTR = 0x28,
    STM32_ADCSEQ_SQR1 = 0x2C, STM32_ADCSEQ_SQR2 = 0x30, STM32_ADCSEQ_SQR3 = 0x34, STM32_ADCSEQ_JSQR = 0x38,
    STM32_ADCSEQ_JDR1 = 0x3C, STM32_ADCSEQ_DR = 0x4C,
};
/* Bits at the same place on both families. SR (RM0008 11.12.1, RM0090 13.13.1); SR_OVR is the F4's only. */
#define STM32_ADCSEQ_SR_AWD   (1u << 0)
#define STM32_ADCSEQ_SR_EOC   (1u << 1)
#define STM32_ADCSEQ_SR_JEOC  (1u << 2)
#define STM32_ADCSEQ_SR_JSTRT (1u << 3)
#define STM32_ADCSEQ_SR_STRT  (1u << 4)
#define STM32_ADCSEQ_SR_OVR   (1u << 5)
/* CR1 (RM0008 11.12.2, RM0090 13.13.2); OVRIE is the F4's only, the F1 never stores bit 26. */
#define STM32_ADCSEQ_CR1_AWDCH  0x1Fu
#define STM32_ADCSEQ_CR1_EOCIE  (1u << 5)
#define STM32_ADCSEQ_CR1_AWDIE  (1u << 6)
#define STM32_ADCSEQ_CR1_JEOCIE (1u << 7)
#define STM32_ADCSEQ_CR1_SCAN   (1u << 8)
#define STM32_ADCSEQ_CR1_AWDSGL (1u << 9)
#define STM32_ADCSEQ_CR1_JAWDEN (1u << 22)
#define STM32_ADCSEQ_CR1_AWDEN  (1u << 23)
#define STM32_ADCSEQ_CR1_OVRIE  (1u << 26)
/* CR2 (RM0008 11.12.3, RM0090 13.13.3) */
#define STM32_ADCSEQ_CR2_ADON  (1u << 0)
#define STM32_ADCSEQ_CR2_CONT  (1u << 1)
#define STM32_ADCSEQ_CR2_DMA   (1u << 8)
#define STM32_ADCSEQ_CR2_ALIGN (1u << 11)

#define STM32_ADCSEQ_IDLE 0
#define STM32_ADCSEQ_REG  1
#define STM32_ADCSEQ_INJ  2

/* A family: its register map's differences as data, its wiring as hooks. */
typedef struct {
    uint32_t cr2_swstart, cr2_jswstart; /* SWSTART, JSWSTART: cleared as their group starts */
    uint32_t cr2_eocs;           /* EOCS (0: none): EOC after each regular conversion, and overrun detection */
    uint32_t sr_ovr;             /* OVR (0: no overrun detection) */
    uint32_t sr_inj_eoc;         /* what an injected group's end sets in SR beside JEOC */
    uint32_t sr_w0;              /* SR's rc_w0 bits */
    uint32_t smpr1_mask;         /* SMPR1's writable bits */
    bool late_regular_at_inj_end; /* a regular start due during an injected group starts at its end */
    unsigned inj_left_drop;      /* the bits an injected left-aligned result sits below a regular one (SEXT) */
    unsigned res_shift, res_mask; /* CR1's RES field (mask 0: one resolution) */
    uint8_t res_bits[4];         /* RES codes: bits of a result */
    uint16_t conv_half[4];       /* RES codes: the conversion after sampling, half ADC clock cycles */
    uint16_t smp_half[8];        /* SMPx codes: the sampling time, half ADC clock cycles */
    uint16_t tlat_inj_half, tlat_reg_half; /* trigger latencies, half ADC clock cycles */
    /* core cycles of half ADC clock cycles at the ADC clock now */
    uint64_t (*cycles)(const stm32_adcseq_t *s, uint64_t half_ticks);
    /* the voltage channel ch sees at cycle t */
    double (*volts)(const stm32_adcseq_t *s, unsigned ch, uint64_t t);
    /* irq_level changed (or may have): drive the line */
    void (*irq)(stm32_adcseq_t *s);
    /* a CR2 write (the word, its lanes merged) */
    void (*write_cr2)(stm32_adcseq_t *s, uint32_t v);
    /* the word a write of size bytes at off makes of the register's old value */
    uint32_t (*lanes)(uint32_t old, uint32_t off, unsigned size, uint32_t value);
} stm32_adcseq_family_t;

struct stm32_adcseq {
    /* wiring, kept across reset */
    const stm32_adcseq_family_t *fam;
    mmio_dma_req_t dma;          /* .request NULL: no DMA */
    unsigned dma_line;           /* the request's number on dma */
    double vref_v;               /* VREF+, V (VDDA on packages without a VREF+ pin) */
    uint32_t cr1_keep, cr1_unmodeled; /* CR1's stored bits; those a write reports unmodeled */
    /* registers */
    uint32_t sr, cr1, cr2, smpr1, smpr2, jofr[4], htr, ltr, sqr1, sqr2, sqr3, jsqr, jdr[4], dr;
    /* state */
    uint64_t now;                /* the cycle advance() last reached */
    uint64_t clear_at[2];        /* a self-clearing CR2 bit, clear_bit[k], clears at clear_at[k] (MMIO_NEVER: none); */
    uint32_t clear_bit[2];       /* the family's (the F1's RSTCAL, CAL), slot 0 first within a cycle */
    uint64_t reg_start, inj_start; /* a group's start (trigger + latency), MMIO_NEVER: none */
    bool reg_sw, inj_sw;         /* that start came from SWSTART / JSWSTART */
    int group;                   /* STM32_ADCSEQ_IDLE, _REG or _INJ: the group converting */
    unsigned pos;                /* the rank converting within its group */
    unsigned reg_pos;            /* the regular rank to resume after an injected group */
    bool reg_resume;             /* an injected group interrupted the regular group */
    uint64_t sample_at, end_at;  /* the conversion's sampling instant and end, MMIO_NEVER: none */
    unsigned channel;            /* the channel converting */
    uint16_t code;               /* its result once sampled */
    bool dr_unread;              /* a regular result not yet read */
    bool dma_level, irq_level;
    unsigned long conversions;   /* regular and injected, since power-on */
};

/* Wiring; then stm32_adcseq_reset. */
void stm32_adcseq_init(stm32_adcseq_t *s, const stm32_adcseq_family_t *fam, mmio_dma_req_t dma, unsigned dma_line,
                       double vref_v);
uint64_t stm32_adcseq_cycles(const stm32_adcseq_t *s, uint64_t half_ticks);
/* A group's trigger at cycle t (sw: from (J)SWSTART): it starts after its latency; ignored with ADON 0
 * or while that group converts or is about to. */
void stm32_adcseq_trigger(stm32_adcseq_t *s, int group, bool sw, uint64_t t);
/* ADON 0: nothing converts or waits. */
void stm32_adcseq_power_off(stm32_adcseq_t *s);
void stm32_adcseq_set_dma(stm32_adcseq_t *s, bool level);
/* mmio operations on the family's model (its first member the engine) */
mmio_status_t stm32_adcseq_read(void *self, uint32_t off, unsigned size, uint32_t *value);
mmio_status_t stm32_adcseq_write(void *self, uint32_t off, unsigned size, uint32_t value);
void stm32_adcseq_advance(void *self, uint64_t now);
uint64_t stm32_adcseq_next_event(void *self);
void stm32_adcseq_reset(void *self);

#endif
