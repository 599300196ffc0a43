#!/usr/bin/env python3
"""Write the near-fault ground acceleration bench/opensees/records/near-fault.txt.

The record is a Mavroeidis & Papageorgiou velocity pulse plus a small,
deterministic broadband part, sampled at dt = 0.005 s over 20 s. It is read by
the isolation scenarios (bench/opensees/scenarios-isolation/*.toml), both by
the Rust tool and by bench/opensees/isolation.py.

Pulse (Mavroeidis, G. P. & Papageorgiou, A. S., 2003, "A mathematical
representation of near-fault ground motions", Bull. Seismol. Soc. Am. 93(3),
1099-1131, eq. 1), ground velocity

    v_p(t) = (A/2) [1 + cos(2 pi fp (t - t0) / gamma)] cos(2 pi fp (t - t0) + nu)
             for |t - t0| <= gamma / (2 fp), and 0 otherwise,

with fp = 1/Tp, Tp = 2.5 s, A = 0.8 m/s, gamma = 2.0, nu = 0, t0 = 5 s (the
pulse lasts from 2.5 s to 7.5 s). Its acceleration is the exact derivative,
with theta = 2 pi fp (t - t0):

    a_p(t) = -pi fp A [ sin(theta/gamma) cos(theta + nu) / gamma
                        + (1 + cos(theta/gamma)) sin(theta + nu) ]

(continuous, 0 at both ends of the pulse).

Broadband part: 60 cosines of equal amplitude at frequencies evenly spaced
over 0.5-10 Hz (numpy.linspace(0.5, 10, 60)), phases uniform in [0, 2 pi)
from numpy.random.default_rng(2026), times a trapezoid envelope (0 at t = 0,
1 from 1 s to 10 s, back to 0 at 16 s, 0 after), scaled so that its peak
|acceleration| over the samples is 1.0 m/s^2.

Total a(t) = a_p(t) + a_noise(t), written in g (divided by 9.80665) as two
columns `time (s), acceleration (g)` with a `#` comment header, a row t = 0,
a = 0 (ground at rest; the envelope is 0 there and the pulse has not begun)
and then t = 0.005 ... 20.000 s. Prints PGA, PGV and PGD (trapezoidal
integration of the samples from rest) and the pulse's own peak velocity.

    /tmp/opensees-venv/bin/python bench/opensees/near_fault.py [--out PATH]

Needs only NumPy. Peer material only: not a dependency of the Rust tool.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
G = 9.80665  # m/s^2 per g

DT, DURATION = 0.005, 20.0
# Pulse (Mavroeidis & Papageorgiou 2003)
TP, AMP, GAMMA, NU, T0 = 2.5, 0.8, 2.0, 0.0, 5.0
# Broadband part
N_COS, F_LO, F_HI, SEED, NOISE_PEAK = 60, 0.5, 10.0, 2026, 1.0
ENV = (0.0, 1.0, 10.0, 16.0)  # trapezoid: 0 at ENV[0], 1 on [ENV[1], ENV[2]], 0 from ENV[3]


def pulse(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Velocity (m/s) and acceleration (m/s^2) of the M&P pulse."""
    fp = 1.0 / TP
    theta = 2.0 * np.pi * fp * (t - T0)
    inside = np.abs(t - T0) <= GAMMA / (2.0 * fp)
    v = 0.5 * AMP * (1.0 + np.cos(theta / GAMMA)) * np.cos(theta + NU)
    a = -np.pi * fp * AMP * (np.sin(theta / GAMMA) * np.cos(theta + NU) / GAMMA
                             + (1.0 + np.cos(theta / GAMMA)) * np.sin(theta + NU))
    return np.where(inside, v, 0.0), np.where(inside, a, 0.0)


def envelope(t: np.ndarray) -> np.ndarray:
    return np.interp(t, ENV, [0.0, 1.0, 1.0, 0.0], left=0.0, right=0.0)


