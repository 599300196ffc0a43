#!/usr/bin/env python3
"""OpenSees peer: floor-to-column pounding, a slab striking a neighbour's column between its floors.

What it does
------------
Reads bench/opensees/scenarios-column/*.toml (the Rust tool's format with `[[column_contact]]`), builds each
scenario in OpenSeesPy with the struck columns as elastic beam-columns and integrates it at several constant
time steps. The buildings are those of soil.py (`model basic -ndm 2 -ndf 3`, every y dof fixed, all nodes on
x = 0, a floor at its elevation; fixed base, so every floor's rotation is fixed: rigid floors that translate
without rotating); storeys are `twoNodeLink`s (shear, dir 2) with the storey's law and a `Viscous a1 k`
dashpot in parallel, and each floor has a `Viscous a0 m_i` dashpot to the ground (the building's fixed-base
Rayleigh damping on its modes 1 and 2, inelastic.rayleigh). Per `[[column_contact]]` (slab of building S at
elevation z, column of the neighbour C, struck in C's storey j at a = z - z_(j-1), b = L - a, L = h_j):

    The column: `elasticBeamColumn` elements (geomTransf Linear; E = EI, Iz = 1, A = 1: the axial dof is fixed
      anyway) from C's node below storey j (its floor j - 1, or its ground node for j = 1) to its floor j's
      node, through a node P at (0, z_(j-1) + a) free in x and rotation. The floors do not rotate, so the
      column is fixed-fixed relative to them. Its rotations inside are free.
    Storey j keeps the stiffness the scenario gives: its storey link gets k_j - 12 EI / L^3 (the column's sway
      stiffness, which the beam adds), its dashpot a1 (k_j - 12 EI / L^3), and the beams get stiffness-
      proportional Rayleigh damping a1 K_beam (`region -ele ... -rayleigh 0 a1 0 0`). So the storey's total
      stiffness and damping are the tool's, and the beam's condensed stiffness on (u_below, u_P, u_above) is
      12 EI / L^3 (u_above - u_below)^2 + k_p (u_P - N1 u_below - N2 u_above)^2 with k_p = 3 EI L^3 / (a^3
      b^3) and N1, N2 the cubic Hermite weights: the tool's point spring, exactly (the beam's rotation dofs
      are massless and follow the condensation: with damping a1 K on the whole element they obey
      psi + a1 psi' = 0 from rest, psi = 0).
    Mass, variant "point" (the default): one element on each side of P, massless; P carries the tool's point
      mass m_p = column_mass (1/L) int (y / y(a))^2 dx over the column's static deflection y under a force at
      P (Rayleigh's equivalent mass; 13/35 at mid-height). This is the tool's model exactly.
      Variant "distributed" (`--variants point,distributed`): the column in n elements per side (--segments,
      default 8), column_mass lumped at the nodes by tributary length (the end halves on C's floors, or on the
      ground), no point mass: the continuous column's mass distribution, to show the modelling difference.
    Contact: `zeroLength` from the left building's node to the right one's (the slab's floor node and P), dir
      1, the material of two_sdof.contact_material with mEff = 1 / (1/m_slab + 1/m_p) (the tool's effective
      mass of the site, in both variants).
    Ground: `UniformExcitation` of the scenario's record (every mass, P's and the column's included, gets
      -m a_g). `constraints Transformation`, `numberer RCM`, `system BandGeneral`, `test NormDispIncr 1e-12
      50`, Newton (two_sdof.analyze's fallbacks), `Newmark 0.5 0.25`, constant dt.

Reported per scenario, variant and dt (JSON, default results-column.json), from every step: per floor the peak
|u|, per storey the peak |drift|, per contact site the impacts (open -> closed transitions of strain < -gap;
also of F != 0), the peak contact force; per column: the point force k_p delta from the displacements, the
same from the element forces (the jump of the beams' local shear at P), the end shears and moments from the
element forces (`localForce` of the lowest element at its i end and of the highest at its j end) in total and
less their storey-drift part (12 EI / L^3 and 6 EI / L^2 times the drift: what is left is the contact's part,
the tool's `column` demand), and the check that the massless column's end forces equal the closed forms.
Checks: the periods of each building with its point masses (OpenSees eigen vs numpy on the condensed M, K),
and the point stiffness and the end shears per unit force from a static OpenSees analysis of the column alone.

    /tmp/opensees-venv/bin/python bench/opensees/column.py --quick --out /tmp/q.json
    nice -n 10 /tmp/opensees-venv/bin/python bench/opensees/column.py
    /tmp/opensees-venv/bin/python bench/opensees/column.py --table bench/opensees/results-column.json

Peer measurement only: OpenSeesPy and NumPy are never dependencies of the Rust tool. See README.md, "Soil,
supports and floor-to-column contacts".
"""

