#!/usr/bin/env python3
"""OpenSees peer: pounding of shear buildings with inelastic storeys under El Centro.

What it does
------------
Reads the scenario files in bench/opensees/scenarios-inelastic/*.toml (the Rust
tool's own format, with the storey keys `storey_model`, `yield_forces`,
`post_yield_ratio`, `bouc_wen`), builds each one in OpenSeesPy and integrates it
at several constant time steps, with and without the contacts:

    ndm = 1, ndf = 1; one fixed ground node per building; one node and one
    lumped mass per floor; storey j = one zeroLength element from floor j-1
    (node i) to floor j (node j) carrying the storey law:
        linear   -> uniaxialMaterial Elastic  k
        bilinear -> uniaxialMaterial Steel01  Fy k a            (a1..a4 defaults)
        bouc-wen -> uniaxialMaterial BoucWen  a k n gamma/dy^n beta/dy^n 1 0 0 0 tol maxIter
    Rayleigh damping C = a0 M + a1 K_init per building (modes 1 and 2 of its
    initial stiffness): `region -ele <its storey elements> -rayleigh a0 0 a1 0`
    (nodes of the region get a0 M, the elements a1 K_init) and `-doRayleigh 1`
    on the storey elements; the contact elements belong to no region.
    Contact = one zeroLength from the left building's floor (node i) to the
    right building's floor (node j) per contact floor pair, with the material
    of two_sdof.py (e.g. Hertzdamp Kh xiNorm -gap n).
    UniformExcitation + Path timeSeries (linear between samples, ground at rest
    at t = 0, zero after the record); Newmark average acceleration, Newton,
    NormDispIncr 1e-12 m, constant dt (two_sdof.py's analysis and fallbacks).

Every run goes to the long duration (45 s by default: the record, 31.18 s, then
free vibration) and is split at the record's end, so one run gives both the
"record" window [0, 31.18 s] and the "long" window [0, 45 s]. Reported per
window: per floor peak |u| (over every step) and its time, u at the end
(residual), and over the last `--tail` seconds the mid-range (max + min) / 2 and
half-range (max - min) / 2 (how much free vibration is left); per storey peak
|drift|, residual drift, peak |storey force| (the material stress), force at the
end, ductility peak |drift| / d_y; per contact impacts counted on the step
sequence (by penetration and by force != 0), peak force. Envelopes come from
OpenSees EnvelopeNode / EnvelopeElement recorders (17 digits); at dt = 1e-4 the
script also records every step and checks the envelopes against them.

Checks (--checks, on by default): Steel01 and BoucWen driven along a drift
path (testUniaxialMaterial) against our bilinear and Bouc-Wen laws; the linear
model without contact against the exact solution (matrix-exponential
propagator of the linear MDOF with the same Rayleigh C under the
piecewise-linear record), which verifies the per-building Rayleigh damping;
and the elastic limit: each inelastic scenario with yield
forces 1e20 N against its linear twin (same dt), with and without contact.
Timing: build + analysis without recorders at dt = 1e-4 (median of N).

    nice -n 10 /tmp/opensees-venv/bin/python bench/opensees/inelastic.py --max-run-seconds 900
    /tmp/opensees-venv/bin/python bench/opensees/inelastic.py --table bench/opensees/results-inelastic.json
    /tmp/opensees-venv/bin/python bench/opensees/inelastic.py --quick --out /tmp/q.json

Peer measurement only: OpenSeesPy and NumPy are never dependencies of the Rust
tool. Needs Python >= 3.11 (tomllib). See README.md, "Inelastic storeys".
"""

from __future__ import annotations

import argparse
import copy
import datetime
import math
import os
import platform
import statistics
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import two_sdof as base  # noqa: E402  (record loading, contact materials, analysis loop, BLAS workaround)

ops = base.ops
REPO = base.REPO
SCENARIO_DIR = HERE / "scenarios-inelastic"
SCENARIOS = ["bilinear-sdof", "bouc-wen-sdof", "bilinear-mdof"]
DEFAULT_DTS = [1e-4, 1e-5, 5e-6]
LONG_DURATION = 45.0
TAIL = 2.0
HUGE_FY = 1.0e20
BW_TOL, BW_MAXITER = 1.0e-12, 50  # BoucWen's own Newton on z (OpenSees defaults: 1e-8, 20)


# --------------------------------------------------------------------------
# Scenario
# --------------------------------------------------------------------------
def per_storey(value, n: int, key: str, name: str) -> list:
    if isinstance(value, list):
        if len(value) != n:
            raise SystemExit(f"building {name!r}: {key} has {len(value)} entries for {n} storeys")
        return list(value)
    return [value] * n


def load_scenario(path: Path) -> dict:
    with open(path, "rb") as f:
        raw = tomllib.load(f)
    return expand(raw, path)


