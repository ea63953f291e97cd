/* fputest.c - the Cortex-M4F's floating-point context across exceptions
 * (ARMv7-M ARM DDI 0403E B1.5.6-B1.5.8, B3.2.20; PM0214 2.3.7 and 4.6):
 * built for an FPU (-mfpu=fpv4-sp-d16 -mfloat-abi=hard) and run on the
 * stm32f405xg by test/unit/test_armcore.c. Thread code holding S0-S15 and FPSCR
 * is preempted by an interrupt that overwrites them, itself preempted by a
 * higher one that overwrites them again: each level must find its own
 * values after the return, which only the extended (26-word) frame gives. */
#include <stdint.h>

#include "armtest.h"

__attribute__((section(".mailbox"))) mailbox_t mb;

enum { FP_NESTED = 1, FP_NONE };

#define FPCCR REG(0xE000EF34u) /* B3.2.20 */
#define FPCAR REG(0xE000EF38u)
#define CPACR REG(0xE000ED88u)

static const uint32_t thread_vals[16] = { 0x3F800000, 0x40000000, 0x40400000, 0x40800000, 0x40A00000, 0x40C00000, 0x40E00000, 0x41000000,
                                          0x41100000, 0x41200000, 0x41300000, 0x41400000, 0x41500000, 0x41600000, 0x41700000, 0x41800000 };
static const uint32_t irq0_vals[16] = { 0xC0000001, 0xC0000002, 0xC0000003, 0xC0000004, 0xC0000005, 0xC0000006, 0xC0000007, 0xC0000008,
                                        0xC0000009, 0xC000000A, 0xC000000B, 0xC000000C, 0xC000000D, 0xC000000E, 0xC000000F, 0xC0000010 };
static const uint32_t irq1_vals[16] = { 0 };

#define FP_REGS "s0", "s1", "s2", "s3", "s4", "s5", "s6", "s7", "s8", "s9", "s10", "s11", "s12", "s13", "s14", "s15"
static uint32_t control(void) { uint32_t v; __asm volatile("mrs %0, control" : "=r"(v)); return v; }

void irq1_handler(void)
{
    uint32_t lr;
    __asm volatile("mov %0, lr" : "=r"(lr));
    mb.v[5] = lr;
    __asm volatile("vldmia %0, {s0-s15}\n vmsr fpscr, %1" :: "r"(irq1_vals), "r"(0x00400000u) : FP_REGS, "memory");
}

void irq0_handler(void)
{
    uint32_t lr, sp, fpscr;
    __asm volatile("mov %0, lr\n mov %1, sp" : "=r"(lr), "=r"(sp));
    mb.v[2] = control(), mb.v[3] = lr, mb.v[6] = FPCAR, mb.v[7] = FPCCR, mb.v[9] = sp;
    if (mb.scenario != FP_NESTED) return;
    /* S0-S15 and FPSCR of our own, then the higher IRQ1 overwrites them: ours must come back */
    __asm volatile("vldmia %1, {s0-s15}\n vmsr fpscr, %2\n"
                   "mrs r0, control\n str r0, [%3]\n"
                   "str %4, [%5]\n dsb\n isb\n"
                   "vstmia %6, {s0-s15}\n vmrs %0, fpscr"
                   : "=&r"(fpscr)
                   : "r"(irq0_vals), "r"(0x00800000u), "r"(&mb.v[4]), "r"(2u), "r"(&NVIC_ISPR0), "r"(&mb.log[16])
                   : FP_REGS, "r0", "memory");
    mb.v[10] = fpscr;
    mb.v[12] = REG(mb.v[6]), mb.v[13] = REG(mb.v[6] + 0x40u); /* the frame's S0 and FPSCR, read after our FP use (B1.5.7) */
}

/* Thread code: its S0-S15 and FPSCR loaded, IRQ0 pended, all of them read back after the return. */
static void thread_fp(void)
{
    uint32_t fpscr;
    NVIC_IPR(0) = 0x40; NVIC_IPR(1) = 0x00; NVIC_ISER0 = 3u;
    __asm volatile("vldmia %1, {s0-s15}\n vmsr fpscr, %2\n"
                   "mrs r0, control\n str r0, [%3]\n"
                   "str %4, [%5]\n dsb\n isb\n"
                   "vstmia %6, {s0-s15}\n vmrs %0, fpscr"
                   : "=&r"(fpscr)
                   : "r"(thread_vals), "r"(0x03C00000u), "r"(&mb.v[0]), "r"(1u), "r"(&NVIC_ISPR0), "r"(&mb.log[0])
                   : FP_REGS, "r0", "memory");
    mb.v[1] = control(), mb.v[8] = fpscr;
}

int main(void)
{
    uint32_t sp;
    mb.scenario = FAKE_SCENARIO;
    mb.v[15] = FPCCR;
    CPACR |= 0xFu << 20; /* CP10, CP11 full access before any FP instruction (PM0214 4.6.1) */
    __asm volatile("dsb\n isb" ::: "memory");
    mb.v[14] = CPACR;
    switch (mb.scenario) {
    case FP_NESTED: thread_fp(); break;
    case FP_NONE: /* no FP instruction yet: the basic frame */
        NVIC_ISER0 = 1u;
        __asm volatile("mov %0, sp" : "=r"(sp));
        mb.v[11] = sp;
        NVIC_ISPR0 = 1u;
        __asm volatile("dsb\n isb" ::: "memory");
        mb.v[1] = control();
        break;
    }
    mb.done = 1;
    return 0;
}
