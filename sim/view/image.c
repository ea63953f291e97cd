/* image.c - RGB raster and PNG output (see image.h). */
#include "image.h"

#include <math.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>

#include "font.h"
#include "io/outfile.h"

int image_init(image_t *im, int w, int h, uint32_t rgb)
{
    im->w = w;
    im->h = h;
    im->px = malloc((size_t)w * (size_t)h * 3);
    if (!im->px) return -1;
    image_rect(im, 0, 0, w, h, rgb);
    return 0;
}

void image_free(image_t *im)
{
    free(im->px);
    im->px = NULL;
}

void image_set(image_t *im, int x, int y, uint32_t rgb)
{
    if (x < 0 || y < 0 || x >= im->w || y >= im->h) return;
    uint8_t *p = im->px + ((size_t)y * (size_t)im->w + (size_t)x) * 3;
    p[0] = (uint8_t)(rgb >> 16);
    p[1] = (uint8_t)(rgb >> 8);
    p[2] = (uint8_t)rgb;
}

void image_rect(image_t *im, int x0, int y0, int x1, int y1, uint32_t rgb)
{
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > im->w) x1 = im->w;
    if (y1 > im->h) y1 = im->h;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) image_set(im, x, y, rgb);
}

void image_disc(image_t *im, double cx, double cy, double r, uint32_t rgb)
{
    for (int y = (int)floor(cy - r); y <= (int)ceil(cy + r); y++)
        for (int x = (int)floor(cx - r); x <= (int)ceil(cx + r); x++)
            if ((x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy) <= r * r) image_set(im, x, y, rgb);
}

void image_line(image_t *im, double x0, double y0, double x1, double y1, double w, uint32_t rgb)
{
    double r = w / 2, dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
    int xa = (int)floor(fmin(x0, x1) - r), xb = (int)ceil(fmax(x0, x1) + r);
    int ya = (int)floor(fmin(y0, y1) - r), yb = (int)ceil(fmax(y0, y1) + r);
    for (int y = ya; y <= yb; y++)
        for (int x = xa; x <= xb; x++) {
            double px = x + 0.5 - x0, py = y + 0.5 - y0;
            double t = len2 > 0 ? (px * dx + py * dy) / len2 : 0;
            if (t < 0) t = 0;
            if (t > 1) t = 1;
            double ex = px - t * dx, ey = py - t * dy;
            if (ex * ex + ey * ey <= r * r) image_set(im, x, y, rgb);
        }
}

void image_text(image_t *im, int x, int y, int scale, uint32_t rgb, const char *s)
{
    for (; *s; s++, x += FONT_ADVANCE * scale)
        for (int row = 0; row < FONT_H; row++) {
            int bits = font_row(*s, row);
            for (int k = 0; k < FONT_W; k++)
                if (bits & (1 << (FONT_W - 1 - k)))
                    image_rect(im, x + k * scale, y + row * scale, x + (k + 1) * scale, y + (row + 1) * scale, rgb);
        }
}

/* The PNG into f (name for err): 0, or -1 with one line in err. */
static int png_to(const uint8_t *rgb, int w, int h, int bottom_up, FILE *f, const char *name, char *err, size_t errlen)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    png_bytep *rows = malloc((size_t)h * sizeof *rows);
    if (!png || !info || !rows) {
        png_destroy_write_struct(&png, &info);
        free(rows);
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        free(rows);
        snprintf(err, errlen, "%s: cannot write PNG", name);
        return -1;
    }
    for (int y = 0; y < h; y++)
        rows[y] = (png_bytep)(rgb + (size_t)(bottom_up ? h - 1 - y : y) * (size_t)w * 3);
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(rows);
    return 0;
}

int image_write_png_rows(const uint8_t *rgb, int w, int h, int bottom_up, const char *path, char *err, size_t errlen)
{
    outfile_t o;
    if (outfile_open(&o, path, err, errlen) != 0) return -1;
    if (png_to(rgb, w, h, bottom_up, o.f, path, err, errlen) != 0) {
        outfile_abort(&o);
        return -1;
    }
    return outfile_commit(&o, err, errlen);
}

int image_write_png_file(const image_t *im, FILE *f, const char *name, char *err, size_t errlen)
{
    return png_to(im->px, im->w, im->h, 0, f, name, err, errlen);
}
