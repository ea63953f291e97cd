/* extint_level.c - INT0/INT1's low-level mode without simavr's per-cycle
 * check (see extint_level.h for what simavr does and why this matches it). */
#include "extint_level.h"

#include <string.h>

#include <simavr/avr_extint.h>
#include <simavr/avr_ioport.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_cycle_timers.h>
#include <simavr/sim_interrupts.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

/* each core's level state, found from the core by the host's sleep callback
 * (simavr passes it the core only); simavr never frees a core, so a core's
 * address names one state for the whole process */
#define EXTINT_LEVEL_CORES_MAX 64
static extint_level_t *known[EXTINT_LEVEL_CORES_MAX];
static unsigned nknown;

static int level_mode(avr_t *avr, avr_extint_t *p, int n) { return avr_regbit_get_array(avr, p->eint[n].isc, 2) == 0; }

static int pin_low(avr_t *avr, const avr_extint_t *p, int n)
{
    avr_ioport_state_t st;
    if (avr_ioctl(avr, AVR_IOCTL_IOPORT_GETSTATE(p->eint[n].port_ioctl & 0xFFu), &st) < 0) return 0;
    return !((st.pin >> p->eint[n].port_pin) & 1u);
}

static int flagged(avr_t *avr, avr_int_vector_t *v) { return avr_regbit_get(avr, v->raised) || v->pending; }

/* A reset (ours or the watchdog's) ends simavr's checks and turns its
 * strict level trigger back on: seen here as the flag being on again. */
static void after_reset(extint_level_t *x)
{
    for (int n = 0; n < EXTINT_LEVEL_MAX; n++)
        if (x->ext->eint[n].strict_lvl_trig) {
            for (int k = 0; k < EXTINT_LEVEL_MAX; k++) x->in[k].alive = 0;
            for (int k = 0; k < EXTINT_LEVEL_MAX; k++) avr_extint_set_strict_lvl_trig(x->avr, (uint8_t)k, 0);
            return;
        }
}

/* the check at an instruction boundary, as simavr's: ends when the pin is
 * high or the mode is not level; raises INTn when interrupts are on and its
 * flag is clear; sleeps while the flag is set or pending (nothing to raise) */
static avr_cycle_count_t check(avr_t *avr, avr_cycle_count_t when, void *param)
{
    extint_level_in_t *li = param;
    avr_extint_t *p = li->x->ext;
    avr_int_vector_t *v = &p->eint[li->no].vector;
    if (!level_mode(avr, p, li->no) || !pin_low(avr, p, li->no)) return li->alive = 0, 0;
    if (!flagged(avr, v) && avr->sreg[S_I]) avr_raise_interrupt(avr, v);
    return flagged(avr, v) ? 0 : when + 1;
}

static void wake(extint_level_in_t *li)
{
    after_reset(li->x);
    if (li->alive && !avr_cycle_timer_status(li->x->avr, check, li)) avr_cycle_timer_register(li->x->avr, 1, check, li);
}

/* the INTn pin as simavr's extint hears it: low in level mode starts the check */
static void on_pin(avr_irq_t *irq, uint32_t value, void *param)
{
    extint_level_in_t *li = param;
    (void)irq;
    after_reset(li->x);
    if (value || !level_mode(li->x->avr, li->x->ext, li->no)) {
        li->alive = 0;
        avr_cycle_timer_cancel(li->x->avr, check, li);
        return;
    }
    li->alive = 1;
    avr_cycle_timer_register(li->x->avr, 1, check, li);
}

/* a write to EICRA: a mode other than level ends the check */
static void on_eicra(avr_irq_t *irq, uint32_t value, void *param)
{
    extint_level_t *x = param;
    (void)irq, (void)value;
    after_reset(x);
    for (int n = 0; n < EXTINT_LEVEL_MAX; n++)
        if (!level_mode(x->avr, x->ext, n)) {
            x->in[n].alive = 0;
            avr_cycle_timer_cancel(x->avr, check, &x->in[n]);
        }
}

/* a write to EIFR may clear a flag: the sleeping checks wake */
static void on_eifr(avr_irq_t *irq, uint32_t value, void *param)
{
    extint_level_t *x = param;
    (void)irq, (void)value;
    for (int n = 0; n < EXTINT_LEVEL_MAX; n++) wake(&x->in[n]);
}

/* INTn's pending state cleared (it was serviced; its flag is cleared with
 * it): its check wakes */
static void on_cleared(avr_irq_t *irq, uint32_t value, void *param)
{
    (void)irq;
    if (!value) wake(param);
}

/* every write to the register at addr to fn (its IRQ unfiltered: a value written twice is heard twice) */
static void on_write(avr_t *avr, uint16_t addr, avr_irq_notify_t fn, void *param)
{
    avr_irq_t *w = avr_iomem_getirq(avr, addr, NULL, AVR_IOMEM_IRQ_ALL);
    if (!w) return;
    w->flags &= ~(uint8_t)IRQ_FLAG_FILTERED;
    avr_irq_register_notify(w, fn, param);
}

avr_cycle_count_t extint_level_sleep(avr_t *avr, avr_cycle_count_t plain)
{
    for (unsigned i = 0; i < nknown && i < EXTINT_LEVEL_CORES_MAX; i++) {
        extint_level_t *x = known[i];
        if (x->avr != avr) continue;
        after_reset(x);
        for (int n = 0; n < EXTINT_LEVEL_MAX; n++)
            if (x->in[n].alive && !avr_cycle_timer_status(avr, check, &x->in[n])) return 1; /* simavr's check: due next cycle */
        return plain;
    }
    return plain;
}

void extint_level_init(extint_level_t *x, avr_t *avr)
{
    memset(x, 0, sizeof *x);
    x->avr = avr;
    for (avr_io_t *io = avr->io_port; io; io = io->next)
        if (!strcmp(io->kind, "extint")) x->ext = (avr_extint_t *)io;
    for (int n = 0; x->ext && n < EXTINT_LEVEL_MAX; n++)
        if (!x->ext->eint[n].port_ioctl || !x->ext->eint[n].isc[1].reg) x->ext = NULL; /* not INT0/INT1 with level mode */
    if (!x->ext) return;
    known[nknown++ % EXTINT_LEVEL_CORES_MAX] = x;
    for (int n = 0; n < EXTINT_LEVEL_MAX; n++) {
        x->in[n] = (extint_level_in_t){ x, n, 0 };
        avr_extint_set_strict_lvl_trig(avr, (uint8_t)n, 0);
        avr_irq_register_notify(x->ext->io.irq + n, on_pin, &x->in[n]);
        avr_irq_register_notify(&x->ext->eint[n].vector.irq[AVR_INT_IRQ_PENDING], on_cleared, &x->in[n]);
    }
    on_write(avr, x->ext->eint[0].isc[0].reg, on_eicra, x);
    on_write(avr, x->ext->eint[0].vector.raised.reg, on_eifr, x);
}
