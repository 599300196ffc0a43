#!/usr/bin/env python3
"""OpenSees peer: two SDOF oscillators pounding under the 1940 El Centro N-S record.

What it does
------------
Reads the scenario files in bench/opensees/scenarios/*.toml (the same TOML the
Rust tool reads, so there is one source of truth), builds each one in
OpenSeesPy and integrates it over the whole record at several constant time
steps, to show how the OpenSees answer converges:

    ndm = 1, ndf = 1; ground nodes fixed; one lumped mass per building;
    storey spring (Elastic) and storey dashpot (Viscous, alpha = 1) as
    zeroLength elements from ground to mass; the contact as one zeroLength
    element from the left mass (node i) to the right mass (node j);
    UniformExcitation with a Path timeSeries (linear interpolation, ground at
    rest at t = 0); Newmark average acceleration (gamma 1/2, beta 1/4), full
    Newton, NormDispIncr 1e-12 m, constant dt; no Rayleigh damping anywhere.

Displacements u are relative to the ground, positive to the right. The
zeroLength "strain" is u_j - u_i = u_R - u_L, so the contact closes when the
strain drops below -gap; every OpenSees contact material used here is a
compression-only gap material that takes that negative gap and returns a
negative (compressive) stress. The contact force reported is F = -stress
(F > 0 pushes the buildings apart; F < 0 would be tension).

Reported per model and time step (to results.json and as a table):
    peak |u| of left and right and the time of each (over the step sequence),
    impacts counted two ways on the step sequence (open -> closed transitions
    of u_L - u_R > gap, and of "contact force nonzero"), peak and minimum
    contact force, the run time, and a per-impact list (first step inside the
    gap, relative approach velocity there and at the linearly interpolated
    instant of touch, first step outside again and the relative velocity there,
    steps inside, peak force), and the same peaks read only on the scenario's
    output grid (output_dt).
Timing: build + analysis with no recorders at dt = 1e-4, median of N runs.
No-contact check (--no-contact): the same model with gap = 10 m, against an
exact solution of the linear SDOF under the piecewise-linear record
(matrix-exponential propagator), i.e. the 5 %-damped spectral displacements
at T = 0.5 s and 1.0 s.

How to run (see README.md)
--------------------------
    python3 -m venv /tmp/opensees-venv
    /tmp/opensees-venv/bin/pip install openseespy numpy
    nice -n 10 /tmp/opensees-venv/bin/python bench/opensees/two_sdof.py --no-contact
    /tmp/opensees-venv/bin/python bench/opensees/two_sdof.py --quick      # smoke run

This is a peer measurement only: OpenSeesPy and NumPy are never dependencies
of the Rust tool. Needs Python >= 3.11 (tomllib).
"""

from __future__ import annotations

import argparse
import csv
import ctypes
import datetime
import importlib.util
import json
import math
import os
import platform
import re
import statistics
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
SCENARIOS = HERE / "scenarios"
MODELS = ["hooke", "kelvin-voigt", "jankowski", "hertzdamp"]
DEFAULT_DTS = [1e-4, 5e-5, 2e-5, 1e-5]
G = 9.80665  # m/s^2 per g

# Built-in records of the Rust tool (pounding::ground_motion::Record) that this
# script can read: name -> CSV with columns `time,acc (g)` and a leading t = 0 row.
BUILTIN_RECORDS = {"el-centro-1940": REPO / "crates" / "pounding" / "data" / "elcentro1940_ns.csv"}
UNIT_FACTORS = {"g": G, "m/s2": 1.0, "cm/s2": 0.01}


# --------------------------------------------------------------------------
# OpenSeesPy import
# --------------------------------------------------------------------------
def import_opensees():
    """Import openseespy.opensees; if the wheel's shared library cannot find
    libblas.so.3 & co. (no system BLAS installed), preload the copies the
    openseespylinux wheel bundles in its lib/ folder and try again. Same effect
    as LD_LIBRARY_PATH=<site-packages>/openseespylinux/lib."""
    try:
        import openseespy.opensees as ops  # noqa: PLC0415
        return ops
    except (ImportError, RuntimeError):
        spec = importlib.util.find_spec("openseespylinux")
        if spec is None or spec.origin is None:
            raise
        libdir = Path(spec.origin).parent / "lib"
        # dependency order: quadmath <- gfortran <- blas <- lapack
        for name in ("libquadmath.so.0", "libgfortran.so.4", "libgomp.so.1",
                     "libblas.so.3", "liblapack.so.3"):
            if (libdir / name).exists():
                ctypes.CDLL(str(libdir / name), mode=ctypes.RTLD_GLOBAL)
        import openseespy.opensees as ops  # noqa: PLC0415
        return ops


