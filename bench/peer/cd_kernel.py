"""Fixed-step central-difference kernel for two single-storey buildings pounding (issue 28's peer).

The model is the two-SDOF pair of examples/two-sdof.toml as the tool builds it:

    m1 u1'' + c1 u1' + k1 u1 + F = -m1 a_g(t)          (left, u relative to the ground)
    m2 u2'' + c2 u2' + k2 u2 - F = -m2 a_g(t)          (right)
    c_i = 2 zeta sqrt(k_i m_i)                          (a single storey: Rayleigh with w2 = w1, zeta = 0.05)
    d = u1 - u2 - gap (penetration), contact closed while d > 0
    hooke:          F = k d
    kelvin-voigt:   F = k d + c d',  c = 2 zeta_c sqrt(k m1 m2 / (m1 + m2)),
                    zeta_c = -ln e / sqrt(pi^2 + ln^2 e)   (exact for the law with tension, the tool's default)

a_g linear between the record's samples: the step divides the record's interval (nsub steps per sample) and\na_g is interpolated in the loop (no per-step array). The run covers the record, as the tool's default duration.

Central difference as in Chopra (Table 5.3.1 / 5.7.1) and OpenSees' CentralDifference: the acceleration and the
velocity at step i are the centred differences of u(i-1), u(i), u(i+1); every stiffness force is explicit (at
u(i)), every viscous force implicit through the centred velocity, so the step solves
    (M / dt^2 + C_i / (2 dt)) u(i+1) = p_i - f_s(u_i) + (2 M / dt^2) u_i - (M / dt^2 - C_i / (2 dt)) u(i-1)
with C_i the storeys' damping plus, while the contact is closed at step i, its dashpot (a 2x2 matrix whose
inverse is computed once). Peaks are read at the steps (no interpolation between them); an impact is counted
at each step where the contact goes from open to closed.

All of it is plain loops compiled by numba (@njit, fastmath off so that results are reproducible); `sweep`
runs many gaps in parallel with prange.
"""

import math

import numpy as np
from numba import njit, prange

G = 9.80665


def load_el_centro(path):
    """(dt, accelerations in m/s^2) of the built-in El Centro record (crates/pounding/data/elcentro1940_ns.csv)."""
    rows = np.loadtxt(path, delimiter=",", skiprows=1)
    t, a = rows[:, 0], rows[:, 1] * G
    dt = float(t[1] - t[0])
    assert np.allclose(np.diff(t), dt)
    return dt, a


def kv_zeta(e):
    le = math.log(e)
    return -le / math.sqrt(math.pi ** 2 + le ** 2)


@njit(cache=True)
def run(acc, nsub, dt, m1, k1, c1, m2, k2, c2, gap, kc, cc):
    """One run over the whole record, nsub steps per record interval (dt = record dt / nsub), a_g linear
    between samples. Returns (peak |u1|, peak |u2|, peak contact force, impacts). cc = 0 gives hooke."""
    idt2 = 1.0 / (dt * dt)
    i2dt = 0.5 / dt
    # open contact: diagonal left-hand side
    a1 = m1 * idt2 + c1 * i2dt
    a2 = m2 * idt2 + c2 * i2dt
    r1 = 1.0 / a1
    r2 = 1.0 / a2
    # closed contact: [[a1 + q, -q], [-q, a2 + q]], q = cc / (2 dt); its inverse
    q = cc * i2dt
    det = (a1 + q) * (a2 + q) - q * q
    j11 = (a2 + q) / det
    j22 = (a1 + q) / det
    j12 = q / det
    b1 = m1 * idt2 - c1 * i2dt  # coefficients of u(i-1)
    b2 = m2 * idt2 - c2 * i2dt
    s1 = 2.0 * m1 * idt2 - k1   # coefficients of u(i)
    s2 = 2.0 * m2 * idt2 - k2
    # start from rest: u(-1) = u(0) + dt^2/2 a(0) with a(0) = -a_g(0)
    u1 = 0.0
    u2 = 0.0
    p1 = -0.5 * dt * dt * acc[0]
    p2 = p1
    pk1 = 0.0
    pk2 = 0.0
    fmax = 0.0
    impacts = 0
    closed = False
    inv = 1.0 / nsub
    for k in range(acc.shape[0] - 1):
        a0 = acc[k]
        da = (acc[k + 1] - a0) * inv
        for s in range(nsub):
            ag = a0 + da * s
            d = u1 - u2 - gap
            g1 = s1 * u1 - b1 * p1 - m1 * ag
            g2 = s2 * u2 - b2 * p2 - m2 * ag
            if d > 0.0:
                if not closed:
                    impacts += 1
                    closed = True
                fs = kc * d
                # the dashpot's u(i-1) part, q d(i-1), moves to the right-hand side
                h = q * (p1 - p2)
                g1 += h - fs
                g2 += fs - h
                n1 = j11 * g1 + j12 * g2
                n2 = j12 * g1 + j22 * g2
                f = fs + cc * ((n1 - n2) - (p1 - p2)) * i2dt
                if f > fmax:
                    fmax = f
            else:
                closed = False
                n1 = g1 * r1
                n2 = g2 * r2
            p1 = u1
            p2 = u2
            u1 = n1
            u2 = n2
            a = abs(u1)
            if a > pk1:
                pk1 = a
            a = abs(u2)
            if a > pk2:
                pk2 = a
    return pk1, pk2, fmax, impacts


@njit(parallel=True, cache=True)
def sweep(acc, nsub, dt, m1, k1, c1, m2, k2, c2, gaps, kc, cc):
    n = gaps.shape[0]
    out = np.empty((n, 4))
    for j in prange(n):
        r = run(acc, nsub, dt, m1, k1, c1, m2, k2, c2, gaps[j], kc, cc)
        out[j, 0] = r[0]
        out[j, 1] = r[1]
        out[j, 2] = r[2]
        out[j, 3] = r[3]
    return out
