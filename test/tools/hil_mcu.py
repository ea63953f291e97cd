#!/usr/bin/env python3
"""hil_mcu.py - plays the microcontroller on mmsim's --pty link, for
test/cli/cli_hil.sh. Its own implementation of the wire protocol (COBS,
CRC-16/CCITT-FALSE, the compat layout), so the simulator's codec is checked
against an independent one.

usage: hil_mcu.py compat|framed PTY SECONDS
Drives forward at 250/1023 until the front ToF reads under 150 mm, then
stops; at 20 % it sends one garbage chunk, at 40 % it goes quiet for 0.3 s,
at 60 % it unplugs for 0.3 s (reconnects).
Prints one line of what it saw; exit 0 if sensors and encoders arrived.

usage: hil_mcu.py once PTY SECONDS
A compat MCU like a sketch of the paper's library, which sends a motor
command only when the value changes: it asks for the sensors,
averages the first 8 front readings at rest (decoded with the paper's 1.0 m
scale), sends one motor command (300 on both sides) and then only reads.
Prints what it saw; exit 0 if readings kept arriving.

usage: hil_mcu.py framed LINK SECONDS --own SESSIONS
A board that stays up while the simulator is stopped and started again
(mmsim --serial LINK, run SESSIONS times): it owns the device (a pty whose
slave LINK points to) and never reopens it. It drives as above, answers every
HELLO of the simulator with its own, and keeps going while no simulator has
the device open, as a UART would (its bytes are lost). Exit 0 if every
session sent sensors and a HELLO that it answered, and its decoder counted
exactly the errors the sessions' ends caused: a frame cut off by a
simulator's exit is completed by the next simulator's first bytes, one bad
chunk; a simulator that ended between frames costs nothing. Ends after
SESSIONS sessions, or after SECONDS."""
import os, select, struct, sys, time, tty

mode, path, seconds = sys.argv[1], sys.argv[2], float(sys.argv[3])
own = int(sys.argv[5]) if len(sys.argv) > 5 and sys.argv[4] == '--own' else 0
compat = mode in ('compat', 'once')
RANGE_MM = 1200         # framed: our robot's ToF range, in HELLO (WIRE_TOF_RANGE_MM)
COMPAT_RANGE_MM = 1000  # compat: 65535 stands for 1.0 m, as the paper's library (WIRE_COMPAT_RANGE_MM)

def crc16(b):
    c = 0xFFFF
    for x in b:
        c ^= x << 8
        for _ in range(8):
            c = ((c << 1) ^ 0x1021) & 0xFFFF if c & 0x8000 else (c << 1) & 0xFFFF
    return c

def cobs(b):
    out, blk = bytearray(), bytearray()
    for x in b:
        if x == 0:
            out.append(len(blk) + 1); out += blk; blk = bytearray()
        else:
            blk.append(x)
    out.append(len(blk) + 1); out += blk; out.append(0)
    return bytes(out)

def uncobs(b):
    out, i = bytearray(), 0
    while i < len(b):
        code = b[i]; i += 1
        if i + code - 1 > len(b): return None
        out += b[i:i + code - 1]; i += code - 1
        if code != 0xFF and i < len(b): out.append(0)
    return bytes(out)

def frame(t, payload):
    raw = bytes([t]) + payload
    return cobs(raw + struct.pack('<H', crc16(raw)))

class Mcu:
    def __init__(self):
        self.fd = None
        self.enc = [0, 0]; self.front = None; self.dists = 0; self.encs = 0
        self.hellos = 0; self.bad = 0; self.buf = bytearray(); self.t0 = time.monotonic()
        self.fronts = []  # compat: every front reading, mm
    def open(self):
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(self.fd)
        self.buf = bytearray()
    def own(self):
        """the device itself: a pty, LINK -> its slave (closed here)"""
        self.fd, s = os.openpty()
        tty.setraw(self.fd)
        os.set_blocking(self.fd, False)
        name = os.ttyname(s)
        os.close(s)
        if os.path.lexists(path): os.unlink(path)
        os.symlink(name, path)
    def send(self, b):
        try:
            os.write(self.fd, b)
        except BlockingIOError:
            if not own: raise  # the owned device: a full buffer loses bytes, as a UART
    def motor(self, l, r):
        if compat:
            self.send(bytes([5]) + struct.pack('<h', l) + bytes([6]) + struct.pack('<h', r))
        else:
            us = int((time.monotonic() - self.t0) * 1e6) & 0xFFFFFFFF
            self.send(frame(2, struct.pack('<Ihh', us, l, r)))
    def hello(self):
        self.send(frame(1, struct.pack('<BBHIH', 1, 1, RANGE_MM, 35832, 1000)))
    def log(self, text):
        if compat: self.send(bytes([8]) + text.encode() + b'\0')
        else: self.send(frame(7, text.encode()))
    def sensors(self, on):
        if compat: self.send(bytes([7, 2 if on else 3]))
        else: self.send(frame(5, bytes([1 if on else 0])))
    def poll(self, timeout):
        r, _, _ = select.select([self.fd], [], [], timeout)
        if not r: return
        try:
            data = os.read(self.fd, 4096)
        except BlockingIOError:
            return
        self.buf += data
        if compat: self.parse_compat()
        else: self.parse_framed()
    def parse_compat(self):
        b = self.buf
        while len(b) >= 3:
            i, v = b[0], struct.unpack('<H', b[1:3])[0]
            if i > 4: self.bad += 1; del b[0]; continue
            if i in (3, 4):
                self.enc[i - 3] += struct.unpack('<h', b[1:3])[0]; self.encs += 1
            else:
                self.dists += 1
                if i == 2:
                    self.front = None if v == 65535 else v * COMPAT_RANGE_MM / 65535
                    if self.front is not None: self.fronts.append(self.front)
            del b[:3]
    def parse_framed(self):
        while 0 in self.buf:
            k = self.buf.index(0); chunk = bytes(self.buf[:k]); del self.buf[:k + 1]
            if not chunk: continue
            raw = uncobs(chunk)
            if raw is None or len(raw) < 3 or crc16(raw[:-2]) != struct.unpack('<H', raw[-2:])[0]:
                self.bad += 1; continue
            t, p = raw[0], raw[1:-2]
            if t == 1:
                self.hellos += 1
                ver, role, rng = struct.unpack('<BBH', p[:4])
                # this MCU speaks version 1; a version-2 sim takes it (and sends it nothing newer)
                assert ver in (1, 2) and role == 0 and rng == RANGE_MM, p
                self.hello()
            elif t == 3:
                _, l, r = struct.unpack('<Iii', p); self.enc = [l, r]; self.encs += 1
            elif t == 4:
                _, s, to, mm = struct.unpack('<IBBH', p); self.dists += 1
                if s == 1: self.front = None if to else mm
            else:
                self.bad += 1

