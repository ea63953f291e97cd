#!/usr/bin/env python3
"""mrc_check.py MAZE RESULT.json - mazerunner-core's search on the emulated
board against the true maze: every wall set its log reports ("- [x,y,H] LFR":
the walls it sees of the cell ahead at its sensing point) and, if the console
has a map (its W command), every visited cell's walls in that map, equal the
maze's. Prints one line a mismatch and a summary; exit 1 on any mismatch."""
import json, re, sys

rows = [l.rstrip('\n') for l in open(sys.argv[1]) if l.strip()]
H, W = (len(rows) - 1) // 2, (len(rows[0]) - 1) // 4

def wall(rs, x, y, d):  # d: 0 N, 1 E, 2 S, 3 W; rs[0] is the north edge
    r = 2 * (H - 1 - y) + 1
    if d == 0: return rs[r - 1][4 * x + 1:4 * x + 4] == '---'
    if d == 2: return rs[r + 1][4 * x + 1:4 * x + 4] == '---'
    return rs[r][4 * x + (4 if d == 1 else 0)] == '|'

j = json.loads(open(sys.argv[2]).read().splitlines()[-1])
con = j['console'].replace('\r', '')
HD, STEP = 'NESW', ((0, 1), (1, 0), (0, -1), (-1, 0))
bad, seen, visited = 0, 0, {(0, 0)}
for m in re.finditer(r'- \[\s*(\d+),\s*(\d+),([NESW])\]\s+([L-])([F-])([R-])', con):
    x, y, h = int(m.group(1)), int(m.group(2)), HD.index(m.group(3))
    nx, ny = x + STEP[h][0], y + STEP[h][1]
    visited |= {(x, y), (nx, ny)}
    want = ''.join(c if wall(rows, nx, ny, d) else '-' for c, d in (('L', (h + 3) % 4), ('F', h), ('R', (h + 1) % 4)))
    got = m.group(4) + m.group(5) + m.group(6)
    seen += 1
    if got != want:
        bad += 1
        print('sensed at [%d,%d,%s]: cell %d,%d %s, the maze has %s' % (x, y, m.group(3), nx, ny, got, want))
maps = re.findall(r'((?:o[-o ]+o\n\|[^\n]*\|\n){%d}o[-o ]+o)\n' % H, con)
cells = 0
if maps:
    mp = maps[-1].split('\n')
    for (x, y) in sorted(visited):
        cells += 1
        for d in range(4):
            if wall(mp, x, y, d) != wall(rows, x, y, d):
                bad += 1
                print("map (W): cell %d,%d side %s: %s, the maze %s" % (x, y, HD[d], wall(mp, x, y, d), wall(rows, x, y, d)))
print('%d wall sets sensed, %d visited cells in its map, %d mismatches' % (seen, cells, bad))
sys.exit(1 if bad or not seen else 0)