ops = import_opensees()


# --------------------------------------------------------------------------
# Scenario (TOML) and record
# --------------------------------------------------------------------------
def load_scenario(path: Path) -> dict:
    with open(path, "rb") as f:
        scn = tomllib.load(f)
    buildings = {b["name"]: b for b in scn["building"]}
    if len(scn["building"]) != 2 or len(scn.get("contact", [])) != 1:
        raise SystemExit(f"{path}: this peer handles exactly two buildings and one contact")
    for b in scn["building"]:
        if len(b["masses"]) != 1 or len(b["stiffnesses"]) != 1:
            raise SystemExit(f"{path}: building {b['name']!r} is not single-storey")
    contact = scn["contact"][0]
    left, right = contact["between"]
    return {"path": path, "raw": scn, "left": buildings[left], "right": buildings[right],
            "contact": contact}


def load_record(gm: dict) -> tuple[float, list[float], float, float]:
    """Return (dt, values in the record's units starting with the t = 0 value,
    factor to m/s^2 (units x scale), duration)."""
    if "record" in gm:
        path = BUILTIN_RECORDS[gm["record"]]
    else:
        path = Path(gm["file"])
        if not path.is_absolute():
            path = REPO / path
        if gm.get("format", "time-acc") != "time-acc":
            raise SystemExit("only built-in records and time-acc CSV files are supported here")
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r]
    if not rows[0][0].replace(".", "").replace("-", "").isdigit():
        rows = rows[1:]  # header
    t = np.array([float(r[0]) for r in rows])
    a = np.array([float(r[1]) for r in rows])
    dts = np.diff(t)
    dt = float(np.round(dts.mean(), 12))
    if not np.allclose(dts, dt, rtol=0, atol=1e-9) or t[0] != 0.0:
        raise SystemExit(f"{path}: expected uniform samples starting at t = 0")
    factor = UNIT_FACTORS[gm.get("units", "g")] * float(gm.get("scale", 1.0))
    return dt, [float(x) for x in a], factor, float(t[-1])


# --------------------------------------------------------------------------
# Mapping of our contact parameters to OpenSees materials
# --------------------------------------------------------------------------
def contact_material(contact: dict, m_eff: float, gap_override: float | None = None):
    """Return (OpenSees material name, argument list after the tag, notes dict).

    Every OpenSees material here works in the zeroLength element's strain
    u_R - u_L and closes when strain < gap_os with gap_os = -gap < 0.
    """
    model = contact["model"]
    gap = float(contact["gap"] if gap_override is None else gap_override)
    k = float(contact["stiffness"])
    gap_os = -gap
    e = contact.get("e")
    if model == "hooke":
        # F = k d, elastic: ElasticPPGap E Fy gap eta with a compressive yield
        # force far beyond anything reachable (-1e20 N), eta = 0, no "damage".
        fy = -1.0e20
        return "ElasticPPGap", [k, fy, gap_os, 0.0], {"E": k, "Fy": fy, "gap": gap_os, "eta": 0.0}
    if model == "kelvin-voigt":
        if contact.get("tension", "allow") != "allow":
            raise SystemExit("kelvin-voigt: OpenSees ViscoelasticGap has no clamped variant")
        # Anagnostopoulos: c = 2 zeta sqrt(k m_eff), zeta = -ln e / sqrt(pi^2 + ln^2 e)
        # (docs/contact-models.md, section 2, row kelvin-voigt).
        ln_e = math.log(e)
        zeta = -ln_e / math.sqrt(math.pi ** 2 + ln_e ** 2)
        c = 2.0 * zeta * math.sqrt(k * m_eff)
        return "ViscoelasticGap", [k, c, gap_os], {"K": k, "C": c, "gap": gap_os, "zeta": zeta}
    if model == "jankowski":
        n = float(contact.get("exponent", 1.5))
        # Jankowski (2006): xi = (9 sqrt 5 / 2) (1 - e^2) / (e (e (9 pi - 16) + 16))
        # (docs/contact-models.md, row jankowski; also the formula the OpenSees manual recommends).
        xi = 9.0 * math.sqrt(5.0) / 2.0 * (1.0 - e ** 2) / (e * (e * (9.0 * math.pi - 16.0) + 16.0))
        return "JankowskiImpact", [k, xi, m_eff, gap_os, n], {
            "Kh": k, "xi": xi, "mEff": m_eff, "gap": gap_os, "n": n}
    if model == "hertzdamp":
        n = float(contact.get("exponent", 1.5))
        # Ye, Li & Zhu (2009) normalised damping chi = 8 (1 - e) / (5 e)
        # (docs/contact-models.md, row hertzdamp; the manual's recommended xiNorm).
        chi = 8.0 * (1.0 - e) / (5.0 * e)
        return "Hertzdamp", [k, chi, gap_os, n], {"Kh": k, "xiNorm": chi, "gap": gap_os, "n": n}
    raise SystemExit(f"contact model {model!r} has no OpenSees counterpart in this script")