from __future__ import annotations

import argparse
import datetime
import json
import math
import os
import platform
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import soil  # noqa: E402  (buildings, records; imports two_sdof, inelastic, isolation)

base, inel = soil.base, soil.inel
ops = base.ops
REPO = base.REPO
SCENARIO_DIR = HERE / "scenarios-column"
SCENARIOS = ["column-three"]
DEFAULT_DTS = [1e-4, 5e-5, 2e-5, 1e-5]
CHUNK_S = 1.0


# --------------------------------------------------------------------------
# The struck column's closed forms (the tool's crates/pounding/src/structure/column.rs, independently)
# --------------------------------------------------------------------------
def column_numbers(ei: float, L: float, a: float, mass: float) -> dict:
    b = L - a
    kp = 3.0 * ei * L ** 3 / (a ** 3 * b ** 3)
    n1 = b * b * (3.0 * a + b) / L ** 3
    n2 = a * a * (3.0 * b + a) / L ** 3
    m1, m2 = a * b * b / L ** 2, a * a * b / L ** 2

    def y(x):  # static deflection under a unit force at a (fixed-fixed), up to a factor
        x = np.asarray(x, dtype=float)
        xr = L - x
        return np.where(x <= a, b * b * x * x * (3 * a * L - 3 * a * x - b * x),
                        a * a * xr * xr * (3 * b * L - 3 * b * xr - a * xr))

    gx, gw = np.polynomial.legendre.leggauss(20)
    ya = float(y(a))
    integral = 0.0
    for x0, x1 in ((0.0, a), (a, L)):
        m, h = 0.5 * (x0 + x1), 0.5 * (x1 - x0)
        integral += h * float(np.sum(gw * (y(m + h * gx) / ya) ** 2))
    return {"EI": ei, "L": L, "a": a, "b": b, "column_mass": mass, "k_point": kp, "N1": n1, "N2": n2,
            "moment_lower_per_N": m1, "moment_upper_per_N": m2, "k_sway": 12.0 * ei / L ** 3,
            "m_sway": 6.0 * ei / L ** 2, "point_mass": mass * integral / L}


# --------------------------------------------------------------------------
# Scenario
# --------------------------------------------------------------------------
def load_scenario(path: Path) -> dict:
    with open(path, "rb") as f:
        raw = tomllib_load(f)
    scn = soil.expand(raw, path)
    for b in scn["buildings"]:
        if b["foundation"] or b["motion"] is not None or any(l["model"] != "linear" for l in b["storeys"]):
            raise SystemExit(f"{path}: this peer takes linear fixed-base buildings on the scenario's ground")
    if scn["links"]:
        raise SystemExit(f"{path}: [[contact]] and [[wall]] are not handled by this peer (soil.py does them)")
    index = {b["name"]: i for i, b in enumerate(scn["buildings"])}
    cols = []
    for cc in raw.get("column_contact", []):
        sname, floor = cc["slab"][0], int(cc["slab"][1])
        s, c = index[sname], index[cc["column"]]
        if abs(s - c) != 1:
            raise SystemExit("the column's building must be the slab's neighbour")
        z = scn["buildings"][s]["z"][floor - 1]
        zc = scn["buildings"][c]["z"]
        if any(abs(w - z) <= 1e-3 for w in zc):
            raise SystemExit(f"{path}: slab {sname} {floor} meets a floor: a floor contact, not handled here")
        j = next(k for k, w in enumerate(zc) if w > z) + 1  # storey struck, 1-based
        below = zc[j - 2] if j > 1 else 0.0
        if cc["model"] in ("hertzdamp", "jankowski") and cc.get("damping", "exact") != "formula":
            raise SystemExit(f"{path}: write damping = \"formula\" (OpenSees' law)")
        num = column_numbers(float(cc["EI"]), zc[j - 1] - below, z - below, float(cc["column_mass"]))
        left, right = min(s, c), max(s, c)
        m_slab = scn["buildings"][s]["m"][floor - 1]
        cols.append({"name": f"{scn['buildings'][left]['name']}|{scn['buildings'][right]['name']}:{sname}{floor}",
                     "slab": s, "floor": floor, "column": c, "storey": j, "z": z, "z_below": below,
                     "column_on_left": c == left, "gap": float(cc["gap"]), "raw": cc, **num,
                     "m_eff": 1.0 / (1.0 / m_slab + 1.0 / num["point_mass"])})
    seen = {(x["column"], x["storey"]) for x in cols}
    if len(seen) != len(cols):
        raise SystemExit(f"{path}: two slabs striking one storey's column are not handled by this peer")
    scn["columns"] = cols
    return scn


