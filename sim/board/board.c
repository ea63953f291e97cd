/* board.c - the board's core (board.h): the image into simavr, the parts
 * wired to it, and the lockstep: each physics step runs the AVR exactly
 * f_cpu x step cycles, stopping at each encoder edge's cycle to put it on
 * the pins. */
#include "board_int.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <simavr/avr_ioport.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <simavr/sim_hex.h>
#include <simavr/sim_io.h>
#include <simavr/sim_irq.h>

#include "avrlog.h"
#include "io/infile.h"


avr_irq_t *board_pin_irq(board_t *b, board_pin_t p) { return avr_io_getirq(b->avr, AVR_IOCTL_IOPORT_GETIRQ(p.port), p.bit); }

static const char *VECTORS_X8[26] = { "RESET", "INT0", "INT1", "PCINT0", "PCINT1", "PCINT2", "WDT", "TIMER2_COMPA",
                                      "TIMER2_COMPB", "TIMER2_OVF", "TIMER1_CAPT", "TIMER1_COMPA", "TIMER1_COMPB",
                                      "TIMER1_OVF", "TIMER0_COMPA", "TIMER0_COMPB", "TIMER0_OVF", "SPI_STC", "USART_RX",
                                      "USART_UDRE", "USART_TX", "ADC", "EE_READY", "ANALOG_COMP", "TWI", "SPM_READY" };

const char *board_vector_name(const board_t *b, unsigned v)
{
    (void)b; /* board_load admits the ATmega48/88/168/328 family only: one table */
    return v < 26 ? VECTORS_X8[v] : NULL;
}

/* the image's code into the AVR: ELF (its .mmcu section must name the board's MCU, if it has one) or HEX */
static int load_image(board_t *b, const char *image, char *err, size_t errn)
{
    size_t n = strlen(image);
    if (access(image, R_OK) != 0) return snprintf(err, errn, "%s: cannot read: %s", image, strerror(errno)), -1;
    FILE *f = infile_open(image, BOARD_IMAGE_MAX_BYTES, NULL, err, errn); /* a FIFO would hang the open */
    if (!f) return -1;
    uint8_t h[20] = { 0 };
    size_t got = fread(h, 1, sizeof h, f);
    fclose(f);
    if (n > 4 && !strcmp(image + n - 4, ".hex")) {
        ihex_chunk_p chunks = NULL;
        int nc = got > 0 && h[0] == ':' ? read_ihex_chunks(image, &chunks) : -1;
        if (nc <= 0) return snprintf(err, errn, "%s: not an Intel HEX image", image), -1;
        for (int i = 0; i < nc; i++) {
            if (chunks[i].baseaddr + chunks[i].size > b->avr->flashend + 1u) {
                free_ihex_chunks(chunks);
                return snprintf(err, errn, "%s: larger than the %s's flash (%u bytes)", image, b->spec.mcu, b->avr->flashend + 1u), -1;
            }
            avr_loadcode(b->avr, chunks[i].data, chunks[i].size, chunks[i].baseaddr);
        }
        free_ihex_chunks(chunks);
        return 0;
    }
    if (got < sizeof h || memcmp(h, "\x7f" "ELF", 4) != 0 || h[18] != 83 || h[19] != 0)
        return snprintf(err, errn, "%s: not an AVR ELF image (or a .hex file)", image), -1;
    /* e_flags' low bits: the AVR architecture the image was built for (avr4: ATmega48/88, avr5: 168/328) */
    unsigned arch = 0, want = strstr(b->spec.mcu, "168") || strstr(b->spec.mcu, "328") ? 5u : 4u;
    FILE *g = fopen(image, "rb");
    uint8_t fl[4] = { 0 };
    if (g && fseek(g, 36, SEEK_SET) == 0 && fread(fl, 1, 4, g) == 4) arch = fl[0] & 0x7Fu;
    if (g) fclose(g);
    if (arch && arch != want)
        return snprintf(err, errn, "%s: built for another MCU (AVR architecture avr%u; the board %s has an %s: avr%u)", image,
                        arch, b->spec.name, b->spec.mcu, want), -1;
    static elf_firmware_t fw; /* large: keep it off the stack */
    memset(&fw, 0, sizeof fw);
    avrlog_clear();
    if (elf_read_firmware(image, &fw) != 0 || fw.flashsize == 0)
        return snprintf(err, errn, "%s: not an AVR ELF image%s%s", image, avrlog_sep(), avrlog_last()), -1;
    if (fw.mmcu[0] && strcmp(fw.mmcu, b->spec.mcu))
        return snprintf(err, errn, "%s: built for the %s; the board %s has an %s", image, fw.mmcu, b->spec.name, b->spec.mcu), -1;
    if (fw.flashsize > b->avr->flashend + 1u)
        return snprintf(err, errn, "%s: %u bytes of code: larger than the %s's flash (%u bytes): built for another MCU?", image,
                        fw.flashsize, b->spec.mcu, b->avr->flashend + 1u), -1;
    snprintf(fw.mmcu, sizeof fw.mmcu, "%s", b->spec.mcu);
    fw.frequency = b->spec.f_cpu;
    avr_load_firmware(b->avr, &fw);
    return 0;
}

