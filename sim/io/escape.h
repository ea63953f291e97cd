/* escape.h - text from a device or another program, made safe to print as
 * part of one of our lines: it cannot end the line, move the cursor, change
 * colours or the terminal's state, or reorder text, so it cannot forge or
 * hide a line of ours. */
#ifndef ESCAPE_H
#define ESCAPE_H

#include <stddef.h>

/* Worst case: every byte as \xNN. */
#define IO_ESCAPE_MAX(n) (4 * (n) + 1)

/* The n bytes at in (NUL bytes included) into out as text: printable ASCII
 * and valid UTF-8 of printable characters as they are, a backslash as \\,
 * every other byte as \xNN (control bytes with tab, CR, LF and ESC, DEL,
 * bytes not in valid UTF-8, and whole the UTF-8 of the C1 controls, the
 * line and paragraph separators, bidirectional and zero-width controls).
 * out always ends with a NUL (outlen >= 1); what does not fit whole is
 * left out (IO_ESCAPE_MAX(n) always fits). Returns the length of out. */
size_t io_escape(char *out, size_t outlen, const char *in, size_t n);

#endif
