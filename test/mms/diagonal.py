#!/usr/bin/env python3
"""mms 1.2 test algorithm with diagonals. Run 1: floodfill to the centre
goal in whole cells (sensing with wallFront/wallLeft/wallRight), then back
to the start. Run 2: the shortest path through the cells it has seen,
driven as mms 1.2 allows: every corner cut by a 45-degree turn on a cell
boundary, staircases as one diagonal; every diagonal of two or more half
steps starts with `moveForward` (one step: two diagonal half steps), the
rest is `moveForwardHalf N`. Before each diagonal it checks the wall queries
(wallFront/wallLeft/wallRight with half-step arguments) against its own
map on the half-cell grid, and once it sends a diagonal move into a wall
(`crash`, nothing moves); at the goal it turns 45 degrees at the centre,
where a diagonal aims at a post (`crash`). At the goal it checks getStat
against its own count of the run and prints `expect TURNS DISTANCE
EFFECTIVE CRASHES` and `used COMMANDS` (the diagonal commands it sent)
on stderr. Exits 0 at the goal of run 2, 3 on any unexpected answer (the
reason on stderr)."""
import sys


def cmd(line, answer=True):
    sys.stdout.write(line + "\n")
    sys.stdout.flush()
    return sys.stdin.readline().strip() if answer else None


def fail(why):
    sys.stderr.write("diagonal.py: %s\n" % why)
    sys.exit(3)


def expect(line, want):
    got = cmd(line)
    if got != want:
        fail("%s: %s, expected %s" % (line, got, want))


