#!/usr/bin/env python3
"""mms test algorithm: floodfill to the centre goal, sensing with
wallFront/wallLeft/wallRight, drawing walls, colours and distances. With an
argument N: N runs (back to the start between runs, straights driven as
moveForward K). With a second argument 'half': every move of K cells is
driven as moveForwardHalf 1 (onto the boundary, where the posts are checked
with wallLeft/wallRight/wallBack) then moveForwardHalf 2K-1. Exits 0 at the
goal of the last run."""
import sys

runs = int(sys.argv[1]) if len(sys.argv) > 1 else 1
half = len(sys.argv) > 2 and sys.argv[2] == "half"


def cmd(line, answer=True):
    sys.stdout.write(line + "\n")
    sys.stdout.flush()
    return sys.stdin.readline().strip() if answer else None


w, h = int(cmd("mazeWidth")), int(cmd("mazeHeight"))
goal = {(x, y) for x in {(w - 1) // 2, w // 2} for y in {(h - 1) // 2, h // 2}}
step = [(0, 1), (1, 0), (0, -1), (-1, 0)]
wall = set()  # (x, y, d) known walls
for x in range(w):
    wall.add((x, 0, 2)); wall.add((x, h - 1, 0))
for y in range(h):
    wall.add((0, y, 3)); wall.add((w - 1, y, 1))


def add_wall(x, y, d):
    wall.add((x, y, d))
    cmd("setWall %d %d %s" % (x, y, "nesw"[d]), answer=False)
    nx, ny = x + step[d][0], y + step[d][1]
    if 0 <= nx < w and 0 <= ny < h:
        wall.add((nx, ny, (d + 2) % 4))


def flood(targets):
    dist = {t: 0 for t in targets}
    q = list(targets)
    while q:
        x, y = q.pop(0)
        for d in range(4):
            if (x, y, d) in wall:
                continue
            n = (x + step[d][0], y + step[d][1])
            if n not in dist:
                dist[n] = dist[(x, y)] + 1
                q.append(n)
    return dist


x, y, hd = 0, 0, 0
seen = set()  # cells whose walls were read from inside


def sense():
    seen.add((x, y))
    for rel, q in ((0, "wallFront"), (-1, "wallLeft"), (1, "wallRight")):
        if cmd(q) == "true":
            add_wall(x, y, (hd + rel) % 4)


def turn_to(d):
    global hd
    q = (d - hd) % 4
    if q == 1:
        cmd("turnRight")
    elif q == 3:
        cmd("turnLeft")
    elif q == 2:
        cmd("turnRight"); cmd("turnRight")
    hd = d


def go(targets, fast):
    global x, y
    while (x, y) not in targets:
        sense()
        dist = flood(targets)
        cmd("setText %d %d %d" % (x, y, dist.get((x, y), -1)), answer=False)
        best = min((dist.get((x + step[d][0], y + step[d][1]), 10**9), d) for d in range(4) if (x, y, d) not in wall)
        turn_to(best[1])
        n = 1
        if fast:  # a straight of known cells with falling distance
            cx, cy = x + step[hd][0], y + step[hd][1]
            while (cx, cy) in seen and (cx, cy, hd) not in wall and (cx, cy) not in targets and \
                    dist.get((cx + step[hd][0], cy + step[hd][1]), 10**9) == dist[(cx, cy)] - 1:
                cx, cy, n = cx + step[hd][0], cy + step[hd][1], n + 1
        if half:
            # on a boundary: posts left and right, the open cell behind
            if cmd("moveForwardHalf") != "ack" or (cmd("wallLeft"), cmd("wallRight"), cmd("wallBack")) != ("true", "true", "false"):
                sys.exit(3)
            r = cmd("moveForwardHalf %d" % (2 * n - 1))
        else:
            r = cmd("moveForward" if n == 1 else "moveForward %d" % n)
        if r != "ack":
            sys.exit(3)  # walls are sensed before each move: a crash is a fault
        x, y = x + step[hd][0] * n, y + step[hd][1] * n
        cmd("setColor %d %d c" % (x, y), answer=False)


for r in range(runs):
    go(goal, r > 0)
    if r + 1 < runs:
        go({(0, 0)}, False)
sys.exit(0)
