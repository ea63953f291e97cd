#!/usr/bin/env python3
"""mms protocol conformance client for mmsim --mms on mazes/gen-5x5-s1.txt
(start (0,0) facing north, walls west, east and south; (0,1) has a wall to
the north; row 1 is open from (0,1) to (3,1); the goal (2,2) is open to the
south) with --mms-reset-at 0.1. Sends every command of the mms API, valid
and invalid, and checks each answer's format and value against the mms
README (and mms's source for half steps: on a boundary the posts are walls
along it), then drives to the goal with whole and half steps and checks the
stats. Prints 'conform: N checks ok' on stderr and exits 0, or names the
first failed check and exits 1."""
import re
import sys

checks = 0


def send(line):
    sys.stdout.write(line + "\n")
    sys.stdout.flush()


def ask(line):
    send(line)
    return sys.stdin.readline().rstrip("\n")


def want(line, pattern, value=None):
    global checks
    got = ask(line)
    if not re.fullmatch(pattern, got) or (value is not None and got != value):
        sys.stderr.write("conform: FAILED %r -> %r (want %s%s)\n" % (line, got, pattern, "" if value is None else " = " + value))
        sys.exit(1)
    checks += 1
    return got


INT = r"-?[0-9]+"
FLOAT = r"-?[0-9]+(\.[0-9]+)?(e[-+][0-9]+)?"
BOOL = r"true|false"


def ignored(line):
    """An invalid or no-answer command: the next answer belongs to the next query."""
    send(line)
    want("mazeWidth", INT, "5")


want("mazeWidth", INT, "5")
want("mazeHeight", INT, "5")
for q, v in (("wallFront", "false"), ("wallLeft", "true"), ("wallRight", "true"), ("wallBack", "true"),
             ("wallFront 1", "false"), ("wallFront 2", "false"), ("wallFront 3", "true"), ("wallFront 0", "false"),
             ("wallFront x", "false"), ("wallLeft 3", "true"), ("wallFrontLeft", "true"), ("wallFrontRight", "true"),
             ("wallBackLeft", "true"), ("wallBackRight 2", "true")):
    want(q, BOOL, v if q != "wallFront 3" else None)
for s in ("total-distance", "total-turns", "current-run-distance", "current-run-turns"):
    want("getStat " + s, INT, "0")
for s in ("best-run-distance", "best-run-turns", "best-run-effective-distance"):
    want("getStat " + s, INT, "-1")
for s in ("total-effective-distance", "current-run-effective-distance"):
    want("getStat " + s, FLOAT, "0")
want("getStat score", FLOAT, "2000")
want("wasReset", BOOL, "false")
# refused moves answer crash at once
for m in ("moveForward 0", "moveForward -2", "moveForward x", "moveForwardHalf 0", "moveForwardHalf -1",
          "moveForwardHalf x"):
    want(m, "crash")
# turns: ack once done (four quarter turns face north again)
for t in ("turnRight", "turnLeft90", "turnRight90", "turnLeft"):
    want(t, "ack")
# 45-degree turns (mms 1.2): ack; at a centre a diagonal aims at a post, so
# every wall query along a diagonal is true and a move crashes, nothing moving
want("turnLeft45", "ack")
for q in ("wallFront", "wallLeft", "wallRight 2", "wallBack"):
    want(q, BOOL, "true")
want("moveForwardHalf", "crash")
want("moveForward", "crash")
want("getStat total-distance", INT, "0")
want("turnRight45", "ack")
want("getStat total-turns", INT, "6")
want("wallFront", BOOL, "false")
# no-answer commands and invalid ones are ignored
for line in ("setWall 0 0 w", "setWall 0 0 W", "clearWall 0 0 w", "setColor 0 0 r", "setColor 1 1 Y", "clearColor 1 1",
             "setColor 2 2 k", "clearAllColor", "setColor 3 3 G", "setText 0 0 hello world!", "setText 1 0 a\tb",
             "setText 2 0 x", "clearText 2 0", "setText 3 0 y", "clearAllText", "setText 4 4 abc", "setText 0 1 ok", "setText 1 1 hello world!", "setText 2 2 a\tb\x7f",
             "setText 3 3 ", "setText 3 4 two  spaces",
             "", "   ", "foo", "mazeWidth 3", "mazeWidth 1 2", "getStat", "getStat nope", "getStat score 1",
             "setColor 0 0 z", "setColor 0 0 rr", "setColor 9 9 r", "setWall 0 0 q", "setWall 9 9 n", "setWall a 0 n",
             "clearWall", "clearWall 0 0", "clearWall 0 0 x", "clearWall 0 0 nn", "clearWall a 0 n", "clearWall 0 b n",
             "clearWall 9 9 n", "clearWall -1 0 n", "clearWall 0 0 n 1", "clearwall 0 0 n",
             "clearColor 0", "setText x 0 t", "moveForward 1 2", "turnLeft 1", "wasReset 1", "ackReset 1",
             "clearAllText 1", "MAZEWIDTH", "mazewidth"):
    ignored(line)
