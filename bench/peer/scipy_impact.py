#!/usr/bin/env python3
"""Peer benchmark: one Hunt-Crossley-type impact integrated with SciPy's solve_ivp.

What it measures
----------------
The time SciPy's general-purpose ODE solvers take to integrate ONE impact,
and how accurate the delivered coefficient of restitution is. The Rust
library's single-impact integrator is reported as a ratio against these
numbers (see docs/performance.md).

Physics (SI units). Two bodies with effective mass m touch at t = 0 with
penetration d = 0 and rate d' = v_i > 0; relative motion obeys m d'' = -F with
the "papi" force law (energy-split reading):

    approach     (d' > 0):  F = k d^n (1 + chi   * d' / v_i)
    restitution  (d' <= 0): F = k d^n (1 + chi_r * d' / v_i)

The approach is integrated until the event d' = 0 (direction -1, terminal);
a second solve_ivp call restarts from the event state and integrates the
restitution until the event d = 0 (direction -1, terminal). The delivered
coefficient of restitution is e_post = -d'(end) / v_i.

Parameters: k = 1e9 N/m^n, m = 1e5 kg, v_i = 1 m/s, chi = 0.9817043069215692,
chi_r = 0.6945845081932873 (calibrated for e = 0.65). Cases n = 1 (linear)
and n = 1.5 (Hertz-type). For Hunt-Crossley-type laws the delivered e does not
depend on n, so the exact e_post is 0.65 in both cases.

For each method in {RK45, DOP853, LSODA} and rtol in {1e-8, 1e-10, 1e-12}
(atol = rtol * [d_scale, v_i], d_scale = v_i * sqrt(m/k)), the full impact
(both solve_ivp calls) is timed with time.perf_counter. Repetitions: at least
20, or enough for ~1 s per configuration, whichever is more, capped at 200
(--quick: 3). Reported: median microseconds per impact, total RHS
evaluations (nfev of both calls), and |e_post - 0.65|.

How to run
----------
    python3 -m venv /tmp/peer-venv && /tmp/peer-venv/bin/pip install scipy numpy
    /tmp/peer-venv/bin/python bench/peer/scipy_impact.py            # full run
    /tmp/peer-venv/bin/python bench/peer/scipy_impact.py --quick    # smoke run
    /tmp/peer-venv/bin/python bench/peer/scipy_impact.py --json > rows.json

With --json the table goes to stderr and a JSON list of rows
{method, rtol, n, median_us, nfev, abs_error} goes to stdout.

This script is a peer measurement only. SciPy/NumPy are never dependencies
of the Rust project.
"""

import argparse
import json
import math
import platform
import statistics
import sys
import time

import numpy as np
import scipy
from scipy.integrate import solve_ivp

K = 1e9  # N/m^n
M = 1e5  # kg
V_I = 1.0  # m/s
CHI = 0.9817043069215692
CHI_R = 0.6945845081932873
E_EXACT = 0.65

METHODS = ("RK45", "DOP853", "LSODA")
RTOLS = (1e-8, 1e-10, 1e-12)
EXPONENTS = (1.0, 1.5)

MIN_REPS = 20
MAX_REPS = 200
TARGET_SECONDS = 1.0
QUICK_REPS = 3


