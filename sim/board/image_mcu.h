/* image_mcu.h - what a firmware image's flash bytes reveal about the MCU
 * it was built for, checked against the MCU it is to run on (an Intel HEX
 * file says nothing else; an ELF's e_flags and .mmcu name are checked in
 * avrhost.c). Read from avr-gcc's and avr-libc's start-up code:
 *   - the vector table: the number of `jmp`s 4 bytes apart (MCUs with more
 *     than 8 KiB of flash) or of `rjmp`s 2 bytes apart (8 KiB or less)
 *     from address 0, and their targets within the MCU's flash;
 *   - the stack pointer the start-up code sets (`ldi` then `out SPH` /
 *     `out SPL`): the MCU's RAMEND;
 *   - the I/O registers the start-up code (up to its call of main) reads
 *     or writes: each one the MCU has (the ATmega48/88/168/328 family's
 *     I/O map only; the ATmega2560's EIND and RAMPZ are not in it).
 * What the bytes cannot reveal: an image without avr-libc's start-up code
 * (-nostartfiles, assembler) or with its stack moved (__stack) shows no
 * table or stack to compare; among MCUs of one layout (ATmega328 and
 * 328P, 168 and 168P, 88 and 88P) they are the same; peripherals the
 * program uses later are not traced. */
#ifndef IMAGE_MCU_H
#define IMAGE_MCU_H

#include <stddef.h>
#include <stdint.h>

/* The n bytes of flash at flash (from address 0) checked against mcu. 0:
 * consistent with it, or mcu not in our table (nothing known to compare);
 * -1 with one line in err (no path: the caller adds it): "built for
 * another MCU than the MCU: WHAT (the MCU's: ...); it fits the OTHER". */
int image_mcu_check(const uint8_t *flash, size_t n, const char *mcu, char *err, size_t errn);

#endif
