/* image_mcu.c - an image's vector table, stack and start-up I/O against
 * its MCU's (see image_mcu.h). Opcodes: the AVR Instruction Set Manual
 * (Microchip DS40002198): jmp 1001 010k kkkk 110k + 16-bit k, call the
 * same with 111k, rjmp 1100 kkkk kkkk kkkk, rcall 1101 ..., ldi 1110 KKKK
 * dddd KKKK (r16-r31), in 1011 0AAr rrrr AAAA, out 1011 1AAr rrrr AAAA,
 * cbi/sbic/sbi/sbis 1001 10xx AAAA Abbb, lds/sts 1001 00xd dddd 0000 + k. */
#include "image_mcu.h"

#include <stdio.h>
#include <string.h>

#define SCAN_WORDS 64u  /* start-up code words read from the reset vector's target to main's call */
#define IO_SPL 0x3Du    /* I/O addresses of the stack pointer (every AVR with SRAM) */
#define IO_SPH 0x3Eu

/* One MCU's layout, from avr-libc 2.0's io headers (_VECTORS_SIZE, RAMEND,
 * FLASHEND; each from its datasheet's "Reset and Interrupt Vectors" table
 * and memory map) and avr-gcc 5.4's start-up code built for it. */
typedef struct {
    const char *mcu;
    unsigned vectors;     /* interrupt vectors, reset included */
    unsigned vbytes;      /* bytes per vector: 4 (jmp), 2 (rjmp) */
    uint32_t ramend;      /* the last SRAM address: the stack's start */
    uint32_t flash_bytes;
    int m328_io;          /* 1: the ATmega48/88/168/328 family's I/O map (m328_io_has) */
} layout_t;

static const layout_t layouts[] = {
    { "atmega328p", 26, 4, 0x8FF, 32768, 1 }, { "atmega328", 26, 4, 0x8FF, 32768, 1 },
    { "atmega168", 26, 4, 0x4FF, 16384, 1 },  { "atmega168p", 26, 4, 0x4FF, 16384, 1 },
    { "atmega88", 26, 2, 0x4FF, 8192, 1 },    { "atmega88p", 26, 2, 0x4FF, 8192, 1 },
    { "atmega48", 26, 2, 0x2FF, 4096, 1 },    { "atmega8", 19, 2, 0x45F, 8192, 0 },
    { "atmega16", 21, 4, 0x45F, 16384, 0 },   { "atmega32", 21, 4, 0x85F, 32768, 0 },
    { "atmega644p", 31, 4, 0x10FF, 65536, 0 }, { "atmega1284p", 35, 4, 0x40FF, 131072, 0 },
    { "atmega1280", 57, 4, 0x21FF, 131072, 0 }, { "atmega2560", 57, 4, 0x21FF, 262144, 0 },
    { "atmega32u4", 43, 4, 0xAFF, 32768, 0 },  { "attiny85", 15, 2, 0x25F, 8192, 0 },
    { "attiny45", 15, 2, 0x15F, 4096, 0 },     { "attiny84", 17, 2, 0x25F, 8192, 0 },
};
#define NLAYOUTS (sizeof layouts / sizeof layouts[0])

/* Does the ATmega48/88/168/328(P) have I/O register A (0x00-0x3F)? avr-libc's iom328p.h: PINB..PORTD
 * 0x03-0x0B, TIFR0-2 0x15-0x17, PCIFR..OCR0B 0x1B-0x28, GPIOR1..SPDR 0x2A-0x2E, ACSR 0x30, SMCR, MCUSR,
 * MCUCR 0x33-0x35, SPMCSR 0x37; SPL, SPH, SREG 0x3D-0x3F (avr/common.h). */
static int m328_io_has(unsigned a)
{
    return (a >= 0x03 && a <= 0x0B) || (a >= 0x15 && a <= 0x17) || (a >= 0x1B && a <= 0x28) ||
           (a >= 0x2A && a <= 0x2E) || a == 0x30 || (a >= 0x33 && a <= 0x35) || a == 0x37 || a >= 0x3D;
}

/* What the bytes show. */
typedef struct {
    unsigned vbytes, vectors;   /* the table: 4 or 2 bytes per entry, entries (0 0: none) */
    uint32_t reset;             /* the reset vector's target, a byte address */
    uint32_t far_target;        /* a vector's target past the MCU's flash (0: none) */
    int sp_known;
    uint32_t sp;                /* the stack pointer the start-up code sets */
    int bad_io;                 /* an I/O address the start-up code uses that the MCU lacks (-1: none) */
} seen_t;

static unsigned word(const uint8_t *f, size_t n, uint32_t at) { return at + 1u < n ? f[at] | (unsigned)f[at + 1u] << 8 : 0xFFFFu; }
static int is_jmp(unsigned w) { return (w & 0xFE0Eu) == 0x940Cu; }
static int is_rjmp(unsigned w) { return (w & 0xF000u) == 0xC000u; }
static int is_long(unsigned w) { return (w & 0xFE0Cu) == 0x940Cu || (w & 0xFC0Fu) == 0x9000u; } /* jmp/call, lds/sts */
static uint32_t jmp_target(unsigned w, unsigned k) { return ((uint32_t)(w & 0x1F0u) << 13 | (uint32_t)(w & 1u) << 16 | k) * 2u; }
static uint32_t rjmp_target(unsigned w, uint32_t at) { int k = (int)(w & 0xFFFu); return at + 2u + (uint32_t)(2 * (k >= 2048 ? k - 4096 : k)); }

