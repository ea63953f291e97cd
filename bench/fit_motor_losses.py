#!/usr/bin/env python3
"""fit_motor_losses.py - the paper robot's motor losses (robots/paper.ini,
[motor.*] friction_load_a) from the Pololu datasheet.

Standard library only. Run: python3 bench/fit_motor_losses.py

Source: Pololu, "Micro Metal Gearmotors", Rev 2.0 (May 2018), p. 1, the
30:1 LP 6V (items 993, 2202) at 6 V: no load 450 rpm, 0.02 A; at maximum
efficiency 320 rpm, 0.66 kg*mm, 0.11 A, 0.22 W out; max power 0.31 W;
stall (extrapolated) 2.9 kg*mm, 0.36 A.

The model (sim/world/motor.h, datasheet model), steady state at the output
shaft, w = output speed, i = motor current, V = rated voltage:
  R = V / i_stall,  k = (V - R*i_noload) / w_noload          (N*Ke, V*s/rad)
  w(i) = (V - R*i) / k
  i_f(i) = i_noload + F*(1 - exp(-max(0, |i| - i_noload) / (2F)))
           friction in amperes of motor current: i_noload running free,
           rising by F once the motor carries a load (F = friction_load_a)
  eta = T_stall / (k*(i_stall - i_f(i_stall)))                (gearbox)
  T(i) = eta*k*(i - i_f(i))
The rise's scale 2F is the model's, not fitted: the friction grows at most
half as fast as the current at no load, so the free-running state is the
only one (a loop gain of 1/2; at 1 or more a free motor could lock into its
loaded friction).

Fit: R, k and eta from no load and stall (exact, as today's model); F, the
one further parameter, from the one further figure, the maximum output
power (0.31 W), by bisection. Not used: the maximum-efficiency figures (320
rpm, 0.66 kg*mm, 0.11 A, 0.22 W out of 6 V x 0.11 A = 33.3 %): they are the
predictions, which mmsim --validate grades in the simulator (the load swept
on the bench, not these equations). This script prints them too, from the
equations, as a preview.
"""
import math

V = 6.0                                 # V, rated
NL_RPM, NL_A = 450.0, 0.02              # no load
ST_NM, ST_A = 2.9 * 9.80665e-3, 0.36    # stall: 2.9 kg*mm
PMAX_W = 0.31                           # the fitted figure
ME_RPM, ME_KGMM, ME_A, ME_OUT_W = 320.0, 0.66, 0.11, 0.22  # predicted, not used by the fit
KGMM = 9.80665e-3                       # N*m per kg*mm
RPM = 2 * math.pi / 60                  # rad/s per rpm

R = V / ST_A
K = (V - R * NL_A) / (NL_RPM * RPM)


def friction_a(i, f):
    return NL_A + f * (1 - math.exp(-max(0.0, abs(i) - NL_A) / (2 * f))) if f > 0 else NL_A


def curve(f, n=40000):
    """(torque N*m, speed rad/s, current A) from no load to stall."""
    eta = ST_NM / (K * (ST_A - friction_a(ST_A, f)))
    pts = []
    for j in range(1, n):
        i = NL_A + (ST_A - NL_A) * j / n
        pts.append((eta * K * (i - friction_a(i, f)), (V - R * i) / K, i))
    return pts, eta


def max_power(f):
    return max(t * w for t, w, _ in curve(f)[0])


def fit():
    lo, hi = 0.0, 0.2  # F in A; the power falls as F grows
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if max_power(mid) > PMAX_W:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def main():
    f = fit()
    pts, eta = curve(f)
    t, w, i = max(pts, key=lambda p: p[0] * p[1] / (V * p[2]))
    tm, wm, im = min(pts, key=lambda p: abs(p[0] - ME_KGMM * KGMM))
    print("R %.3f ohm, N*Ke %.5f V*s/rad, eta %.4f" % (R, K, eta))
    print("friction_load_a = %.4f  (fitted: max power %.3f W)" % (f, max_power(f)))
    eff = 100 * t * w / (V * i)
    ds_eff = 100 * ME_OUT_W / (V * ME_A)
    print("preview of the predictions (mmsim --validate grades them in the simulator):")
    print("  max efficiency speed   %6.1f rpm   datasheet %5.1f  %+5.1f %%" % (w / RPM, ME_RPM, 100 * (w / RPM / ME_RPM - 1)))
    print("  max efficiency current %6.4f A     datasheet %5.3f  %+5.1f %%" % (i, ME_A, 100 * (i / ME_A - 1)))
    print("  max efficiency         %6.2f %%     datasheet %5.1f  %+5.1f %%" % (eff, ds_eff, 100 * (eff / ds_eff - 1)))
    print("  current at 0.66 kg*mm  %6.4f A     datasheet %5.3f  %+5.1f %%" % (im, ME_A, 100 * (im / ME_A - 1)))


if __name__ == "__main__":
    main()