# --------------------------------------------------------------------------
# Model and analysis
# --------------------------------------------------------------------------
# Node and element tags
GROUND_L, MASS_L, GROUND_R, MASS_R = 1, 2, 3, 4
ELE_L, ELE_R, ELE_CONTACT = 1, 2, 3
TOL, MAX_ITER = 1.0e-12, 50  # NormDispIncr: |du| <= 1e-12 m


def build(scn: dict, gap_override: float | None = None) -> dict:
    """Build the OpenSees model of a scenario (domain is wiped first)."""
    L, R, contact = scn["left"], scn["right"], scn["contact"]
    gm_dt, gm_values, gm_factor, gm_duration = load_record(scn["raw"]["ground_motion"])
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for tag in (GROUND_L, MASS_L, GROUND_R, MASS_R):
        ops.node(tag, 0.0)
    ops.fix(GROUND_L, 1)
    ops.fix(GROUND_R, 1)
    info = {}
    for side, b, ground, mass_node, ele, mat_k, mat_c in (
            ("left", L, GROUND_L, MASS_L, ELE_L, 11, 12),
            ("right", R, GROUND_R, MASS_R, ELE_R, 21, 22)):
        m, k, zeta = float(b["masses"][0]), float(b["stiffnesses"][0]), float(b["damping_ratio"])
        c = 2.0 * zeta * math.sqrt(k * m)  # viscous storey damping, c = 2 zeta sqrt(k m)
        ops.mass(mass_node, m)
        ops.uniaxialMaterial("Elastic", mat_k, k)
        ops.uniaxialMaterial("Viscous", mat_c, c, 1.0)  # F = c v (alpha = 1)
        ops.element("zeroLength", ele, ground, mass_node, "-mat", mat_k, mat_c, "-dir", 1, 1)
        info[side] = {"m": m, "k": k, "c": c, "T": 2.0 * math.pi * math.sqrt(m / k)}
    m_eff = info["left"]["m"] * info["right"]["m"] / (info["left"]["m"] + info["right"]["m"])
    mat_name, mat_args, mat_notes = contact_material(contact, m_eff, gap_override)
    ops.uniaxialMaterial(mat_name, 31, *mat_args)
    # i = left, j = right: strain = u_R - u_L (negative when closing)
    ops.element("zeroLength", ELE_CONTACT, MASS_L, MASS_R, "-mat", 31, "-dir", 1)
    # Ground motion: Path series through the samples (leading 0 at t = 0 included),
    # linear interpolation, times 9.80665 for a record in g.
    ops.timeSeries("Path", 1, "-dt", gm_dt, "-values", *gm_values, "-factor", gm_factor)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", TOL, MAX_ITER)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    gap = float(contact["gap"] if gap_override is None else gap_override)
    return {"buildings": info, "m_eff": m_eff, "gap": gap, "duration": gm_duration,
            "material": {"type": mat_name, "args": mat_args, **mat_notes}}


# Algorithms tried, in order, on a step where full Newton fails.
FALLBACKS = [("KrylovNewton",), ("NewtonLineSearch",), ("ModifiedNewton", "-initial")]


