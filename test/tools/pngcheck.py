#!/usr/bin/env python3
"""pngcheck.py - read an 8-bit RGB/RGBA PNG with the standard library only
(zlib) and answer questions about its pixels, for the CLI tests.

  pngcheck.py FILE QUESTION...   one answer line per question:
  size                          -> "W H"
  colours                       -> number of distinct colours
  near:RRGGBB:TOL[:X0:Y0:X1:Y1] -> pixels within TOL (max channel
      difference) of the colour, in the box (fractions 0..1 of the size;
      default the whole image)
  centroid:RRGGBB:TOL[:box]     -> "X Y", mean pixel position of those
      pixels ("- -" if none)
  bbox:RRGGBB:TOL[:box]         -> "X0 Y0 X1 Y1", the pixel bounds of
      those pixels, inclusive ("- - - -" if none)
  diff:OTHER.png:TOL[:box]      -> pixels of the box whose colour differs
      from OTHER's (same size) by more than TOL in some channel
Exit 2 with one line on stderr if the file is not such a PNG."""
import struct
import sys
import zlib


def read_png(path):
    """(w, h, bpp, rows): rows[y] the row's bytes, bpp 3 (RGB) or 4 (RGBA).
    Pillow decodes when it is there (Debian's python3-pil, which
    python3-matplotlib brings: much faster), else the standard library."""
    try:
        from PIL import Image
    except ImportError:
        return read_png_zlib(path)
    try:
        with Image.open(path) as im:
            if im.format != 'PNG' or im.mode not in ('RGB', 'RGBA') or im.info.get('interlace'):
                raise ValueError('not a PNG' if im.format != 'PNG' else 'only 8-bit RGB/RGBA, not interlaced')
            w, h = im.size
            bpp = 3 if im.mode == 'RGB' else 4
            raw = im.tobytes()
    except OSError as e:
        raise ValueError('not a PNG' if 'cannot identify' in str(e) else str(e))
    stride = w * bpp
    return w, h, bpp, [bytearray(raw[y * stride:(y + 1) * stride]) for y in range(h)]


def read_png_zlib(path):
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError('not a PNG')
    pos, idat, w = 8, b'', None
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b'IHDR':
            w, h, depth, ctype, _, _, interlace = struct.unpack('>IIBBBBB', body)
            if depth != 8 or ctype not in (2, 6) or interlace:
                raise ValueError('only 8-bit RGB/RGBA, not interlaced')
            bpp = 3 if ctype == 2 else 4
        elif kind == b'IDAT':
            idat += body
        elif kind == b'IEND':
            break
    if w is None:
        raise ValueError('no IHDR')
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows, prev, p = [], bytearray(stride), 0
    for _ in range(h):
        f = raw[p]
        cur = bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        for i in range(stride):
            a = cur[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                cur[i] = (cur[i] + a) & 255
            elif f == 2:
                cur[i] = (cur[i] + b) & 255
            elif f == 3:
                cur[i] = (cur[i] + (a + b) // 2) & 255
            elif f == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pr = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                cur[i] = (cur[i] + pr) & 255
        rows.append(cur)
        prev = cur
    return w, h, bpp, rows


def main():
    path = sys.argv[1]
    try:
        w, h, bpp, rows = read_png(path)
    except (OSError, ValueError, zlib.error, struct.error) as e:
        print(f'{path}: {e}', file=sys.stderr)
        sys.exit(2)
    px = lambda x, y: tuple(rows[y][x * bpp:x * bpp + 3])
    for q in sys.argv[2:]:
        a = q.split(':')
        if a[0] == 'size':
            print(w, h)
        elif a[0] == 'colours':
            print(len({px(x, y) for y in range(h) for x in range(w)}))
        elif a[0] == 'diff':
            ow, oh, obpp, orows = read_png(a[1])
            if (ow, oh) != (w, h):
                print(f'{a[1]}: size {ow}x{oh}, not {w}x{h}', file=sys.stderr)
                sys.exit(2)
            tol = int(a[2])
            box = [float(v) for v in a[3:7]] if len(a) >= 7 else [0, 0, 1, 1]
            x0, y0, x1, y1 = int(box[0] * w), int(box[1] * h), int(box[2] * w), int(box[3] * h)
            n = 0
            for y in range(y0, y1):
                for x in range(x0, x1):
                    o = tuple(orows[y][x * obpp:x * obpp + 3])
                    if max(abs(u - v) for u, v in zip(px(x, y), o)) > tol:
                        n += 1
            print(n)
        elif a[0] in ('near', 'centroid', 'bbox'):
            col = int(a[1], 16)
            want = (col >> 16, (col >> 8) & 255, col & 255)
            tol = int(a[2])
            box = [float(v) for v in a[3:7]] if len(a) >= 7 else [0, 0, 1, 1]
            x0, y0, x1, y1 = int(box[0] * w), int(box[1] * h), int(box[2] * w), int(box[3] * h)
            n = sx = sy = 0
            bx0, by0, bx1, by1 = w, h, -1, -1
            for y in range(y0, y1):
                for x in range(x0, x1):
                    if max(abs(u - v) for u, v in zip(px(x, y), want)) <= tol:
                        n += 1
                        sx += x
                        sy += y
                        bx0, by0, bx1, by1 = min(bx0, x), min(by0, y), max(bx1, x), max(by1, y)
            if a[0] == 'bbox':
                print(f'{bx0} {by0} {bx1} {by1}' if n else '- - - -')
            elif a[0] == 'near':
                print(n)
            else:
                print(f'{sx / n:.2f} {sy / n:.2f}' if n else '- -')
        else:
            print(f'unknown question {q}', file=sys.stderr)
            sys.exit(2)


if __name__ == '__main__':
    main()