/* simavr has no call that frees a whole core: a board stays allocated and
 * reachable (the last one that failed to open here) until the process ends */
static board_t *volatile failed_board; /* volatile: written only, it must stay */

static board_t *open_fail(board_t *b)
{
    if (b->avr) avr_terminate(b->avr);
    failed_board = b;
    return NULL;
}

board_t *board_open(const board_spec_t *spec, const char *image, sim_t *s, char *err, size_t errn)
{
    board_t *b = calloc(1, sizeof *b);
    if (!b) return snprintf(err, errn, "out of memory"), NULL;
    b->spec = *spec;
    b->sim = s;
    avrlog_install();
    b->avr = avr_make_mcu_by_name(spec->mcu);
    if (!b->avr) return snprintf(err, errn, "%s: simavr does not know the MCU '%s'", spec->path, spec->mcu), open_fail(b);
    avr_init(b->avr);
    b->avr->log = LOG_NONE;
    if (load_image(b, image, err, errn) != 0) return open_fail(b);
    b->avr->frequency = spec->f_cpu;
    b->avr->vcc = b->avr->avcc = b->avr->aref = (uint32_t)lround(spec->vcc_v * 1000.0);
    b->avr->sleep = avrlog_no_sleep;
    if (board_console_init(b, err, errn) != 0 || board_adc_init(b, err, errn) != 0) return open_fail(b);
    board_encoder_init(b);
    for (int m = 0; m < 2; m++) b->st.duty_min[m] = b->st.duty_max[m] = 0.0;
    b->cycles_per_step = (uint64_t)llround((double)spec->f_cpu * s->model->cfg->step_s);
    b->target = b->avr->cycle;
    return b;
}

/* run the AVR up to cycle `until`: 0, or -1 with the reason */
static int run_to(board_t *b, uint64_t until, char *err, size_t errn)
{
    while (b->avr->cycle < until) {
        int state = avr_run(b->avr);
        if (state == cpu_Done || state == cpu_Crashed)
            return snprintf(err, errn, "AVR %s at cycle %llu%s%s", state == cpu_Crashed ? "crashed" : "halted",
                            (unsigned long long)b->avr->cycle, avrlog_sep(), avrlog_last()), -1;
    }
    return 0;
}

int board_step(board_t *b, char *err, size_t errn)
{
    uint64_t start = b->target;
    b->target += b->cycles_per_step;
    board_console_feed(b);
    board_encoder_plan(b, start);
    for (int i = 0; i < b->nedges; i++) {
        if (run_to(b, b->edges[i].cycle, err, errn) != 0) return -1;
        board_encoder_apply(b, &b->edges[i]);
    }
    if (run_to(b, b->target, err, errn) != 0) return -1;
    b->st.cycles = b->avr->cycle;
    if (board_adc_check(b, err, errn) != 0) return -1;
    board_motor_step(b);
    return 0;
}

void board_close(board_t *b)
{
    if (!b || !b->avr) return;
    /* simavr has no call that frees a whole core: avr_terminate closes its
     * parts; the board stays allocated (the caller keeps it) and its stats
     * and console readable */
    avr_terminate(b->avr);
}

void board_set_switches(board_t *b, unsigned n) { b->switches = n & 15u; }
void board_button(board_t *b, int down) { b->button = down != 0; }

void board_panel(const board_t *b, board_panel_t *out)
{
    memset(out, 0, sizeof *out);
    out->switches = b->switches;
    out->button = b->button;
    out->nleds = b->spec.nleds;
    for (int i = 0; i < b->spec.nleds && i < BOARD_LEDS_MAX; i++) {
        out->led[i] = b->led_level[i];
        out->led_name[i] = b->spec.led_name[i];
    }
}

void board_reset(board_t *b)
{
    /* a reset keeps SRAM (a .noinit variable survives; the C runtime clears .bss itself) */
    uint32_t lo = b->avr->ioend + 1u, n = b->avr->ramend + 1u - lo;
    uint8_t *keep = malloc(n);
    if (keep) memcpy(keep, b->avr->data + lo, n);
    avr_reset(b->avr);
    if (keep) memcpy(b->avr->data + lo, keep, n);
    free(keep);
    board_uart_flags(b);
    for (int i = 0; i < SIM_EMITTER_GROUPS; i++) b->emitter_level[i] = 0;
    for (int i = 0; i < BOARD_LEDS_MAX; i++) b->led_level[i] = 0;
    board_encoder_restore(b);
    b->xoff = 0;
    b->st.resets++;
}

int board_send(board_t *b, const char *text)
{
    size_t n = strlen(text);
    if (n > BOARD_IN_MAX - b->in_len) return -1;
    for (size_t i = 0; i < n; i++) b->in[(b->in_head + b->in_len++) % BOARD_IN_MAX] = (uint8_t)text[i];
    board_console_feed(b);
    return 0;
}

const char *board_console(const board_t *b, size_t *len)
{
    if (len) *len = b->con_len;
    return b->con;
}

void board_set_echo(board_t *b, FILE *f) { b->echo = f; }
const board_stats_t *board_stats(const board_t *b) { return &b->st; }
struct avr_t *board_avr(board_t *b) { return b->avr; }