def analyze(nsteps: int, dt: float) -> int:
    """ops.analyze(nsteps, dt) with full Newton. A step on which Newton fails is
    redone, same dt, with the FALLBACKS in turn (up to 200 iterations, same
    tolerance), then full Newton resumes. Newton can fail because the contact
    materials' tangents are approximate: JankowskiImpact's grows without bound
    as the penetration tends to 0 (its damping force goes as d^((n-1)/2) v),
    Hertzdamp's and JankowskiImpact's have the wrong sign, and no gap material
    returns a damping tangent. Returns the number of steps redone."""
    fallback = 0
    while True:
        status = ops.analyze(nsteps - int(round(ops.getTime() / dt)), dt)
        if status == 0:
            break
        ops.test("NormDispIncr", TOL, 200)
        for alg in FALLBACKS:
            ops.algorithm(*alg)
            status = ops.analyze(1, dt)
            if status == 0:
                break
        ops.test("NormDispIncr", TOL, MAX_ITER)
        ops.algorithm("Newton")
        if status != 0:
            raise RuntimeError(f"analysis failed (status {status}) at t = {ops.getTime()}")
        fallback += 1
    if int(round(ops.getTime() / dt)) != nsteps:
        raise RuntimeError("step count mismatch")
    return fallback


def read_binary_recorder(path: Path, ncols: int) -> np.ndarray:
    """OpenSees '-binary' recorders write each row as raw native doubles
    followed by one newline byte."""
    raw = np.fromfile(path, dtype=np.dtype([("v", "<f8", (ncols,)), ("nl", "u1")]))
    return raw["v"]


def run(scn: dict, dt: float, record: bool, gap_override: float | None = None) -> dict:
    """Build + analyse once; with record=True return the step histories too."""
    with tempfile.TemporaryDirectory(prefix="opensees-two-sdof-") as tmp:
        tmp = Path(tmp)
        t0 = time.perf_counter()
        model = build(scn, gap_override)
        nsteps = int(round(model["duration"] / dt))
        if record:
            ops.recorder("Node", "-binary", str(tmp / "disp.bin"), "-time",
                         "-node", MASS_L, MASS_R, "-dof", 1, "disp")
            ops.recorder("Node", "-binary", str(tmp / "vel.bin"),
                         "-node", MASS_L, MASS_R, "-dof", 1, "vel")
            ops.recorder("Element", "-binary", str(tmp / "stress.bin"),
                         "-ele", ELE_CONTACT, "material", "1", "stress")
        fallback_steps = analyze(nsteps, dt)
        ops.wipe()  # also closes and flushes the recorders
        wall = time.perf_counter() - t0
        out = {"dt": dt, "steps": nsteps, "wall_s": wall, "model": model,
               "output_dt": float(scn["raw"].get("analysis", {}).get("output_dt", 0.005)),
               "fallback_steps": fallback_steps}
        if record:
            disp = read_binary_recorder(tmp / "disp.bin", 3)
            vel = read_binary_recorder(tmp / "vel.bin", 2)
            stress = read_binary_recorder(tmp / "stress.bin", 1)[:, 0]
            if not (len(disp) == len(vel) == len(stress) == nsteps):
                raise RuntimeError("recorder lengths do not match the step count")
            out["hist"] = {"t": disp[:, 0], "uL": disp[:, 1], "uR": disp[:, 2],
                           "vL": vel[:, 0], "vR": vel[:, 1], "F": 0.0 - stress}
    return out


# --------------------------------------------------------------------------
# Post-processing
# --------------------------------------------------------------------------
def rising_edges(flag: np.ndarray) -> np.ndarray:
    """Indices k where flag goes False -> True (the state before step 1, t = 0,
    is at rest: open, zero force)."""
    prev = np.concatenate(([False], flag[:-1]))
    return np.nonzero(flag & ~prev)[0]


# One row per impact (v = u_L' - u_R', > 0 approaching; "inside" = u_L - u_R > gap).
IMPACT_COLUMNS = ["t_first_inside", "v_first_inside", "t_touch_interp", "v_touch_interp",
                  "t_first_outside", "v_first_outside", "steps_inside", "peak_force"]