def expand(raw: dict, path: Path | None = None) -> dict:
    """Per-storey laws and contact floor pairs, as the Rust tool reads them."""
    blds = []
    for b in raw["building"]:
        n = len(b["masses"])
        if len(b["stiffnesses"]) != n or len(b["heights"]) != n:
            raise SystemExit(f"building {b['name']!r}: masses, stiffnesses, heights differ in length")
        models = per_storey(b.get("storey_model", "linear"), n, "storey_model", b["name"])
        fy = per_storey(b.get("yield_forces", None), n, "yield_forces", b["name"])
        ratio = per_storey(b.get("post_yield_ratio", 0.0), n, "post_yield_ratio", b["name"])
        bw = {"n": 1.0, "beta": 0.5, "gamma": 0.5, **b.get("bouc_wen", {})}
        storeys = []
        for j in range(n):
            law = {"model": models[j], "k": float(b["stiffnesses"][j])}
            if models[j] != "linear":
                if fy[j] is None:
                    raise SystemExit(f"building {b['name']!r}: {models[j]} storey without yield_forces")
                law.update(Fy=float(fy[j]), a=float(ratio[j]))
            if models[j] == "bouc-wen":
                law.update(n=float(bw["n"]), beta=float(bw["beta"]), gamma=float(bw["gamma"]))
            if models[j] not in ("linear", "bilinear", "bouc-wen"):
                raise SystemExit(f"storey_model {models[j]!r} unknown")
            storeys.append(law)
        blds.append({"name": b["name"], "m": [float(x) for x in b["masses"]], "storeys": storeys,
                     "heights": [float(x) for x in b["heights"]],
                     "zeta": float(b.get("damping_ratio", 0.05))})
    index = {b["name"]: i for i, b in enumerate(blds)}
    contacts = []
    for c in raw.get("contact", []):
        i, j = sorted(index[x] for x in c["between"])
        if j != i + 1:
            raise SystemExit(f"contact {c['between']}: not neighbours")
        L, R = blds[i], blds[j]
        if "floors" in c:
            pairs = [tuple(int(x) for x in p) for p in c["floors"]]
        else:  # every pair of floors at the same height (within 1 mm)
            zl, zr = np.cumsum(L["heights"]), np.cumsum(R["heights"])
            pairs = [(a + 1, b + 1) for a in range(len(zl)) for b in range(len(zr))
                     if abs(zl[a] - zr[b]) <= 1e-3]
        contacts.append({"left": i, "right": j, "pairs": pairs, "raw": c, "gap": float(c["gap"])})
    gm = base.load_record(raw["ground_motion"])
    duration = float(raw.get("analysis", {}).get("duration", gm[3]))
    return {"path": path, "raw": raw, "buildings": blds, "contacts": contacts, "gm": gm,
            "duration": duration}


def variant(scn: dict, *, linear: bool = False, fy: float | None = None) -> dict:
    """The same scenario with every storey linear, or with every yield force = fy."""
    s = copy.deepcopy(scn)
    for b in s["buildings"]:
        for law in b["storeys"]:
            if linear:
                for key in ("Fy", "a", "n", "beta", "gamma"):
                    law.pop(key, None)
                law["model"] = "linear"
            elif fy is not None and law["model"] != "linear":
                law["Fy"] = fy
    return s


# --------------------------------------------------------------------------
# Linear structural matrices, Rayleigh coefficients
# --------------------------------------------------------------------------
def matrices(b: dict) -> tuple[np.ndarray, np.ndarray]:
    n = len(b["m"])
    K = np.zeros((n, n))
    for j, law in enumerate(b["storeys"]):  # storey j joins floor j-1 (ground for j = 0) and floor j
        k = law["k"]
        K[j, j] += k
        if j > 0:
            K[j - 1, j - 1] += k
            K[j - 1, j] -= k
            K[j, j - 1] -= k
    return np.diag(b["m"]), K


def rayleigh(b: dict) -> dict:
    """a0, a1 with the building's damping ratio on modes 1 and 2 of its initial
    stiffness (one storey: w2 = w1, so a0 m + a1 k = 2 zeta sqrt(k m))."""
    M, K = matrices(b)
    minv = np.diag(1.0 / np.sqrt(np.diag(M)))
    w = np.sqrt(np.sort(np.linalg.eigvalsh(minv @ K @ minv)))
    w1, w2 = w[0], (w[1] if len(w) > 1 else w[0])
    z = b["zeta"]
    return {"a0": 2.0 * z * w1 * w2 / (w1 + w2), "a1": 2.0 * z / (w1 + w2),
            "periods": [float(2.0 * math.pi / x) for x in w]}


# --------------------------------------------------------------------------
# OpenSees model
# --------------------------------------------------------------------------
def node_tag(b: int, floor: int) -> int:
    return 1000 * (b + 1) + floor          # floor 0 = the building's ground node


def storey_tag(b: int, j: int) -> int:
    return 1000 * (b + 1) + j              # element / material of storey j (1-based)


def contact_tag(c: int, p: int) -> int:
    return 100000 + 100 * c + p


def storey_material(tag: int, law: dict) -> tuple[str, list]:
    k = law["k"]
    if law["model"] == "linear":
        return "Elastic", [k]
    if law["model"] == "bilinear":
        # Steel01 argument order: Fy, E0, b (a1..a4 omitted = 0, 55, 0, 55: no isotropic hardening)
        return "Steel01", [law["Fy"], k, law["a"]]
    if law["model"] == "bouc-wen":
        n = law["n"]
        dy = law["Fy"] / k
        # BoucWen argument order: alpha, ko, n, gamma, beta, Ao, deltaA, deltaNu, deltaEta, tol, maxIter
        return "BoucWen", [law["a"], k, n, law["gamma"] / dy ** n, law["beta"] / dy ** n,
                           1.0, 0.0, 0.0, 0.0, BW_TOL, BW_MAXITER]
    raise SystemExit(f"storey_model {law['model']!r}")


def build(scn: dict, contact: bool) -> dict:
    gm_dt, gm_values, gm_factor, _ = scn["gm"]
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    info = {"buildings": [], "contacts": []}
    for bi, b in enumerate(scn["buildings"]):
        ops.node(node_tag(bi, 0), 0.0)
        ops.fix(node_tag(bi, 0), 1)
        for f, m in enumerate(b["m"], start=1):
            ops.node(node_tag(bi, f), 0.0)
            ops.mass(node_tag(bi, f), m)
        mats, eles = [], []
        for j, law in enumerate(b["storeys"], start=1):
            tag = storey_tag(bi, j)
            name, args = storey_material(tag, law)
            ops.uniaxialMaterial(name, tag, *args)
            ops.element("zeroLength", tag, node_tag(bi, j - 1), node_tag(bi, j),
                        "-mat", tag, "-dir", 1, "-doRayleigh", 1)
            mats.append({"storey": j, "uniaxialMaterial": [name, tag, *args]})
            eles.append(tag)
        ray = rayleigh(b)
        # region -ele: the elements get betaKinit = a1, the nodes they connect get alphaM = a0
        ops.region(bi + 1, "-ele", *eles, "-rayleigh", ray["a0"], 0.0, ray["a1"], 0.0)
        info["buildings"].append({"name": b["name"], **ray, "materials": mats,
                                  "region": ["region", bi + 1, "-ele", *eles, "-rayleigh",
                                             ray["a0"], 0.0, ray["a1"], 0.0]})
    if contact:
        for ci, c in enumerate(scn["contacts"]):
            L, R = scn["buildings"][c["left"]], scn["buildings"][c["right"]]
            for p, (fl, fr) in enumerate(c["pairs"]):
                m_eff = L["m"][fl - 1] * R["m"][fr - 1] / (L["m"][fl - 1] + R["m"][fr - 1])
                name, args, notes = base.contact_material(c["raw"], m_eff)
                tag = contact_tag(ci, p)
                ops.uniaxialMaterial(name, tag, *args)
                # i = left floor, j = right floor: strain = u_R - u_L, closed when < -gap
                ops.element("zeroLength", tag, node_tag(c["left"], fl), node_tag(c["right"], fr),
                            "-mat", tag, "-dir", 1)
                info["contacts"].append({"between": [L["name"], R["name"]], "floors": [fl, fr],
                                         "gap": c["gap"], "uniaxialMaterial": [name, tag, *args]})
    ops.timeSeries("Path", 1, "-dt", gm_dt, "-values", *gm_values, "-factor", gm_factor)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")  # bit-identical to FullGeneral here, 25 % faster for the MDOF case
    ops.test("NormDispIncr", base.TOL, base.MAX_ITER)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    return info


