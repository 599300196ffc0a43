"""Writes the synthetic contact-test data of this folder (see PROVENANCE.md). Plain Python, no packages:
the same files on every machine.

    python3 data/contact-tests/make.py

Both data sets are SYNTHETIC: made from the Hunt-Crossley law with a material damping constant,
F = K d^n (1 + c d'), with a stated seed and noise, for the worked examples of docs/contact-models.md
section 2.8. They are not measurements.
"""

import math
import random
from pathlib import Path

HERE = Path(__file__).resolve().parent


def material_e(chi):
    """e of F = K d^n (1 + c d') at chi = c v_i: the root of chi - ln(1 + chi) = -chi e - ln(1 - chi e)."""
    lhs = chi - math.log1p(chi)
    lo, hi = 0.0, min(1.0, 1.0 / chi - 1e-15)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if -chi * mid - math.log1p(-chi * mid) < lhs:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def restitution(path, c=0.3, seed=2024, noise=0.02):
    rng = random.Random(seed)
    rows = []
    for k in range(16):
        v = 0.1 * 1.25 ** k
        e = material_e(c * v) * (1.0 + noise * rng.gauss(0.0, 1.0))
        rows.append((v, min(e, 1.0)))
    with open(path, "w") as f:
        f.write("# SYNTHETIC, not measured: e = e(c v_i) of F = K d^n (1 + c d'), c = D/K = 0.3 s/m,\n")
        f.write(f"# times (1 + 2 % Gaussian noise), seed {seed} (data/contact-tests/make.py)\n")
        f.write("v_i_m_per_s,e\n")
        for v, e in rows:
            f.write(f"{v:.6g},{e:.6g}\n")


def force_history(path, seed=7, noise=0.02):
    # A concrete ball (R = 0.1 m, E = 30 GPa, nu = 0.2, 2400 kg/m^3: m = 10.053 kg, Hertz stiffness
    # k = (4/3) E* sqrt(R) with 1/E* = 2 (1 - nu^2) / E) striking a rigid slab at 3.13 m/s (a 0.5 m drop;
    # gravity left out over the 1 ms contact), c = 0.15 s/m.
    r, young, nu, rho, v = 0.1, 30e9, 0.2, 2400.0, 3.13
    m = 4.0 / 3.0 * math.pi * r ** 3 * rho
    k = 4.0 / 3.0 * young / (2.0 * (1.0 - nu * nu)) * math.sqrt(r)
    n, c = 1.5, 0.15

    def force(d, dv):
        return max(k * max(d, 0.0) ** n * (1.0 + c * dv), 0.0) if d > 0.0 else 0.0

    def acc(d, dv):
        return -force(d, dv) / m

    # Classical RK4 at 1/50000 of the contact's scale; the force sampled every 20 microseconds.
    d_max = ((n + 1.0) * m * v * v / (2.0 * k)) ** (1.0 / (n + 1.0))
    h = 4.0 * d_max / v / 50000.0
    t, d, dv = 0.0, 0.0, v
    samples, every, t_next = [], 20e-6, 0.0
    t_touch = 1.0e-4  # s on the recorder's clock
    rng = random.Random(seed)
    peak = k * d_max ** n
    while True:
        while t_next - t_touch <= t + 1e-15 and t_next < t_touch + 2.0e-3:
            s = t_next - t_touch
            f = 0.0 if s < 0.0 else force(d, dv)
            samples.append((t_next, f))
            t_next += every
        if t > 2.0e-3:
            break
        k1d, k1v = dv, acc(d, dv)
        k2d, k2v = dv + 0.5 * h * k1v, acc(d + 0.5 * h * k1d, dv + 0.5 * h * k1v)
        k3d, k3v = dv + 0.5 * h * k2v, acc(d + 0.5 * h * k2d, dv + 0.5 * h * k2v)
        k4d, k4v = dv + h * k3v, acc(d + h * k3d, dv + h * k3v)
        d += h / 6.0 * (k1d + 2 * k2d + 2 * k3d + k4d)
        dv += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v)
        t += h
        if d < 0.0 or force(d, dv) <= 0.0 and dv < 0.0:
            d, dv = -1.0, 0.0  # the ball has left: no force after
    with open(path, "w") as f:
        f.write("# SYNTHETIC, not measured: a concrete ball, R = 0.1 m, E = 30 GPa, nu = 0.2, m = 10.053 kg,\n")
        f.write(f"# on a rigid slab at 3.13 m/s; F = k d^1.5 (1 + c d'), k = {k:.6g} N/m^1.5, c = 0.15 s/m;\n")
        f.write(f"# touch at t = 1e-4 s; noise on every sample, 2 % of the peak force, Gaussian, seed {seed} (data/contact-tests/make.py)\n")
        f.write("time_s,force_N\n")
        for tt, ff in samples:
            # Sensor noise on every sample, before and after the contact too.
            noisy = ff + noise * peak * rng.gauss(0.0, 1.0)
            f.write(f"{tt:.6g},{noisy:.6g}\n")


if __name__ == "__main__":
    restitution(HERE / "restitution-synthetic.csv")
    force_history(HERE / "force-history-synthetic.csv")