def broadband(t: np.ndarray) -> np.ndarray:
    """Sum of N_COS cosines with seeded phases under the trapezoid, peak NOISE_PEAK m/s^2."""
    rng = np.random.default_rng(SEED)
    freqs = np.linspace(F_LO, F_HI, N_COS)
    phases = rng.uniform(0.0, 2.0 * np.pi, N_COS)
    raw = envelope(t) * np.cos(2.0 * np.pi * np.outer(t, freqs) + phases).sum(axis=1)
    return raw * (NOISE_PEAK / np.max(np.abs(raw)))


def integrate(t: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Cumulative trapezoid from 0 at t[0]."""
    return np.concatenate(([0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(t))))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=str(HERE / "records" / "near-fault.txt"))
    args = ap.parse_args()

    n = int(round(DURATION / DT))
    t = np.arange(n + 1) * DT          # 0, 0.005, ..., 20.0
    v_p, a_p = pulse(t)
    a = a_p + broadband(t)             # m/s^2
    a[0] = 0.0                         # exactly at rest (both parts are 0 there)
    vel = integrate(t, a)
    disp = integrate(t, vel)
    ipga, ipgv, ipgd = (int(np.argmax(np.abs(x))) for x in (a, vel, disp))
    ivp = int(np.argmax(np.abs(v_p)))

    header = [
        "near-fault ground acceleration for the OpenSees peer (bench/opensees/near_fault.py writes it; do not edit)",
        "Mavroeidis & Papageorgiou (2003, BSSA 93(3)) velocity pulse "
        "v = (A/2)[1 + cos(2 pi fp (t - t0)/gamma)] cos(2 pi fp (t - t0) + nu), |t - t0| <= gamma/(2 fp):",
        f"  Tp = 1/fp = {TP:g} s, A = {AMP:g} m/s, gamma = {GAMMA:g}, nu = {NU:g}, t0 = {T0:g} s; "
        "acceleration = its exact derivative",
        f"plus broadband: {N_COS} cosines, equal amplitudes, f = linspace({F_LO:g}, {F_HI:g}, {N_COS}) Hz, "
        f"phases uniform [0, 2 pi) from numpy default_rng({SEED}),",
        f"  trapezoid envelope 0 at {ENV[0]:g} s, 1 from {ENV[1]:g} to {ENV[2]:g} s, 0 from {ENV[3]:g} s; "
        f"scaled to peak {NOISE_PEAK:g} m/s^2",
        f"dt = {DT:g} s, {DURATION:g} s, first row t = 0 (ground at rest); "
        f"PGA = {abs(a[ipga]) / G:.5f} g at {t[ipga]:.3f} s, PGV = {abs(vel[ipgv]):.5f} m/s at {t[ipgv]:.3f} s, "
        f"PGD = {abs(disp[ipgd]):.5f} m at {t[ipgd]:.3f} s (trapezoid integration)",
        "columns: time (s), acceleration (g); read with format = \"time-acc\", units = \"g\"",
    ]
    lines = [f"# {h}" for h in header] + ["time_s,acceleration_g"]
    lines += [f"{tk:.3f},{ak / G:.12e}" for tk, ak in zip(t, a)]
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text("\n".join(lines) + "\n")

    print(f"wrote {out}: {n + 1} rows (t = 0 ... {t[-1]:g} s, dt = {DT:g} s)")
    print(f"PGA  = {abs(a[ipga]) / G:.5f} g ({a[ipga]:+.5f} m/s^2) at t = {t[ipga]:.3f} s")
    print(f"PGV  = {abs(vel[ipgv]):.5f} m/s ({vel[ipgv]:+.5f}) at t = {t[ipgv]:.3f} s (integrated)")
    print(f"PGD  = {abs(disp[ipgd]):.5f} m ({disp[ipgd]:+.5f}) at t = {t[ipgd]:.3f} s (integrated); "
          f"at the end: v = {vel[-1]:+.5f} m/s, d = {disp[-1]:+.5f} m")
    print(f"pulse peak velocity = {abs(v_p[ivp]):.5f} m/s at t = {t[ivp]:.3f} s (analytic, A = {AMP:g}); "
          f"pulse peak acceleration = {np.max(np.abs(a_p)):.5f} m/s^2; "
          f"broadband peak = {NOISE_PEAK:g} m/s^2")


if __name__ == "__main__":
    main()