def make_impact(n, k=K, m=M, v_i=V_I, chi=CHI, chi_r=CHI_R):
    """Return a function (method, rtol, atol) -> (e_post, nfev) for one impact."""
    c_app = chi / v_i
    c_res = chi_r / v_i
    # Generous time bound; both phases end on terminal events long before it.
    t_bound = 1000.0 * math.sqrt(m / k)

    def rhs_approach(t, y):
        d = y[0]
        v = y[1]
        f = k * d**n * (1.0 + c_app * v) if d > 0.0 else 0.0
        return [v, -f / m]

    def rhs_restitution(t, y):
        d = y[0]
        v = y[1]
        f = k * d**n * (1.0 + c_res * v) if d > 0.0 else 0.0
        return [v, -f / m]

    def ev_max_compression(t, y):
        return y[1]

    ev_max_compression.terminal = True
    ev_max_compression.direction = -1

    def ev_separation(t, y):
        return y[0]

    ev_separation.terminal = True
    ev_separation.direction = -1

    y0 = [0.0, v_i]

    def impact(method, rtol, atol):
        s1 = solve_ivp(rhs_approach, (0.0, t_bound), y0, method=method,
                       rtol=rtol, atol=atol, events=ev_max_compression)
        if s1.status != 1 or len(s1.t_events[0]) == 0:
            raise RuntimeError(f"{method}: approach did not reach d'=0: {s1.message}")
        t1 = s1.t_events[0][0]
        y1 = s1.y_events[0][0]
        s2 = solve_ivp(rhs_restitution, (t1, t1 + t_bound), y1, method=method,
                       rtol=rtol, atol=atol, events=ev_separation)
        if s2.status != 1 or len(s2.t_events[0]) == 0:
            raise RuntimeError(f"{method}: restitution did not reach d=0: {s2.message}")
        v_end = s2.y_events[0][0][1]
        return -v_end / v_i, s1.nfev + s2.nfev

    return impact


def bench_one(impact, n, method, rtol, atol, quick):
    # Warm-up call (also gives accuracy and nfev; these are deterministic).
    t0 = time.perf_counter()
    e_post, nfev = impact(method, rtol, atol)
    single = time.perf_counter() - t0

    if quick:
        reps = QUICK_REPS
    else:
        want = math.ceil(TARGET_SECONDS / max(single, 1e-9))
        reps = min(MAX_REPS, max(MIN_REPS, want))

    times = []
    for _ in range(reps):
        t0 = time.perf_counter()
        impact(method, rtol, atol)
        times.append(time.perf_counter() - t0)
    return {
        "method": method,
        "rtol": rtol,
        "n": n,
        "median_us": statistics.median(times) * 1e6,
        "nfev": int(nfev),
        "abs_error": abs(e_post - E_EXACT),
    }, reps


def cpu_model():
    try:
        with open("/proc/cpuinfo") as fh:
            for line in fh:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    ap.add_argument("--quick", action="store_true",
                    help=f"smoke run: {QUICK_REPS} repetitions per configuration")
    ap.add_argument("--json", action="store_true",
                    help="print JSON rows to stdout (table goes to stderr)")
    args = ap.parse_args(argv)

    out = sys.stderr if args.json else sys.stdout
    d_scale = V_I * math.sqrt(M / K)

    print(f"# scipy {scipy.__version__}, numpy {np.__version__}, "
          f"python {platform.python_version()}", file=out)
    print(f"# cpu: {cpu_model()}", file=out)
    print(f"# k={K:g} m={M:g} v_i={V_I:g} chi={CHI!r} chi_r={CHI_R!r} "
          f"e_exact={E_EXACT} d_scale={d_scale:g}", file=out)
    header = f"{'method':<7} {'n':>4} {'rtol':>7} {'reps':>5} {'median_us':>11} {'nfev':>6} {'abs_error':>10}"
    print(header, file=out)
    print("-" * len(header), file=out)

    rows = []
    for n in EXPONENTS:
        impact = make_impact(n)
        for method in METHODS:
            for rtol in RTOLS:
                atol = rtol * np.array([d_scale, V_I])
                row, reps = bench_one(impact, n, method, rtol, atol, args.quick)
                rows.append(row)
                print(f"{method:<7} {n:>4g} {rtol:>7.0e} {reps:>5d} "
                      f"{row['median_us']:>11.1f} {row['nfev']:>6d} "
                      f"{row['abs_error']:>10.2e}", file=out, flush=True)

    if args.json:
        json.dump(rows, sys.stdout, indent=2)
        sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
