/* image.h - an RGB raster with the few drawing calls the run report needs,
 * written as PNG with libpng (atomically, see outfile.h). Pixel (0,0) is
 * the top-left corner; colours are 0xRRGGBB. */
#ifndef IMAGE_H
#define IMAGE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef struct {
    int w, h;    /* pixels */
    uint8_t *px; /* w * h * 3 bytes, rows top to bottom */
} image_t;

/* A w x h image filled with colour rgb. Returns 0, or -1 out of memory. */
int image_init(image_t *im, int w, int h, uint32_t rgb);
void image_free(image_t *im);
void image_set(image_t *im, int x, int y, uint32_t rgb);
/* Filled rectangle [x0,x1) x [y0,y1), clipped. */
void image_rect(image_t *im, int x0, int y0, int x1, int y1, uint32_t rgb);
/* Line of width w_px (round caps), coordinates in pixels. */
void image_line(image_t *im, double x0, double y0, double x1, double y1, double w_px, uint32_t rgb);
/* Filled disc. */
void image_disc(image_t *im, double cx, double cy, double r_px, uint32_t rgb);
/* Text in the built-in font, top-left at (x, y), scale pixels per font pixel. */
void image_text(image_t *im, int x, int y, int scale, uint32_t rgb, const char *s);
/* A raw RGB buffer (rows bottom-up if bottom_up, as glReadPixels returns
 * them) written as an 8-bit RGB PNG. Returns 0, or -1 with one line in err. */
int image_write_png_rows(const uint8_t *rgb, int w, int h, int bottom_up, const char *path, char *err, size_t errlen);
/* The PNG into an open stream f (an outfile's temporary; name for err).
 * Returns 0, or -1 with one line in err. */
int image_write_png_file(const image_t *im, FILE *f, const char *name, char *err, size_t errlen);

#endif
