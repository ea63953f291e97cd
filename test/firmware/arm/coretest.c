/* coretest.c - scenarios for the Cortex-M core and its system peripherals,
 * one chosen by the host through the fake peripheral (test/unit/test_armcore.c
 * checks what each logs in the mailbox against the ARMv7-M ARM / PM0056). */
#include <stdint.h>

#include "armtest.h"

__attribute__((section(".mailbox"))) mailbox_t mb;

enum { PREEMPT = 1, PREEMPT_HW, TAILCHAIN, PRIMASK, BASEPRI, SYSTICK, COUNTFLAG, DWT, VTOR, WFI, FAULT_UNMAPPED, FAULT_PERIPH,
       UNDEF, SVC, UNMODELED, BITBAND, CLOCK, CHURN, RESET, PRIGROUP_SUB, PRIGROUP_NONE, SPIN, STORM, PSP,
       IDLE_CYCCNT, IDLE_TICK, IDLE_COUNTFLAG, IDLE_BENCH, IDLE_BITS, IDLE_RECUR, IDLE_COUNT, IDLE_MASKED };

#define ISB() __asm volatile("dsb\n isb" ::: "memory")
static void log_ev(uint32_t e) { if (mb.nlog < MAILBOX_LOG) mb.log[mb.nlog++] = e; }
static volatile uint32_t flag, ticks, acc;

static void dwt_on(void) { SCB_DEMCR |= 1u << 24; DWT_CYCCNT = 0; DWT_CTRL |= 1u; }
static void systick(uint32_t reload, uint32_t csr) { SYST_RVR = reload; SYST_CVR = 0; SYST_CSR = csr; }

void systick_handler(void)
{
    switch (mb.scenario) {
    case PREEMPT:
        log_ev('S' << 8 | '1');
        NVIC_ISPR0 = 1u;
        ISB();
        log_ev('S' << 8 | '2');
        SYST_CSR = 0;
        break;
    case PREEMPT_HW:
        log_ev('S' << 8 | '1');
        FAKE_AFTER = 50;
        while (!flag) {}
        log_ev('S' << 8 | '2');
        SYST_CSR = 0;
        break;
    case IDLE_CYCCNT: case IDLE_TICK: case IDLE_BENCH: case IDLE_RECUR: case IDLE_COUNT: case IDLE_MASKED: ticks++; break;
    case SYSTICK: case WFI:
        if (ticks < 16) mb.v[ticks] = DWT_CYCCNT;
        if (++ticks == (mb.scenario == WFI ? 50u : 5u)) SYST_CSR = 0;
        break;
    case STORM: ticks++; break;
    case CHURN:
        acc = acc * 31u + DWT_CYCCNT;
        FAKE_AFTER = 333u + (acc & 255u);
        ticks++;
        break;
    default: log_ev('S'); SYST_CSR = 0; break;
    }
}

void irq0_handler(void)
{
    log_ev('I' << 8 | '0');
    if (mb.scenario == PRIGROUP_SUB || mb.scenario == PRIGROUP_NONE) {
        NVIC_ISPR0 = 2u;
        ISB();
        log_ev('I' << 8 | 'b');
    }
}
void irq1_handler(void) { log_ev('I' << 8 | '1'); }
void irq2_handler(void)
{
    FAKE_LOWER = 2;
    flag = 1;
    if (mb.scenario == CHURN) acc ^= DWT_CYCCNT;
    else log_ev('I' << 8 | '2');
}
static void alt_systick(void) { log_ev('A'); SYST_CSR = 0; }
void svc_handler(void)
{
    uint32_t lr, msp;
    __asm volatile("mov %0, lr\n mrs %1, msp" : "=r"(lr), "=r"(msp));
    if (mb.scenario == PSP) { mb.v[2] = lr, mb.v[3] = msp; log_ev('V'); return; }
    log_ev('V'); SCB_ICSR = 1u << 28; ISB(); log_ev('v');
}
void pendsv_handler(void) { log_ev('P'); }