# --------------------------------------------------------------------------
# Runs
# --------------------------------------------------------------------------
def floor_nodes(scn):
    return [node_tag(bi, f) for bi, b in enumerate(scn["buildings"]) for f in range(1, len(b["m"]) + 1)]


def storey_eles(scn):
    return [storey_tag(bi, j) for bi, b in enumerate(scn["buildings"]) for j in range(1, len(b["m"]) + 1)]


def read_envelope(path: Path) -> dict:
    """EnvelopeNode/EnvelopeElement with -time: rows min, max, absmax; per column (time, value)."""
    a = np.loadtxt(path, ndmin=2)
    return {"tmin": a[0, 0::2], "min": a[0, 1::2], "tmax": a[1, 0::2], "max": a[1, 1::2],
            "tabs": a[2, 0::2], "abs": a[2, 1::2]}


def run(scn: dict, dt: float, contact: bool, long_duration: float, tail: float,
        full: bool = False, record: bool = True) -> dict:
    """One run to long_duration, split at the scenario's duration. Segments:
    [0, T-tail], [T-tail, T], [T, L-tail], [L-tail, L] (T = duration, L = long)."""
    T = scn["duration"]
    L = max(long_duration, T)
    bounds = [T - tail, T, L - tail, L]
    steps = [int(round(x / dt)) for x in bounds]
    if any(abs(s * dt - x) > 1e-9 for s, x in zip(steps, bounds)):
        raise SystemExit(f"dt = {dt} does not divide the segment ends {bounds}")
    nodes, eles = floor_nodes(scn), storey_eles(scn)
    if not record:  # timing: one analyze call over the scenario's duration, no recorders
        t0, c0 = time.perf_counter(), time.process_time()
        info = build(scn, contact)
        fallback = base.analyze(steps[1], dt)
        ops.wipe()
        return {"dt": dt, "steps": steps[1], "wall_s": time.perf_counter() - t0,
                "cpu_s": time.process_time() - c0, "fallback_steps": fallback, "info": info}
    with tempfile.TemporaryDirectory(prefix="opensees-inelastic-") as tmp:
        tmp = Path(tmp)
        t0, c0 = time.perf_counter(), time.process_time()
        info = build(scn, contact)
        ctags = [contact_tag(ci, p) for ci, c in enumerate(scn["contacts"]) for p in range(len(c["pairs"]))] \
            if contact else []
        seg_out, ends, fallback, done = [], [], 0, 0
        for s, n_end in enumerate(steps):
            if n_end <= done:  # empty segment (long duration == duration)
                seg_out.append(None)
                ends.append(ends[-1])
                continue
            ops.recorder("EnvelopeNode", "-file", str(tmp / f"en{s}.txt"), "-precision", 17, "-time",
                         "-node", *nodes, "-dof", 1, "disp")
            ops.recorder("EnvelopeElement", "-file", str(tmp / f"ed{s}.txt"), "-precision", 17, "-time",
                         "-ele", *eles, "deformation")
            ops.recorder("EnvelopeElement", "-file", str(tmp / f"es{s}.txt"), "-precision", 17, "-time",
                         "-ele", *eles, "material", "1", "stress")
            if ctags:
                ops.recorder("Element", "-binary", str(tmp / f"cd{s}.bin"), "-ele", *ctags, "deformation")
                ops.recorder("Element", "-binary", str(tmp / f"cs{s}.bin"), "-ele", *ctags,
                             "material", "1", "stress")
            if full:
                ops.recorder("Node", "-binary", str(tmp / f"fn{s}.bin"), "-time", "-node", *nodes,
                             "-dof", 1, "disp")
                ops.recorder("Element", "-binary", str(tmp / f"fs{s}.bin"), "-ele", *eles,
                             "material", "1", "stress")
            fallback += base.analyze(n_end, dt)
            ops.remove("recorders")  # closes and flushes this segment's files
            ends.append({"t": ops.getTime(),
                         "u": [ops.nodeDisp(t, 1) for t in nodes],
                         "F": [ops.eleResponse(e, "material", "1", "stress")[0] for e in eles]})
            seg_out.append(s)
            done = n_end
        ops.wipe()
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
        out = {"dt": dt, "steps": steps, "wall_s": wall, "cpu_s": cpu, "fallback_steps": fallback,
               "info": info}
        segs = []
        for s in range(4):
            if seg_out[s] is None:
                segs.append(None)
                continue
            seg = {"n": read_envelope(tmp / f"en{s}.txt"), "d": read_envelope(tmp / f"ed{s}.txt"),
                   "s": read_envelope(tmp / f"es{s}.txt")}
            nrows = steps[s] - (steps[s - 1] if s else 0)
            if ctags:
                seg["cd"] = base.read_binary_recorder(tmp / f"cd{s}.bin", len(ctags))
                seg["cs"] = base.read_binary_recorder(tmp / f"cs{s}.bin", len(ctags))
                if not len(seg["cd"]) == len(seg["cs"]) == nrows:
                    raise RuntimeError("contact recorder length does not match the step count")
            if full:
                fn = base.read_binary_recorder(tmp / f"fn{s}.bin", len(nodes) + 1)
                fs = base.read_binary_recorder(tmp / f"fs{s}.bin", len(eles))
                if not len(fn) == len(fs) == nrows:
                    raise RuntimeError("full recorder length does not match the step count")
                seg["check"] = envelope_check(seg, fn, fs)
            segs.append(seg)
        out.update(segs=segs, ends=ends, ctags=ctags)
    return out


