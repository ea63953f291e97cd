/* board.c - the board's core (board.h): the image on an AVR host
 * (avrhost.h), the parts wired to it as the board file says, and the
 * lockstep: each physics step runs the AVR exactly f_cpu x step cycles,
 * stopping at each encoder edge's cycle to put it on the pins. The parts
 * (board_motor, board_encoder, board_adc, board_switch, board_led,
 * board_console) each keep their own state and hear the AVR through
 * simavr's IRQs; this file calls them, never the other way. */
#include "board.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <simavr/avr_ioport.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_interrupts.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

#include "avrhost.h"
#include "board_adc.h"
#include "board_console.h"
#include "board_eeprom.h"
#include "board_encoder.h"
#include "board_led.h"
#include "board_motor.h"
#include "board_switch.h"

_Static_assert(BOARD_IN_MAX == AVRHOST_IN_MAX, "board_send's queue is the AVR host's");
_Static_assert(BOARD_LED_PINS_MAX >= BOARD_LEDS_MAX && BOARD_LED_PINS_MAX >= SIM_EMITTER_GROUPS, "LED part too small");
_Static_assert(BOARD_ADC_EMITTERS >= BOARD_LED_PINS_MAX, "every emitter pin has an ADC input");

struct board_s {
    board_spec_t spec;
    sim_state_t *sim;
    avrhost_t host;
    board_stats_t st;
    board_motor_t motor;
    board_encoder_t enc;
    board_adc_t adc;
    board_switches_t sw;
    board_leds_t leds, emitters;
    board_console_t con;
    board_eeprom_t eeprom;
};

static const char *VECTORS_X8[26] = { "RESET", "INT0", "INT1", "PCINT0", "PCINT1", "PCINT2", "WDT", "TIMER2_COMPA",
                                      "TIMER2_COMPB", "TIMER2_OVF", "TIMER1_CAPT", "TIMER1_COMPA", "TIMER1_COMPB",
                                      "TIMER1_OVF", "TIMER0_COMPA", "TIMER0_COMPB", "TIMER0_OVF", "SPI_STC", "USART_RX",
                                      "USART_UDRE", "USART_TX", "ADC", "EE_READY", "ANALOG_COMP", "TWI", "SPM_READY" };

const char *board_vector_name(const board_t *b, unsigned v)
{
    (void)b; /* board_load admits the ATmega48/88/168/328 family only: one table */
    return v < 26 ? VECTORS_X8[v] : NULL;
}

/* each vector's services counted: its "running" IRQ is 1 when serviced, 0 at its RETI */
static void on_vector(struct avr_irq_t *irq, uint32_t value, void *param)
{
    board_t *b = param;
    avr_int_table_p t = &b->host.avr->interrupts;
    if (!value) return;
    for (int i = 0; i < t->vector_count; i++)
        if (&t->vector[i]->irq[AVR_INT_IRQ_RUNNING] == irq && t->vector[i]->vector < BOARD_VECTORS_MAX)
            b->st.interrupts[t->vector[i]->vector]++;
}

/* simavr has no call that frees a whole core: a board stays allocated and
 * reachable (the last one that failed to open here) until the process ends */
static board_t *volatile failed_board; /* volatile: written only, it must stay */

static board_t *open_fail(board_t *b)
{
    avrhost_close(&b->host);
    failed_board = b;
    return NULL;
}

/* the parts onto the core, as the board file wires them */
static int wire(board_t *b, char *err, size_t errn)
{
    avr_t *avr = b->host.avr;
    const board_spec_t *sp = &b->spec;
    if (board_console_init(&b->con, &b->st, err, errn) != 0) return -1;
    if (avrhost_uart_open(&b->host, board_console_byte, &b->con, NULL, err, errn) != 0) return -1;
    board_leds_init(&b->leds, avr, sp->led_pin, sp->nleds, b->st.led_changes);
    board_leds_init(&b->emitters, avr, sp->emitter_pin, sp->nemitters, NULL);
    avr_int_table_p t = &avr->interrupts;
    for (int i = 0; i < t->vector_count; i++) avr_irq_register_notify(&t->vector[i]->irq[AVR_INT_IRQ_RUNNING], on_vector, b);
    board_switches_init(&b->sw, avr, sp);
    if (board_adc_init(&b->adc, avr, sp, b->sim, &b->st, err, errn) != 0) return -1;
    /* the parts' outputs onto the ADC's inputs (simavr's IRQ chaining), then the ladder's voltage raised once */
    avr_connect_irq(b->sw.out, &b->adc.input[BOARD_ADC_IN_LADDER]);
    for (int e = 0; e < sp->nemitters && e < BOARD_ADC_EMITTERS; e++) avr_connect_irq(board_leds_irq(&b->emitters, e), &b->adc.input[BOARD_ADC_IN_EMITTER + e]);
    board_switches_set(&b->sw, 0, 0);
    board_encoder_init(&b->enc, avr, sp, b->sim, &b->st);
    return board_motor_init(&b->motor, avr, sp, &b->st, err, errn);
}

