#!/usr/bin/env python3
"""pngdiff.py A.png B.png [MAX_PCT] - the share of pixels that differ between
two 8-bit PNGs (grey, RGB or RGBA, not interlaced, as libpng and our
viewer write them): a pixel differs when a channel moves by more than 16 of
255 (anti-aliasing and a GL driver's rounding stay under it). Prints
"N of M pixels differ (P %)" and exits 1 when P exceeds MAX_PCT (default
0.5), 2 when a file is not such a PNG or the sizes differ. Standard library
only (the project's machines have no PIL)."""
import struct
import sys
import zlib

CHANNELS = {0: 1, 2: 3, 6: 4}  # colour type -> channels


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("%s: not a PNG" % path)
    pos, idat, w = 8, b"", None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or ctype not in CHANNELS or interlace:
                raise ValueError("%s: depth %d, colour type %d, interlace %d: not read here" % (path, depth, ctype, interlace))
            ch = CHANNELS[ctype]
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    if w is None:
        raise ValueError("%s: no IHDR" % path)
    raw, stride = zlib.decompress(idat), w * ch
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - ch] if i >= ch else 0
            b = prev[i]
            c = prev[i - ch] if i >= ch else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, ch, rows


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    limit = float(sys.argv[3]) if len(sys.argv) == 4 else 0.5
    try:
        a, b = read_png(sys.argv[1]), read_png(sys.argv[2])
    except (OSError, ValueError, zlib.error, struct.error) as e:
        print("pngdiff: %s" % e)
        sys.exit(2)
    if a[:2] != b[:2]:
        print("pngdiff: sizes differ: %dx%d and %dx%d" % (a[0], a[1], b[0], b[1]))
        sys.exit(2)
    w, h = a[0], a[1]
    ca, cb, differ = a[2], b[2], 0
    for ra, rb in zip(a[3], b[3]):
        for x in range(w):
            pa, pb = ra[x * ca:x * ca + min(ca, 3)], rb[x * cb:x * cb + min(cb, 3)]
            if len(pa) != len(pb):  # grey against colour: compare grey with each channel
                pa, pb = (pa * 3)[:3], (pb * 3)[:3]
            if any(abs(p - q) > 16 for p, q in zip(pa, pb)):
                differ += 1
    pct = 100.0 * differ / (w * h)
    print("%d of %d pixels differ (%.3f %%)" % (differ, w * h, pct))
    sys.exit(1 if pct > limit else 0)


if __name__ == "__main__":
    main()