def envelope_check(seg: dict, fn: np.ndarray, fs: np.ndarray) -> float:
    """Largest relative difference between the envelope recorders and the
    per-step records of the same segment (peaks and their times)."""
    worst = 0.0
    t = fn[:, 0]
    for env, hist in ((seg["n"], fn[:, 1:]), (seg["s"], fs)):
        for c in range(hist.shape[1]):
            i = int(np.argmax(np.abs(hist[:, c])))
            worst = max(worst, abs(abs(hist[i, c]) - env["abs"][c]) / max(env["abs"][c], 1e-300),
                        abs(hist[:, c].max() - env["max"][c]) / max(env["abs"][c], 1e-300),
                        abs(hist[:, c].min() - env["min"][c]) / max(env["abs"][c], 1e-300))
            if abs(t[i] - env["tabs"][c]) > 1e-9:
                worst = max(worst, 1.0)
    return worst


def combine(segs: list, key: str, which: list[int], col: int) -> dict:
    """Peak |x| (and its signed value and time) over the segments `which`."""
    best = None
    for s in which:
        e = segs[s][key]
        a = e["abs"][col]
        if best is None or a > best[0]:
            val = e["max"][col] if e["max"][col] >= -e["min"][col] else e["min"][col]
            best = (a, float(round(e["tabs"][col], 9)), float(val))
    return {"peak": float(best[0]), "t": best[1], "at_peak": best[2]}


def rising_edges(flag: np.ndarray) -> np.ndarray:
    prev = np.concatenate(([False], flag[:-1]))
    return np.nonzero(flag & ~prev)[0]


def summarise(scn: dict, res: dict, contact: bool) -> dict:
    segs, ends, dt = res["segs"], res["ends"], res["dt"]
    windows = {"record": (list(range(2)), 1), "long": (list(range(4)), 3)}
    out = {"dt": dt, "wall_s": res["wall_s"], "cpu_s": res["cpu_s"], "fallback_steps": res["fallback_steps"],
           "steps": {"record": res["steps"][1], "long": res["steps"][3]}}
    checks = [s["check"] for s in segs if s is not None and "check" in s]
    if checks:
        out["envelope_vs_every_step_max_rel_diff"] = max(checks)
    for wname, (which, tail_seg) in windows.items():
        which = [s for s in which if segs[s] is not None]
        if segs[tail_seg] is None:
            continue
        end = ends[tail_seg]
        w = {"t_end": float(round(end["t"], 9)), "buildings": [], "contacts": []}
        col = 0
        for bi, b in enumerate(scn["buildings"]):
            floors, storeys = [], []
            n = len(b["m"])
            for f in range(n):
                c = col + f
                tl = segs[tail_seg]["n"]
                floors.append({**{k if k != "peak" else "peak_u": v for k, v in
                                  combine(segs, "n", which, c).items()},
                               "residual_u": float(end["u"][c]),
                               "tail_mid_u": float((tl["max"][c] + tl["min"][c]) / 2),
                               "tail_half_range_u": float((tl["max"][c] - tl["min"][c]) / 2)})
            for j in range(n):
                c = col + j
                law = b["storeys"][j]
                d = combine(segs, "d", which, c)
                F = combine(segs, "s", which, c)
                resid_drift = end["u"][c] - (end["u"][c - 1] if j > 0 else 0.0)
                row = {"model": law["model"], "peak_drift": d["peak"], "t_peak_drift": d["t"],
                       "drift_at_peak": d["at_peak"], "residual_drift": float(resid_drift),
                       "peak_force": F["peak"], "t_peak_force": F["t"], "force_at_peak": F["at_peak"],
                       "force_end": float(end["F"][c])}
                if "Fy" in law:
                    dy = law["Fy"] / law["k"]
                    row.update(yield_force=law["Fy"], peak_force_over_Fy=F["peak"] / law["Fy"],
                               ductility=d["peak"] / dy)
                storeys.append(row)
            w["buildings"].append({"name": b["name"], "floors": floors, "storeys": storeys})
            col += n
        if contact:
            cd = np.concatenate([segs[s]["cd"] for s in which])
            cs = np.concatenate([segs[s]["cs"] for s in which])
            k = 0
            for ci, c in enumerate(scn["contacts"]):
                for p, (fl, fr) in enumerate(c["pairs"]):
                    closed = cd[:, k] < -c["gap"]       # the materials' own test: strain < gap_os
                    F = 0.0 - cs[:, k]                  # 0.0 - x: no -0.0 where the contact is open
                    ipk = int(np.argmax(F)) if F.max() > 0.0 else None
                    w["contacts"].append({
                        "between": [scn["buildings"][c["left"]]["name"], scn["buildings"][c["right"]]["name"]],
                        "floors": [fl, fr], "impacts_gap": int(len(rising_edges(closed))),
                        "impacts_force": int(len(rising_edges(F != 0.0))),
                        "peak_force": float(F.max()),
                        "t_peak_force": float(round((ipk + 1) * dt, 9)) if ipk is not None else None,
                        "min_force": float(F.min()), "steps_in_contact": int(closed.sum()),
                        "closed_at_end": bool(closed[-1])})
                    k += 1
        out[wname] = w
    return out