m = Mcu()
if own:
    m.own()
    sessions, hello_sessions, enc_sessions, expect_bad = 0, set(), set(), 0
    present = False
    h0, e0 = 0, 0  # hellos and encoder frames before this session
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        try:
            m.poll(0.002)
        except OSError:  # EIO: no simulator has the device open
            if present:  # it just went: a frame it cut off makes one bad chunk with the next one's bytes
                present = False
                expect_bad += 1 if m.buf else 0
                h0, e0 = m.hellos, m.encs
                if sessions == own: break
            time.sleep(0.01)
            continue
        if not present:  # a simulator opened the device
            present = True
            sessions += 1
        if m.hellos > h0: hello_sessions.add(sessions)
        if m.encs > e0 + 100: enc_sessions.add(sessions)
        near = m.front is not None and m.front < 150
        m.motor(0, 0) if near else m.motor(250, 250)
    print("mcu: sessions %d answered hellos in %d, encoders in %d, hellos %d bad %d expected %d" %
          (sessions, len(hello_sessions), len(enc_sessions), m.hellos, m.bad, expect_bad))
    sys.exit(0 if sessions == own and len(hello_sessions) == own and len(enc_sessions) == own
             and m.bad == expect_bad else 1)
m.open()
if mode == 'once':
    m.sensors(True)
    end = time.monotonic() + seconds
    while len(m.fronts) < 8 and time.monotonic() < end: m.poll(0.002)
    at_rest = sum(m.fronts[:8]) / 8 if len(m.fronts) >= 8 else None
    m.motor(300, 300)                               # the only command: the paper's Motor sends on change
    encs0 = m.encs
    try:
        while time.monotonic() < end: m.poll(0.002)
    except OSError:
        pass                                        # the simulator ended
    print("mcu: once front_at_rest %s front_last %s encoders %d enc %d %d bad %d" %
          (None if at_rest is None else round(at_rest), None if m.front is None else round(m.front),
           m.encs - encs0, m.enc[0], m.enc[1], m.bad))
    sys.exit(0 if at_rest is not None and m.encs - encs0 > 500 and m.bad == 0 else 1)
if mode == 'framed': m.hello()
m.sensors(True)
m.log('hello from the test MCU')
end = time.monotonic() + seconds
quiet_at, unplug_at = time.monotonic() + seconds * 0.4, time.monotonic() + seconds * 0.6
garbage_at = time.monotonic() + seconds * 0.2
quiet_done = unplug_done = garbage_done = False
stopped_at_wall = False
while time.monotonic() < end:
    now = time.monotonic()
    if not garbage_done and now >= garbage_at:  # one corrupt chunk: the sim counts exactly one error
        m.send(bytes([0x42]) if mode == 'compat' else bytes([0x13, 0x37, 0xFF, 0x00]))
        garbage_done = True
    if not quiet_done and now >= quiet_at:
        time.sleep(0.3); quiet_done = True          # silence: the sim must stop the motors
    if not unplug_done and now >= unplug_at:
        os.close(m.fd); time.sleep(0.3); m.open()   # unplug and replug
        if mode == 'framed': m.hello()
        unplug_done = True
    try:
        m.poll(0.002)
    except OSError:
        break                                       # the simulator ended
    near = m.front is not None and m.front < 150
    stopped_at_wall = stopped_at_wall or near
    try:
        m.motor(0, 0) if near else m.motor(250, 250)
    except OSError:
        break
print("mcu: mode %s encoders %d distances %d enc %d %d front %s hellos %d bad %d wall %s" %
      (mode, m.encs, m.dists, m.enc[0], m.enc[1], m.front, m.hellos, m.bad, stopped_at_wall))
ok = m.encs > 500 and m.dists > 20 and m.enc[0] > 50 and m.enc[1] > 50 and m.bad == 0 and \
     (mode == 'compat' or m.hellos >= 1)
sys.exit(0 if ok else 1)