want("  mazeHeight  ", INT, "5")
want("mazeHeight\r", INT, "5")
# a move: ack; then the wall ahead is sensed; a move into it crashes
want("moveForward", "ack")
want("wallFront", BOOL, "true")
want("wallBack", BOOL, "false")
want("moveForward", "crash")
want("getStat total-distance", INT, "1")
want("getStat current-run-distance", INT, "1")
want("getStat current-run-effective-distance", FLOAT, "1")
# --mms-reset-at 0.1: the move took longer, so the Reset button was pressed
want("wasReset", BOOL, "true")
want("wasReset", BOOL, "true")
want("ackReset", "ack")
want("wasReset", BOOL, "false")
want("wallFront", BOOL, "false")  # back at the start, facing north
want("moveForward", "ack")
want("getStat current-run-effective-distance", FLOAT, "16")  # 15-point reset penalty
want("getStat total-effective-distance", FLOAT, "17")
want("turnLeft", "ack")
want("turnLeft", "ack")
want("moveForward", "ack")
want("getStat current-run-distance", INT, "2")  # back at the start: the run ended unfinished (kept until the next)
want("turnLeft", "ack")
want("turnLeft", "ack")
want("moveForward", "ack")  # a new run from the start: current-run stats restart, no penalty now
want("getStat current-run-distance", INT, "1")
want("getStat current-run-effective-distance", FLOAT, "1")
want("getStat current-run-turns", INT, "0")
want("getStat total-turns", INT, "10")  # 4 + 2 eighths + 4
want("getStat score", FLOAT, "2000")


def stat(name):
    return float(want("getStat " + name, FLOAT))


# whole steps of several cells along row 1 (moveForward 3: effective 2.5)
want("turnRight", "ack")  # east, at (0,1)
want("wallRight", BOOL, "false")  # (0,1)'s south side: open to the start
want("wallRight 2", BOOL, "false")
want("wallRight 3", BOOL, "true")  # the start's south wall
d0, e0 = stat("total-distance"), stat("total-effective-distance")
want("moveForward 3", "ack")  # to (3,1)
want("getStat total-distance", INT, "%d" % (d0 + 3))
want("getStat total-effective-distance", FLOAT, "%g" % (e0 + 2.5))
want("wallFront", BOOL, "true")
want("wallBack 3", BOOL, "false")  # back to (2,1)'s west side: open
want("wallBack 7", BOOL, "true")  # (0,1)'s west wall, seven half steps back
want("wallRight", BOOL, "true")  # (3,1)'s south wall
want("wallRight 3", BOOL, "true")
want("turnLeft", "ack")
want("turnLeft", "ack")  # west
want("moveForward 2", "ack")  # to (1,1)
want("getStat total-effective-distance", FLOAT, "%g" % (e0 + 4.5))
want("moveForwardHalf 2", "ack")  # an even number of half steps: to (0,1)
want("getStat total-distance", INT, "%d" % (d0 + 6))
want("getStat total-effective-distance", FLOAT, "%g" % (e0 + 5.5))
want("turnRight", "ack")
want("turnRight", "ack")  # east
# one half step: on the boundary between (0,1) and (1,1)
want("moveForwardHalf", "ack")
for q, v in (("wallFront", "false"), ("wallLeft", "true"), ("wallRight", "true"), ("wallBack", "false"),
             ("wallFront 2", "false"), ("wallFront 6", "true"), ("wallBack 2", "true"), ("wallLeft 3", "true"),
             ("wallFrontLeft", "true"), ("wallFrontRight", "true"), ("wallBackLeft", "true"), ("wallBackRight", "false")):
    want(q, BOOL, v)  # posts left and right; diagonals: the walls of (1,1) and (0,1) north and south
want("getStat total-distance", INT, "%d" % (d0 + 6))  # 6.5 cells, whole cells answered
want("getStat total-effective-distance", FLOAT, "%g" % (e0 + 6))
want("turnLeft", "ack")  # facing a post: it may turn, not move
want("wallFront", BOOL, "true")
want("wallBack", BOOL, "true")
want("wallLeft", BOOL, "false")
want("moveForward", "crash")
want("moveForwardHalf", "crash")
want("turnRight", "ack")  # east again
want("moveForward", "ack")  # a whole step from a boundary: to the next boundary
want("moveForwardHalf", "ack")  # to (2,1)'s centre
want("getStat total-distance", INT, "%d" % (d0 + 8))
want("getStat total-effective-distance", FLOAT, "%g" % (e0 + 7.5))
want("getStat best-run-distance", INT, "-1")
# to the goal: onto its south boundary, which mms counts as the cell north of it
want("turnLeft", "ack")
want("moveForwardHalf", "ack")
want("getStat best-run-distance", INT, "9")  # this run: 1 + 3 + 2 + 1 + 0.5 + 1 + 0.5 + 0.5 cells
want("getStat best-run-turns", INT, "8")
want("getStat best-run-effective-distance", FLOAT, "9")
tt, te = stat("total-turns"), stat("total-effective-distance")
score = stat("score")
if not (score < 2000 and abs(score - (8 + 9 + 0.1 * (tt + te))) < 1e-3):
    sys.stderr.write("conform: FAILED score %g, want %g\n" % (score, 8 + 9 + 0.1 * (tt + te)))
    sys.exit(1)
want("moveForwardHalf", "ack")  # the goal's centre
want("getStat current-run-distance", INT, "9")  # the run ended on the boundary
sys.stderr.write("conform: %d checks ok\n" % checks)
