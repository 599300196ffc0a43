#!/usr/bin/env python3
"""OpenSees peer: buildings in plan (floors with x, y and rotation) pounding under two ground components.

What it does
------------
Reads the scenario files in bench/opensees/scenarios-plan/*.toml (the Rust tool's
format with `[building.plan]`, `[[building.line]]`, `[ground_motion.y]` and
contacts between façades), builds each one in OpenSeesPy and integrates it at
several constant time steps:

    model basic -ndm 2 -ndf 3 (dofs ux, uy, rz); u relative to the ground.
    Per building and floor: a master node at the floor's mass centre (site
      frame) with mass (m, m, J). Nothing else carries mass.
    Per line (along x at ordinate y_l, or along y at abscissa x_l) and floor:
      a massless node at (x_ref, y_l) (x_ref = the plan's middle) or (x_l,
      y_ref), tied to the floor's master by `rigidLink beam` (u_s = u_m - dy th,
      v_s = v_m + dx th, th_s = th_m: the small-rotation kinematics); the
      ground's copy is fixed. Storey s of the line: `zeroLength` from the
      line's node on floor s-1 (i; the ground for s = 1) to the one on floor s
      (j), `-mat <law> <dashpot> -dir d d` (d = 1 along x, 2 along y), so its
      deformation is the line's drift in that storey:
        linear   -> uniaxialMaterial Elastic k
        bilinear -> uniaxialMaterial Steel01 Fy k a        (a1..a4 defaults)
        bouc-wen -> uniaxialMaterial BoucWen a k n gamma/dy^n beta/dy^n 1 0 0 0 1e-12 50
      as bench/opensees/inelastic.py maps them.
    Damping C = a0 M + a1 K0 (Rayleigh, of each building), as explicit
      dashpots (uniaxialMaterial Viscous c 1.0): a1 k in parallel with every
      line storey (the dashpot above), and a `zeroLength` from a fixed node at
      each master to the master with c = a0 m along dirs 1, 2 and a0 J along
      dir 3 (the rotation). No `rayleigh` command, no region. a0, a1 give the
      damping ratio on two modes of the building's own 3n-dof model:
      `damping_modes` if given, else the two lowest whose largest effective
      mass ratio is along x (ratios: (sum m phi_x)^2 / sum m,
      (sum m phi_y)^2 / sum m, (sum J phi_th)^2 / sum J; "along x" = x ratio
      > 1e-9 and >= the other two; one such mode -> it twice; none -> 1, 2).
      The modes come from numpy (K assembled from the lines), and the same
      model built alone in OpenSees (`eigen -fullGenLapack`) is checked
      against them.
    [[contact]] between two buildings in plan: their façades that face each
      other from the plans' positions (apart along x with overlapping y
      extents -> normal +x; apart along y -> +y), gap = the clear distance
      rounded to 1e-12 m, points = `points` or both ends of the façades'
      overlap, on the "left" building's façade; floor pairs = `floors` or the
      floors at equal heights (1 mm). Per floor pair and point: a node on each
      floor at the point, tied to its master (rigidLink beam; the two nodes
      coincide: along the normal a point of the right building's floor moves
      by n.(u - r x th) with the same r_t), and a `zeroLength` from the left
      building's node (i) to the right one's (j) along the normal (dir 1 or
      2): strain = n.(u_R - u_L), closed when strain < -gap. Material from
      two_sdof.contact_material with m_eff = 1/(1/m_L' + 1/m_R'),
      m' = 1/(1/m + (r x n)^2/J) (r from each floor's own mass centre).
    Ground: record x along dir 1, record y along dir 2 (two Path series,
      linear between samples, ground at rest at t = 0 (a record whose first
      sample is at t = dt gets 0 prepended), 0 after its last sample, two
      UniformExcitation patterns). `constraints Transformation`, `numberer
      RCM`, `system BandGeneral`, `test NormDispIncr 1e-12 50`, Newton (with
      the fallbacks of two_sdof.analyze), Newmark average acceleration,
      constant dt, over [analysis] duration.

Reported per scenario and dt (JSON, default results-plan.json): per floor the
peak |ux|, |uy| of the mass centre and |theta| with times, and per corner (ccw
from (xmin, ymin)) the peak |ux - (y_c - yc) th|, |uy + (x_c - xc) th|, all over
every step (binary Node recorder of the masters in 1-s segments, 17 digits);
per line and storey peak |drift| and peak |spring force| (EnvelopeElement);
per contact element (floor pair and point) the impacts (open -> closed
transitions of strain < -gap on the step sequence; also of F != 0), the first
step inside of each, peak force, largest penetration. Then the changes between
successive dts, and checks (--checks): the modes of each building in OpenSees
against numpy; each linear scenario without contact at dt = 1e-4 against the
exact solution of M u'' + C u' + K u = -M (r_x a_x + r_y a_y) (matrix
exponential, grid 1e-4 s), which checks the damping, the lines' kinematics and
the two components together. Timing (--timing-repeats): build + analysis at
dt = 1e-4 without recorders, median.

    /tmp/opensees-venv/bin/python bench/opensees/plan.py --quick --out /tmp/q.json
    nice -n 10 /tmp/opensees-venv/bin/python bench/opensees/plan.py
    /tmp/opensees-venv/bin/python bench/opensees/plan.py --table bench/opensees/results-plan.json

Peer measurement only: OpenSeesPy and NumPy are never dependencies of the Rust
tool. Needs Python >= 3.11 (tomllib). See README.md, "Buildings in plan".
"""

from __future__ import annotations

import argparse
import datetime
import json
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
import two_sdof as base  # noqa: E402  (BLAS workaround, contact materials, analysis loop, JSON)
import inelastic as inel  # noqa: E402  (storey laws, envelopes)
import isolation as iso  # noqa: E402  (record files as the tool reads them)

ops = base.ops
REPO = base.REPO
SCENARIO_DIR = HERE / "scenarios-plan"
SCENARIOS = ["three-linear", "three-bilinear", "six-linear", "six-bouc-wen"]
DEFAULT_DTS = [1e-4, 5e-5, 2e-5, 1e-5]
PARTICIPATES = 1e-9
CHUNK_S = 1.0  # simulated seconds per recorder segment (bounds the per-step contact files)