# --------------------------------------------------------------------------
# Exact linear solution (no contact)
# --------------------------------------------------------------------------
def propagator(M, C, K, gm_dt: float, h: float) -> np.ndarray:
    """The exact propagators over h, 2h, ..., gm_dt of the state [u, u', a_g, a_g'] of
    M u'' + C u' + K u = -M 1 a_g with a_g linear in time (a_g' constant): shape
    (gm_dt / h, 2n + 2, 2n + 2), the last one over a whole sample interval."""
    n = len(M)
    Minv = np.linalg.inv(M)
    A = np.zeros((2 * n + 2, 2 * n + 2))
    A[:n, n:2 * n] = np.eye(n)
    A[n:2 * n, :n] = -Minv @ K
    A[n:2 * n, n:2 * n] = -Minv @ C
    A[n:2 * n, 2 * n] = -1.0
    A[2 * n, 2 * n + 1] = 1.0
    nsub = int(round(gm_dt / h))
    phi = base.expm(A * h)
    powers = np.empty((nsub, 2 * n + 2, 2 * n + 2))
    p = np.eye(2 * n + 2)
    for i in range(nsub):
        p = phi @ p
        powers[i] = p
    return powers


def exact_linear(b: dict, gm, t_ends: list[float], h: float = 1e-5) -> dict:
    """Linear MDOF M u'' + C u' + K u = -M 1 a_g, C = a0 M + a1 K, at rest at
    t = 0, a_g piecewise linear through the samples and 0 after the record:
    exact propagation of [u, u', a_g, a_g'] on a grid h. Returns per window end
    the peaks of |u| and |drift| (on the grid) and u at the end."""
    gm_dt, values, factor, rec_T = gm
    ag = [factor * v for v in values]
    M, K = matrices(b)
    ray = rayleigh(b)
    C = ray["a0"] * M + ray["a1"] * K
    n = len(M)
    powers = propagator(M, C, K, gm_dt, h)
    rows = powers[:, :n, :]
    D = np.eye(n) - np.eye(n, k=-1)  # drift_j = u_j - u_{j-1}
    z = np.zeros(2 * n + 2)
    peak_u, t_u = np.zeros(n), np.zeros(n)
    peak_d, t_d = np.zeros(n), np.zeros(n)
    out = {}
    nint = int(round(max(t_ends) / gm_dt))
    targets = {int(round(t / gm_dt)): t for t in t_ends}
    for j in range(nint):
        if j + 1 < len(ag):
            z[2 * n], z[2 * n + 1] = ag[j], (ag[j + 1] - ag[j]) / gm_dt
        else:
            z[2 * n], z[2 * n + 1] = 0.0, 0.0
        u = rows @ z                       # (nsub, n)
        d = u @ D.T
        for arr, pk, tk in ((u, peak_u, t_u), (d, peak_d, t_d)):
            i = np.argmax(np.abs(arr), axis=0)
            v = np.abs(arr[i, np.arange(n)])
            better = v > pk
            pk[better] = v[better]
            tk[better] = j * gm_dt + (i[better] + 1) * h
        z = powers[-1] @ z
        if j + 1 in targets:
            out[targets[j + 1]] = {"peak_u": peak_u.tolist(), "t_peak_u": np.round(t_u, 9).tolist(),
                                   "peak_drift": peak_d.tolist(), "t_peak_drift": np.round(t_d, 9).tolist(),
                                   "u_end": z[:n].tolist(),
                                   "peak_force": (peak_d * np.array([law["k"] for law in b["storeys"]])).tolist()}
    return out


def rel(a: float, b: float, scale: float) -> float:
    return abs(a - b) / scale


def compare_runs(sa: dict, sb: dict) -> dict:
    """Largest differences between two summaries of the same problem: peaks
    relative to the peak, residuals relative to the building's peak |u|."""
    worst = {"peak_u": 0.0, "t_peak_u": 0.0, "residual_u": 0.0, "peak_drift": 0.0,
             "peak_force": 0.0, "impacts_equal": True, "contact_peak_force": 0.0}
    for wname in ("record", "long"):
        if wname not in sa:
            continue
        for ba, bb in zip(sa[wname]["buildings"], sb[wname]["buildings"]):
            scale = max(f["peak_u"] for f in ba["floors"])
            for fa, fb in zip(ba["floors"], bb["floors"]):
                worst["peak_u"] = max(worst["peak_u"], rel(fa["peak_u"], fb["peak_u"], fa["peak_u"]))
                worst["t_peak_u"] = max(worst["t_peak_u"], abs(fa["t"] - fb["t"]))
                worst["residual_u"] = max(worst["residual_u"], rel(fa["residual_u"], fb["residual_u"], scale))
            for xa, xb in zip(ba["storeys"], bb["storeys"]):
                worst["peak_drift"] = max(worst["peak_drift"], rel(xa["peak_drift"], xb["peak_drift"], xa["peak_drift"]))
                worst["peak_force"] = max(worst["peak_force"], rel(xa["peak_force"], xb["peak_force"], xa["peak_force"]))
        for ca, cb in zip(sa[wname]["contacts"], sb[wname]["contacts"]):
            worst["impacts_equal"] &= (ca["impacts_gap"] == cb["impacts_gap"]
                                       and ca["impacts_force"] == cb["impacts_force"])
            if ca["peak_force"] > 0:
                worst["contact_peak_force"] = max(worst["contact_peak_force"],
                                                  rel(ca["peak_force"], cb["peak_force"], ca["peak_force"]))
    return worst


# --------------------------------------------------------------------------
# Material checks: the OpenSees materials against our storey laws under a
# prescribed drift path (ops.testUniaxialMaterial; every setStrain commits)
# --------------------------------------------------------------------------
def drift_path(dy: float, per_dy: int) -> np.ndarray:
    """0 -> 3 dy -> -2 dy -> 4 dy -> -4 dy -> 1 dy in increments dy / per_dy."""
    turns = [0.0, 3.0, -2.0, 4.0, -4.0, 1.0]
    pts = [np.array([0.0])]
    for a, b in zip(turns[:-1], turns[1:]):
        n = int(round(abs(b - a) * per_dy))
        pts.append(np.linspace(a, b, n + 1)[1:])
    return np.concatenate(pts) * dy


