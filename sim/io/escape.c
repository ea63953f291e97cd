/* escape.c - text from outside, safe to print (see escape.h). */
#include "escape.h"

#include <stdint.h>
#include <stdio.h>

/* Length of the valid UTF-8 sequence of 2 to 4 bytes at s (n bytes left)
 * and its code point in *cp; 0 if there is none (RFC 3629: no overlong
 * forms, no surrogates, nothing above U+10FFFF). */
static size_t utf8_seq(const unsigned char *s, size_t n, uint32_t *cp)
{
    unsigned char b = s[0], lo = 0x80, hi = 0xBF;
    size_t len;
    if (b >= 0xC2 && b <= 0xDF) len = 2, *cp = b & 0x1Fu;
    else if (b >= 0xE0 && b <= 0xEF) len = 3, *cp = b & 0x0Fu;
    else if (b >= 0xF0 && b <= 0xF4) len = 4, *cp = b & 0x07u;
    else return 0;
    if (b == 0xE0) lo = 0xA0;      /* overlong */
    else if (b == 0xED) hi = 0x9F; /* surrogates */
    else if (b == 0xF0) lo = 0x90; /* overlong */
    else if (b == 0xF4) hi = 0x8F; /* above U+10FFFF */
    if (len > n) return 0;
    for (size_t i = 1; i < len; i++) {
        unsigned char c = s[i];
        if (c < (i == 1 ? lo : 0x80) || c > (i == 1 ? hi : 0xBF)) return 0;
        *cp = (*cp << 6) | (c & 0x3Fu);
    }
    return len;
}

/* Code points that are valid UTF-8 but still steer the terminal or the
 * reading order: C1 controls, zero-width and bidirectional marks and
 * overrides, the line and paragraph separators, the byte order mark. */
static int steering(uint32_t cp)
{
    return (cp >= 0x80 && cp <= 0x9F) || (cp >= 0x200B && cp <= 0x200F) || (cp >= 0x2028 && cp <= 0x202E) ||
           (cp >= 0x2060 && cp <= 0x2069) || cp == 0xFEFF;
}

size_t io_escape(char *out, size_t outlen, const char *in, size_t n)
{
    const unsigned char *s = (const unsigned char *)in;
    size_t o = 0, i = 0;
    while (i < n) {
        char piece[24];
        size_t plen;
        uint32_t cp = 0;
        size_t seq = s[i] >= 0x80 ? utf8_seq(s + i, n - i, &cp) : 0;
        if (s[i] >= 0x20 && s[i] < 0x7F) { /* printable ASCII */
            plen = s[i] == '\\' ? 2 : 1;
            piece[0] = (char)s[i];
            piece[1] = '\\';
        } else if (seq && !steering(cp)) { /* a printable character, as it is */
            plen = seq;
            for (size_t k = 0; k < seq; k++) piece[k] = (char)s[i + k];
        } else { /* each byte of it as \xNN */
            size_t bytes = seq ? seq : 1;
            plen = 0;
            for (size_t k = 0; k < bytes; k++) plen += (size_t)snprintf(piece + plen, sizeof piece - plen, "\\x%02X", s[i + k]);
            seq = bytes;
        }
        if (o + plen + 1 > outlen) break;
        for (size_t k = 0; k < plen; k++) out[o++] = piece[k];
        i += seq ? seq : 1;
    }
    if (outlen) out[o < outlen ? o : outlen - 1] = '\0';
    return o;
}