# --------------------------------------------------------------------------
# Scenario
# --------------------------------------------------------------------------
def per_storey(value, n: int, what: str) -> list:
    if isinstance(value, list):
        if len(value) != n:
            raise SystemExit(f"{what}: {len(value)} entries for {n} storeys")
        return list(value)
    return [value] * n


def per_floor_pairs(value, n: int, default, what: str) -> list:
    """mass_centre: one [x, y] for all floors or a list of them."""
    if value is None:
        return [default] * n
    if len(value) == 2 and not isinstance(value[0], list):
        return [tuple(float(x) for x in value)] * n
    if len(value) != n:
        raise SystemExit(f"{what}: {len(value)} entries for {n} floors")
    return [tuple(float(x) for x in v) for v in value]


def load_scenario(path: Path) -> dict:
    with open(path, "rb") as f:
        raw = tomllib.load(f)
    return expand(raw, path)


def line_laws(ln: dict, n: int, what: str) -> list:
    models = per_storey(ln.get("storey_model", "linear"), n, f"{what}.storey_model")
    ks = per_storey(ln["stiffnesses"], n, f"{what}.stiffnesses")
    fy = per_storey(ln.get("yield_forces", None), n, f"{what}.yield_forces")
    ratio = per_storey(ln.get("post_yield_ratio", 0.0), n, f"{what}.post_yield_ratio")
    bw = {"n": 1.0, "beta": 0.5, "gamma": 0.5, **ln.get("bouc_wen", {})}
    laws = []
    for j in range(n):
        law = {"model": models[j], "k": float(ks[j])}
        if models[j] not in ("linear", "bilinear", "bouc-wen"):
            raise SystemExit(f"{what}: storey_model {models[j]!r} unknown")
        if models[j] != "linear":
            if fy[j] is None:
                raise SystemExit(f"{what}: {models[j]} storey without yield_forces")
            law.update(Fy=float(fy[j]), a=float(ratio[j]))
        if models[j] == "bouc-wen":
            law.update(n=float(bw["n"]), beta=float(bw["beta"]), gamma=float(bw["gamma"]))
        laws.append(law)
    return laws


def expand(raw: dict, path: Path) -> dict:
    for key in ("wall", "device"):
        if raw.get(key):
            raise SystemExit(f"{path}: [[{key}]] is not handled by this peer")
    gm = raw["ground_motion"]
    if float(gm.get("angle", 0.0)) != 0.0:
        raise SystemExit(f"{path}: ground_motion.angle is not handled by this peer")
    blds = []
    for b in raw["building"]:
        name, m = b["name"], [float(x) for x in b["masses"]]
        n = len(m)
        if "plan" not in b:
            raise SystemExit(f"{path}: building {name!r} has no [building.plan]")
        if "isolator" in b:
            raise SystemExit(f"{path}: building {name!r}: isolators are not handled by this peer")
        p = b["plan"]
        a_, b_ = (float(x) for x in p["size"])
        origin = tuple(float(x) for x in p.get("position", [0.0, 0.0]))
        centres = per_floor_pairs(p.get("mass_centre"), n, (a_ / 2.0, b_ / 2.0), f"{name}.plan.mass_centre")
        inertia = p.get("inertia")
        if inertia is None:
            J = [mi * (a_ * a_ + b_ * b_) / 12.0 for mi in m]
        else:
            J = [float(x) for x in per_storey(inertia, n, f"{name}.plan.inertia")]
        lines = []
        for li, ln in enumerate(b["line"]):
            lines.append({"direction": ln["direction"], "at": float(ln["at"]),
                          "laws": line_laws(ln, n, f"{name}.line.{li + 1}")})
        bd = {"name": name, "m": m, "J": J, "heights": [float(x) for x in b["heights"]],
              "z": np.cumsum([float(x) for x in b["heights"]]).tolist(),
              "zeta": float(b.get("damping_ratio", 0.05)), "size": (a_, b_), "origin": origin,
              "centres": centres, "lines": lines,
              "damping_modes_given": tuple(p["damping_modes"]) if "damping_modes" in p else None}
        bd["centres_site"] = [(origin[0] + cx, origin[1] + cy) for cx, cy in centres]
        bd.update(modal(bd))
        blds.append(bd)
    index = {b["name"]: i for i, b in enumerate(blds)}
    sites = []
    for c in raw.get("contact", []):
        if c["model"] in ("hertzdamp", "jankowski") and c.get("damping", "exact") != "formula":
            raise SystemExit(f"{path}: contact {c['between']}: OpenSees' {c['model']} material has the published "
                             "damping formula only: write damping = \"formula\"")
        if "gap" in c:
            raise SystemExit(f"{path}: contact {c['between']}: between buildings in plan the gap comes from the "
                             "positions")
        ia, ib = (index[x] for x in c["between"])
        f = facing(blds[ia], blds[ib])
        left, right = (ia, ib) if f["first_is_left"] else (ib, ia)
        L, R = blds[left], blds[right]
        if "floors" in c:
            pairs = [(int(x), int(y)) if ia == left else (int(y), int(x)) for x, y in c["floors"]]
        else:
            pairs = [(i + 1, j + 1) for i, z in enumerate(L["z"]) for j, w in enumerate(R["z"])
                     if abs(w - z) <= 1e-3]
            pairs = [p for k, p in enumerate(pairs) if p[0] not in [q[0] for q in pairs[:k]]]
        lo, hi = f["overlap"]
        along = [float(x) for x in c["points"]] if "points" in c else [lo, hi]
        along = [min(max(x, lo), hi) for x in along]
        levels = []
        for fl, fr in pairs:
            for t in along:
                pt = (f["plane"], t) if f["normal"][0] else (t, f["plane"])
                ml = point_mass(L, fl, pt, f["normal"])
                mr = point_mass(R, fr, pt, f["normal"])
                levels.append({"floors": [fl, fr], "point": pt, "along": t,
                               "m_left": ml, "m_right": mr, "m_eff": ml * mr / (ml + mr)})
        sites.append({"name": f"{L['name']}|{R['name']}", "left": left, "right": right, "raw": c,
                      "normal": f["normal"], "gap": f["gap"], "overlap": f["overlap"], "levels": levels})
    gx = iso.load_record(gm, path)
    gy = iso.load_record(gm["y"], path) if "y" in gm else None
    duration = float(raw.get("analysis", {}).get("duration", gx[3]))
    return {"path": path, "raw": raw, "buildings": blds, "sites": sites, "gm": gx, "gm_y": gy,
            "duration": duration}