/* The vector table from address 0, each target checked against flash_bytes. */
static void read_table(const uint8_t *f, size_t n, uint32_t flash_bytes, seen_t *s)
{
    unsigned w0 = word(f, n, 0);
    s->vbytes = is_jmp(w0) ? 4 : is_rjmp(w0) ? 2 : 0;
    for (uint32_t at = 0; s->vbytes && at + s->vbytes <= n; at += s->vbytes) {
        unsigned w = word(f, n, at);
        if (s->vbytes == 4 ? !is_jmp(w) : !is_rjmp(w)) break;
        uint32_t t = s->vbytes == 4 ? jmp_target(w, word(f, n, at + 2u)) : rjmp_target(w, at) % flash_bytes;
        if (s->vectors == 0) s->reset = t;
        if (t >= flash_bytes && !s->far_target) s->far_target = t;
        s->vectors++;
    }
}

/* The start-up code from the reset target up to its first call: the stack pointer it sets, the I/O it uses. */
static void read_startup(const uint8_t *f, size_t n, int m328_io, seen_t *s)
{
    int known[32] = { 0 };
    unsigned val[32] = { 0 }, sph = 0, spl = 0;
    int got_h = 0, got_l = 0;
    uint32_t at = s->reset;
    for (unsigned i = 0; i < SCAN_WORDS && at + 1u < n; i++) {
        unsigned w = word(f, n, at);
        if ((w & 0xFE0Eu) == 0x940Eu || (w & 0xF000u) == 0xD000u) break; /* call, rcall: main */
        unsigned a = (w >> 5 & 0x30u) | (w & 0xFu), r = w >> 4 & 0x1Fu;
        if ((w & 0xF000u) == 0xE000u) known[16 + (w >> 4 & 0xFu)] = 1, val[16 + (w >> 4 & 0xFu)] = (w >> 4 & 0xF0u) | (w & 0xFu);
        if ((w & 0xF800u) == 0xB800u && a == IO_SPH && known[r]) sph = val[r], got_h = 1;
        if ((w & 0xF800u) == 0xB800u && a == IO_SPL && known[r]) spl = val[r], got_l = 1;
        if ((w & 0xF000u) == 0xB000u && m328_io && !m328_io_has(a) && s->bad_io < 0) s->bad_io = (int)a;
        if ((w & 0xFC00u) == 0x9800u && m328_io && !m328_io_has(w >> 3 & 0x1Fu) && s->bad_io < 0) s->bad_io = (int)(w >> 3 & 0x1Fu);
        at += is_long(w) ? 4u : 2u;
    }
    if (got_h && got_l) s->sp_known = 1, s->sp = sph << 8 | spl;
}

/* The MCUs of our table whose layout matches what was seen ("" if none). */
static void fits(const seen_t *s, char *out, size_t outn)
{
    out[0] = '\0';
    for (size_t i = 0, k = 0; i < NLAYOUTS && k < 3; i++) {
        const layout_t *l = &layouts[i];
        if (l->vbytes != s->vbytes || l->vectors != s->vectors || (s->sp_known && l->ramend != s->sp)) continue;
        size_t used = strlen(out);
        snprintf(out + used, outn - used, "%s%s", k++ ? " or the " : "; it fits the ", l->mcu);
    }
}

static const char *kind(unsigned vbytes) { return vbytes == 4 ? "jmp" : "rjmp"; }

int image_mcu_check(const uint8_t *flash, size_t n, const char *mcu, char *err, size_t errn)
{
    const layout_t *l = NULL;
    for (size_t i = 0; i < NLAYOUTS; i++)
        if (!strcmp(layouts[i].mcu, mcu)) l = &layouts[i];
    if (!l) return 0;
    seen_t s = { .bad_io = -1 };
    read_table(flash, n, l->flash_bytes, &s);
    if (s.vectors >= 2) read_startup(flash, n, l->m328_io, &s);
    int other_ramend = 0;
    for (size_t i = 0; i < NLAYOUTS; i++) other_ramend |= s.sp_known && layouts[i].ramend == s.sp;
    char what[200] = "", fit[120];
    if (s.vectors >= 2 && (s.vbytes != l->vbytes || s.vectors != l->vectors))
        snprintf(what, sizeof what, "its vector table is %u %s's %u bytes apart (the %s's: %u %s's %u bytes apart)", s.vectors,
                 kind(s.vbytes), s.vbytes, mcu, l->vectors, kind(l->vbytes), l->vbytes);
    else if (s.vectors >= 2 && s.far_target)
        snprintf(what, sizeof what, "a vector jumps to 0x%X, past the %s's %u bytes of flash", (unsigned)s.far_target, mcu,
                 (unsigned)l->flash_bytes);
    else if (s.sp_known && s.sp != l->ramend && (s.sp > l->ramend || other_ramend))
        snprintf(what, sizeof what, "its start-up code sets the stack to 0x%04X (the %s's RAMEND: 0x%04X)", (unsigned)s.sp,
                 mcu, (unsigned)l->ramend);
    else if (s.bad_io >= 0)
        snprintf(what, sizeof what, "its start-up code uses I/O register 0x%02X, which the %s does not have", (unsigned)s.bad_io,
                 mcu);
    else
        return 0;
    fits(&s, fit, sizeof fit);
    return snprintf(err, errn, "built for another MCU than the %s: %s%s", mcu, what, fit), -1;
}
