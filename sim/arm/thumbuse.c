/* thumbuse.c - registers and flags a Thumb instruction reads and writes (see thumbuse.h). */
#include "thumbuse.h"

#include <stdbool.h>

#define R(n) (1u << (n))
#define NZ (THUMB_N | THUMB_Z)

/* the flags a condition code reads (A7.3) */
static uint32_t cond_flags(unsigned cond)
{
    static const uint32_t f[14] = { THUMB_Z, THUMB_Z, THUMB_C, THUMB_C, THUMB_N, THUMB_N, THUMB_V, THUMB_V,
                                    THUMB_C | THUMB_Z, THUMB_C | THUMB_Z, THUMB_N | THUMB_V, THUMB_N | THUMB_V,
                                    NZ | THUMB_V, NZ | THUMB_V };
    return cond < 14 ? f[cond] : 0;
}

static int ok(thumb_use_t *u, uint32_t rd, uint32_t wr) { u->rd = rd, u->wr = wr; return THUMB_OK; }
static int bits(thumb_use_t *u, uint32_t rd, uint32_t wr) { u->bits = 1; return ok(u, rd, wr); }

/* 010000: AND EOR LSL LSR ASR ADC SBC ROR TST RSB CMP CMN ORR MUL BIC MVN (A6.2.2) */
static int data_proc16(uint16_t h, thumb_use_t *u)
{
    unsigned op = (h >> 6) & 0xFu, rm = (h >> 3) & 7u, rdn = h & 7u;
    uint32_t rd = R(rm) | (op == 9 || op == 15 ? 0u : R(rdn)), wr = (op == 8 || op == 10 || op == 11) ? 0u : R(rdn);
    if (op == 5 || op == 6) rd |= THUMB_C;                               /* ADC, SBC */
    if (op == 5 || op == 6 || op == 9 || op == 10 || op == 11) wr |= THUMB_NZCV;
    else if (op >= 2 && op <= 4) wr |= NZ | THUMB_C, rd |= THUMB_C;      /* a shift by 0 keeps C */
    else if (op == 7) wr |= NZ | THUMB_C, rd |= THUMB_C;
    else wr |= NZ;
    u->bits = !(op == 5 || op == 6 || op == 9 || op == 10 || op == 11);
    return ok(u, rd, wr);
}

static int special16(uint16_t h, thumb_use_t *u)
{
    unsigned op = (h >> 8) & 3u, rdn = (h & 7u) | ((h >> 4) & 8u), rm = (h >> 3) & 0xFu;
    switch (op) {
    case 0: return rdn == 15 ? THUMB_OTHER : ok(u, R(rdn) | R(rm), R(rdn));  /* ADD (high registers) */
    case 1: return ok(u, R(rdn) | R(rm), THUMB_NZCV);                         /* CMP (high registers) */
    case 2: return rdn == 15 ? THUMB_OTHER : ok(u, R(rm), R(rdn));            /* MOV (high registers) */
    default: return (h & 0x80u) ? ok(u, R(rm), R(14)) : ok(u, R(rm), 0);      /* BLX, BX */
    }
}

static int misc16(uint16_t h, thumb_use_t *u)
{
    if ((h & 0xFF00u) == 0xB000u) return ok(u, R(13), R(13));                          /* ADD/SUB SP, #imm */
    if ((h & 0xFF00u) == 0xB200u) return bits(u, R((h >> 3) & 7u), R(h & 7u));         /* SXTH SXTB UXTH UXTB */
    if ((h & 0xF500u) == 0xB100u) return ok(u, R(h & 7u), 0);                          /* CBZ, CBNZ */
    if ((h & 0xFF00u) == 0xBA00u && ((h >> 6) & 3u) != 2u) return bits(u, R((h >> 3) & 7u), R(h & 7u)); /* REV REV16 REVSH */
    if (h == 0xBF00u || h == 0xBF10u) return ok(u, 0, 0);                              /* NOP, YIELD */
    return THUMB_OTHER;                                                                 /* PUSH, POP, IT, WFI, CPS, BKPT... */
}

static int thumb16(uint16_t h, thumb_use_t *u)
{
    unsigned top5 = h >> 11, rd3 = h & 7u, rn3 = (h >> 3) & 7u;
    if (top5 <= 2) {                                                                    /* LSL LSR ASR #imm (MOVS: LSL #0 keeps C) */
        bool movs = top5 == 0 && !(h & 0x7C0u);
        u->bits = !movs;
        return ok(u, R(rn3), R(rd3) | NZ | (movs ? 0u : THUMB_C));
    }
    if (top5 == 3) return ok(u, R(rn3) | ((h & 0x400u) ? 0u : R((h >> 6) & 7u)), R(rd3) | THUMB_NZCV); /* ADD/SUB reg, imm3 */
    if (top5 >= 4 && top5 <= 7) {
        unsigned r = (h >> 8) & 7u;
        if (top5 == 4) return ok(u, 0, R(r) | NZ);                                     /* MOV #imm8 */
        if (top5 == 5) return ok(u, R(r), THUMB_NZCV);                                 /* CMP #imm8 */
        return ok(u, R(r), R(r) | THUMB_NZCV);                                         /* ADD/SUB #imm8 */
    }
    if ((h >> 10) == 0x10) return data_proc16(h, u);
    if ((h >> 10) == 0x11) return special16(h, u);
    if (top5 == 9) return ok(u, 0, R((h >> 8) & 7u));                                  /* LDR (literal) */
    if ((h >> 12) == 5) return ((h >> 9) & 7u) < 3 ? THUMB_OTHER : ok(u, R(rn3) | R((h >> 6) & 7u), R(rd3)); /* loads (register) */
    if (top5 == 0xD || top5 == 0xF || top5 == 0x11) return ok(u, R(rn3), R(rd3));     /* LDR LDRB LDRH #imm5 */
    if (top5 == 0x13) return ok(u, R(13), R((h >> 8) & 7u));                           /* LDR SP-relative */
    if (top5 == 0x14) return ok(u, 0, R((h >> 8) & 7u));                               /* ADR */
    if (top5 == 0x15) return ok(u, R(13), R((h >> 8) & 7u));                           /* ADD Rd, SP, #imm */
    if ((h >> 12) == 0xB) return misc16(h, u);
    if ((h >> 12) == 0xD) return ((h >> 8) & 0xFu) >= 0xE ? THUMB_OTHER : ok(u, cond_flags((h >> 8) & 0xFu), 0); /* B<cond> (not UDF, SVC) */
    if (top5 == 0x1C) return ok(u, 0, 0);                                              /* B */
    return THUMB_OTHER;                                                                 /* stores, STM/LDM */
}