def facing(A: dict, B: dict) -> dict:
    """How plans A and B face each other (the tool's rule, analysis/facades.rs)."""
    def extent(P, axis):
        return (P["origin"][axis], P["origin"][axis] + P["size"][axis])

    def along(axis):
        (a0, a1), (b0, b1) = extent(A, axis), extent(B, axis)
        gap = round(max(b0 - a1, a0 - b1) * 1e12) / 1e12
        return gap, min(a1, b1) - max(a0, b0), a1 <= b0, (max(a0, b0), min(a1, b1))

    gx, ox, ax_first, rx = along(0)
    gy, oy, ay_first, ry = along(1)
    scale = max(*A["size"], *B["size"])
    shared = 1e-9 * scale

    def on(axis, gap, first, overlap):
        left = A if first else B
        return {"first_is_left": first, "normal": (1.0, 0.0) if axis == 0 else (0.0, 1.0), "gap": gap,
                "plane": extent(left, axis)[1], "overlap": overlap}

    if gx >= 0.0 and oy > shared:
        return on(0, gx, ax_first, ry)
    if gy >= 0.0 and ox > shared:
        return on(1, gy, ay_first, rx)
    raise SystemExit(f"plans {A['name']!r} and {B['name']!r} do not face each other")


def point_mass(b: dict, floor: int, p, n) -> float:
    cx, cy = b["centres_site"][floor - 1]
    arm = (p[0] - cx) * n[1] - (p[1] - cy) * n[0]
    m, J = b["m"][floor - 1], b["J"][floor - 1]
    return 1.0 / (1.0 / m + arm * arm / J)


# --------------------------------------------------------------------------
# Linear matrices, modes, Rayleigh
# --------------------------------------------------------------------------
def line_vector(b: dict, li: int, floor: int) -> np.ndarray:
    """Coefficients over the building's dofs (x block, y block, theta block) of the
    displacement along the line of line li's point on floor `floor` (>= 1)."""
    n = len(b["m"])
    ln = b["lines"][li]
    g = np.zeros(3 * n)
    cx, cy = b["centres"][floor - 1]
    if ln["direction"] == "x":
        g[floor - 1] = 1.0
        g[2 * n + floor - 1] = -(ln["at"] - cy)
    else:
        g[n + floor - 1] = 1.0
        g[2 * n + floor - 1] = ln["at"] - cx
    return g


def matrices(b: dict) -> tuple[np.ndarray, np.ndarray]:
    n = len(b["m"])
    K = np.zeros((3 * n, 3 * n))
    for li, ln in enumerate(b["lines"]):
        for s, law in enumerate(ln["laws"], start=1):
            g = line_vector(b, li, s) - (line_vector(b, li, s - 1) if s > 1 else 0.0)
            K += law["k"] * np.outer(g, g)
    M = np.diag(b["m"] + b["m"] + b["J"])
    return M, K


def modal(b: dict) -> dict:
    M, K = matrices(b)
    n = len(b["m"])
    s = 1.0 / np.sqrt(np.diag(M))
    lam, V = np.linalg.eigh(K * np.outer(s, s))
    order = np.argsort(lam)
    lam, V = lam[order], V[:, order]
    Phi = V * s[:, None]                     # mass-normalised shapes
    m, J = np.array(b["m"]), np.array(b["J"])
    part = []
    for r in range(3 * n):
        ph = Phi[:, r]
        gx, gy, gt = m @ ph[:n], m @ ph[n:2 * n], J @ ph[2 * n:]
        part.append((gx * gx / m.sum(), gy * gy / m.sum(), gt * gt / J.sum()))
    w = np.sqrt(np.maximum(lam, 0.0))
    if b["damping_modes_given"]:
        modes = tuple(int(x) for x in b["damping_modes_given"])
    else:
        along_x = [r + 1 for r, p in enumerate(part) if p[0] > PARTICIPATES and p[0] >= p[1] and p[0] >= p[2]][:2]
        modes = (along_x[0], along_x[1]) if len(along_x) == 2 else (
            (along_x[0], along_x[0]) if along_x else (1, 2))
    w1, w2 = w[modes[0] - 1], w[modes[1] - 1]
    z = b["zeta"]
    if w1 == w2:
        a0, a1 = z * w1, z / w1
    else:
        a0, a1 = 2 * z * w1 * w2 / (w1 + w2), 2 * z / (w1 + w2)
    C = a0 * M + a1 * K
    zetas = [float(Phi[:, r] @ C @ Phi[:, r] / (2 * w[r])) for r in range(3 * n)]
    return {"periods": [float(2 * math.pi / x) for x in w], "participation": [list(map(float, p)) for p in part],
            "modal_damping": zetas, "damping_modes": list(modes), "a0": float(a0), "a1": float(a1)}


# --------------------------------------------------------------------------
# OpenSees model
# --------------------------------------------------------------------------
def B(bi: int) -> int:
    return 100000 * (bi + 1)


def master(bi, f):          # node: floor f's mass centre
    return B(bi) + 1000 * f


def line_node(bi, f, li):   # node: line li on floor f (f = 0: ground, fixed)
    return B(bi) + 1000 * f + 10 + li


def damp_ground(bi, f):     # node: fixed, under the master, for the a0 M dashpots
    return B(bi) + 1000 * f + 900


def point_node(bi, f, si, k):  # node: contact level k of site si on floor f
    return B(bi) + 1000 * f + 600 + 50 * si + k


def line_ele(bi, s, li):    # element and spring material: storey s of line li
    return B(bi) + 1000 * s + 10 + li


def line_dashpot(bi, s, li):  # material: a1 k dashpot of storey s of line li
    return B(bi) + 1000 * s + 300 + li


def mass_ele(bi, f):        # element: a0 M dashpot of floor f; materials +0 (a0 m) and +1 (a0 J)
    return B(bi) + 1000 * f + 900


def contact_ele(si, k):     # element and material
    return 9000000 + 1000 * si + k


