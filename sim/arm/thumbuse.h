/* thumbuse.h - what a Thumb instruction reads and writes, for the core's
 * idle-loop skipping (armcore.c): registers R0-R15 as bits 0-15, the
 * flags N, Z, C, V as bits 16-19 (ARMv7-M ARM DDI 0403E chapter A6, the
 * Thumb encodings; A7 for each instruction's operands and flags). Only the
 * instructions a wait loop is made of are known: loads, moves, arithmetic,
 * logic, compares, branches, calls and returns through LR. Anything else
 * (a store, a push, an IT block, a system instruction, an encoding not
 * listed) answers THUMB_OTHER, and a loop holding one is never skipped. */
#ifndef THUMBUSE_H
#define THUMBUSE_H

#include <stdint.h>

#define THUMB_N (1u << 16)
#define THUMB_Z (1u << 17)
#define THUMB_C (1u << 18)
#define THUMB_V (1u << 19)
#define THUMB_NZCV (THUMB_N | THUMB_Z | THUMB_C | THUMB_V)

enum { THUMB_OK, THUMB_OTHER };

typedef struct {
    uint32_t rd, wr;   /* registers and flags read, written (a flag an instruction may keep is both) */
    unsigned len;      /* 2 or 4 bytes */
    int bits;          /* 1: a value's bits taken apart (logic, shifts, multiply, extends, bit fields), not only added and compared */
} thumb_use_t;

/* The instruction whose first halfword is h1 (h2 the next one): THUMB_OK with *u filled, or THUMB_OTHER. */
int thumb_use(uint16_t h1, uint16_t h2, thumb_use_t *u);

#endif
