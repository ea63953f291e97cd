#!/usr/bin/env python3
"""mms protocol conformance client for mmsim --mms on mazes/gen-5x5-s1.txt
(start (0,0) facing north, walls west, east and south; (0,1) has a wall to
the north) with --mms-reset-at 0.1. Sends every command of the mms API,
valid and invalid, and checks each answer's format and value against the
mms README. Prints 'conform: N checks ok' on stderr and exits 0, or names
the first failed check and exits 1."""
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
for m in ("moveForward 0", "moveForward -2", "moveForward x", "moveForwardHalf 1", "moveForwardHalf 0",
          "turnLeft45", "turnRight45"):
    want(m, "crash")
# turns: ack once done (four quarter turns face north again)
for t in ("turnRight", "turnLeft90", "turnRight90", "turnLeft"):
    want(t, "ack")
want("getStat total-turns", INT, "4")
want("wallFront", BOOL, "false")
# no-answer commands and invalid ones are ignored
for line in ("setWall 0 0 w", "setWall 0 0 W", "clearWall 0 0 w", "setColor 0 0 r", "setColor 1 1 Y", "clearColor 1 1",
             "setColor 2 2 k", "clearAllColor", "setColor 3 3 G", "setText 0 0 hello world!", "setText 1 0 a\tb",
             "setText 2 0 x", "clearText 2 0", "setText 3 0 y", "clearAllText", "setText 4 4 abc", "setText 0 1 ok", "setText 1 1 hello world!", "setText 2 2 a\tb\x7f",
             "setText 3 3 ", "setText 3 4 two  spaces",
             "", "   ", "foo", "mazeWidth 3", "mazeWidth 1 2", "getStat", "getStat nope", "getStat score 1",
             "setColor 0 0 z", "setColor 0 0 rr", "setColor 9 9 r", "setWall 0 0 q", "setWall 9 9 n", "setWall a 0 n",
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
want("getStat total-turns", INT, "8")
want("getStat score", FLOAT, "2000")
sys.stderr.write("conform: %d checks ok\n" % checks)