def summarise(res: dict) -> dict:
    h, gap = res["hist"], res["model"]["gap"]
    t = np.round(h["t"], 9)  # the domain clock accumulates dt: 2.6903000000012 -> 2.6903
    uL, uR, F = h["uL"], h["uR"], h["F"]
    iL, iR = int(np.argmax(np.abs(uL))), int(np.argmax(np.abs(uR)))
    delta = uL - uR                      # closes when delta > gap
    vrel = h["vL"] - h["vR"]             # d' (> 0 approaching)
    closed = delta > gap
    on = rising_edges(closed)
    off = np.nonzero(~closed & np.concatenate(([False], closed[:-1])))[0]  # first open step after contact
    impacts = []
    for k in on:
        # instant of touch by linear interpolation of delta between steps k-1 and k
        d0, v0 = (delta[k - 1], vrel[k - 1]) if k > 0 else (0.0, 0.0)
        s = (gap - d0) / (delta[k] - d0)
        later = off[off > k]
        j = int(later[0]) if len(later) else None
        k = int(k)
        impacts.append([
            float(t[k]), float(vrel[k]),
            float(round(t[k] - (1.0 - s) * res["dt"], 9)), float(v0 + s * (vrel[k] - v0)),
            float(t[j]) if j is not None else None, float(vrel[j]) if j is not None else None,
            int(j - k) if j is not None else None,
            float(F[k:j].max()) if j is not None else float(F[k:].max()),
        ])
    # The same peaks read only on the scenario's output grid (t = j * output_dt),
    # as a tool that reports peaks from its written history would see them.
    stride = int(round(res["output_dt"] / res["dt"]))
    grid = np.arange(stride - 1, len(t), stride)  # hist index k is t = (k + 1) dt
    jL, jR = grid[np.argmax(np.abs(uL[grid]))], grid[np.argmax(np.abs(uR[grid]))]
    return {
        "dt": res["dt"], "steps": res["steps"], "wall_s": res["wall_s"],
        "fallback_steps": res["fallback_steps"],
        "peak_uL": float(abs(uL[iL])), "t_peak_uL": float(t[iL]), "uL_at_peak": float(uL[iL]),
        "peak_uR": float(abs(uR[iR])), "t_peak_uR": float(t[iR]), "uR_at_peak": float(uR[iR]),
        "output_dt": res["output_dt"],
        "peak_uL_output_grid": float(abs(uL[jL])), "t_peak_uL_output_grid": float(t[jL]),
        "peak_uR_output_grid": float(abs(uR[jR])), "t_peak_uR_output_grid": float(t[jR]),
        "impacts_gap": int(len(on)),
        "impacts_force": int(len(rising_edges(F != 0.0))),
        "peak_force": float(F.max()),
        "min_force": float(F.min()),
        "steps_in_contact": int(closed.sum()),
        "impact_columns": IMPACT_COLUMNS,
        "impact_list": impacts,
    }


# --------------------------------------------------------------------------
# Exact linear SDOF (no-contact check)
# --------------------------------------------------------------------------
def expm(a: np.ndarray) -> np.ndarray:
    """Matrix exponential by scaling and squaring of a Taylor series (small matrices)."""
    norm = np.linalg.norm(a, 1)
    s = max(0, int(math.ceil(math.log2(norm))) + 1) if norm > 0 else 0
    b = a / 2 ** s
    term, out = np.eye(len(a)), np.eye(len(a))
    for i in range(1, 30):
        term = term @ b / i
        out = out + term
    for _ in range(s):
        out = out @ out
    return out