static void prio_scenarios(uint32_t s)
{
    switch (s) {
    case PREEMPT:
        NVIC_IPR(0) = 0x00; SCB_SHPR(15) = 0xF0; NVIC_ISER0 = 1u;
        systick(999, 7);
        while (SYST_CSR & 1u) {}
        break;
    case PREEMPT_HW:
        NVIC_IPR(2) = 0x00; SCB_SHPR(15) = 0xF0; NVIC_ISER0 = 4u;
        systick(999, 7);
        while (SYST_CSR & 1u) {}
        break;
    case TAILCHAIN:
        __asm volatile("cpsid i");
        NVIC_IPR(0) = 0x40; NVIC_IPR(1) = 0x40; NVIC_ISER0 = 3u; NVIC_ISPR0 = 3u;
        __asm volatile("cpsie i");
        ISB();
        log_ev('M');
        break;
    case PRIMASK:
        __asm volatile("cpsid i");
        NVIC_ISER0 = 1u; NVIC_ISPR0 = 1u;
        ISB();
        for (volatile int i = 0; i < 100; i++) {}
        mb.v[0] = mb.nlog, mb.v[1] = NVIC_ISPR0;
        __asm volatile("cpsie i");
        ISB();
        log_ev('M');
        break;
    case BASEPRI:
        NVIC_IPR(0) = 0x80; NVIC_IPR(1) = 0x20; NVIC_ISER0 = 3u;
        __asm volatile("msr basepri, %0" :: "r"(0x40u));
        NVIC_ISPR0 = 3u;
        ISB();
        log_ev('M' << 8 | '1');
        __asm volatile("msr basepri, %0" :: "r"(0u));
        ISB();
        log_ev('M' << 8 | '2');
        break;
    case PRIGROUP_SUB: case PRIGROUP_NONE:
        SCB_AIRCR = 0x05FA0000u | (s == PRIGROUP_SUB ? 5u : 0u) << 8; /* PRIGROUP 5: group [7:6], subpriority [5:0] */
        NVIC_IPR(0) = 0x60; NVIC_IPR(1) = 0x40; NVIC_ISER0 = 3u;
        NVIC_ISPR0 = 1u;
        ISB();
        log_ev('M');
        break;
    }
}

static void timer_scenarios(uint32_t s)
{
    switch (s) {
    case SYSTICK:
        dwt_on();
        systick(99, 7);
        while (ticks < 5) __asm volatile("wfi");
        break;
    case COUNTFLAG:
        dwt_on();
        systick(49, 1); /* HCLK / 8, no interrupt */
        while (!(SYST_CSR & (1u << 16))) {}
        mb.v[2] = DWT_CYCCNT;
        while (!((mb.v[0] = SYST_CSR) & (1u << 16))) {}
        mb.v[3] = DWT_CYCCNT;
        mb.v[1] = SYST_CSR;
        break;
    case DWT: {
        DWT_CTRL |= 1u; /* TRCENA clear: no counting */
        uint32_t a = DWT_CYCCNT, b, c;
        for (volatile int i = 0; i < 10; i++) {}
        mb.v[0] = DWT_CYCCNT - a;
        SCB_DEMCR |= 1u << 24;
        __asm volatile("b 2f\n 2: ldr %0, [%2]\n nop\n nop\n nop\n nop\n nop\n nop\n nop\n nop\n nop\n nop\n b 1f\n 1: ldr %1, [%2]"
                       : "=&r"(b), "=&r"(c) : "r"(&DWT_CYCCNT));
        mb.v[1] = c - b;
        break;
    }
    case WFI:
        dwt_on();
        systick(999, 7);
        while (ticks < 50) __asm volatile("wfi");
        mb.v[15] = DWT_CYCCNT;
        break;
    case CLOCK:
        for (volatile int i = 0; i < 100; i++) {}
        FAKE_HCLK = 72000000u;
        break;
    case SPIN: case STORM: /* bench/armcore_speed.c: the loop alone, and under SysTick every 200 cycles */
        if (s == STORM) systick(199, 7);
        for (uint32_t i = 0;; i++) {
            acc += i * i;
            if ((i & 63u) == 0) ((volatile uint32_t *)mb.v)[0] = acc;
        }
    case CHURN:
        dwt_on();
        NVIC_IPR(2) = 0x40; NVIC_ISER0 = 4u;
        systick(777, 7);
        for (uint32_t i = 0;; i++) {
            acc += i * i;
            if ((i & 63u) == 0) ((volatile uint32_t *)mb.v)[0] = acc, ((volatile uint32_t *)mb.v)[1] = ticks;
        }
    }
}

