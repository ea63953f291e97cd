/* font.h - a tiny built-in 5x7 pixel font for text in run reports and the
 * viewer's HUD (no font files, no font library). Printable ASCII; lower
 * case is drawn as upper case. */
#ifndef FONT_H_INCLUDED
#define FONT_H_INCLUDED

#define FONT_W 5       /* glyph width, pixels */
#define FONT_H 7       /* glyph height, pixels */
#define FONT_ADVANCE 6 /* pen advance per character, pixels */
#define FONT_LINE 10   /* line pitch, pixels */

/* Row `row` (0 = top) of character c: bit 4 = leftmost pixel. */
int font_row(char c, int row);
/* Width of s in pixels at this scale (pixels per font pixel). */
int font_text_width(const char *s, int scale);

#endif
