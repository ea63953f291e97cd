#!/usr/bin/env python3
"""hil_replug.py - a serial device that is unplugged and plugged back, for
test/cli/cli_hil.sh: makes a pseudo-terminal, points the symlink LINK at its
slave (the "device" mmsim opens with --serial LINK), plays a compat MCU
(enable sensors, read encoders), then closes the pty (unplug: the device
disappears), makes a new one, re-points LINK (replug) and reads again.
usage: hil_replug.py LINK SECONDS_EACH ; prints what it saw, exit 0 if
sensor bytes arrived both times."""
import os, select, sys, time, tty

link, each = sys.argv[1], float(sys.argv[2])

def plug():
    m, s = os.openpty()
    tty.setraw(m)
    name = os.ttyname(s)
    tmp = link + '.new'
    if os.path.lexists(tmp): os.unlink(tmp)
    os.symlink(name, tmp)
    os.replace(tmp, link)
    return m, s

def play(m, seconds):
    got, end = 0, time.monotonic() + seconds
    while time.monotonic() < end:
        os.write(m, bytes([7, 2, 5, 100, 0, 6, 100, 0]))  # requestEnableSensors, motors
        r, _, _ = select.select([m], [], [], 0.01)
        if r:
            try: got += len(os.read(m, 4096))
            except OSError: time.sleep(0.01)  # EIO: mmsim has not (re)opened the device yet
    return got

m, s = plug()
first = play(m, each)
os.close(m); os.close(s)                    # unplug
time.sleep(0.8)
m, s = plug()                               # replug at the same path
second = play(m, each)
os.close(m); os.close(s)
print("replug: bytes before %d after %d" % (first, second))
sys.exit(0 if first > 1000 and second > 1000 else 1)