board_t *board_open(const board_spec_t *spec, const char *image, sim_state_t *s, char *err, size_t errn)
{
    board_t *b = calloc(1, sizeof *b);
    if (!b) return snprintf(err, errn, "out of memory"), NULL;
    b->spec = *spec;
    b->sim = s;
    if (board_fits_robot(spec, s->model->cfg, err, errn) != 0) return free(b), NULL; /* no core made yet */
    avrhost_image_t img;
    if (avrhost_make(&b->host, spec->mcu, spec->path, err, errn) != 0) return open_fail(b);
    if (avrhost_read(&img, image, 1, spec->mcu, spec->name, err, errn) != 0 ||
        avrhost_put(&b->host, &img, image, spec->mcu, spec->f_cpu, s->model->cfg->sim.step_s, err, errn) != 0)
        return open_fail(b);
    avr_t *avr = b->host.avr;
    avr->vcc = avr->avcc = avr->aref = (uint32_t)lround(spec->vcc_v * 1000.0);
    if (wire(b, err, errn) != 0) return open_fail(b);
    sim_set_supply_drop(s, spec->bat_diode_drop_v); /* the diode feeds the H-bridges and the divider alike */
    return b;
}

int board_step(board_t *b, char *err, size_t errn)
{
    avrhost_t *h = &b->host;
    uint64_t start = h->target, edge;
    h->target += h->cycles_per_step;
    avrhost_feed(h);
    board_encoder_plan(&b->enc, start, h->cycles_per_step);
    int rc = 0;
    while (rc == 0 && board_encoder_next(&b->enc, &edge)) {
        rc = avrhost_run_to(h, edge, err, errn);
        if (rc == 0) board_encoder_apply_next(&b->enc);
    }
    if (rc == 0) rc = avrhost_run_to(h, h->target, err, errn);
    b->st.uart_bytes_in = h->bytes_in;
    b->st.uart_bytes_dropped = h->bytes_dropped;
    if (rc != 0) return -1;
    b->st.cycles = h->avr->cycle;
    if (board_adc_check(&b->adc, err, errn) != 0) return -1;
    board_motor_step(&b->motor, b->sim->cmd);
    return 0;
}

void board_close(board_t *b)
{
    /* simavr has no call that frees a whole core: avrhost_close closes its
     * parts; the board stays allocated (the caller keeps it) and its stats
     * and console readable */
    if (b) avrhost_close(&b->host);
}

void board_set_switches(board_t *b, unsigned n) { board_switches_set(&b->sw, n & 15u, b->sw.button); }
void board_button(board_t *b, int down) { board_switches_set(&b->sw, b->sw.switches, down != 0); }

void board_panel(const board_t *b, board_panel_t *out)
{
    memset(out, 0, sizeof *out);
    out->switches = b->sw.switches;
    out->button = b->sw.button;
    out->nleds = b->spec.nleds;
    for (int i = 0; i < b->spec.nleds && i < BOARD_LEDS_MAX; i++) {
        out->led[i] = board_leds_level(&b->leds, i);
        out->led_name[i] = b->spec.led_name[i];
    }
}

void board_reset(board_t *b)
{
    avr_t *avr = b->host.avr;
    /* a reset keeps SRAM (a .noinit variable survives; the C runtime clears .bss itself) */
    uint32_t lo = avr->ioend + 1u, n = avr->ramend + 1u - lo;
    uint8_t *keep = malloc(n);
    if (keep) memcpy(keep, avr->data + lo, n);
    avr_reset(avr);
    if (keep) memcpy(avr->data + lo, keep, n);
    free(keep);
    /* avr_reset clears DDRx and PORTx without raising their IRQs: raise
     * them with the cleared value, so the parts that follow them and the
     * IRQs' filters (a value equal to the last one is not passed on) agree
     * with the registers again */
    for (char p = 'B'; p <= 'D'; p++) {
        avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(p), IOPORT_IRQ_DIRECTION_ALL), 0);
        avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(p), IOPORT_IRQ_REG_PORT), 0);
    }
    avrhost_uart_flags(&b->host);
    board_leds_clear(&b->emitters);
    board_leds_clear(&b->leds);
    board_encoder_restore(&b->enc);
    b->host.xoff = 0;
    b->st.resets++;
}

int board_send(board_t *b, const char *text)
{
    size_t n = strlen(text);
    if (n > avrhost_room(&b->host)) return -1;
    avrhost_queue(&b->host, (const uint8_t *)text, n);
    avrhost_feed(&b->host);
    b->st.uart_bytes_in = b->host.bytes_in;
    b->st.uart_bytes_dropped = b->host.bytes_dropped;
    return 0;
}

const char *board_console(const board_t *b, size_t *len)
{
    if (len) *len = b->con.con.len;
    return b->con.con.text;
}

console_t *board_console_stream(board_t *b) { return &b->con.con; }

void board_set_echo(board_t *b, FILE *f) { b->con.con.echo = f; }

int board_eeprom_keep(board_t *b, const char *path, char *err, size_t errn)
{
    return board_eeprom_load(&b->eeprom, b->host.avr, b->spec.mcu, path, err, errn);
}

int board_eeprom_end(board_t *b, int *written, int *changed, char *err, size_t errn)
{
    *changed = board_eeprom_changed(&b->eeprom);
    *written = b->eeprom.written || *changed;
    return board_eeprom_save(&b->eeprom, err, errn);
}
const board_spec_t *board_spec(const board_t *b) { return &b->spec; }
const avrhost_t *board_host(const board_t *b) { return &b->host; }
int board_gdb(board_t *b, unsigned port, char *err, size_t errn) { return avrhost_gdb(&b->host, port, err, errn); }

const board_stats_t *board_stats(const board_t *b) { return &b->st; }