def build_building(bi: int, b: dict, log, eigen_only: bool = False) -> None:
    n = len(b["m"])
    (x0, y0), (a_, b_) = b["origin"], b["size"]
    xmid, ymid = x0 + a_ / 2.0, y0 + b_ / 2.0
    for f in range(1, n + 1):
        cx, cy = b["centres_site"][f - 1]
        log("node", master(bi, f), cx, cy)
        log("mass", master(bi, f), b["m"][f - 1], b["m"][f - 1], b["J"][f - 1])
        if not eigen_only:
            log("node", damp_ground(bi, f), cx, cy)
            log("fix", damp_ground(bi, f), 1, 1, 1)
            t = mass_ele(bi, f)
            log("uniaxialMaterial", "Viscous", t, b["a0"] * b["m"][f - 1], 1.0)
            log("uniaxialMaterial", "Viscous", t + 1, b["a0"] * b["J"][f - 1], 1.0)
            log("element", "zeroLength", t, damp_ground(bi, f), master(bi, f), "-mat", t, t, t + 1,
                "-dir", 1, 2, 3)
    for li, ln in enumerate(b["lines"]):
        pt = (xmid, y0 + ln["at"]) if ln["direction"] == "x" else (x0 + ln["at"], ymid)
        d = 1 if ln["direction"] == "x" else 2
        log("node", line_node(bi, 0, li), *pt)
        log("fix", line_node(bi, 0, li), 1, 1, 1)
        for f in range(1, n + 1):
            log("node", line_node(bi, f, li), *pt)
            log("rigidLink", "beam", master(bi, f), line_node(bi, f, li))
        for s, law in enumerate(ln["laws"], start=1):
            t = line_ele(bi, s, li)
            name, args = inel.storey_material(t, law)
            log("uniaxialMaterial", name, t, *args)
            if eigen_only:
                log("element", "zeroLength", t, line_node(bi, s - 1, li), line_node(bi, s, li), "-mat", t,
                    "-dir", d)
            else:
                c = line_dashpot(bi, s, li)
                log("uniaxialMaterial", "Viscous", c, b["a1"] * law["k"], 1.0)
                log("element", "zeroLength", t, line_node(bi, s - 1, li), line_node(bi, s, li),
                    "-mat", t, c, "-dir", d, d)


def build(scn: dict, contact: bool = True) -> dict:
    """Build the model (domain wiped first); returns the commands issued (except the
    records' values)."""
    cmds = []

    def log(name, *args):
        getattr(ops, name)(*args)
        cmds.append([name, *args])

    ops.wipe()
    log("model", "basic", "-ndm", 2, "-ndf", 3)
    for bi, b in enumerate(scn["buildings"]):
        build_building(bi, b, log)
    contact_info = []
    if contact:
        for si, st in enumerate(scn["sites"]):
            d = 1 if st["normal"][0] else 2
            for k, lv in enumerate(st["levels"]):
                fl, fr = lv["floors"]
                ni, nj = point_node(st["left"], fl, si, k), point_node(st["right"], fr, si, k)
                for bi, f, nd in ((st["left"], fl, ni), (st["right"], fr, nj)):
                    log("node", nd, *lv["point"])
                    log("rigidLink", "beam", master(bi, f), nd)
                name, args, notes = base.contact_material(st["raw"], lv["m_eff"], gap_override=st["gap"])
                t = contact_ele(si, k)
                log("uniaxialMaterial", name, t, *args)
                log("element", "zeroLength", t, ni, nj, "-mat", t, "-dir", d)
                contact_info.append({"site": st["name"], "floors": lv["floors"], "point": lv["point"],
                                     "m_eff": lv["m_eff"], "material": [name, t, *args]})
    for tag, gm, d in ((1, scn["gm"], 1), (2, scn["gm_y"], 2)):
        if gm is None:
            continue
        gdt, values, factor = gm[0], gm[1], gm[2]
        ops.timeSeries("Path", tag, "-dt", gdt, "-values", *values, "-factor", factor)
        cmds.append(["timeSeries", "Path", tag, "-dt", gdt, "-values", f"<{len(values)} values>", "-factor", factor])
        log("pattern", "UniformExcitation", tag, d, "-accel", tag)
    log("constraints", "Transformation")
    log("numberer", "RCM")
    log("system", "BandGeneral")
    log("test", "NormDispIncr", base.TOL, base.MAX_ITER)
    log("algorithm", "Newton")
    log("integrator", "Newmark", 0.5, 0.25)
    log("analysis", "Transient")
    return {"commands": cmds, "contacts": contact_info}