def bilinear_reference(d: np.ndarray, k: float, fy: float, a: float) -> np.ndarray:
    """Kinematic hardening (structures-and-studies.md): elastic trial, clamped to
    a k d +- (1 - a) Fy."""
    F = np.zeros_like(d)
    for i in range(1, len(d)):
        trial = F[i - 1] + k * (d[i] - d[i - 1])
        F[i] = min(max(trial, a * k * d[i] - (1 - a) * fy), a * k * d[i] + (1 - a) * fy)
    return F


def bouc_wen_reference(d: np.ndarray, k: float, fy: float, a: float, n: float, beta: float,
                       gamma: float, sub: int = 20) -> np.ndarray:
    """Our law, F = a k d + (1 - a) Fy z, dz/dd = (1 - beta sgn(d') |z|^(n-1) z - gamma |z|^n) / d_y
    (A = 1), by RK4 in d with `sub` substeps per increment of the path."""
    dy = fy / k
    F = np.zeros_like(d)
    z = 0.0
    for i in range(1, len(d)):
        h = (d[i] - d[i - 1]) / sub
        sg = 1.0 if h > 0 else -1.0

        def f(zz):
            return (1.0 - beta * sg * abs(zz) ** (n - 1) * zz - gamma * abs(zz) ** n) / dy if zz != 0.0 \
                else 1.0 / dy
        for _ in range(sub):
            k1 = f(z)
            k2 = f(z + 0.5 * h * k1)
            k3 = f(z + 0.5 * h * k2)
            k4 = f(z + h * k3)
            z += h * (k1 + 2 * k2 + 2 * k3 + k4) / 6.0
        F[i] = a * k * d[i] + (1 - a) * fy * z
    return F


def opensees_path(name: str, args: list, d: np.ndarray) -> np.ndarray:
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.uniaxialMaterial(name, 1, *args)
    ops.testUniaxialMaterial(1)
    out = np.zeros_like(d)
    for i in range(1, len(d)):
        ops.setStrain(float(d[i]))
        out[i] = ops.getStress()
    ops.wipe()
    return out