def tomllib_load(f):
    import tomllib
    return tomllib.load(f)


def with_column_storeys(scn: dict, b: dict, bi: int) -> dict:
    """Building b with each struck storey's link reduced by the column's sway stiffness 12 EI / L^3."""
    storeys = [dict(s) for s in b["storeys"]]
    for col in scn["columns"]:
        if col["column"] == bi:
            k = storeys[col["storey"] - 1]["k"] - col["k_sway"]
            if k <= 0.0:
                raise SystemExit(f"{col['name']}: the column's sway stiffness exceeds its storey's")
            storeys[col["storey"] - 1]["k"] = k
    return dict(b, storeys=storeys)


def point_node(ci):
    return 700000 + 100 * ci


def column_nodes(ci, n):  # interior nodes other than P
    return [700000 + 100 * ci + 1 + k for k in range(n)]


def beam_tag(ci, k):
    return 800000 + 100 * ci + k


def contact_tag(ci):
    return 900000 + ci


def build(scn: dict, variant: str, segments: int, contact: bool = True, eigen_only: bool = False) -> dict:
    cmds = []

    def log(name, *args):
        getattr(ops, name)(*args)
        cmds.append([name, *args])

    ops.wipe()
    log("model", "basic", "-ndm", 2, "-ndf", 3)
    extra_mass = {}  # floor node -> column mass lumped on it (distributed variant)
    blds = [with_column_storeys(scn, b, bi) for bi, b in enumerate(scn["buildings"])]
    for bi, b in enumerate(blds):
        soil.build_building(bi, b, log, eigen_only=eigen_only)
    log("geomTransf", "Linear", 1)
    info = {"commands": cmds, "columns": []}
    for ci, col in enumerate(scn["columns"]):
        c, j = col["column"], col["storey"]
        lo = soil.below_node(c, scn["buildings"][c], j)
        hi = soil.floor_node(c, j)
        P = point_node(ci)
        n_side = 1 if variant == "point" else segments
        # positions along the column (from its lower end), nodes
        xs_lo = [col["a"] * k / n_side for k in range(n_side + 1)]
        xs_hi = [col["a"] + col["b"] * k / n_side for k in range(n_side + 1)]
        xs = xs_lo + xs_hi[1:]
        inner = column_nodes(ci, len(xs) - 3)
        nodes = [lo] + inner[:n_side - 1] + [P] + inner[n_side - 1:] + [hi]
        assert len(nodes) == len(xs)
        for nd, x in zip(nodes[1:-1], xs[1:-1]):
            log("node", nd, 0.0, col["z_below"] + x)
            log("fix", nd, 0, 1, 0)
        if variant == "point":
            log("mass", P, col["point_mass"], 0.0, 0.0)
        else:
            mu = col["column_mass"] / col["L"]
            for k, nd in enumerate(nodes):
                trib = ((xs[k] - xs[k - 1]) if k > 0 else 0.0) / 2.0 + ((xs[k + 1] - xs[k]) if k + 1 < len(xs) else 0.0) / 2.0
                if 0 < k < len(nodes) - 1:
                    log("mass", nd, mu * trib, 0.0, 0.0)
                elif nd != soil.ground_node(c):
                    extra_mass[nd] = extra_mass.get(nd, 0.0) + mu * trib
        beams = []
        for k in range(len(nodes) - 1):
            t = beam_tag(ci, k)
            log("element", "elasticBeamColumn", t, nodes[k], nodes[k + 1], 1.0, col["EI"], 1.0, 1)
            beams.append(t)
        a1 = scn["buildings"][c]["rayleigh"]["a1"]
        if not eigen_only and a1 > 0.0:
            log("region", 100 + ci, "-ele", *beams, "-rayleigh", 0.0, a1, 0.0, 0.0)
        info["columns"].append({"nodes": nodes, "P": P, "lo": lo, "hi": hi, "beams": beams,
                                "below_P": beams[n_side - 1], "above_P": beams[n_side]})
    for nd, m in extra_mass.items():  # the column's end halves on its floors (mass adds to the floor's)
        bi = (nd // 10000) - 1
        f = nd - soil.B(bi) - 10
        log("mass", nd, scn["buildings"][bi]["m"][f - 1] + m, 0.0, 0.0)
    info["extra_floor_mass"] = extra_mass
    if eigen_only:
        return info
    links = []
    if contact:
        for ci, col in enumerate(scn["columns"]):
            name, args, _ = base.contact_material(col["raw"], col["m_eff"])
            t = contact_tag(ci)
            log("uniaxialMaterial", name, t, *args)
            slab = soil.floor_node(col["slab"], col["floor"])
            P = point_node(ci)
            ni, nj = (P, slab) if col["column_on_left"] else (slab, P)
            log("element", "zeroLength", t, ni, nj, "-mat", t, "-dir", 1)
            links.append(t)
    info["links"] = links
    gdt, values, factor = scn["gm"][0], scn["gm"][1], scn["gm"][2]
    ops.timeSeries("Path", 1, "-dt", gdt, "-values", *values, "-factor", factor)
    cmds.append(["timeSeries", "Path", 1, "-dt", gdt, "-values", f"<{len(values)} values from t = 0>", "-factor", factor])
    log("pattern", "UniformExcitation", 1, 1, "-accel", 1)
    log("constraints", "Transformation")
    log("numberer", "RCM")
    log("system", "BandGeneral")
    log("test", "NormDispIncr", base.TOL, base.MAX_ITER)
    log("algorithm", "Newton")
    log("integrator", "Newmark", 0.5, 0.25)
    log("analysis", "Transient")
    return info


# --------------------------------------------------------------------------
# Checks: periods with the point masses, the column's statics
# --------------------------------------------------------------------------
def numpy_periods(scn: dict, bi: int) -> list[float]:
    """Building bi with its struck columns' points (variant "point"): dofs [floors, points], K = the storeys
    + k_p (u_P - N1 u_lo - N2 u_hi)^2 per point."""
    b = scn["buildings"][bi]
    n = len(b["m"])
    cols = [c for c in scn["columns"] if c["column"] == bi]
    d = n + len(cols)
    K = np.zeros((d, d))
    for j, law in enumerate(b["storeys"]):
        g = np.zeros(d)
        g[j] = 1.0
        if j > 0:
            g[j - 1] = -1.0
        K += law["k"] * np.outer(g, g)
    masses = list(b["m"])
    for k, c in enumerate(cols):
        g = np.zeros(d)
        g[n + k] = 1.0
        g[c["storey"] - 1] -= c["N2"]
        if c["storey"] > 1:
            g[c["storey"] - 2] -= c["N1"]
        K += c["k_point"] * np.outer(g, g)
        masses.append(c["point_mass"])
    s = 1.0 / np.sqrt(np.array(masses))
    lam = np.sort(np.linalg.eigvalsh(K * np.outer(s, s)))
    return [float(2.0 * math.pi / math.sqrt(x)) for x in lam]


def opensees_periods(scn: dict, bi: int) -> list[float]:
    """All periods of the whole model (variant "point", no contact), those of building bi picked by count:
    the model is built whole, so its eigenvalues are the union of the buildings'."""
    build(scn, "point", 1, contact=False, eigen_only=True)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("FullGeneral")
    d = sum(len(b["m"]) for b in scn["buildings"]) + len(scn["columns"])
    lam = ops.eigen("-fullGenLapack", d)
    ops.wipe()
    return sorted((2 * math.pi / math.sqrt(x) for x in lam), reverse=True)


def column_statics(col: dict) -> dict:
    """The column alone in OpenSees (two elasticBeamColumns, ends fixed, P free in x and rotation), a unit
    force at P: P's deflection (1 / k_p) and the end reactions (shears and moments per unit force)."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, col["a"])
    ops.node(3, 0.0, col["L"])
    ops.fix(1, 1, 1, 1)
    ops.fix(3, 1, 1, 1)
    ops.fix(2, 0, 1, 0)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 2, 1.0, col["EI"], 1.0, 1)
    ops.element("elasticBeamColumn", 2, 2, 3, 1.0, col["EI"], 1.0, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0, 0.0, 0.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-14, 10)
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    ops.analyze(1)
    ops.reactions()
    k = 1.0 / ops.nodeDisp(2, 1)
    r1, r3 = -ops.nodeReaction(1, 1), -ops.nodeReaction(3, 1)
    m1, m3 = abs(ops.nodeReaction(1, 3)), abs(ops.nodeReaction(3, 3))
    ops.wipe()
    return {"k_point": k, "N1": r1, "N2": r3, "moment_lower_per_N": m1, "moment_upper_per_N": m3,
            "rel_diff": max(abs(k / col["k_point"] - 1.0), abs(r1 - col["N1"]), abs(r3 - col["N2"]),
                            abs(m1 - col["moment_lower_per_N"]) / col["moment_lower_per_N"],
                            abs(m3 - col["moment_upper_per_N"]) / col["moment_upper_per_N"])}


# --------------------------------------------------------------------------
# Runs
# --------------------------------------------------------------------------
def run(scn: dict, dt: float, variant: str, segments: int, record: bool = True, contact: bool = True) -> dict:
    nsteps = int(round(scn["duration"] / dt))
    if not record:
        t0, c0 = time.perf_counter(), time.process_time()
        info = build(scn, variant, segments, contact)
        fb = base.analyze(nsteps, dt)
        ops.wipe()
        return {"dt": dt, "steps": nsteps, "wall_s": time.perf_counter() - t0, "cpu_s": time.process_time() - c0,
                "fallback_steps": fb}
    blds = scn["buildings"]
    floor_nodes = [soil.floor_node(bi, f) for bi, b in enumerate(blds) for f in range(1, len(b["m"]) + 1)]
    with tempfile.TemporaryDirectory(prefix="opensees-column-") as tmp:
        tmp = Path(tmp)
        t0, c0 = time.perf_counter(), time.process_time()
        info = build(scn, variant, segments, contact)
        pnodes = [c["P"] for c in info["columns"]]
        nodes = floor_nodes + pnodes
        beams = []
        for c in info["columns"]:
            beams += [c["beams"][0], c["below_P"], c["above_P"], c["beams"][-1]]
        per_chunk = int(round(CHUNK_S / dt))
        ends = list(range(per_chunk, nsteps, per_chunk)) + [nsteps]
        U, D, S, FE, fb = [], [], [], [], 0
        for s, n_end in enumerate(ends):
            ops.recorder("Node", "-binary", str(tmp / f"n{s}.bin"), "-node", *nodes, "-dof", 1, "disp")
            ops.recorder("Element", "-binary", str(tmp / f"f{s}.bin"), "-ele", *beams, "localForce")
            if info["links"]:
                ops.recorder("Element", "-binary", str(tmp / f"d{s}.bin"), "-ele", *info["links"], "deformation")
                ops.recorder("Element", "-binary", str(tmp / f"s{s}.bin"), "-ele", *info["links"], "material", "1",
                             "stress")
            fb += base.analyze(n_end, dt)
            ops.remove("recorders")
            nrows = n_end - (ends[s - 1] if s else 0)
            parts = [(U, "n", len(nodes)), (FE, "f", 6 * len(beams))]
            if info["links"]:
                parts += [(D, "d", len(info["links"])), (S, "s", len(info["links"]))]
            for store, p, ncol in parts:
                x = base.read_binary_recorder(tmp / f"{p}{s}.bin", ncol).astype(np.float64)
                if len(x) != nrows:
                    raise RuntimeError(f"recorder {p}: {len(x)} rows for {nrows} steps")
                store.append(x)
                (tmp / f"{p}{s}.bin").unlink()
        ops.wipe()
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    return {"dt": dt, "steps": nsteps, "wall_s": wall, "cpu_s": cpu, "fallback_steps": fb, "variant": variant,
            "segments": segments if variant != "point" else 1, "nodes": nodes, "floor_nodes": floor_nodes,
            "info": info, "U": np.concatenate(U), "FE": np.concatenate(FE),
            "D": np.concatenate(D) if D else None, "S": np.concatenate(S) if S else None}


def peak(x: np.ndarray, dt: float) -> dict:
    i = int(np.argmax(np.abs(x)))
    return {"peak": float(abs(x[i])), "t": float(round((i + 1) * dt, 9))}


def fit_sign(total: np.ndarray, impact: np.ndarray, sway: np.ndarray) -> tuple[float, float, float]:
    """total = s1 impact + s2 sway with s1, s2 = +-1 (the element's sign conventions): the pair that fits
    best and the largest residual relative to max |total|."""
    best = None
    for s1 in (1.0, -1.0):
        for s2 in (1.0, -1.0):
            r = float(np.abs(total - s1 * impact - s2 * sway).max()) / max(float(np.abs(total).max()), 1e-300)
            if best is None or r < best[2]:
                best = (s1, s2, r)
    return best


def summarise(scn: dict, res: dict) -> dict:
    dt, U, FE = res["dt"], res["U"], res["FE"]
    col_of = {nd: k for k, nd in enumerate(res["nodes"])}
    out = {"dt": dt, "variant": res["variant"], "segments": res["segments"], "steps": res["steps"],
           "wall_s": res["wall_s"], "cpu_s": res["cpu_s"], "fallback_steps": res["fallback_steps"],
           "buildings": [], "sites": []}

    def u(nd):
        return U[:, col_of[nd]] if nd in col_of else np.zeros(len(U))  # a (fixed) ground node: 0

    for bi, b in enumerate(scn["buildings"]):
        n = len(b["m"])
        fl = [u(soil.floor_node(bi, f)) for f in range(1, n + 1)]
        out["buildings"].append({
            "name": b["name"],
            "floors": [peak(x, dt) for x in fl],
            "storeys": [peak(fl[j] - (fl[j - 1] if j else 0.0), dt) for j in range(n)]})
    nbeam = 4
    for ci, (col, ci_info) in enumerate(zip(scn["columns"], res["info"]["columns"])):
        ulo, uhi, up = u(ci_info["lo"]), u(ci_info["hi"]), u(ci_info["P"])
        drift = uhi - ulo
        fp = col["k_point"] * (up - col["N1"] * ulo - col["N2"] * uhi)
        f = FE[:, 6 * nbeam * ci: 6 * nbeam * (ci + 1)].reshape(len(FE), nbeam, 6)
        v_lo, m_lo = f[:, 0, 1], f[:, 0, 2]          # lowest element, i end
        v_hi, m_hi = f[:, 3, 4], f[:, 3, 5]          # highest element, j end
        jump = f[:, 1, 4] + f[:, 2, 1]               # below P (j end) + above P (i end): the force on P
        sv = fit_sign(v_lo, col["N1"] * fp, col["k_sway"] * drift)
        su = fit_sign(v_hi, col["N2"] * fp, col["k_sway"] * drift)
        sm = fit_sign(m_lo, col["moment_lower_per_N"] * fp, col["m_sway"] * drift)
        sn = fit_sign(m_hi, col["moment_upper_per_N"] * fp, col["m_sway"] * drift)
        sj = fit_sign(jump, fp, np.zeros_like(fp))
        site = {"name": col["name"], "storey": col["storey"], "a": col["a"],
                "point_force_from_displacements": peak(fp, dt),
                "point_force_from_elements": peak(jump, dt),
                "end_shear_total": [peak(v_lo, dt), peak(v_hi, dt)],
                "end_moment_total": [peak(m_lo, dt), peak(m_hi, dt)],
                "end_shear_contact_part": [peak(v_lo - sv[1] * col["k_sway"] * drift, dt),
                                           peak(v_hi - su[1] * col["k_sway"] * drift, dt)],
                "end_moment_contact_part": [peak(m_lo - sm[1] * col["m_sway"] * drift, dt),
                                            peak(m_hi - sn[1] * col["m_sway"] * drift, dt)],
                "closed_form_residual": max(sv[2], su[2], sm[2], sn[2], sj[2]),
                "peak_drift_storey": peak(drift, dt)}
        if res["D"] is not None:
            strain, F = res["D"][:, ci], 0.0 - res["S"][:, ci]
            closed = strain < -col["gap"]
            first = inel.rising_edges(closed)
            site.update(impacts=int(len(first)), impacts_force=int(len(inel.rising_edges(F != 0.0))),
                        first_steps_inside_s=[float(round((i + 1) * dt, 9)) for i in first],
                        peak_contact_force=float(F.max()), min_contact_force=float(F.min()),
                        max_penetration=float(max(0.0, -(strain.min() + col["gap"]))))
        out["sites"].append(site)
    return out


def quantities(s: dict) -> dict:
    q = {}
    for b in s["buildings"]:
        for i, f in enumerate(b["floors"], 1):
            q[f"{b['name']}.floor{i}.floor"] = f["peak"]
        for j, f in enumerate(b["storeys"], 1):
            q[f"{b['name']}.storey{j}.drift"] = f["peak"]
    for c in s["sites"]:
        q[f"{c['name']}.force"] = c["point_force_from_displacements"]["peak"]
        for k, end in enumerate(("lower", "upper")):
            q[f"{c['name']}.{end}.shear"] = c["end_shear_contact_part"][k]["peak"]
            q[f"{c['name']}.{end}.moment"] = c["end_moment_contact_part"][k]["peak"]
        if "impacts" in c:
            q[f"{c['name']}.impacts"] = c["impacts"]
    return q


def convergence(runs: list) -> list:
    out = []
    for a, b in zip(runs, runs[1:]):
        qa, qb = quantities(a), quantities(b)
        groups = {}
        for k, v in qb.items():
            if k.endswith(".impacts"):
                continue
            g = k.rsplit(".", 1)[-1]
            groups[g] = max(groups.get(g, 0.0), abs(qa[k] - v) / abs(v) if v else abs(qa[k]))
        ia = {k: v for k, v in qa.items() if k.endswith(".impacts")}
        ib = {k: v for k, v in qb.items() if k.endswith(".impacts")}
        out.append({"dt_a": a["dt"], "dt_b": b["dt"], "max_rel": groups, "impacts_equal": ia == ib,
                    "impacts_a": ia, "impacts_b": ib})
    return out


def g(x, d=6):
    return "-" if x is None else f"{x:.{d}g}"


def print_tables(res: dict) -> None:
    for key, entry in res["scenarios"].items():
        runs = entry["runs"]
        print(f"\n**{key}**: peak |u| of each floor (m); per site: impacts, peak point force (N), end shears "
              f"(contact part, N)\n")
        head = ["dt (s)"]
        for b in runs[0]["buildings"]:
            head += [f"{b['name']}{i + 1}" for i in range(len(b["floors"]))]
        head += [f"{c['name']}" for c in runs[0]["sites"]] + ["CPU (s)"]
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for r in runs:
            row = [f"{r['dt']:g}"]
            for b in r["buildings"]:
                row += [g(f["peak"], 7) for f in b["floors"]]
            row += [f"{c.get('impacts', '-')}; {g(c['point_force_from_displacements']['peak'])}; "
                    f"{g(c['end_shear_contact_part'][0]['peak'])} / {g(c['end_shear_contact_part'][1]['peak'])}"
                    for c in r["sites"]]
            row.append(f"{r['cpu_s']:.1f}")
            print("| " + " | ".join(row) + " |")
        conv = entry.get("convergence", [])
        if conv:
            keys = ["floor", "drift", "force", "shear", "moment"]
            print(f"\n{key}: largest relative change between successive dts\n")
            print("| dts | " + " | ".join(keys) + " | impacts equal |")
            print("|---|" + "---|" * (len(keys) + 1))
            for c in conv:
                print(f"| {c['dt_a']:g} -> {c['dt_b']:g} | " + " | ".join(g(c["max_rel"].get(k), 2) for k in keys)
                      + f" | {'yes' if c['impacts_equal'] else 'no'} |")
    for k, v in res.get("checks", {}).items():
        print(f"- check {k}: {json.dumps(v)[:400]}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scenarios", default=",".join(SCENARIOS))
    ap.add_argument("--variants", default="point,distributed", help="point (the tool's model), distributed")
    ap.add_argument("--segments", type=int, default=8, help="elements per side of P, variant distributed")
    ap.add_argument("--dts", default=",".join(f"{d:g}" for d in DEFAULT_DTS),
                    help="time steps of the point variant, s")
    ap.add_argument("--dts-distributed", default="1e-4,5e-5,2e-5", help="time steps of the distributed variant")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out", default=str(HERE / "results-column.json"))
    ap.add_argument("--table", metavar="JSON")
    ap.add_argument("--merge", metavar="JSON,JSON,...", help="merge result files into --out (the runs of one "
                                                              "scenario and variant into one ladder), run nothing")
    args = ap.parse_args()
    if args.merge:
        parts = [json.loads(Path(x).read_text()) for x in args.merge.split(",")]
        out = parts[0]
        out["merged_from"] = [{"command": p_["command"], "generated": p_["generated"]} for p_ in parts]
        for p_ in parts[1:]:
            for key, entry in p_["scenarios"].items():
                if key in out["scenarios"]:
                    runs = {r["dt"]: r for r in out["scenarios"][key]["runs"] + entry["runs"]}
                    out["scenarios"][key]["runs"] = [runs[d] for d in sorted(runs, reverse=True)]
                    out["scenarios"][key]["convergence"] = convergence(out["scenarios"][key]["runs"])
                else:
                    out["scenarios"][key] = entry
            out["checks"].update(p_["checks"])
            out["notes"] += p_["notes"]
        Path(args.out).write_text(base.to_json(out))
        print(f"wrote {args.out}")
        return
    if args.table:
        print_tables(json.loads(Path(args.table).read_text()))
        return
    ops.logFile(os.devnull, "-noEcho")
    names = [x for x in args.scenarios.split(",") if x]
    variants = [x for x in args.variants.split(",") if x]
    dts = {"point": [float(x) for x in args.dts.split(",")],
           "distributed": [float(x) for x in args.dts_distributed.split(",")]}
    if args.quick:
        dts = {"point": [1e-3], "distributed": [1e-3]}
    results = {
        "about": "OpenSeesPy peer of floor-to-column pounding: the struck column as elastic beam-columns; see "
                 "bench/opensees/README.md, 'Soil, supports and floor-to-column contacts'",
        "generated": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "command": " ".join([Path(sys.argv[0]).name] + sys.argv[1:]),
        "environment": {"openseespy": base._version("openseespy"), "opensees": ops.version(),
                        "numpy": np.__version__, "python": platform.python_version(),
                        "platform": platform.platform(), "cpu": base._cpu_model(), "cpus": os.cpu_count()},
        "analysis": {"integrator": "Newmark gamma=0.5 beta=0.25", "algorithm": "Newton",
                     "test": "NormDispIncr 1e-12, max 50 iterations (fallbacks as two_sdof.py)",
                     "system": "BandGeneral", "numberer": "RCM", "constraints": "Transformation",
                     "peaks": "max |x| over every step", "impacts": "open -> closed transitions of strain < -gap",
                     "contact force": "F = -stress (> 0 compressive)",
                     "column forces": "elasticBeamColumn localForce (no damping force), lowest element i end, "
                                      "highest element j end; contact part = total less 12 EI/L^3 (shear) or "
                                      "6 EI/L^2 (moment) times the storey drift"},
        "scenarios": {}, "checks": {}, "notes": []}
    for nm in names:
        scn = load_scenario(SCENARIO_DIR / f"{nm}.toml")
        chk = {"columns": [], "periods": []}
        for col in scn["columns"]:
            st = column_statics(col)
            chk["columns"].append({"name": col["name"], "numbers": {k: col[k] for k in (
                "EI", "L", "a", "b", "column_mass", "k_point", "N1", "N2", "moment_lower_per_N",
                "moment_upper_per_N", "k_sway", "point_mass", "m_eff")}, "opensees_statics": st})
        tos = opensees_periods(scn, 0)
        tnp = sorted((t for bi in range(len(scn["buildings"])) for t in numpy_periods(scn, bi)), reverse=True)
        chk["periods"] = {"opensees": tos, "numpy": tnp,
                          "max_rel_diff": max(abs(a / b - 1.0) for a, b in zip(tos, tnp))}
        chk["per_building_numpy"] = {b["name"]: numpy_periods(scn, bi) for bi, b in enumerate(scn["buildings"])}
        print(f"  check {nm}: statics {max(c['opensees_statics']['rel_diff'] for c in chk['columns']):.1e}, "
              f"periods {chk['periods']['max_rel_diff']:.1e}", file=sys.stderr, flush=True)
        results["checks"][nm] = chk
        for var in variants:
            key = f"{nm}/{var}"
            entry = {"scenario": str((SCENARIO_DIR / f"{nm}.toml").relative_to(REPO)), "variant": var,
                     "segments": args.segments if var != "point" else 1, "runs": []}
            for dt in dts[var]:
                r = run(scn, dt, var, args.segments)
                s = summarise(scn, r)
                entry["runs"].append(s)
                print(f"  {key} dt={dt:g} ({s['wall_s']:.1f} s, fallback {s['fallback_steps']}): "
                      + "; ".join(f"{b['name']} top {g(b['floors'][-1]['peak'])}" for b in s["buildings"]) + "; "
                      + "; ".join(f"{c['name']} {c.get('impacts')} F {g(c['point_force_from_displacements']['peak'])}"
                                  f" res {c['closed_form_residual']:.1e}" for c in s["sites"]),
                      file=sys.stderr, flush=True)
            entry["convergence"] = convergence(entry["runs"])
            results["scenarios"][key] = entry
            Path(args.out).write_text(base.to_json(results))
    print_tables(results)
    Path(args.out).write_text(base.to_json(results))
    print(f"\nwrote {args.out}")


if __name__ == "__main__":
    main()