w, h = int(cmd("mazeWidth")), int(cmd("mazeHeight"))
goal = {(x, y) for x in {(w - 1) // 2, w // 2} for y in {(h - 1) // 2, h // 2}}
step = [(0, 1), (1, 0), (0, -1), (-1, 0)]
step8 = [(0, 1), (1, 1), (1, 0), (1, -1), (0, -1), (-1, -1), (-1, 0), (-1, 1)]
wall = set()  # (x, y, d) known walls
for x in range(w):
    wall.add((x, 0, 2)); wall.add((x, h - 1, 0))
for y in range(h):
    wall.add((0, y, 3)); wall.add((w - 1, y, 1))
seen = set()  # cells whose four walls are known (sensed from inside)


def add_wall(x, y, d):
    wall.add((x, y, d))
    cmd("setWall %d %d %s" % (x, y, "nesw"[d]), answer=False)
    nx, ny = x + step[d][0], y + step[d][1]
    if 0 <= nx < w and 0 <= ny < h:
        wall.add((nx, ny, (d + 2) % 4))


def flood(targets, only_seen):
    dist = {t: 0 for t in targets}
    q = list(targets)
    while q:
        x, y = q.pop(0)
        for d in range(4):
            n = (x + step[d][0], y + step[d][1])
            if (x, y, d) in wall or n in dist or (only_seen and n not in seen):
                continue
            dist[n] = dist[(x, y)] + 1
            q.append(n)
    return dist


# ---- run 1: whole cells, heading in quarters ----
x, y, hd = 0, 0, 0


def sense():
    seen.add((x, y))
    for rel, q in ((0, "wallFront"), (-1, "wallLeft"), (1, "wallRight")):
        if cmd(q) == "true":
            add_wall(x, y, (hd + rel) % 4)


def turn_to(d):
    global hd
    q = (d - hd) % 4
    for c in {1: ["turnRight"], 3: ["turnLeft"], 2: ["turnRight", "turnRight"]}.get(q, []):
        expect(c, "ack")
    hd = d


def go(targets):
    global x, y
    while (x, y) not in targets:
        sense()
        dist = flood(targets, False)
        best = min((dist.get((x + step[d][0], y + step[d][1]), 10**9), d) for d in range(4) if (x, y, d) not in wall)
        turn_to(best[1])
        expect("moveForward", "ack")
        x, y = x + step[hd][0], y + step[hd][1]
    if (x, y) not in seen:
        sense()


go(goal)
go({(0, 0)})

# ---- run 2: on the half-cell grid (mms's SemiPosition), heading in eighths ----


def known_wall(cx, cy, d):
    """The wall on side d of cell (cx, cy): True/False, None if not known."""
    n = (cx + step[d][0], cy + step[d][1])
    if (cx, cy, d) in wall:
        return True
    return False if (cx, cy) in seen or n in seen else None


def semi_wall(sx, sy, d8):
    """mms 1.2's isWall(position, direction) from our own map."""
    if sx < 0 or sy < 0 or sx > 2 * w or sy > 2 * h or (sx % 2 == 0 and sy % 2 == 0):
        return True
    cx, cy = sx // 2, sy // 2
    if sx % 2 and sy % 2:  # a centre: a diagonal aims at a post
        return True if d8 % 2 else known_wall(cx, cy, d8 // 2)
    if sx % 2 == 0:  # on a boundary between west and east
        if d8 in (0, 4):
            return True
        if d8 in (2, 6):
            return False
        east = d8 in (1, 3)
        if (east and sx == 2 * w) or (not east and sx == 0):
            return False
        return known_wall(cx if east else cx - 1, cy, 0 if d8 in (1, 7) else 2)
    if d8 in (2, 6):  # on a boundary between south and north
        return True
    if d8 in (0, 4):
        return False
    north = d8 in (1, 7)
    if (north and sy == 2 * h) or (not north and sy == 0):
        return False
    return known_wall(cx, cy if north else cy - 1, 1 if d8 in (1, 3) else 3)


def semi_wall_ahead(sx, sy, d8, away):
    """wallFront & co with `away` half steps: None if not known."""
    unknown = False
    for i in range(away):
        v = semi_wall(sx + i * step8[d8][0], sy + i * step8[d8][1], d8)
        if v:
            return True
        unknown |= v is None
    return None if unknown else False


sx, sy, h8 = 1, 1, 2 * hd
turns = halves = crashes = 0
eff = 0.0
in_run = finished = False
used = set()  # the diagonal commands sent: printed at the end


def check_queries():
    """wallFront/wallLeft/wallRight N (N = 1..3) where our map knows the answer."""
    for q, rel in (("wallFront", 0), ("wallLeft", -2), ("wallRight", 2)):
        for n in (1, 2, 3):
            v = semi_wall_ahead(sx, sy, (h8 + rel) % 8, n)
            if v is not None:
                expect("%s %d" % (q, n), "true" if v else "false")
                used.add(q + " N")


def turn8(to):
    global h8, turns
    k = (to - h8) % 8
    seq = {1: ["turnRight45"], 2: ["turnRight"], 3: ["turnRight", "turnRight45"], 4: ["turnRight", "turnRight"],
           5: ["turnLeft", "turnLeft45"], 6: ["turnLeft"], 7: ["turnLeft45"]}.get(k, [])
    for c in seq:
        expect(c, "ack")
        if c.endswith("45"):
            used.add(c)
        turns += in_run
    h8 = to


def move(line, n):
    """A forward move of n half steps along h8, counted as mms's stats do:
    a run starts with a move from the start cell and ends where the
    position counts in a goal cell (a boundary: the cell north or east)."""
    global sx, sy, halves, eff, in_run, turns, finished
    if (sx // 2, sy // 2) == (0, 0) and not finished:
        in_run, turns, halves, eff = True, 0, 0, 0.0
    expect(line, "ack")
    sx, sy = sx + n * step8[h8][0], sy + n * step8[h8][1]
    if in_run:
        cells = n / 2
        halves += n
        eff += cells / 2 + 1 if cells > 2 else cells
        if (sx // 2, sy // 2) in goal:
            in_run, finished = False, True


def crash_into_wall():
    """Once, where the diagonal ahead meets a wall within 3 half steps: crash, nothing moves."""
    global crashes
    for n in (1, 2, 3):
        if semi_wall_ahead(sx, sy, h8, n):
            before = cmd("getStat total-distance")
            expect("moveForwardHalf %d" % n, "crash")
            expect("getStat total-distance", before)
            crashes += 1
            return True
    return False


# the shortest path through seen cells, as cell-to-cell directions
dist = flood(goal, True)
if (0, 0) not in dist:
    fail("no path through the seen cells")
path, cx, cy = [], 0, 0
while (cx, cy) not in goal:
    d = min((dist.get((cx + step[d][0], cy + step[d][1]), 10**9), -(len(path) and (d - path[-1]) % 2), d)
            for d in range(4) if (cx, cy, d) not in wall)[2]  # ties: prefer a turn (more diagonals)
    path.append(d)
    cx, cy = cx + step[d][0], cy + step[d][1]

# segments (heading in eighths, half steps) between boundary middles
segs = [(2 * path[0], 1)]
for a, b in zip(path, path[1:]):
    segs.append((2 * a, 2) if a == b else ((2 * a + (1 if (b - a) % 4 == 1 else -1)) % 8, 1))
segs.append((2 * path[-1], 1))
merged = []
for s8, n in segs:
    if merged and merged[-1][0] == s8:
        merged[-1] = (s8, merged[-1][1] + n)
    else:
        merged.append((s8, n))
if not any(s8 % 2 for s8, _ in merged):
    fail("no diagonal on the path")

tested_crash = False
for s8, n in merged:
    turn8(s8)
    if s8 % 2:  # a diagonal: from a boundary middle
        check_queries()
        if not tested_crash:
            tested_crash = crash_into_wall()
        if semi_wall_ahead(sx, sy, h8, n) is not False:
            fail("diagonal of %d half steps from (%d,%d) not free in our map" % (n, sx, sy))
        expect("wallFront %d" % n, "false")
        if n >= 2:
            move("moveForward", 2)
            used.add("moveForward")
            n -= 2
        if n:
            move("moveForwardHalf %d" % n, n)
            used.add("moveForwardHalf")
        check_queries()
    else:
        move("moveForward %d" % (n // 2) if n % 2 == 0 else "moveForwardHalf %d" % n, n)
if not finished:
    fail("the run did not end in a goal cell")
# at the goal's centre (after the run: no in-place turns before the first
# diagonal): a diagonal aims at a post
turn8((h8 + 1) % 8)
expect("wallFront", "true")
expect("moveForwardHalf", "crash")
crashes += 1
if not tested_crash:
    fail("no diagonal met a wall within 3 half steps")
dist_cells = halves // 2
for stat, want in (("best-run-turns", turns), ("best-run-distance", dist_cells), ("best-run-effective-distance", eff)):
    got = cmd("getStat " + stat)
    if float(got) != float(want):
        fail("getStat %s: %s, expected %s" % (stat, got, want))
sys.stderr.write("expect %d %g %g %d\n" % (turns, halves / 2, eff, crashes))
sys.stderr.write("used %s\n" % ", ".join(sorted(used)))
sys.exit(0)
