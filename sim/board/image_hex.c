/* image_hex.c - Intel HEX images parsed strictly (see image.h): every line
 * ":LLAAAATT<data>CC" of hex digits, its length and checksum consistent,
 * record types 00-05 only, segment and linear extended addresses, every
 * data byte within IMAGE_FLASH_MAX_BYTES, one end record with nothing but
 * blank lines after it. */
#include "image.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/infile.h"

#define HEX_RECORD_MAX_BYTES (255u + 5u) /* data plus length, address, type and checksum */
#define HEX_SEGMENT_BYTES 0x10000u       /* a record's 16-bit address space */

enum { REC_DATA = 0, REC_END = 1, REC_SEGMENT = 2, REC_START_SEGMENT = 3, REC_LINEAR = 4, REC_START_LINEAR = 5 };

typedef struct {
    const char *path;
    unsigned line;   /* 1-based */
    char *err;
    size_t errn;
    uint64_t base;   /* the extended address records' base, bytes */
    int ended;       /* the end record seen */
    image_hex_t *out;
    int cap;         /* chunks allocated */
} hex_t;

static int hfail(const hex_t *x, const char *what)
{
    snprintf(x->err, x->errn, "%s:%u: %s", x->path, x->line, what);
    return -1;
}

static int hexval(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

/* the n characters at s (":" first) as record bytes into rec; their count, or -1 with the error */
static int decode(const hex_t *x, const char *s, size_t n, uint8_t *rec)
{
    char m[120];
    if (n == 0 || s[0] != ':') return hfail(x, "not an Intel HEX record (it must start with ':')");
    if (n % 2 == 0 || n < 11 || n > 1 + 2 * HEX_RECORD_MAX_BYTES)
        return snprintf(m, sizeof m, "a record of %zu characters (11 to %u, an odd count)", n, 1 + 2 * HEX_RECORD_MAX_BYTES),
               hfail(x, m);
    for (size_t i = 1; i < n; i += 2) {
        int hi = hexval(s[i]), lo = hexval(s[i + 1]);
        if (hi < 0 || lo < 0) return snprintf(m, sizeof m, "a character that is not a hex digit at column %zu",
                                              hi < 0 ? i + 1 : i + 2), hfail(x, m);
        rec[i / 2] = (uint8_t)(hi << 4 | lo);
    }
    int count = (int)(n - 1) / 2;
    if (rec[0] + 5 != count)
        return snprintf(m, sizeof m, "its length byte says %u data bytes, the record has %d", rec[0], count - 5), hfail(x, m);
    unsigned sum = 0;
    for (int i = 0; i < count; i++) sum += rec[i];
    if ((sum & 0xFFu) != 0) return snprintf(m, sizeof m, "bad checksum (0x%02X; the bytes sum to 0x%02X, not 0x00)",
                                            rec[count - 1], sum & 0xFFu), hfail(x, m);
    return count;
}

/* len bytes at flash byte address at lie within IMAGE_FLASH_MAX_BYTES */
static int within_flash(uint64_t at, uint32_t len) { return at <= IMAGE_FLASH_MAX_BYTES && len <= IMAGE_FLASH_MAX_BYTES - at; }

/* a data record's bytes at base + its address, extending the last chunk or starting one */
static int put_data(hex_t *x, const uint8_t *rec)
{
    uint32_t len = rec[0], addr = rec[1] << 8 | rec[2];
    char m[160];
    if (addr + len > HEX_SEGMENT_BYTES) return hfail(x, "its bytes wrap past the end of their 64 KiB segment");
    uint64_t at = x->base + addr;
    if (!within_flash(at, len))
        return snprintf(m, sizeof m, "bytes at 0x%llX beyond any AVR's flash (%u bytes)", (unsigned long long)at,
                        IMAGE_FLASH_MAX_BYTES), hfail(x, m);
    image_hex_t *h = x->out;
    memcpy(h->flash + at, rec + 4, len);
    if (at + len > h->end) h->end = (uint32_t)(at + len);
    if (len == 0) return 0;
    if (h->nchunks > 0 && h->chunks[h->nchunks - 1].base + h->chunks[h->nchunks - 1].size == at) {
        h->chunks[h->nchunks - 1].size += len;
        return 0;
    }
    if (h->nchunks == x->cap) {
        int cap = x->cap ? 2 * x->cap : 16;
        image_chunk_t *c = realloc(h->chunks, (size_t)cap * sizeof *c);
        if (!c) return hfail(x, "out of memory");
        h->chunks = c, x->cap = cap;
    }
    h->chunks[h->nchunks++] = (image_chunk_t){ .base = (uint32_t)at, .size = len };
    return 0;
}

/* one decoded record of count bytes */
static int record(hex_t *x, const uint8_t *rec)
{
    char m[120];
    unsigned len = rec[0], type = rec[3];
    switch (type) {
    case REC_DATA: return put_data(x, rec);
    case REC_END:
        if (len != 0 || rec[1] || rec[2]) return hfail(x, "an end record with data or an address (it is :00000001FF)");
        x->ended = 1;
        return 0;
    case REC_SEGMENT:
    case REC_LINEAR:
        if (len != 2) return snprintf(m, sizeof m, "an extended address record with %u data bytes (it has 2)", len), hfail(x, m);
        x->base = type == REC_SEGMENT ? (uint64_t)(rec[4] << 8 | rec[5]) << 4 : (uint64_t)(rec[4] << 8 | rec[5]) << 16;
        return 0;
    case REC_START_SEGMENT:
    case REC_START_LINEAR:
        if (len != 4) return snprintf(m, sizeof m, "a start address record with %u data bytes (it has 4)", len), hfail(x, m);
        return 0;
    default: return snprintf(m, sizeof m, "record type %02X (an Intel HEX record is of type 00 to 05)", type), hfail(x, m);
    }
}

/* each line of the n bytes at text */
static int parse(hex_t *x, const char *text, size_t n)
{
    uint8_t rec[HEX_RECORD_MAX_BYTES];
    for (size_t at = 0; at < n; x->line++) {
        const char *nl = memchr(text + at, '\n', n - at);
        size_t end = nl ? (size_t)(nl - text) : n, len = end - at;
        const char *s = text + at;
        at = nl ? end + 1 : n;
        while (len > 0 && s[len - 1] == '\r') len--;
        if (len == 0) continue;
        if (x->ended) return hfail(x, "a line after the end record");
        if (decode(x, s, len, rec) < 0 || record(x, rec) != 0) return -1;
    }
    x->line--;
    if (!x->ended) return snprintf(x->err, x->errn, "%s: no end record (:00000001FF): a truncated file?", x->path), -1;
    if (x->out->nchunks == 0) return snprintf(x->err, x->errn, "%s: no data records", x->path), -1;
    return 0;
}

void image_hex_free(image_hex_t *h)
{
    free(h->flash);
    free(h->chunks);
    memset(h, 0, sizeof *h);
}

int image_read_hex(const char *path, size_t max_bytes, image_hex_t *out, char *err, size_t errn)
{
    memset(out, 0, sizeof *out);
    size_t n = 0;
    char *text = infile_read(path, max_bytes, &n, err, errn);
    if (!text) return -1;
    out->flash = malloc(IMAGE_FLASH_MAX_BYTES);
    hex_t x = { .path = path, .line = 1, .err = err, .errn = errn, .out = out };
    int rc = out->flash ? 0 : (snprintf(err, errn, "%s: out of memory", path), -1);
    if (rc == 0) {
        memset(out->flash, 0xFF, IMAGE_FLASH_MAX_BYTES);
        rc = parse(&x, text, n);
    }
    free(text);
    if (rc != 0) image_hex_free(out);
    return rc;
}
