/* avrhost.h - one AVR core in simavr as both --avr (pil.c) and --board
 * (board.c) run it: the image read and checked (ELF, or Intel HEX where
 * the caller admits it), the core made quiet (simavr's error messages kept
 * for ours, never printed; no host sleep when the AVR sleeps), UART0
 * (simavr's own printing and polling sleep off; each byte the firmware
 * sends to a sink; typed bytes queued until the receiver takes them,
 * respecting its XON/XOFF), and the run up to a cycle. Time is cycles:
 * nothing here reads a clock.
 *
 * Order of use: avrhost_read, avrhost_make, avrhost_put (any order of the
 * first two: pil takes the MCU from the image, board from its board file),
 * then avrhost_uart_open; avrhost_run_to each step. */
#ifndef AVRHOST_H
#define AVRHOST_H

#include <stddef.h>
#include <stdint.h>

#include "avrgdb.h"
#include "extint_level.h"
#include "image.h"

struct avr_t;
struct avr_irq_t;

#define AVRHOST_IN_MAX 4096u              /* bytes waiting for the UART's receive FIFO */
/* AVR cycles simavr may run in one avr_run call (its run_cycle_limit); the
 * PC is checked for erased flash (0xFFFF) at each batch's end, so a slide
 * through erased flash of about this many words is caught there */
#define AVRHOST_BATCH_MAX_CYCLES 1024u
#define AVRHOST_NO_TIMER_SLEEP_CYCLES 1000u /* AVR cycles simavr lets a core sleep when no cycle timer is set */
#define AVRHOST_IMAGE_MAX_BYTES (64u << 20) /* an ELF with its debug sections; a Mega's flash is 256 KiB */
#define AVRHOST_F_CPU_MIN_HZ 1000000u      /* the clocks an AVR is run at: 1 to 32 MHz */
#define AVRHOST_F_CPU_MAX_HZ 32000000u
#define AVRHOST_DEFAULT_MCU "atmega328p"  /* --avr's MCU when neither --mcu nor the image names one */
#define AVRHOST_WDT_LOOP_RESETS 8u        /* watchdog resets in a row, each within a second of the last: a reset loop */

struct avrhost_watch_t;

/* An image read from its file, not yet in a core. */
typedef struct {
    int hex;                      /* 1: Intel HEX bytes, 0: the ELF (kept inside avrhost.c) */
    image_hex_t bytes;            /* the HEX file's bytes as our reader parsed them */
    char mcu[IMAGE_MCU_NAME_BYTES]; /* the ELF's .mmcu MCU name ("" if none or HEX) */
    uint32_t f_cpu;               /* the ELF's .mmcu clock, Hz (0 if none or HEX) */
} avrhost_image_t;

/* Where each byte the firmware sends on UART0 goes. */
typedef void avrhost_sink_fn(void *ctx, uint8_t byte);

typedef struct {
    struct avr_t *avr;
    struct avr_irq_t *uart_in;
    struct avr_uart_t *uart;      /* UART0 (its receiver-enable bit), NULL before avrhost_uart_open */
    avrhost_sink_fn *sink;
    void *sink_ctx;
    int xoff;                     /* the UART's receive FIFO is full */
    uint8_t in[AVRHOST_IN_MAX];   /* typed bytes not yet in the FIFO */
    size_t in_head, in_len;
    uint64_t bytes_in;            /* bytes the UART's receiver took */
    uint64_t bytes_dropped;       /* bytes that arrived with the receiver off (RXEN0 = 0): lost, as on the chip */
    uint64_t cycles_per_step;     /* AVR cycles of one physics step */
    uint64_t target;              /* the cycle the current step runs to */
    struct avrhost_watch_t *watch; /* the stack pointer's guard and the reset counter (in the core's IO list) */
    int running;                  /* inside avr_run: a reset now is the watchdog's (simavr's only own reset) */
    uint64_t wdt_resets;          /* watchdog resets so far */
    uint32_t wdt_in_row;          /* watchdog resets since the last other reset, each within a second of the last */
    uint64_t wdt_last_cycle;      /* the cycle of the last watchdog reset */
    int init_sp_known;            /* init_sp_pc found since the last reset */
    uint32_t init_sp_pc;          /* flash byte address of the first `out SPH` of RAMEND's high byte after a reset
                                   * (avr-libc's start-up code setting the stack) */
    uint64_t restarts;            /* that instruction run again without a reset: the program started over (a jump to 0) */
    uint32_t restarts_in_row;     /* ... in a row, each within a second of the last */
    uint64_t restart_last_cycle;  /* the cycle of the last one */
    const char *crash;            /* why the firmware crashed (NULL: it has not): see avrhost_run_to */
    uint32_t crash_pc;            /* the program counter then, a byte address in flash */
    uint32_t crash_sp;            /* the stack pointer then */
    extint_level_t lvl;           /* INT0/INT1's low-level mode at edge-mode cost */
    int gdb;                      /* simavr's gdb stub is on (avrhost_gdb) */
    avrgdb_t stub;                /* its sockets */
} avrhost_t;

