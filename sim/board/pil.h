/* pil.h - processor in the loop: an AVR image (ELF) runs in simavr
 * (avrhost.h), in-process and in lockstep with the physics: each physics
 * step advances the AVR by exactly that step's cycles (f_cpu x step). Its
 * UART0 is one end of a socketpair whose other end is the simulator's link
 * (sim/link.h), so the bytes obey the link's baud budget and simavr's
 * cycle-timed UART. No wall clock anywhere: the same ELF and inputs give
 * the same run. */
#ifndef PIL_H
#define PIL_H

#include <stddef.h>
#include <stdint.h>

#include "avrhost.h"

#define PIL_PAINT 0xA5   /* SRAM fill before reset: untouched bytes keep it */

typedef struct {
    avrhost_t host;           /* the core, its image and UART0 */
    int fd;                   /* the AVR's end of the socketpair */
    uint64_t cycles;          /* AVR cycles run */
    uint64_t bytes_in, bytes_out; /* UART0 bytes to and from the AVR */
    uint64_t bytes_dropped;       /* sent before the AVR enabled its receiver: lost, as on the chip */
    char mcu[64];
    uint32_t f_cpu;
} pil_t;

/* Load elf into simavr. mcu / f_cpu: NULL / 0 = the ELF's .mmcu section,
 * else atmega328p / 16 MHz; the image is checked first (avrhost_read,
 * image.h). On success *link_fd is the simulator's end of the serial line
 * (for link_open_fd) and 0 is returned; else -2 (bad input: the image, its
 * MCU or clock) or -1 (the host could not make the serial line), and a
 * one-line message in err. */
int pil_open(pil_t *p, const char *elf, const char *mcu, uint32_t f_cpu, double step_s, int *link_fd, char *err,
             size_t errn);
/* One physics step of AVR time. Returns 0, or -1 if the AVR stopped
 * (crashed or halted) with the reason in err. */
int pil_step(pil_t *p, char *err, size_t errn);
/* Stack high-water mark so far, bytes below the top of SRAM, and the
 * smallest gap that stayed untouched between .bss and the stack (SRAM is
 * painted at load; the firmware must not malloc). */
void pil_stack(const pil_t *p, uint32_t *stack_max, uint32_t *free_min);
void pil_close(pil_t *p);

#endif