/* HAL_Delay's shape (ST's Cube HAL): a call to read a tick an interrupt increments, until n ticks went by. */
__attribute__((noinline)) static uint32_t get_tick(void) { return ticks; }
static void delay_ticks(uint32_t n)
{
    uint32_t start = get_tick();
    while (get_tick() - start < n) {}
}

/* A margin computed the slow way, as bulebule's required_micrometers_to_speed calls soft-float: a call that
 * pushes and pops, stores on its stack, divides by repeated subtraction, and stores a value already there. */
static volatile uint32_t same = 5;
__attribute__((noinline)) static uint32_t margin(uint32_t k)
{
    volatile uint32_t tmp[4];
    uint32_t q = 0, r = 100003u + k;
    for (uint32_t i = 0; i < 4; i++) tmp[i] = r >> i;
    while (r >= 7919u) r -= 7919u, q++;
    same = 5;
    return (q + tmp[3] - tmp[3]) >> 30;
}

static volatile uint32_t count;

static void cyccnt_wait(uint32_t n)
{
    uint32_t s = DWT_CYCCNT;
    while (DWT_CYCCNT - s < n) {}
}

/* The idle loops the core jumps over (test_armcore: the same state with and without skipping). */
static void idle_scenarios(uint32_t s)
{
    switch (s) {
    case IDLE_CYCCNT: /* busy waits on CYCCNT with SysTick interrupting every 10,000 cycles */
        dwt_on();
        systick(9999, 7);
        for (uint32_t i = 0; i < 5; i++) cyccnt_wait(23457u + 1000u * i), mb.v[i] = DWT_CYCCNT;
        SYST_CSR = 0;
        break;
    case IDLE_TICK: /* HAL_Delay on a SysTick tick, then WFI */
        dwt_on();
        systick(999, 7);
        for (uint32_t i = 0; i < 5; i++) delay_ticks(7u + i), mb.v[i] = DWT_CYCCNT;
        for (uint32_t i = 5; i < 8; i++) {
            __asm volatile("wfi");
            mb.v[i] = DWT_CYCCNT;
        }
        SYST_CSR = 0;
        break;
    case IDLE_COUNTFLAG: /* SysTick without its interrupt: COUNTFLAG polled */
        dwt_on();
        systick(4999, 5);
        for (uint32_t i = 0; i < 4; i++) {
            while (!(SYST_CSR & (1u << 16))) {}
            mb.v[i] = DWT_CYCCNT;
        }
        break;
    case IDLE_BITS: /* a CYCCNT bit polled: its exit comes and goes, never jumped over */
        dwt_on();
        for (uint32_t i = 0; i < 6; i++) {
            while (!(DWT_CYCCNT & (1u << 12))) {}
            while (DWT_CYCCNT & (1u << 12)) {}
            mb.v[i] = DWT_CYCCNT;
        }
        break;
    case IDLE_RECUR: /* a wait whose iteration calls, pushes, stores: its state recurs until the next tick */
        dwt_on();
        systick(9999, 7);
        for (uint32_t i = 0; i < 5; i++) {
            uint32_t until = get_tick() + 3u + i;
            while (get_tick() < until - margin(i)) {}
            mb.v[i] = DWT_CYCCNT;
        }
        SYST_CSR = 0;
        break;
    case IDLE_MASKED: /* the same wait in a critical section: SysTick pends while masked, taken at the CPSIE */
        dwt_on();
        systick(9999, 7);
        for (uint32_t i = 0; i < 5; i++) {
            uint32_t until = get_tick() + 3u + i, t, m;
            do {
                __asm volatile("cpsid i" ::: "memory");
                t = get_tick(), m = margin(i);
                __asm volatile("cpsie i" ::: "memory");
            } while (t < until - m);
            mb.v[i] = DWT_CYCCNT;
        }
        SYST_CSR = 0;
        break;
    case IDLE_COUNT: /* a wait that counts its iterations in RAM, its registers the same each time: never jumped over */
        dwt_on();
        systick(9999, 7);
        for (uint32_t i = 0; i < 4; i++) {
            uint32_t until = get_tick() + 2u;
            while (get_tick() < until - margin(i)) __asm volatile("ldr r3, [%0]\n adds r3, #1\n str r3, [%0]\n movs r3, #0" :: "r"(&count) : "r3", "cc", "memory");
            mb.v[i] = DWT_CYCCNT;
        }
        SYST_CSR = 0;
        break;
    case IDLE_BENCH: /* bench/armcore_speed.c at 168 MHz: 1 ms ticks; work, a CYCCNT wait, HAL_Delay, WFI */
        dwt_on();
        systick(167999, 7);
        for (;;) {
            for (uint32_t i = 0; i < 2000; i++) acc += i * i;
            cyccnt_wait(50000);
            delay_ticks(2);
            __asm volatile("wfi");
            ((volatile uint32_t *)mb.v)[0] = ticks;
        }
    }
}

