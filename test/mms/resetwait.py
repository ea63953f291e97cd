#!/usr/bin/env python3
"""mms test algorithm in the idiom of algorithms that wait for Reset (as
SlimRunner/mms-floodfill does): floodfill to the centre goal, then poll
wasReset until it answers true (the user pressed Reset), ackReset (mms puts
the mouse back on the start cell, facing north) and go again with the walls
it learned. With an argument N: N runs to the goal, polling for Reset after
each but the last; then it exits 0. With a second argument 'forever' it
polls for Reset after the last run too, for ever. Tells on its stderr when
it is at the goal and when it is done. Written for test/cli/cli_mms.sh and
test/cli/cli_mms_view.sh."""
import sys

runs = int(sys.argv[1]) if len(sys.argv) > 1 else 2
forever = len(sys.argv) > 2 and sys.argv[2] == "forever"


def cmd(line, answer=True):
    sys.stdout.write(line + "\n")
    sys.stdout.flush()
    return sys.stdin.readline().strip() if answer else None


w, h = int(cmd("mazeWidth")), int(cmd("mazeHeight"))
goal = {(x, y) for x in {(w - 1) // 2, w // 2} for y in {(h - 1) // 2, h // 2}}
step = [(0, 1), (1, 0), (0, -1), (-1, 0)]
wall = set()


def add_wall(x, y, d):
    wall.add((x, y, d))
    nx, ny = x + step[d][0], y + step[d][1]
    wall.add((nx, ny, (d + 2) % 4))


for i in range(w):
    add_wall(i, 0, 2); add_wall(i, h - 1, 0)
for i in range(h):
    add_wall(0, i, 3); add_wall(w - 1, i, 1)


def flood():
    dist = {g: 0 for g in goal}
    q = list(goal)
    while q:
        x, y = q.pop(0)
        for d in range(4):
            n = (x + step[d][0], y + step[d][1])
            if (x, y, d) not in wall and n not in dist:
                dist[n] = dist[(x, y)] + 1
                q.append(n)
    return dist


def run():
    x, y, hd = 0, 0, 0
    while (x, y) not in goal:
        for rel, q in ((0, "wallFront"), (-1, "wallLeft"), (1, "wallRight")):
            if cmd(q) == "true":
                add_wall(x, y, (hd + rel) % 4)
        dist = flood()
        d = min((dist.get((x + step[d][0], y + step[d][1]), 10**9), d) for d in range(4) if (x, y, d) not in wall)[1]
        for _ in range((d - hd) % 4 if (d - hd) % 4 != 3 else 0):
            cmd("turnRight")
        if (d - hd) % 4 == 3:
            cmd("turnLeft")
        hd = d
        if cmd("moveForward") != "ack":
            sys.exit(3)  # walls are sensed before each move: a crash is a fault
        x, y = x + step[hd][0], y + step[hd][1]


def wait_for_reset():
    while cmd("wasReset") != "true":
        pass
    cmd("ackReset")


for r in range(runs):
    run()
    print("resetwait: run %d at the goal" % (r + 1), file=sys.stderr, flush=True)  # for test/cli/cli_mms_view.sh
    if r + 1 < runs or forever:
        wait_for_reset()
print("resetwait: done", file=sys.stderr, flush=True)
sys.exit(0)