/* Read and check the image at path before simavr reads it (image.h): a
 * regular file, an AVR ELF of sound structure (or, if hex_ok and its name
 * ends in .hex, strict Intel HEX). want_mcu is the MCU the image must be
 * built for (NULL: --avr's, the image's .mmcu name or AVRHOST_DEFAULT_MCU):
 * its AVR architecture (ELF e_flags, where image_mcu_arch knows the MCU)
 * and its .mmcu name if it has one; board (NULL: --avr) names the board in
 * those messages. The .mmcu tags that make simavr act (a VCD trace file,
 * command and console registers) are dropped. 0, or -1 with one line in
 * err. Not reentrant: one ELF is held until avrhost_put. */
int avrhost_read(avrhost_image_t *img, const char *path, int hex_ok, const char *want_mcu, const char *board, char *err,
                 size_t errn);
/* Make and initialise a core for mcu (simavr's logger installed, its own
 * logging off). 0, or -1 with "WHO: simavr does not know the MCU 'MCU'". */
int avrhost_make(avrhost_t *h, const char *mcu, const char *who, char *err, size_t errn);
/* The image read by avrhost_read into h's core, clocked at f_cpu Hz, the
 * host never sleeping when the AVR sleeps; then a step is step_s seconds
 * of f_cpu cycles. Refused: f_cpu outside 1-32 MHz or not the clock the
 * image declares, code beyond the flash, variables beyond the SRAM, an
 * .eeprom beyond the EEPROM (HEX bytes freed either way). 0, or -1 with
 * one line in err. */
int avrhost_put(avrhost_t *h, avrhost_image_t *img, const char *path, const char *mcu, uint32_t f_cpu, double step_s,
                char *err, size_t errn);
/* UART0's bytes to sink(ctx, byte); who (NULL: none) prefixes the error
 * line. 0, or -1: the MCU has no UART0 in simavr. */
int avrhost_uart_open(avrhost_t *h, avrhost_sink_fn *sink, void *ctx, const char *who, char *err, size_t errn);
/* Turn off simavr's UART printing and polling sleep again (a reset
 * restores them). */
void avrhost_uart_flags(avrhost_t *h);
/* Room in the input queue, bytes. */
size_t avrhost_room(const avrhost_t *h);
/* Queue n bytes (at most avrhost_room) for the receiver. */
void avrhost_queue(avrhost_t *h, const uint8_t *bytes, size_t n);
/* Hand queued bytes to the receiver until it says XOFF. */
void avrhost_feed(avrhost_t *h);
/* Start simavr's gdb stub on 127.0.0.1:port (avrgdb.h), after
 * avrhost_put: the core halts until gdb continues or steps. From then on
 * avrhost_run_to runs one instruction per avr_run call while gdb is
 * attached (simavr checks breakpoints between calls), in batches while it
 * is not, and while the core is halted serves gdb without advancing its
 * cycle: it returns only when the cycle is reached, so the caller's
 * physics and clock wait with it. A crash that simavr halts for gdb ends
 * the firmware as without gdb. 0, or -1 with "cannot listen on
 * 127.0.0.1:PORT: REASON" in err. */
int avrhost_gdb(avrhost_t *h, unsigned port, char *err, size_t errn);
/* Run the AVR up to cycle until. 0, or -1 with "firmware crashed at cycle
 * N, PC 0xPC: CAUSE (detail)" in err and h->crash set to the cause:
 * "stack_overflow" (the stack pointer left SRAM: the run ends before the
 * next push, which simavr would write past its data array), "bad_jump" (the
 * PC past the program's code or back to 0: simavr stops there),
 * "sleep_with_interrupts_off" (simavr's cpu_Done: nothing can wake it),
 * "watchdog_reset_loop" (AVRHOST_WDT_LOOP_RESETS in a row), "reset_loop"
 * (the program started over without a reset, AVRHOST_WDT_LOOP_RESETS times
 * in a row: a jump to 0, as avr-libc's __bad_interrupt makes for an enabled
 * interrupt without a handler), "erased_flash" (the PC at a word 0xFFFF,
 * what erased flash reads: a reserved opcode; seen where a batch of
 * AVRHOST_BATCH_MAX_CYCLES ends, so a run of fewer erased words that ends
 * in code is not seen) or "crashed"
 * (simavr's cpu_Crashed for another reason). The core is never run again
 * after a crash: later calls return -1 at once. */
int avrhost_run_to(avrhost_t *h, uint64_t until, char *err, size_t errn);
/* Stop the core (simavr cannot free one: h->avr stays pointing at it). */
void avrhost_close(avrhost_t *h);
/* The ioport IRQ of pin bit (0..7) of port 'B', 'C', 'D', ... */
struct avr_irq_t *avrhost_pin_irq(struct avr_t *avr, char port, unsigned bit);

#endif