static uint32_t vtable[64] __attribute__((aligned(256)));

static void fault_scenarios(uint32_t s)
{
    extern void (*const vectors[])(void);
    switch (s) {
    case VTOR:
        for (int i = 0; i < 59; i++) vtable[i] = (uint32_t)vectors[i];
        vtable[15] = (uint32_t)alt_systick;
        SCB_VTOR = (uint32_t)vtable;
        mb.v[0] = SCB_VTOR;
        systick(99, 7);
        while (SYST_CSR & 1u) {}
        break;
    case FAULT_UNMAPPED:
        __asm volatile("ldr r2, =0x60000000\n adr r1, 1f\n str r1, [%0]\n .balign 4\n 1: ldr r0, [r2]" :: "r"(&mb.v[0]) : "r0", "r1", "r2", "memory");
        break;
    case FAULT_PERIPH:
        __asm volatile("ldr r2, =0x40010014\n adr r1, 1f\n str r1, [%0]\n .balign 4\n 1: ldr r0, [r2]" :: "r"(&mb.v[0]) : "r0", "r1", "r2", "memory");
        break;
    case UNDEF:
        __asm volatile("adr r1, 1f\n str r1, [%0]\n .balign 4\n 1: udf #0" :: "r"(&mb.v[0]) : "r1", "memory");
        break;
    case SVC:
        SCB_SHPR(11) = 0x80; SCB_SHPR(14) = 0xF0;
        __asm volatile("svc #0");
        log_ev('M');
        break;
    case UNMODELED:
        mb.v[0] = REG(0x40007000u);
        REG(0xE000EDF0u) = 0; /* DHCSR: debug, not modeled */
        break;
    case BITBAND:
        mb.v[0] = 0;
        REG(0x22000000u + ((uint32_t)&mb.v[0] - 0x20000000u) * 32u + 3u * 4u) = 1u;
        mb.v[1] = REG(0x22000000u + ((uint32_t)&mb.v[0] - 0x20000000u) * 32u + 3u * 4u);
        REG(0x42000000u + (FAKE_BASE + 0x18u - 0x40000000u) * 32u + 5u * 4u) = 1u;
        mb.v[2] = REG(FAKE_BASE + 0x18u);
        break;
    case PSP: { /* thread mode on the process stack: the frame goes there, the handler runs on MSP, the return restores it */
        static uint32_t pstack[64] __attribute__((aligned(8)));
        uint32_t psp = (uint32_t)&pstack[64], ctrl, sp_after, r4 = 0x4444u;
        __asm volatile("msr psp, %0\n mov r0, #2\n msr control, r0\n isb" :: "r"(psp) : "r0");
        __asm volatile("mov r4, %1\n svc #1\n mov %0, r4" : "=r"(r4) : "r"(r4) : "r4");
        __asm volatile("mrs %0, control\n mov %1, sp" : "=r"(ctrl), "=r"(sp_after));
        mb.v[0] = ctrl, mb.v[1] = sp_after, mb.v[4] = psp, mb.v[5] = r4;
        __asm volatile("mov r0, #0\n msr control, r0\n isb" ::: "r0");
        break;
    }
    case RESET:
        if (mb.step == 0) {
            mb.step = 1;
            SCB_AIRCR = 0x05FA0004u; /* SYSRESETREQ */
            for (;;) {}
        }
        log_ev('R');
        break;
    }
}

int main(void)
{
    mb.scenario = FAKE_SCENARIO;
    mb.v[14] = SCB_CPUID;
    prio_scenarios(mb.scenario);
    timer_scenarios(mb.scenario);
    fault_scenarios(mb.scenario);
    idle_scenarios(mb.scenario);
    mb.done = 1;
    return 0;
}