def exact_sdof_peak(m: float, k: float, zeta: float, gm_dt: float, ag: list[float], h: float):
    """Peak |u| (and its time) of m u'' + c u' + k u = -m a_g(t), a_g piecewise
    linear through the samples, at rest at t = 0; exact propagation with
    state [u, u', a_g, a_g'] on a grid of step h (h divides the record step)."""
    w = math.sqrt(k / m)
    a = np.array([[0.0, 1.0, 0.0, 0.0],
                  [-w * w, -2.0 * zeta * w, -1.0, 0.0],
                  [0.0, 0.0, 0.0, 1.0],
                  [0.0, 0.0, 0.0, 0.0]])
    nsub = int(round(gm_dt / h))
    phi = expm(a * h)
    powers = np.empty((nsub, 4, 4))
    p = np.eye(4)
    for i in range(nsub):
        p = phi @ p
        powers[i] = p
    u_rows = powers[:, 0, :]  # u after 1..nsub substeps as a linear map of the interval's start state
    z = np.zeros(4)
    best, t_best = 0.0, 0.0
    for j in range(len(ag) - 1):
        z[2], z[3] = ag[j], (ag[j + 1] - ag[j]) / gm_dt
        u = u_rows @ z
        i = int(np.argmax(np.abs(u)))
        if abs(u[i]) > best:
            best, t_best = abs(u[i]), j * gm_dt + (i + 1) * h
        z = powers[-1] @ z
    return best, t_best


# --------------------------------------------------------------------------
# Main
# --------------------------------------------------------------------------
def fmt(x: float) -> str:
    return f"{x:.6g}"