/* AND BIC ORR ORN EOR ADD ADC SBC SUB RSB by a modified immediate or a shifted register (A6.3.1, A6.3.11) */
static int data_proc32(uint16_t h1, uint16_t h2, bool shifted, thumb_use_t *u)
{
    unsigned op = (h1 >> 5) & 0xFu, s = (h1 >> 4) & 1u, rn = h1 & 0xFu, rd = (h2 >> 8) & 0xFu;
    bool logic = op <= 4, movlike = (op == 2 || op == 3) && rn == 15;
    if (!logic && op != 8 && op != 10 && op != 11 && op != 13 && op != 14) return THUMB_OTHER;
    if (rd == 13 || (rd == 15 && !s)) return THUMB_OTHER;
    uint32_t r = (movlike ? 0u : R(rn)) | (shifted ? R(h2 & 0xFu) : 0u), w = rd == 15 ? 0u : R(rd);
    if (op == 10 || op == 11) r |= THUMB_C;
    if (s) w |= logic ? NZ | THUMB_C : THUMB_NZCV;
    if (s && logic) r |= THUMB_C; /* C from the shifter or the constant, or kept */
    u->bits = (logic && !movlike) || (shifted && (h2 & 0x70F0u)); /* a shift other than LSL #0 */
    return ok(u, r, w);
}

static int thumb32(uint16_t h1, uint16_t h2, thumb_use_t *u)
{
    unsigned rn = h1 & 0xFu, rt = h2 >> 12, op1 = (h1 >> 4) & 0x1Fu;
    if ((h1 & 0xF800u) == 0xF000u && (h2 & 0x8000u)) {
        if ((h2 & 0xD000u) == 0xD000u) return ok(u, 0, R(14));                          /* BL */
        if ((h2 & 0xD000u) == 0x9000u) return ok(u, 0, 0);                              /* B.W */
        if ((h2 & 0xD000u) == 0x8000u && ((h1 >> 7) & 7u) != 7u) return ok(u, cond_flags((h1 >> 6) & 0xFu), 0); /* B<cond>.W */
        return THUMB_OTHER;                                                              /* MSR, MRS, hints, barriers */
    }
    if ((h1 & 0xFE7Fu) == 0xF85Fu || (h1 & 0xFE5Fu) == 0xF81Fu) return rt == 15 ? THUMB_OTHER : ok(u, 0, R(rt)); /* (literal) */
    if ((h1 & 0xFE70u) == 0xF850u || (h1 & 0xFE50u) == 0xF810u) {                       /* loads: imm12, or register */
        if (rt == 15) return THUMB_OTHER;                                                /* a load to the PC: a branch */
        if (h1 & 0x80u) return ok(u, R(rn), R(rt));                                      /* #imm12 */
        if ((h2 & 0x0FC0u) == 0) return ok(u, R(rn) | R(h2 & 0xFu), R(rt));             /* [Rn, Rm, LSL #k] */
        return THUMB_OTHER;                                                              /* pre/post-indexed: writeback */
    }
    if ((h1 & 0xFA00u) == 0xF000u && !(h2 & 0x8000u)) return data_proc32(h1, h2, false, u);
    if ((h1 & 0xFE00u) == 0xEA00u) return data_proc32(h1, h2, true, u);
    if ((h1 & 0xFA00u) == 0xF200u && !(h2 & 0x8000u)) {                                 /* plain binary immediate (A6.3.3) */
        unsigned rd = (h2 >> 8) & 0xFu;
        if (rd >= 13) return THUMB_OTHER;
        if (op1 == 0x14 || op1 == 0x1C) return bits(u, R(rn), R(rd));                  /* SBFX, UBFX */
        if (op1 == 0x00 || op1 == 0x0A) return rn == 15 ? ok(u, 0, R(rd)) : ok(u, R(rn), R(rd)); /* ADDW, SUBW, ADR */
        if (op1 == 0x04) return ok(u, 0, R(rd));                                         /* MOVW */
        if (op1 == 0x0C) return bits(u, R(rd), R(rd));                                   /* MOVT */
    }
    return THUMB_OTHER;
}

int thumb_use(uint16_t h1, uint16_t h2, thumb_use_t *u)
{
    u->rd = u->wr = 0, u->bits = 0;
    if ((h1 >> 11) >= 0x1D) {
        u->len = 4;
        return thumb32(h1, h2, u);
    }
    u->len = 2;
    return thumb16(h1, u);
}
