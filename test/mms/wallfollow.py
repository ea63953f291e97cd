#!/usr/bin/env python3
"""mms test algorithm: left-wall follower. Tracks its own position and stops
(exit 0) in the centre goal; exits 1 after too many moves."""
import sys


def cmd(line, answer=True):
    sys.stdout.write(line + "\n")
    sys.stdout.flush()
    return sys.stdin.readline().strip() if answer else None


w, h = int(cmd("mazeWidth")), int(cmd("mazeHeight"))
gx = {(w - 1) // 2, w // 2}
gy = {(h - 1) // 2, h // 2}
x, y, d = 0, 0, 0  # north
step = [(0, 1), (1, 0), (0, -1), (-1, 0)]
for _ in range(4 * w * h):
    if x in gx and y in gy:
        sys.exit(0)
    if cmd("wallLeft") == "false":
        cmd("turnLeft")
        d = (d + 3) % 4
    elif cmd("wallFront") == "true":
        cmd("turnRight")
        d = (d + 1) % 4
        continue
    if cmd("moveForward") != "ack":
        sys.exit(2)
    x, y = x + step[d][0], y + step[d][1]
    cmd("setColor %d %d g" % (x, y), answer=False)
sys.exit(1)