def print_table(rows: list[dict], title: str) -> None:
    print(f"\n{title}")
    head = (f"{'model':<13}{'dt':>8}{'peak|uL| m':>12}{'t s':>9}{'peak|uR| m':>12}{'t s':>9}"
            f"{'imp(gap)':>9}{'imp(F)':>7}{'Fmax N':>13}{'Fmin N':>13}{'wall s':>8}")
    print(head)
    print("-" * len(head))
    for r in rows:
        print(f"{r['model']:<13}{r['dt']:>8.0e}{fmt(r['peak_uL']):>12}{r['t_peak_uL']:>9.4f}"
              f"{fmt(r['peak_uR']):>12}{r['t_peak_uR']:>9.4f}{r['impacts_gap']:>9}"
              f"{r['impacts_force']:>7}{fmt(r['peak_force']):>13}{fmt(r['min_force']):>13}"
              f"{r['wall_s']:>8.2f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--models", default=",".join(MODELS),
                    help="comma-separated scenario names (files scenarios/NAME.toml)")
    ap.add_argument("--dts", default=",".join(f"{d:g}" for d in DEFAULT_DTS),
                    help="comma-separated time steps, s")
    ap.add_argument("--timing-repeats", type=int, default=3,
                    help="build+analysis runs without recorders at dt = 1e-4 per model (median)")
    ap.add_argument("--max-run-seconds", type=float, default=180.0,
                    help="skip a smaller dt when the run predicted from the last one would exceed this")
    ap.add_argument("--no-contact", action="store_true",
                    help="also run gap = 10 m and compare with the exact linear SDOF peaks")
    ap.add_argument("--quick", action="store_true", help="smoke run: dt = 1e-3 and 1e-4, one timing run")
    ap.add_argument("--out", default=str(HERE / "results.json"), help="JSON output path")
    args = ap.parse_args()

    models = [m.strip() for m in args.models.split(",") if m.strip()]
    dts = [float(x) for x in args.dts.split(",")]
    repeats = args.timing_repeats
    if args.quick:
        dts, repeats = [1e-3, 1e-4], 1

    ops.logFile(os.devnull, "-noEcho")  # silence the per-impact messages of the contact materials

    results = {
        "about": "OpenSeesPy peer of the two-SDOF pounding problem; see bench/opensees/README.md",
        "generated": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "command": " ".join([Path(sys.argv[0]).name] + sys.argv[1:]),
        "environment": {
            "openseespy": _version("openseespy"), "opensees": ops.version() if hasattr(ops, "version") else None,
            "numpy": np.__version__, "python": platform.python_version(),
            "platform": platform.platform(), "cpu": _cpu_model(), "cpus": os.cpu_count(),
        },
        "analysis": {"integrator": "Newmark gamma=0.5 beta=0.25", "algorithm": "Newton",
                     "test": "NormDispIncr 1e-12 m, max 50 iterations",
                     "fallback": "a step where Newton fails is redone (same dt) with KrylovNewton, "
                                 "NewtonLineSearch or ModifiedNewton -initial, 200 iterations",
                     "system": "FullGeneral",
                     "peaks": "max |u| over the step sequence (every step recorded)"},
        "models": {}, "timing_dt_1e-4": {}, "notes": [],
    }
    rows = []
    for name in models:
        scn = load_scenario(SCENARIOS / f"{name}.toml")
        entry = {"scenario": str((SCENARIOS / f"{name}.toml").relative_to(REPO)), "runs": []}
        last = None
        for dt in dts:
            if last is not None:
                predicted = last["wall_s"] * last["dt"] / dt
                if predicted > args.max_run_seconds:
                    note = f"{name}: dt = {dt:g} skipped (predicted {predicted:.0f} s > {args.max_run_seconds:g} s)"
                    results["notes"].append(note)
                    print(note, file=sys.stderr)
                    continue
            res = run(scn, dt, record=True)
            entry.setdefault("opensees", res["model"])
            summ = summarise(res)
            entry["runs"].append(summ)
            rows.append({"model": name, **summ})
            print(f"  {name:<13} dt={dt:g}: |uL|max={fmt(summ['peak_uL'])} |uR|max={fmt(summ['peak_uR'])} "
                  f"impacts={summ['impacts_gap']}/{summ['impacts_force']} Fmax={fmt(summ['peak_force'])} "
                  f"({summ['wall_s']:.1f} s)", file=sys.stderr, flush=True)
            last = summ
        results["models"][name] = entry
        if repeats > 0:
            times = [run(scn, 1e-4, record=False)["wall_s"] for _ in range(repeats)]
            results["timing_dt_1e-4"][name] = {
                "median_s": statistics.median(times), "runs_s": times,
                "what": "ops.wipe + model build + ops.analyze(311800, 1e-4), no recorders"}

    print_table(rows, "OpenSees results (peaks over the step sequence; F > 0 compression)")
    if results["timing_dt_1e-4"]:
        print("\nWall-clock, build + analysis at dt = 1e-4 (311800 steps), no recorders:")
        for name, tm in results["timing_dt_1e-4"].items():
            print(f"  {name:<13} median {tm['median_s']:.3f} s of {['%.3f' % x for x in tm['runs_s']]}")

    if args.no_contact:
        scn = load_scenario(SCENARIOS / f"{models[0]}.toml")
        gm_dt, values, factor, _ = load_record(scn["raw"]["ground_motion"])
        ag = [factor * v for v in values]
        nc = {"gap_m": 10.0, "scenario": models[0], "runs": [], "exact": {}}
        for side in ("left", "right"):
            b = scn[side]
            peak, tpk = exact_sdof_peak(float(b["masses"][0]), float(b["stiffnesses"][0]),
                                        float(b["damping_ratio"]), gm_dt, ag, 1e-5)
            nc["exact"][side] = {"peak_u": peak, "t_peak": tpk,
                                 "method": "exact propagator for piecewise-linear a_g, grid 1e-5 s"}
        for dt in dts:
            s = summarise(run(scn, dt, record=True, gap_override=10.0))
            s.pop("impact_list")
            s.pop("impact_columns")
            nc["runs"].append(s)
        results["no_contact"] = nc
        print("\nNo contact (gap = 10 m): peak |u| = spectral displacement, 5 % damping")
        print(f"  exact: left (T=0.5 s) {fmt(nc['exact']['left']['peak_u'])} m at {nc['exact']['left']['t_peak']:.4f} s, "
              f"right (T=1.0 s) {fmt(nc['exact']['right']['peak_u'])} m at {nc['exact']['right']['t_peak']:.4f} s")
        for s in nc["runs"]:
            print(f"  dt={s['dt']:<7g} left {fmt(s['peak_uL'])} m at {s['t_peak_uL']:.4f} s, "
                  f"right {fmt(s['peak_uR'])} m at {s['t_peak_uR']:.4f} s, impacts {s['impacts_gap']}")

    Path(args.out).write_text(to_json(results))
    print(f"\nwrote {args.out}")


def to_json(obj) -> str:
    """Indented JSON with every list of scalars kept on one line."""
    text = json.dumps(obj, indent=1)
    return re.sub(r"\[\s+([^\[\]{}]*?)\s+\]",
                  lambda m: "[" + " ".join(m.group(1).split()) + "]", text) + "\n"


def _version(dist: str) -> str | None:
    try:
        from importlib.metadata import version  # noqa: PLC0415
        return version(dist)
    except Exception:  # noqa: BLE001
        return None


def _cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


if __name__ == "__main__":
    main()