def material_checks() -> dict:
    k, fy, a = 1.0e8, 2.0e6, 0.05
    dy = fy / k
    out = {"k": k, "Fy": fy, "a": a, "path": "0 -> 3 dy -> -2 dy -> 4 dy -> -4 dy -> 1 dy, "
           "increments dy / per_dy; error = max |F_opensees - F_reference| / Fy over the path"}
    d = drift_path(dy, 997)  # increments that do not land on the yield points
    ref = bilinear_reference(d, k, fy, a)
    name, args = storey_material(1, {"model": "bilinear", "k": k, "Fy": fy, "a": a})
    out["bilinear_Steel01"] = {"command": [name, 1, *args], "per_dy": 997,
                               "error": float(np.max(np.abs(opensees_path(name, args, d) - ref)) / fy)}
    rows = []
    for n, beta, gamma in ((1.0, 0.5, 0.5), (2.0, 0.7, 0.3), (1.5, 0.25, 0.75)):
        law = {"model": "bouc-wen", "k": k, "Fy": fy, "a": a, "n": n, "beta": beta, "gamma": gamma}
        name, args = storey_material(1, law)
        row = {"n": n, "beta": beta, "gamma": gamma, "command": [name, 1, *args], "errors": {}}
        for per_dy in (200, 2000, 20000):
            d = drift_path(dy, per_dy)
            ref = bouc_wen_reference(d, k, fy, a, n, beta, gamma, sub=max(2, 40000 // per_dy))
            row["errors"][str(per_dy)] = float(np.max(np.abs(opensees_path(name, args, d) - ref)) / fy)
        if beta != gamma:  # the same with beta and gamma swapped in the OpenSees call: must be far off
            swapped = list(args)
            swapped[3], swapped[4] = args[4], args[3]
            d = drift_path(dy, 2000)
            ref = bouc_wen_reference(d, k, fy, a, n, beta, gamma, sub=20)
            row["error_if_beta_gamma_swapped_2000"] = float(
                np.max(np.abs(opensees_path(name, swapped, d) - ref)) / fy)
        rows.append(row)
    out["bouc_wen_BoucWen"] = rows
    return out


# --------------------------------------------------------------------------
# Main
# --------------------------------------------------------------------------
def fmt(x: float) -> str:
    return f"{x:.6g}"


def short(s: dict, wname: str) -> str:
    w = s[wname]
    parts = []
    for b in w["buildings"]:
        pk = max(b["floors"], key=lambda f: f["peak_u"])
        parts.append(f"{b['name']}: max|u|={fmt(pk['peak_u'])} roof res={fmt(b['floors'][-1]['residual_u'])}")
    imp = [c["impacts_gap"] for c in w["contacts"]]
    return "; ".join(parts) + (f"; impacts {imp}" if imp else "")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scenarios", default=",".join(SCENARIOS),
                    help="comma-separated scenario names (scenarios-inelastic/NAME.toml)")
    ap.add_argument("--dts", default=",".join(f"{d:g}" for d in DEFAULT_DTS), help="time steps, s")
    ap.add_argument("--contact", choices=["both", "on", "off"], default="both",
                    help="run with the contacts, without them (the no-contact variant), or both")
    ap.add_argument("--long-duration", type=float, default=LONG_DURATION,
                    help="each run continues in free vibration to this time (s); residuals reported "
                         "at the scenario's duration and at this time")
    ap.add_argument("--tail", type=float, default=TAIL,
                    help="window (s) at the end of each window for the mid-/half-range of u")
    ap.add_argument("--checks", action=argparse.BooleanOptionalAction, default=True,
                    help="materials vs our laws, linear no-contact vs exact, Fy = 1e20 vs linear (dt = 1e-4)")
    ap.add_argument("--timing-repeats", type=int, default=3,
                    help="build+analysis runs without recorders at dt = 1e-4 (median) of --timing-scenario")
    ap.add_argument("--timing-scenario", default="bilinear-mdof")
    ap.add_argument("--max-run-seconds", type=float, default=400.0,
                    help="skip a smaller dt when the run predicted from the last one would exceed this")
    ap.add_argument("--quick", action="store_true", help="smoke run: dt = 1e-3 and 1e-4, 1 timing run")
    ap.add_argument("--out", default=str(HERE / "results-inelastic.json"))
    ap.add_argument("--table", metavar="JSON", help="print the README's markdown tables from a results file, "
                                                    "run nothing")
    ap.add_argument("--materials-only", action="store_true",
                    help="run only the material checks and add them to the results file at --out")
    args = ap.parse_args()
    if args.table:
        print_tables(Path(args.table))
        return
    if args.materials_only:  # add the material checks to an existing results file
        import json  # noqa: PLC0415
        ops.logFile(os.devnull, "-noEcho")
        res = json.loads(Path(args.out).read_text()) if Path(args.out).exists() else {"checks": {}}
        res.setdefault("checks", {})["materials"] = material_checks()
        print(base.to_json(res["checks"]["materials"]))
        Path(args.out).write_text(base.to_json(res))
        return
    names = [x.strip() for x in args.scenarios.split(",") if x.strip()]
    dts = [float(x) for x in args.dts.split(",")]
    repeats = args.timing_repeats
    if args.quick:
        dts, repeats = [1e-3, 1e-4], 1
    variants = {"both": [True, False], "on": [True], "off": [False]}[args.contact]

    ops.logFile(os.devnull, "-noEcho")
    results = {
        "about": "OpenSeesPy peer of inelastic shear buildings pounding; see bench/opensees/README.md, "
                 "section 'Inelastic storeys'",
        "generated": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "command": " ".join([Path(sys.argv[0]).name] + sys.argv[1:]),
        "environment": {"openseespy": base._version("openseespy"), "opensees": ops.version(),
                        "numpy": np.__version__, "python": platform.python_version(),
                        "platform": platform.platform(), "cpu": base._cpu_model(), "cpus": os.cpu_count()},
        "analysis": {"integrator": "Newmark gamma=0.5 beta=0.25", "algorithm": "Newton",
                     "test": "NormDispIncr 1e-12 m, max 50 iterations (fallbacks as two_sdof.py)",
                     "system": "BandGeneral", "numberer": "Plain", "constraints": "Plain",
                     "windows": f"'record' = [0, scenario duration], 'long' = [0, {args.long_duration:g} s] "
                                "(same run continued in free vibration)",
                     "peaks": "max |x| over every step (EnvelopeNode/EnvelopeElement, 17 digits)",
                     "residual": "value at the window's end; tail_mid = (max+min)/2 and tail_half_range = "
                                 f"(max-min)/2 over the window's last {args.tail:g} s",
                     "drift": "u_j - u_{j-1} (zeroLength deformation); storey force = material stress",
                     "contact force": "F = -stress (> 0 compression)"},
        "scenarios": {}, "checks": {}, "timing_dt_1e-4": {}, "notes": [],
    }

    scns = {name: load_scenario(SCENARIO_DIR / f"{name}.toml") for name in names}
    for name, scn in scns.items():
        entry = {"scenario": str((SCENARIO_DIR / f"{name}.toml").relative_to(REPO)),
                 "duration": scn["duration"], "long_duration": args.long_duration}
        for contact in variants:
            vname = "contact" if contact else "no-contact"
            if contact and not scn["contacts"]:
                continue
            runs, last = [], None
            for dt in dts:
                if last is not None:
                    predicted = last["wall_s"] * last["dt"] / dt
                    if predicted > args.max_run_seconds:
                        note = f"{name} {vname}: dt = {dt:g} skipped (predicted {predicted:.0f} s)"
                        results["notes"].append(note)
                        print(note, file=sys.stderr)
                        continue
                res = run(scn, dt, contact, args.long_duration, args.tail, full=abs(dt - 1e-4) < 1e-15)
                entry.setdefault("opensees" if contact else "opensees_no_contact", res["info"])
                s = summarise(scn, res, contact)
                runs.append(s)
                last = s
                print(f"  {name} {vname} dt={dt:g} ({s['wall_s']:.1f} s): {short(s, 'record')}  "
                      f"| long: {short(s, 'long')}", file=sys.stderr, flush=True)
            entry[vname] = runs
        results["scenarios"][name] = entry

    if args.checks:
        chk = {"materials": material_checks()}
        for name, scn in scns.items():
            c = {}
            lin = variant(scn, linear=True)
            big = variant(scn, fy=HUGE_FY)
            dt = 1e-4
            # 1) linear, no contact, vs exact
            s_lin = summarise(lin, run(lin, dt, False, args.long_duration, args.tail), False)
            ex = []
            worst = {"peak_u": 0.0, "t_peak_u": 0.0, "u_end": 0.0, "peak_drift": 0.0}
            for bi, b in enumerate(lin["buildings"]):
                e = exact_linear(b, lin["gm"], [lin["duration"], max(args.long_duration, lin["duration"])])
                ex.append({"name": b["name"], **{f"t={t:g}": v for t, v in e.items()}})
                for wname, t in (("record", lin["duration"]), ("long", max(args.long_duration, lin["duration"]))):
                    ob = s_lin[wname]["buildings"][bi]
                    scale = max(e[t]["peak_u"])
                    for f, fl in enumerate(ob["floors"]):
                        worst["peak_u"] = max(worst["peak_u"], rel(fl["peak_u"], e[t]["peak_u"][f], e[t]["peak_u"][f]))
                        worst["t_peak_u"] = max(worst["t_peak_u"], abs(fl["t"] - e[t]["t_peak_u"][f]))
                        worst["u_end"] = max(worst["u_end"], rel(fl["residual_u"], e[t]["u_end"][f], scale))
                    for j, st in enumerate(ob["storeys"]):
                        worst["peak_drift"] = max(worst["peak_drift"],
                                                  rel(st["peak_drift"], e[t]["peak_drift"][j], e[t]["peak_drift"][j]))
            c["linear_no_contact_vs_exact"] = {
                "dt": dt, "max_rel_diff": worst,
                "what": "peak |u|, peak |drift| relative to the exact peak; u at the window ends "
                        "relative to the building's peak |u|; t_peak_u in s",
                "exact": ex, "opensees": s_lin}
            print(f"  check {name}: linear no contact vs exact: {worst}", file=sys.stderr, flush=True)
            # 2) Fy = 1e20 vs linear, with and without contact
            for contact in variants:
                if contact and not scn["contacts"]:
                    continue
                vname = "contact" if contact else "no-contact"
                s_big = summarise(big, run(big, dt, contact, args.long_duration, args.tail), contact)
                s_ref = s_lin if not contact else summarise(lin, run(lin, dt, True, args.long_duration,
                                                                     args.tail), True)
                d = compare_runs(s_ref, s_big)
                c[f"elastic_limit_{vname}"] = {"dt": dt, "Fy": HUGE_FY, "max_rel_diff_vs_linear": d,
                                               "linear": s_ref if contact else "see linear_no_contact_vs_exact",
                                               "Fy_1e20": s_big}
                print(f"  check {name}: Fy=1e20 vs linear ({vname}): {d}", file=sys.stderr, flush=True)
            chk[name] = c
        results["checks"] = chk

    if repeats > 0 and args.timing_scenario in scns:
        scn = scns[args.timing_scenario]
        tr = [run(scn, 1e-4, True, scn["duration"], args.tail, record=False) for _ in range(repeats)]
        times, cpus = [r["wall_s"] for r in tr], [r["cpu_s"] for r in tr]
        results["timing_dt_1e-4"][args.timing_scenario] = {
            "median_s": statistics.median(times), "runs_s": times,
            "median_cpu_s": statistics.median(cpus), "runs_cpu_s": cpus,
            "steps": int(round(scn["duration"] / 1e-4)),
            "what": "ops.wipe + model build + analysis over the record at dt = 1e-4 with contacts, "
                    "no recorders (the segment split costs two extra ops.analyze calls)"}
        print(f"  timing {args.timing_scenario}: median {statistics.median(times):.3f} s of {times}",
              file=sys.stderr)

    Path(args.out).write_text(base.to_json(results))
    print(f"wrote {args.out}")


# --------------------------------------------------------------------------
# Markdown tables from a results file (--table)
# --------------------------------------------------------------------------
def g(x: float, d: int = 6) -> str:
    return f"{x:.{d}g}"


def print_tables(path: Path) -> None:
    import json  # noqa: PLC0415
    res = json.loads(Path(path).read_text())
    for name, entry in res["scenarios"].items():
        for vname in ("contact", "no-contact"):
            runs = entry.get(vname)
            if not runs:
                continue
            blds = [b["name"] for b in runs[0]["record"]["buildings"]]
            print(f"\n**{name}, {vname}** (convergence; per building: peak |u| over all floors, roof u at "
                  f"31.18 s and at 45 s, tail mid-range at 45 s)\n")
            head = ["dt (s)"]
            for b in blds:
                head += [f"{b} peak \\|u\\| (m)", "t (s)", "roof u(31.18)", "roof u(45)", "roof mid(43-45)"]
            if vname == "contact":
                head += ["impacts"]
            head += ["CPU (s)"]
            print("| " + " | ".join(head) + " |")
            print("|" + "---|" * len(head))
            for r in runs:
                row = [f"{r['dt']:g}"]
                for bi in range(len(blds)):
                    br, bl = r["record"]["buildings"][bi], r["long"]["buildings"][bi]
                    pk = max(br["floors"], key=lambda f: f["peak_u"])
                    row += [g(pk["peak_u"]), f"{pk['t']:.4f}", g(br["floors"][-1]["residual_u"]),
                            g(bl["floors"][-1]["residual_u"]), g(bl["floors"][-1]["tail_mid_u"])]
                if vname == "contact":
                    row += ["/".join(str(c["impacts_gap"]) for c in r["record"]["contacts"])]
                row += [f"{r.get('cpu_s', float('nan')):.1f}"]
                print("| " + " | ".join(row) + " |")
            r = runs[-1]
            print(f"\n**{name}, {vname}, dt = {r['dt']:g}** (floor j / storey j; u and drift in m, forces in N; "
                  f"res = value at the end; mid/half = mid-range / half-range over the last 2 s)\n")
            head = ["building", "j", "peak \\|u\\|", "t", "res u 31.18", "res u 45", "mid 45", "half 45",
                    "peak \\|drift\\|", "res drift 31.18", "res drift 45", "peak \\|F\\|", "F/Fy", "ductility"]
            print("| " + " | ".join(head) + " |")
            print("|" + "---|" * len(head))
            for bi, b in enumerate(blds):
                br, bl = r["record"]["buildings"][bi], r["long"]["buildings"][bi]
                for j in range(len(br["floors"])):
                    f, fl, st, stl = br["floors"][j], bl["floors"][j], br["storeys"][j], bl["storeys"][j]
                    row = [b, str(j + 1), g(f["peak_u"]), f"{f['t']:.4f}", g(f["residual_u"], 5),
                           g(fl["residual_u"], 5), g(fl["tail_mid_u"], 5), g(fl["tail_half_range_u"], 2),
                           g(st["peak_drift"]), g(st["residual_drift"], 5), g(stl["residual_drift"], 5),
                           g(st["peak_force"]), g(st.get("peak_force_over_Fy", float("nan")), 4),
                           g(st.get("ductility", float("nan")), 4)]
                    print("| " + " | ".join(row) + " |")
            if vname == "contact":
                print()
                for c in r["record"]["contacts"]:
                    cl = [x for x in r["long"]["contacts"] if x["floors"] == c["floors"]][0]
                    print(f"- contact floors {c['floors']}: impacts {c['impacts_gap']} (gap) / "
                          f"{c['impacts_force']} (force) to 31.18 s, {cl['impacts_gap']} to 45 s; "
                          + (f"peak force {g(c['peak_force'])} N at {c['t_peak_force']:.4f} s; "
                             if c["t_peak_force"] is not None else "no contact force; ")
                          + f"closed at 31.18 s: {c['closed_at_end']}, at 45 s: {cl['closed_at_end']}")


if __name__ == "__main__":
    main()
