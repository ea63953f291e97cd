#!/usr/bin/env python3
"""board_console.py MMSIM ARGS... - a person at a serial monitor: starts
mmsim with --console pty, opens the pseudo-terminal it names on stderr,
waits for the firmware's prompt, types B and prints what came back.
Exit 0 if the battery line came back within the run."""
import os, re, select, subprocess, sys, time

p = subprocess.Popen(sys.argv[1:], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
path = None
t0 = time.time()
line = b''
while time.time() - t0 < 10 and path is None:
    r, _, _ = select.select([p.stderr], [], [], 0.5)
    if r:
        c = os.read(p.stderr.fileno(), 1)
        if not c: break
        line += c
        m = re.search(rb'console \(UART0\) is on (\S+)\n', line)
        if m: path = m.group(1).decode()
if not path:
    print('no pty path on stderr:', line[-200:]); p.kill(); sys.exit(1)
fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
seen, typed = b'', False
while time.time() - t0 < 15:
    r, _, _ = select.select([fd], [], [], 0.2)
    if r:
        try:
            seen += os.read(fd, 256)
        except OSError:
            break
    if not typed and b'RDY' in seen:
        os.write(fd, b'B\n')
        typed = True
    if b'Volts' in seen:
        break
out, err = p.communicate(timeout=20)
print(seen.decode(errors='replace').replace('\r', ''))
sys.exit(0 if b'MAZERUNNER-CORE' in seen and b'Volts' in seen else 1)
