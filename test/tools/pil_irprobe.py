#!/usr/bin/env python3
# pil_irprobe.py ERR JSON [GYRO_MAX_MDPS] - used by test/cli/cli_pil.sh.
# IrProbe (framed): every sample the MCU logged ("mcu: ir SEQ MASK: v...")
# is the IR frame the simulator reported sending with that seq ("IR seq SEQ,
# emitters 0xMASK: v..."): same groups, same values; the MCU's robot line
# matches the simulator's ROBOT report (IR count, gyro present, battery
# within 2 %), and its gyro reading is within GYRO_MAX_MDPS of 0 (the robot
# is at rest; default 0: a robot without a gyro reads 0).
# Prints: samples, samples equal to the sim's, robot line ok, exit reason,
# the MCU's protocol version, EMITTERs and IR frames the sim counted, decoder
# errors, the values per sample ("-" if none), gyro ok.
import json, re, sys
err = open(sys.argv[1]).read()
d = json.loads(open(sys.argv[2]).read().splitlines()[-1])
gmax = int(sys.argv[3]) if len(sys.argv) > 3 else 0
sim = {}
for m in re.finditer(r'^mmsim: link .*: IR seq (\d+), emitters 0x([0-9a-f]+):(.*) at [0-9.]+ s$', err, re.M):
    vals = m.group(3).strip()
    sim[int(m.group(1))] = (int(m.group(2), 16), [] if vals == '(no IR sensors)' else [int(v) for v in vals.split()])
mcu = [(int(a), int(b), [int(v) for v in c.split()]) for a, b, c in re.findall(r'^mcu: ir (\d+) (\d+):(.*)$', err, re.M)]
same = sum(1 for seq, mask, vals in mcu if sim.get(seq) == (mask, vals))
r = re.search(r'^mmsim: link .*: robot for the MCU: (\d+) IR sensors, gyro (yes|no), battery (\d+) mV', err, re.M)
p = re.search(r'^mcu: IrProbe: ir (\d+), gyro (\d) (-?\d+) mdps, battery (\d+) mV$', err, re.M)
robot = bool(r and p) and r.group(1) == p.group(1) and (r.group(2) == 'yes') == (p.group(2) == '1') \
    and abs(int(p.group(4)) - int(r.group(3))) <= 0.02 * int(r.group(3))
gyro_ok = bool(p) and abs(int(p.group(3))) <= gmax
l = d['link']
nvals = ','.join(sorted({str(len(v)) for _, _, v in mcu})) or '-'
print(len(mcu), same, robot, d['exit_reason'], l['mcu_version'], l['v2']['emitter_msgs'], l['v2']['ir_frames'],
      sum(v for k, v in l['decoder'].items() if k not in ('bytes', 'frames_ok')), nvals, gyro_ok)