def opensees_modes(b: dict) -> list[float]:
    """Periods of building b built alone in OpenSees (masters, line springs, rigid links)."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    build_building(0, b, lambda name, *a: getattr(ops, name)(*a), eigen_only=True)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("FullGeneral")
    lam = ops.eigen("-fullGenLapack", 3 * len(b["m"]))
    ops.wipe()
    return sorted(2 * math.pi / math.sqrt(x) for x in lam)[::-1]


# --------------------------------------------------------------------------
# Runs
# --------------------------------------------------------------------------
def tags(scn: dict) -> dict:
    masters, lines = [], []
    for bi, b in enumerate(scn["buildings"]):
        n = len(b["m"])
        masters += [master(bi, f) for f in range(1, n + 1)]
        lines += [line_ele(bi, s, li) for li in range(len(b["lines"])) for s in range(1, n + 1)]
    contacts = [contact_ele(si, k) for si, st in enumerate(scn["sites"]) for k in range(len(st["levels"]))]
    return {"masters": masters, "lines": lines, "contacts": contacts}


def corner_map(scn: dict) -> np.ndarray:
    """T such that (per-step master disps, 3 columns per master: ux, uy, th) @ T = the corners'
    displacements, 8 columns per floor: corner 1 x, corner 1 y, ..., corner 4 y (ccw from (xmin, ymin)):
    x = ux - (py - yc) th, y = uy + (px - xc) th."""
    nm = sum(len(b["m"]) for b in scn["buildings"])
    T = np.zeros((3 * nm, 8 * nm))
    col = 0
    for b in scn["buildings"]:
        (x0, y0), (a_, b_) = b["origin"], b["size"]
        for f in range(len(b["m"])):
            cx, cy = b["centres_site"][f]
            for k, (px, py) in enumerate([(x0, y0), (x0 + a_, y0), (x0 + a_, y0 + b_), (x0, y0 + b_)]):
                T[3 * col, 8 * col + 2 * k] = 1.0
                T[3 * col + 2, 8 * col + 2 * k] = -(py - cy)
                T[3 * col + 1, 8 * col + 2 * k + 1] = 1.0
                T[3 * col + 2, 8 * col + 2 * k + 1] = px - cx
            col += 1
    return T


class Peaks:
    """Running peak |x| per column over per-step chunks, with the time of the peak."""

    def __init__(self, ncol: int):
        self.peak = np.zeros(ncol)
        self.t = np.zeros(ncol)
        self.val = np.zeros(ncol)

    def update(self, t: np.ndarray, x: np.ndarray) -> None:
        i = np.argmax(np.abs(x), axis=0)
        v = x[i, np.arange(x.shape[1])]
        better = np.abs(v) > self.peak
        self.peak[better] = np.abs(v[better])
        self.t[better] = t[i[better]]
        self.val[better] = v[better]


def run(scn: dict, dt: float, record: bool = True, contact: bool = True) -> dict:
    nsteps = int(round(scn["duration"] / dt))
    if abs(nsteps * dt - scn["duration"]) > 1e-9:
        raise SystemExit(f"dt = {dt} does not divide the duration")
    if not record:
        t0, c0 = time.perf_counter(), time.process_time()
        info = build(scn, contact)
        fallback = base.analyze(nsteps, dt)
        ops.wipe()
        return {"dt": dt, "steps": nsteps, "wall_s": time.perf_counter() - t0,
                "cpu_s": time.process_time() - c0, "fallback_steps": fallback, "info": info}
    tg = tags(scn)
    ctags = tg["contacts"] if contact else []
    T = corner_map(scn)
    pm, pc = Peaks(T.shape[0]), Peaks(T.shape[1])
    per_chunk = int(round(CHUNK_S / dt))
    ends = list(range(per_chunk, nsteps, per_chunk)) + [nsteps]
    with tempfile.TemporaryDirectory(prefix="opensees-plan-") as tmp:
        tmp = Path(tmp)
        t0, c0 = time.perf_counter(), time.process_time()
        info = build(scn, contact)
        fallback, segs, cd, cs = 0, [], [], []
        for s, n_end in enumerate(ends):
            ops.recorder("Node", "-binary", str(tmp / f"m{s}.bin"), "-time", "-node", *tg["masters"],
                         "-dof", 1, 2, 3, "disp")
            ops.recorder("EnvelopeElement", "-file", str(tmp / f"d{s}.txt"), "-precision", 17, "-time",
                         "-ele", *tg["lines"], "deformation")
            ops.recorder("EnvelopeElement", "-file", str(tmp / f"f{s}.txt"), "-precision", 17, "-time",
                         "-ele", *tg["lines"], "material", "1", "stress")
            if ctags:
                ops.recorder("Element", "-binary", str(tmp / f"cd{s}.bin"), "-ele", *ctags, "deformation")
                ops.recorder("Element", "-binary", str(tmp / f"cs{s}.bin"), "-ele", *ctags,
                             "material", "1", "stress")
            fallback += base.analyze(n_end, dt)
            ops.remove("recorders")
            seg = {k: inel.read_envelope(tmp / f"{k}{s}.txt") for k in ("d", "f")}
            segs.append(seg)
            nrows = n_end - (ends[s - 1] if s else 0)
            md = base.read_binary_recorder(tmp / f"m{s}.bin", 1 + T.shape[0]).astype(np.float64)
            (tmp / f"m{s}.bin").unlink()
            if len(md) != nrows:
                raise RuntimeError("node recorder length does not match the step count")
            tt = np.round(md[:, 0], 9)
            pm.update(tt, md[:, 1:])
            pc.update(tt, md[:, 1:] @ T)
            if ctags:
                a = base.read_binary_recorder(tmp / f"cd{s}.bin", len(ctags))
                b_ = base.read_binary_recorder(tmp / f"cs{s}.bin", len(ctags))
                if not len(a) == len(b_) == nrows:
                    raise RuntimeError("contact recorder length does not match the step count")
                cd.append(a.astype(np.float64))
                cs.append(b_.astype(np.float64))
                (tmp / f"cd{s}.bin").unlink()
                (tmp / f"cs{s}.bin").unlink()
        end_state = {"t": ops.getTime(),
                     "masters": [[ops.nodeDisp(t, d) for d in (1, 2, 3)] for t in tg["masters"]]}
        ops.wipe()
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    return {"dt": dt, "steps": nsteps, "wall_s": wall, "cpu_s": cpu, "fallback_steps": fallback,
            "info": info, "segs": segs, "end": end_state, "tags": tg, "pm": pm, "pc": pc,
            "cd": np.concatenate(cd) if ctags else None, "cs": np.concatenate(cs) if ctags else None}


def combine(segs: list, key: str, col: int) -> dict:
    best = None
    for seg in segs:
        e = seg[key]
        a = e["abs"][col]
        if best is None or a > best[0]:
            val = e["max"][col] if e["max"][col] >= -e["min"][col] else e["min"][col]
            best = (float(a), float(round(e["tabs"][col], 9)), float(val))
    return {"peak": best[0], "t": best[1], "at_peak": best[2]}


def summarise(scn: dict, res: dict) -> dict:
    segs, dt = res["segs"], res["dt"]
    out = {"dt": dt, "steps": res["steps"], "wall_s": res["wall_s"], "cpu_s": res["cpu_s"],
           "fallback_steps": res["fallback_steps"], "buildings": [], "contacts": []}
    mcol = lcol = 0
    for bi, b in enumerate(scn["buildings"]):
        n = len(b["m"])
        floors = []
        for f in range(n):
            row = {"floor": f + 1}
            pm, pc = res["pm"], res["pc"]
            for d, key in enumerate(("x", "y", "rotation")):
                c = 3 * (mcol + f) + d
                row[f"peak_{key}"], row[f"t_peak_{key}"], row[f"{key}_at_peak"] = \
                    float(pm.peak[c]), float(pm.t[c]), float(pm.val[c])
            row["end"] = res["end"]["masters"][mcol + f]
            corners = []
            for k in range(4):
                c = 8 * (mcol + f) + 2 * k
                corners.append({"peak_x": float(pc.peak[c]), "t_peak_x": float(pc.t[c]),
                                "peak_y": float(pc.peak[c + 1]), "t_peak_y": float(pc.t[c + 1])})
            row["corners"] = corners
            floors.append(row)
        lines = []
        for li, ln in enumerate(b["lines"]):
            st = []
            for s in range(n):
                e = lcol + li * n + s
                d = combine(segs, "d", 2 * e)       # two materials: spring, dashpot -> 2 deformations
                F = combine(segs, "f", e)
                row = {"storey": s + 1, "peak_drift": d["peak"], "t_peak_drift": d["t"],
                       "peak_force": F["peak"], "t_peak_force": F["t"]}
                law = ln["laws"][s]
                if "Fy" in law:
                    row.update(ductility=d["peak"] / (law["Fy"] / law["k"]), peak_force_over_Fy=F["peak"] / law["Fy"])
                st.append(row)
            lines.append({"direction": ln["direction"], "at": ln["at"], "storeys": st})
        out["buildings"].append({"name": b["name"], "floors": floors, "lines": lines})
        mcol += n
        lcol += len(b["lines"]) * n
    if res["cd"] is not None:
        k = 0
        for si, st in enumerate(scn["sites"]):
            for lv in st["levels"]:
                strain = res["cd"][:, k]
                closed = strain < -st["gap"]
                F = 0.0 - res["cs"][:, k]
                first = inel.rising_edges(closed)
                ipk = int(np.argmax(F)) if F.max() > 0.0 else None
                out["contacts"].append({
                    "site": st["name"], "floors": lv["floors"], "point": list(lv["point"]), "m_eff": lv["m_eff"],
                    "impacts": int(len(first)), "impacts_force": int(len(inel.rising_edges(F != 0.0))),
                    "first_steps_inside_s": [float(round((i + 1) * dt, 9)) for i in first],
                    "peak_force": float(F.max()),
                    "t_peak_force": float(round((ipk + 1) * dt, 9)) if ipk is not None else None,
                    "min_force": float(F.min()),
                    "max_penetration": float(max(0.0, -(strain.min() + st["gap"]))),
                    "steps_in_contact": int(closed.sum())})
                k += 1
    return out


# --------------------------------------------------------------------------
# Exact linear solution without contact
# --------------------------------------------------------------------------
def on_grid(gm, h: float, T: float) -> np.ndarray:
    """Samples (m/s^2) of a record on the grid 0, h, ..., T (linear between its samples, 0 after)."""
    if gm is None:
        return np.zeros(int(round(T / h)) + 1)
    gdt, values, factor = gm[0], gm[1], gm[2]
    t = np.arange(int(round(T / h)) + 1) * h
    tv = np.arange(len(values)) * gdt
    a = np.interp(t, tv, np.array(values) * factor, right=0.0)
    return a


def exact_linear(b: dict, scn: dict, h: float = 1e-4) -> dict:
    """Peaks of |ux|, |uy|, |theta| per floor (and corners) of building b alone, linear, without contact:
    exact propagation of [u, u', ax, ax', ay, ay'] over the grid h (records linear between grid points:
    exact when h divides the records' steps)."""
    for g in (scn["gm"], scn["gm_y"]):
        if g is not None and abs(g[0] / h - round(g[0] / h)) > 1e-9:
            raise SystemExit("h must divide the records' steps")
    M, K = matrices(b)
    C = b["a0"] * M + b["a1"] * K
    d = len(M)
    n = len(b["m"])
    rx, ry = np.zeros(d), np.zeros(d)
    rx[:n], ry[n:2 * n] = 1.0, 1.0
    A = np.zeros((2 * d + 4, 2 * d + 4))
    Minv = np.linalg.inv(M)
    A[:d, d:2 * d] = np.eye(d)
    A[d:2 * d, :d] = -Minv @ K
    A[d:2 * d, d:2 * d] = -Minv @ C
    A[d:2 * d, 2 * d] = -rx
    A[d:2 * d, 2 * d + 2] = -ry
    A[2 * d, 2 * d + 1] = 1.0
    A[2 * d + 2, 2 * d + 3] = 1.0
    P = base.expm(A * h)
    T = scn["duration"]
    ax, ay = on_grid(scn["gm"], h, T), on_grid(scn["gm_y"], h, T)
    N = len(ax) - 1
    U = np.zeros((N + 1, d))
    z = np.zeros(2 * d + 4)
    for j in range(N):
        z[2 * d], z[2 * d + 1] = ax[j], (ax[j + 1] - ax[j]) / h
        z[2 * d + 2], z[2 * d + 3] = ay[j], (ay[j + 1] - ay[j]) / h
        z = P @ z
        U[j + 1] = z[:d]
    out = {"h": h, "floors": []}
    (x0, y0), (a_, b_) = b["origin"], b["size"]
    corners = [(x0, y0), (x0 + a_, y0), (x0 + a_, y0 + b_), (x0, y0 + b_)]
    for f in range(n):
        ux, uy, th = U[:, f], U[:, n + f], U[:, 2 * n + f]
        cx, cy = b["centres_site"][f]
        row = {"peak_x": float(np.abs(ux).max()), "peak_y": float(np.abs(uy).max()),
               "peak_rotation": float(np.abs(th).max()),
               "t_peak_x": float(np.argmax(np.abs(ux)) * h), "corners": []}
        for px, py in corners:
            row["corners"].append({"peak_x": float(np.abs(ux - (py - cy) * th).max()),
                                   "peak_y": float(np.abs(uy + (px - cx) * th).max())})
        out["floors"].append(row)
    return out


def rel(a: float, b: float) -> float:
    return abs(a - b) / abs(b) if b else abs(a - b)


def check_vs_exact(scn: dict, dt: float) -> dict:
    s = summarise(scn, run(scn, dt, contact=False))
    out = {"dt": dt, "buildings": [], "max_rel_diff": 0.0}
    for b, sb in zip(scn["buildings"], s["buildings"]):
        ex = exact_linear(b, scn)
        worst = 0.0
        for fe, fo in zip(ex["floors"], sb["floors"]):
            worst = max(worst, rel(fo["peak_x"], fe["peak_x"]), rel(fo["peak_y"], fe["peak_y"]),
                        rel(fo["peak_rotation"], fe["peak_rotation"]))
            for ce, co in zip(fe["corners"], fo["corners"]):
                worst = max(worst, rel(co["peak_x"], ce["peak_x"]), rel(co["peak_y"], ce["peak_y"]))
        out["buildings"].append({"name": b["name"], "exact": ex, "opensees_no_contact": sb["floors"],
                                 "max_rel_diff": worst})
        out["max_rel_diff"] = max(out["max_rel_diff"], worst)
    return out


# --------------------------------------------------------------------------
# Convergence, tables
# --------------------------------------------------------------------------
def quantities(s: dict) -> dict:
    """Every compared quantity of a run summary, by a flat name."""
    q = {}
    for b in s["buildings"]:
        for f in b["floors"]:
            for k in ("x", "y", "rotation"):
                q[f"{b['name']}.floor{f['floor']}.{k}"] = f[f"peak_{k}"]
            for c, cc in enumerate(f["corners"]):
                q[f"{b['name']}.floor{f['floor']}.corner{c + 1}.x"] = cc["peak_x"]
                q[f"{b['name']}.floor{f['floor']}.corner{c + 1}.y"] = cc["peak_y"]
        for li, ln in enumerate(b["lines"]):
            for st in ln["storeys"]:
                q[f"{b['name']}.line{li + 1}.storey{st['storey']}.drift"] = st["peak_drift"]
    for c in s["contacts"]:
        q[f"{c['site']}.floors{c['floors'][0]}-{c['floors'][1]}.at{c['point']}.impacts"] = c["impacts"]
    return q


def convergence(runs: list) -> list:
    out = []
    for a, b in zip(runs, runs[1:]):
        qa, qb = quantities(a), quantities(b)
        groups = {}
        for k, v in qb.items():
            if k.endswith(".impacts"):
                continue
            grp = k.rsplit(".", 1)[-1] if ".corner" not in k else "corner"
            if ".line" in k:
                grp = "drift"
            groups[grp] = max(groups.get(grp, 0.0), rel(qa[k], v))
        imp_a = {k: v for k, v in qa.items() if k.endswith(".impacts")}
        imp_b = {k: v for k, v in qb.items() if k.endswith(".impacts")}
        out.append({"dt_a": a["dt"], "dt_b": b["dt"], "max_rel": groups,
                    "impacts_equal": imp_a == imp_b,
                    "impacts_a": sum(imp_a.values()), "impacts_b": sum(imp_b.values())})
    return out


def g(x, d: int = 6) -> str:
    return "-" if x is None else f"{x:.{d}g}"


def print_tables(res: dict) -> None:
    for name, entry in res["scenarios"].items():
        runs = entry["runs"]
        print(f"\n**{name}**: peak |u_x|, |u_y| (m), |theta| (rad) of each floor's mass centre at each dt; "
              f"impacts per contact element\n")
        head = ["dt (s)"]
        for b in runs[0]["buildings"]:
            head += [f"{b['name']}{f['floor']} x/y/rot" for f in b["floors"]]
        head += ["impacts", "CPU (s)"]
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for r in runs:
            row = [f"{r['dt']:g}"]
            for b in r["buildings"]:
                row += [f"{g(f['peak_x'], 7)} / {g(f['peak_y'], 7)} / {g(f['peak_rotation'], 6)}" for f in b["floors"]]
            row += ["/".join(str(c["impacts"]) for c in r["contacts"]), f"{r['cpu_s']:.1f}"]
            print("| " + " | ".join(row) + " |")
        conv = entry.get("convergence", [])
        if conv:
            keys = ["x", "y", "rotation", "corner", "drift"]
            print(f"\n{name}: largest relative change between successive dts\n")
            print("| dts | " + " | ".join(keys) + " | impacts equal |")
            print("|---|" + "---|" * (len(keys) + 1))
            for c in conv:
                print(f"| {c['dt_a']:g} -> {c['dt_b']:g} | " + " | ".join(g(c["max_rel"].get(k), 2) for k in keys)
                      + f" | {'yes' if c['impacts_equal'] else 'no: ' + str(c['impacts_a']) + ' vs ' + str(c['impacts_b'])} |")
    if res.get("checks"):
        print("\nchecks:")
        for k, v in res["checks"].items():
            if "max_rel_diff" in v:
                print(f"- {k}: max rel diff {v['max_rel_diff']:.2e}")


def short(s: dict) -> str:
    parts = []
    for b in s["buildings"]:
        top = b["floors"][-1]
        parts.append(f"{b['name']} top x {g(top['peak_x'])} y {g(top['peak_y'])} rot {g(top['peak_rotation'])}")
    if s["contacts"]:
        parts.append("impacts " + "/".join(str(c["impacts"]) for c in s["contacts"]))
    return "; ".join(parts)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scenarios", default=",".join(SCENARIOS), help="comma-separated names (scenarios-plan/NAME.toml)")
    ap.add_argument("--dts", default=",".join(f"{d:g}" for d in DEFAULT_DTS),
                    help="time steps, s (NAME:dt1,dt2;NAME2:... for per-scenario lists)")
    ap.add_argument("--timing-repeats", type=int, default=3, help="runs without recorders at dt = 1e-4 (median) of "
                                                                  "--timing-scenario; 0 skips")
    ap.add_argument("--timing-scenario", default="three-linear")
    ap.add_argument("--checks", action=argparse.BooleanOptionalAction, default=True,
                    help="OpenSees modes vs numpy; linear scenarios without contact vs the exact solution")
    ap.add_argument("--max-run-seconds", type=float, default=600.0,
                    help="skip a smaller dt when the run predicted from the last one would exceed this")
    ap.add_argument("--quick", action="store_true", help="smoke run: first scenario, dt = 1e-3, 1 timing run")
    ap.add_argument("--out", default=str(HERE / "results-plan.json"))
    ap.add_argument("--table", metavar="JSON", help="print the markdown tables of a results file, run nothing")
    ap.add_argument("--merge", metavar="JSON,JSON,...",
                    help="merge result files of separate runs (scenarios, checks, timing, notes) into --out, run nothing")
    args = ap.parse_args()
    if args.merge:
        parts = [json.loads(Path(x).read_text()) for x in args.merge.split(",")]
        out = parts[0]
        out["merged_from"] = [{"command": p_["command"], "generated": p_["generated"]} for p_ in parts]
        for p_ in parts[1:]:
            for key in ("scenarios", "checks", "timing"):
                out[key].update(p_[key])
            out["notes"] += p_["notes"]
        Path(args.out).write_text(base.to_json(out))
        print(f"wrote {args.out}")
        return
    if args.table:
        print_tables(json.loads(Path(args.table).read_text()))
        return
    names = [x.strip() for x in args.scenarios.split(",") if x.strip()]
    if ":" in args.dts:
        per = {}
        for part in args.dts.split(";"):
            k, v = part.split(":")
            per[k.strip()] = [float(x) for x in v.split(",")]
        dts_of = lambda nm: per.get(nm, DEFAULT_DTS)  # noqa: E731
    else:
        dl = [float(x) for x in args.dts.split(",")]
        dts_of = lambda nm: dl  # noqa: E731
    repeats, aux_dt = args.timing_repeats, 1e-4
    if args.quick:
        names, repeats, aux_dt = names[:1], min(repeats, 1), 1e-3
        dts_of = lambda nm: [1e-3]  # noqa: E731

    ops.logFile(os.devnull, "-noEcho")
    results = {
        "about": "OpenSeesPy peer of buildings in plan (x, y, rotation per floor) pounding under two ground "
                 "components; see bench/opensees/README.md, section 'Buildings in plan (plan.py)'",
        "generated": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "command": " ".join([Path(sys.argv[0]).name] + sys.argv[1:]),
        "environment": {"openseespy": base._version("openseespy"), "opensees": ops.version(),
                        "numpy": np.__version__, "python": platform.python_version(),
                        "platform": platform.platform(), "cpu": base._cpu_model(), "cpus": os.cpu_count()},
        "analysis": {"integrator": "Newmark gamma=0.5 beta=0.25", "algorithm": "Newton",
                     "test": "NormDispIncr 1e-12, max 50 iterations (fallbacks as two_sdof.py)",
                     "system": "BandGeneral", "numberer": "RCM", "constraints": "Transformation",
                     "peaks": "max |x| over every step (EnvelopeNode/EnvelopeElement, 17 digits)",
                     "impacts": "per contact element (floor pair and point): open -> closed transitions of "
                                "strain < -gap on the step sequence; impacts_force: of F != 0",
                     "contact force": "F = -stress (> 0 compressive)"},
        "scenarios": {}, "checks": {}, "timing": {}, "notes": [],
    }
    scns = {nm: load_scenario(SCENARIO_DIR / f"{nm}.toml") for nm in names}
    for nm, scn in scns.items():
        entry = {"scenario": str((SCENARIO_DIR / f"{nm}.toml").relative_to(REPO)), "duration": scn["duration"],
                 "inelastic": sorted({law["model"] for b in scn["buildings"] for ln in b["lines"] for law in ln["laws"]}
                                     - {"linear"}),
                 "records": {k: {"file": gm[4], "dt": gm[0], "samples_from_t0": len(gm[1]),
                                 "pga_m_s2": max(abs(x) for x in gm[1]) * gm[2]}
                             for k, gm in (("x", scn["gm"]), ("y", scn["gm_y"])) if gm is not None},
                 "buildings": [{"name": b["name"], "periods": b["periods"], "participation_x_y_rotation": b["participation"],
                                "modal_damping": b["modal_damping"], "damping_modes": b["damping_modes"],
                                "a0": b["a0"], "a1": b["a1"], "inertias": b["J"], "centres_site": b["centres_site"]}
                               for b in scn["buildings"]],
                 "sites": [{"name": st["name"], "normal": st["normal"], "gap": st["gap"], "overlap": st["overlap"],
                            "levels": st["levels"]} for st in scn["sites"]],
                 "runs": []}
        last = None
        for dt in dts_of(nm):
            if last is not None:
                predicted = last["wall_s"] * last["dt"] / dt
                if predicted > args.max_run_seconds:
                    note = f"{nm}: dt = {dt:g} skipped (predicted {predicted:.0f} s > {args.max_run_seconds:g} s)"
                    results["notes"].append(note)
                    print(note, file=sys.stderr)
                    continue
            res = run(scn, dt)
            entry.setdefault("opensees_commands", res["info"]["commands"])
            s = summarise(scn, res)
            entry["runs"].append(s)
            last = s
            print(f"  {nm} dt={dt:g} ({s['wall_s']:.1f} s, fallback steps {s['fallback_steps']}): {short(s)}",
                  file=sys.stderr, flush=True)
        entry["convergence"] = convergence(entry["runs"])
        results["scenarios"][nm] = entry
        if args.checks:
            chk = {"periods_opensees_vs_numpy": []}
            worst = 0.0
            for b in scn["buildings"]:
                tos = opensees_modes(b)
                d = max(rel(x, y) for x, y in zip(tos, b["periods"]))
                worst = max(worst, d)
                chk["periods_opensees_vs_numpy"].append({"name": b["name"], "opensees": tos, "max_rel_diff": d})
            chk["periods_max_rel_diff"] = worst
            print(f"  check {nm}: OpenSees periods vs numpy {worst:.1e}", file=sys.stderr, flush=True)
            if not entry["inelastic"]:
                ex = check_vs_exact(scn, aux_dt)
                chk["no_contact_vs_exact"] = ex
                chk["max_rel_diff"] = ex["max_rel_diff"]
                print(f"  check {nm}: no contact, dt={aux_dt:g}, vs exact: {ex['max_rel_diff']:.2e}",
                      file=sys.stderr, flush=True)
            results["checks"][nm] = chk

    if repeats > 0:
        tn = args.timing_scenario
        tscn = scns.get(tn) or load_scenario(SCENARIO_DIR / f"{tn}.toml")
        tr = [run(tscn, aux_dt, record=False) for _ in range(repeats)]
        times, cpus = [r["wall_s"] for r in tr], [r["cpu_s"] for r in tr]
        results["timing"][tn] = {"dt": aux_dt, "steps": tr[0]["steps"], "median_s": statistics.median(times),
                                 "runs_s": times, "median_cpu_s": statistics.median(cpus), "runs_cpu_s": cpus,
                                 "what": "ops.wipe + model build + ops.analyze over the duration, no recorders"}
        print(f"  timing {tn} dt={aux_dt:g}: median {statistics.median(times):.3f} s wall", file=sys.stderr)

    print_tables(results)
    Path(args.out).write_text(base.to_json(results))
    print(f"\nwrote {args.out}")


if __name__ == "__main__":
    main()
