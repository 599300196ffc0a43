#!/usr/bin/env python3
"""OpenSees peer: buildings on soil springs (soil-structure interaction) and multi-support excitation.

What it does
------------
Reads the scenario files in bench/opensees/scenarios-soil/*.toml (the Rust tool's format with
`[building.foundation]`, `[[support]]`, `support = "name"` on buildings and walls), builds each one in
OpenSeesPy and integrates it at several constant time steps. The model (`model basic -ndm 2 -ndf 3`: ux, uy,
rz; every y dof fixed; all nodes on the line x = 0, a floor at its elevation z_i):

    Per building: a ground node G (its support's ground); floor nodes W_i at (0, z_i) with mass m_i along x.
    On a foundation: a foundation node F at (0, 0) with mass (m_f, -, J) (J with the trapped soil's
      inertia), on one zeroLength G -> F with `Elastic kx`, `Viscous cx 1`, `Elastic ktheta`,
      `Viscous ctheta 1` along dirs 1, 1, 3, 3; every floor's rotation tied to F's (`equalDOF F W_i 3`).
      So the floors' x displacements w_i are free and every floor node turns with the foundation.
    Storey j: a `twoNodeLink` from the node below (F, or G for a fixed base; W_(j-1) above storey 1) to W_j,
      `-dir 2` (shear) with the storey's law (Elastic k / Steel01 Fy k a, as inelastic.py), and a second
      twoNodeLink on the same nodes with `Viscous a1 k 1`. In 2-D with 3 dofs per node the twoNodeLink's
      shear deformation is, exactly (TwoNodeLink::setTranLocalBasic, default shear distance 1/2),
          ub = v_j - v_i - L (theta_i + theta_j) / 2
      in the element's local y (= -X for an element along +Y), L = the distance between its nodes = h_j.
      Both ends turn by the foundation's rotation theta_os (counterclockwise), so ub = -(w_j - w_(j-1) +
      h_j theta_os) = -(w_j - w_(j-1) - h_j theta): the storey deformation d_j of the tool with theta =
      -theta_os (a floor at z moves by u_f + z theta with the foundation). Its force acts on both floors
      and, through T^T, as the moment h_j F on the rotation. No large stiffness, no penalty: exact. A
      fixed-base building has every rotation fixed, so ub = -(w_j - w_(j-1)).
    Mass-proportional damping a0 m_i: a twoNodeLink F -> W_i (G -> W_i for a fixed base) with
      `Viscous a0 m_i 1` along dir 2: its deformation is -(w_i - u_f - z_i theta), the floor relative to the
      base's rigid motion, as the tool has it. a0, a1: the FIXED-BASE building's modes 1 and 2 at its damping
      ratio (inelastic.rayleigh).
    Contacts: zeroLength from the left building's floor node to the right one's, dir 1 (two_sdof's
      materials); walls: a zeroLength between the floor and a wall node (on the wall's support).
    Ground: the scenario's record as a Path series (linear between samples, 0 after the last) in one
      `UniformExcitation` along x: every mass gets -m a_0(t). Buildings and walls on a support s whose
      motion differs from the scenario's are put in the scenario ground's frame: their ground node (or
      wall node) is driven by `imposedMotion` (pattern `MultipleSupport`, `groundMotion Plain -disp -vel
      -accel`) with g_s - g_0, v_s - v_0, a_s - a_0, the EXACT integrals from rest of the piecewise-linear
      accelerations (a cubic between samples; a delayed record is a(t - tau), at rest before tau; the same
      rule for every support, no baseline correction), sampled at every analysis step (Path series of step
      dt, so the values at the step times are exact). Then each floor's displacement in that frame is u +
      g_s - g_0 and its equation m (u + g_s - g_0)'' = -m a_0 - ... is the tool's m u'' = -m a_s - ..., the
      building's elements see only differences to its own ground node, and a contact between buildings on
      supports A and B closes by (u_A + g_A) - (u_B + g_B), as the tool's. No OpenSees integration of
      a record (GroundMotion's own integrator is not used: all three series are given).
    `constraints Transformation` (equalDOF and the imposed motions; the imposed nodes keep the velocity and
      acceleration set by ImposedMotionSP), `numberer RCM`, `system BandGeneral`, `test NormDispIncr 1e-12
      50`, Newton (with the fallbacks of two_sdof.analyze), `integrator Newmark 0.5 0.25`, constant dt.

Reported per scenario and dt (JSON, default results-soil.json), every step (binary Node recorder in 1-s
segments): per floor the peak |w_i| relative to its own support's ground (the node less its ground node), per
storey the peak |d_j| (w_j - w_(j-1) - h_j theta), per foundation the peak |u_f| and |theta|; per contact and
wall element the impacts (open -> closed transitions of strain < -gap; also by F != 0), peak force, largest
penetration. Then the changes between successive dts, and checks (--checks): each building's periods in
OpenSees (eigen) against numpy on the same M, K; the foundation numbers from the formulas of
docs/structures.md; without contact, linear: every building against the exact solution of M q'' + C q' + K q =
-M r a_s(t) (matrix exponential over a 1e-4 grid, its own support's record) at dt = 1e-4; the imposed ground
displacements as recorded against the exact integrals. Timing (--timing-repeats): build + analysis at dt =
1e-4 without recorders, median.

    /tmp/opensees-venv/bin/python bench/opensees/soil.py --quick --out /tmp/q.json
    nice -n 10 /tmp/opensees-venv/bin/python bench/opensees/soil.py
    /tmp/opensees-venv/bin/python bench/opensees/soil.py --table bench/opensees/results-soil.json

Peer measurement only: OpenSeesPy and NumPy are never dependencies of the Rust tool. Needs Python >= 3.11
(tomllib). See README.md, "Soil, supports and floor-to-column contacts".
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
import inelastic as inel  # noqa: E402  (storey laws, Rayleigh coefficients, rising edges)
import isolation as iso  # noqa: E402  (record files as the tool reads them)

ops = base.ops
REPO = base.REPO
SCENARIO_DIR = HERE / "scenarios-soil"
SCENARIOS = ["soil-linear", "soil-bilinear", "bridge-wave", "soil-wave"]
DEFAULT_DTS = [1e-4, 5e-5, 2e-5, 1e-5]
CHUNK_S = 1.0  # simulated seconds per recorder segment
RECORD_KEYS = ("record", "file", "format", "dt", "units", "scale")


# --------------------------------------------------------------------------
# Records: piecewise-linear accelerations and their exact integrals from rest
# --------------------------------------------------------------------------
class Motion:
    """A support's ground motion: a record (samples from t = 0 at step h, m/s^2 after `factor`) arriving
    `delay` s late: a(t) = the record at t - delay, linear between samples, 0 before the delay and after the
    last sample. Velocity and displacement are its exact integrals from rest (a cubic between samples)."""

    def __init__(self, rec, delay: float = 0.0):
        h, values, factor = rec[0], rec[1], rec[2]
        self.h, self.delay, self.src = float(h), float(delay), rec[4]
        self.a = np.asarray(values, dtype=float) * factor
        self.scale_factor = factor
        n = len(self.a)
        self.v = np.zeros(n)
        self.g = np.zeros(n)
        for k in range(n - 1):
            a0, a1 = self.a[k], self.a[k + 1]
            self.v[k + 1] = self.v[k] + h * (a0 + a1) / 2.0
            self.g[k + 1] = self.g[k] + h * self.v[k] + h * h * (2.0 * a0 + a1) / 6.0
        self.end = (n - 1) * h  # last sample, record time

    def key(self):
        return (self.src, self.scale_factor, self.delay)

    def at(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(a, v, g) at times t (array, s)."""
        s = np.asarray(t, dtype=float) - self.delay
        a, v, g = np.zeros_like(s), np.zeros_like(s), np.zeros_like(s)
        inside = (s > 0.0) & (s <= self.end)
        k = np.minimum((s[inside] / self.h).astype(int), len(self.a) - 2)
        r = s[inside] - k * self.h
        a0, b = self.a[k], (self.a[k + 1] - self.a[k]) / self.h
        a[inside] = a0 + b * r
        v[inside] = self.v[k] + a0 * r + b * r * r / 2.0
        g[inside] = self.g[k] + self.v[k] * r + a0 * r * r / 2.0 + b * r ** 3 / 6.0
        after = s > self.end
        v[after] = self.v[-1]
        g[after] = self.g[-1] + self.v[-1] * (s[after] - self.end)
        return a, v, g


# --------------------------------------------------------------------------
# Scenario
# --------------------------------------------------------------------------
def foundation_numbers(fd: dict, name: str) -> dict:
    """Mass, inertia (with the trapped soil's), springs and dashpots of a [building.foundation], by the
    formulas of docs/structures.md ("Soil and foundation"): Gazetas' static stiffnesses of a disk on a
    half-space, Wolf's cone dashpots, V_p capped at 2 V_s and a trapped rocking inertia for nu > 1/3; a
    rectangle a x b as the disk of the same area (sway) and of the same moment of area (rocking)."""
    m = float(fd["mass"])
    out = {"mass": m}
    if "vs" in fd:
        vs, rho, nu = float(fd["vs"]), float(fd.get("density", 1800.0)), float(fd.get("poisson", 0.33))
        if "radius" in fd:
            r = float(fd["radius"])
            rx = rt = r
            own = m * r * r / 4.0
            shape = {"radius": r}
        else:
            a, b = (float(x) for x in fd["size"])
            rx = math.sqrt(a * b / math.pi)
            rt = (b * a ** 3 / (3.0 * math.pi)) ** 0.25
            own = m * a * a / 12.0
            shape = {"size": [a, b]}
        G = rho * vs * vs
        i0 = math.pi * rt ** 4 / 4.0
        if nu > 1.0 / 3.0:
            ct, trapped = rho * 2.0 * vs * i0, 1.2 * (nu - 1.0 / 3.0) * rho * i0 * rt
        else:
            vp = vs * math.sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu))
            ct, trapped = rho * vp * i0, 0.0
        J = float(fd["inertia"]) if "inertia" in fd else own
        out.update(inertia=J + trapped, kx=8.0 * G * rx / (2.0 - nu), ktheta=8.0 * G * rt ** 3 / (3.0 * (1.0 - nu)),
                   cx=rho * vs * math.pi * rx * rx, ctheta=ct,
                   soil={"vs": vs, "density": rho, "poisson": nu, **shape, "r_sway": rx, "r_rocking": rt,
                         "trapped_inertia": trapped})
    else:
        if "inertia" not in fd:
            raise SystemExit(f"building {name!r}: foundation with springs given needs an inertia")
        out.update(inertia=float(fd["inertia"]), kx=float(fd["kx"]), ktheta=float(fd["ktheta"]),
                   cx=float(fd.get("cx", 0.0)), ctheta=float(fd.get("ctheta", 0.0)), soil="given")
    return out


def load_scenario(path: Path) -> dict:
    with open(path, "rb") as f:
        raw = tomllib.load(f)
    return expand(raw, path)


def expand(raw: dict, path: Path) -> dict:
    for key in ("device",):
        if raw.get(key):
            raise SystemExit(f"{path}: [[{key}]] is not handled by this peer")
    gmr = raw["ground_motion"]
    if "y" in gmr or float(gmr.get("angle", 0.0)) != 0.0:
        raise SystemExit(f"{path}: a record along y is not handled by this peer")
    gm = iso.load_record(gmr, path)
    ground = Motion(gm)
    supports = {}
    for s in raw.get("support", []):
        own = {k: s[k] for k in RECORD_KEYS if k in s}
        rec = iso.load_record(own, path) if ("record" in own or "file" in own) else gm
        if "delay" in s:
            tau = float(s["delay"])
        elif "distance" in s:
            tau = float(s["distance"]) / float(s["apparent_velocity"])
        else:
            tau = 0.0
        mo = Motion(rec, tau)
        supports[s["name"]] = {"name": s["name"], "delay": tau, "own_record": rec is not gm, "motion": mo,
                               "record": rec[4], "factor": rec[2]}

    def motion_of(name):
        """None: the scenario's ground (or a support identical to it: the tool runs those as uniform)."""
        if name is None:
            return None
        sp = supports[name]
        if not sp["own_record"] and sp["delay"] == 0.0:
            return None
        return sp["motion"]

    blds = []
    for b in raw["building"]:
        name, n = b["name"], len(b["masses"])
        for key in ("plan", "isolator"):
            if key in b:
                raise SystemExit(f"{path}: building {name!r}: [building.{key}] is not handled by this peer")
        if len(b["stiffnesses"]) != n or len(b["heights"]) != n:
            raise SystemExit(f"building {name!r}: masses, stiffnesses, heights differ in length")
        models = inel.per_storey(b.get("storey_model", "linear"), n, "storey_model", name)
        fy = inel.per_storey(b.get("yield_forces", None), n, "yield_forces", name)
        ratio = inel.per_storey(b.get("post_yield_ratio", 0.0), n, "post_yield_ratio", name)
        bw = {"n": 1.0, "beta": 0.5, "gamma": 0.5, **b.get("bouc_wen", {})}
        storeys = []
        for j in range(n):
            law = {"model": models[j], "k": float(b["stiffnesses"][j])}
            if models[j] not in ("linear", "bilinear", "bouc-wen"):
                raise SystemExit(f"storey_model {models[j]!r} unknown")
            if models[j] != "linear":
                law.update(Fy=float(fy[j]), a=float(ratio[j]))
            if models[j] == "bouc-wen":
                law.update(n=float(bw["n"]), beta=float(bw["beta"]), gamma=float(bw["gamma"]))
            storeys.append(law)
        bd = {"name": name, "m": [float(x) for x in b["masses"]], "storeys": storeys,
              "heights": [float(x) for x in b["heights"]], "zeta": float(b.get("damping_ratio", 0.05)),
              "support": b.get("support"), "motion": motion_of(b.get("support"))}
        bd["z"] = np.cumsum(bd["heights"]).tolist()
        bd["rayleigh"] = inel.rayleigh(bd)  # fixed-base modes 1 and 2
        bd["foundation"] = foundation_numbers(b["foundation"], name) if "foundation" in b else None
        blds.append(bd)
    index = {b["name"]: i for i, b in enumerate(blds)}
    links = []
    for c in raw.get("contact", []):
        if c["model"] in ("hertzdamp", "jankowski") and c.get("damping", "exact") != "formula":
            raise SystemExit(f"{path}: contact {c['between']}: write damping = \"formula\" (OpenSees' law)")
        i, j = sorted(index[x] for x in c["between"])
        L, R = blds[i], blds[j]
        if "floors" in c:
            pairs = [tuple(int(x) for x in p) for p in c["floors"]]
            if index[c["between"][0]] != i:
                pairs = [(q, p) for p, q in pairs]
        else:  # every pair of floors at the same height (within 1 mm)
            pairs = [(a + 1, bb + 1) for a in range(len(L["z"])) for bb in range(len(R["z"]))
                     if abs(L["z"][a] - R["z"][bb]) <= 1e-3]
        for fl, fr in pairs:
            links.append({"kind": "contact", "name": f"{L['name']}|{R['name']}", "left": i, "right": j,
                          "floors": [fl, fr], "gap": float(c["gap"]), "raw": c,
                          "m_eff": L["m"][fl - 1] * R["m"][fr - 1] / (L["m"][fl - 1] + R["m"][fr - 1])})
    for w in raw.get("wall", []):
        if w.get("model") in ("hertzdamp", "jankowski") and w.get("damping", "exact") != "formula":
            raise SystemExit(f"{path}: wall {w.get('name')}: write damping = \"formula\" (OpenSees' law)")
        bi = index[w["facing"]]
        for f in w.get("floors", [1]):
            links.append({"kind": "wall", "name": w.get("name", f"wall-{w['facing']}"), "building": bi,
                          "side": w["side"], "floors": [int(f)], "gap": float(w["gap"]), "raw": w,
                          "m_eff": blds[bi]["m"][int(f) - 1], "support": w.get("support"),
                          "motion": motion_of(w.get("support"))})
    duration = float(raw.get("analysis", {}).get("duration", gm[3]))
    return {"path": path, "raw": raw, "buildings": blds, "links": links, "gm": gm, "ground": ground,
            "supports": supports, "duration": duration}


# --------------------------------------------------------------------------
# Linear matrices (q = [w_1 .. w_n, u_f, theta] on a foundation, [w_1 .. w_n] on a fixed base)
# --------------------------------------------------------------------------
def storey_vectors(b: dict) -> list[np.ndarray]:
    n = len(b["m"])
    fd = b["foundation"] is not None
    d = n + 2 if fd else n
    out = []
    for j in range(n):
        g = np.zeros(d)
        g[j] = 1.0
        if j > 0:
            g[j - 1] = -1.0
        elif fd:
            g[n] = -1.0
        if fd:
            g[n + 1] = -b["heights"][j]
        out.append(g)
    return out


def matrices(b: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """M, C, K (initial stiffness) and the ground's influence vector r of building b."""
    n = len(b["m"])
    f = b["foundation"]
    d = n + 2 if f else n
    a0, a1 = b["rayleigh"]["a0"], b["rayleigh"]["a1"]
    K, C = np.zeros((d, d)), np.zeros((d, d))
    for law, g in zip(b["storeys"], storey_vectors(b)):
        K += law["k"] * np.outer(g, g)
        C += a1 * law["k"] * np.outer(g, g)
    masses = list(b["m"])
    r = np.ones(d)
    for i in range(n):
        h = np.zeros(d)
        h[i] = 1.0
        if f:
            h[n], h[n + 1] = -1.0, -b["z"][i]
        C += a0 * b["m"][i] * np.outer(h, h)
    if f:
        K[n, n] += f["kx"]
        K[n + 1, n + 1] += f["ktheta"]
        C[n, n] += f["cx"]
        C[n + 1, n + 1] += f["ctheta"]
        masses += [f["mass"], f["inertia"]]
        r[n + 1] = 0.0
    return np.diag(masses), C, K, r


def numpy_periods(b: dict) -> list[float]:
    M, _, K, _ = matrices(b)
    s = 1.0 / np.sqrt(np.diag(M))
    lam = np.sort(np.linalg.eigvalsh(K * np.outer(s, s)))
    return [float(2.0 * math.pi / math.sqrt(x)) for x in lam]


# --------------------------------------------------------------------------
# OpenSees model
# --------------------------------------------------------------------------
def B(bi: int) -> int:
    return 10000 * (bi + 1)


def ground_node(bi):
    return B(bi)


def foundation_node(bi):
    return B(bi) + 1


def floor_node(bi, f):  # f >= 1
    return B(bi) + 10 + f


def below_node(bi, b, j):  # the node under storey j (1-based)
    if j > 1:
        return floor_node(bi, j - 1)
    return foundation_node(bi) if b["foundation"] else ground_node(bi)


def storey_ele(bi, j):
    return B(bi) + 100 + j


def storey_dashpot(bi, j):
    return B(bi) + 200 + j


def mass_dashpot(bi, i):
    return B(bi) + 300 + i


def soil_ele(bi):
    return B(bi) + 400  # materials +0 kx, +1 cx, +2 ktheta, +3 ctheta


def link_tag(n):
    return 500000 + n


def wall_node(n):
    return 600000 + n


def build_building(bi: int, b: dict, log, eigen_only: bool = False) -> None:
    n = len(b["m"])
    f = b["foundation"]
    G = ground_node(bi)
    log("node", G, 0.0, 0.0)
    if b["motion"] is None or eigen_only:
        log("fix", G, 1, 1, 1)
    else:
        log("fix", G, 0, 1, 1)  # dof 1 driven by imposedMotion
    if f:
        F = foundation_node(bi)
        log("node", F, 0.0, 0.0)
        log("mass", F, f["mass"], 0.0, f["inertia"])
        log("fix", F, 0, 1, 0)
        t = soil_ele(bi)
        log("uniaxialMaterial", "Elastic", t, f["kx"])
        log("uniaxialMaterial", "Elastic", t + 2, f["ktheta"])
        if eigen_only:
            log("element", "zeroLength", t, G, F, "-mat", t, t + 2, "-dir", 1, 3)
        else:
            log("uniaxialMaterial", "Viscous", t + 1, f["cx"], 1.0)
            log("uniaxialMaterial", "Viscous", t + 3, f["ctheta"], 1.0)
            log("element", "zeroLength", t, G, F, "-mat", t, t + 1, t + 2, t + 3, "-dir", 1, 1, 3, 3)
    for i in range(1, n + 1):
        W = floor_node(bi, i)
        log("node", W, 0.0, b["z"][i - 1])
        log("mass", W, b["m"][i - 1], 0.0, 0.0)
        if f:
            log("fix", W, 0, 1, 0)
            log("equalDOF", foundation_node(bi), W, 3)
        else:
            log("fix", W, 0, 1, 1)
    # local x along +Y (i -> j), local y = -X (2-D rule y = (-x2, x1)); shear = dir 2
    orient = ["-orient", 0.0, 1.0, 0.0, -1.0, 0.0, 0.0]
    a0, a1 = b["rayleigh"]["a0"], b["rayleigh"]["a1"]
    for j, law in enumerate(b["storeys"], start=1):
        t = storey_ele(bi, j)
        name, args = inel.storey_material(t, law)
        log("uniaxialMaterial", name, t, *args)
        log("element", "twoNodeLink", t, below_node(bi, b, j), floor_node(bi, j), "-mat", t, "-dir", 2, *orient)
        if not eigen_only and a1 > 0.0:
            c = storey_dashpot(bi, j)
            log("uniaxialMaterial", "Viscous", c, a1 * law["k"], 1.0)
            log("element", "twoNodeLink", c, below_node(bi, b, j), floor_node(bi, j), "-mat", c, "-dir", 2, *orient)
    if not eigen_only and a0 > 0.0:
        base_node = foundation_node(bi) if f else G
        for i in range(1, n + 1):
            c = mass_dashpot(bi, i)
            log("uniaxialMaterial", "Viscous", c, a0 * b["m"][i - 1], 1.0)
            log("element", "twoNodeLink", c, base_node, floor_node(bi, i), "-mat", c, "-dir", 2, *orient)


def ground_files(scn: dict, dt: float, nsteps: int, tmp: Path) -> dict:
    """Per distinct support motion (other than the scenario's ground): files of g_s - g_0, v_s - v_0,
    a_s - a_0 at t = k dt, k = 0 .. nsteps + 1 (one spare sample)."""
    t = np.arange(nsteps + 2) * dt
    a0, v0, g0 = scn["ground"].at(t)
    out = {}
    motions = [b["motion"] for b in scn["buildings"]] + [lk.get("motion") for lk in scn["links"]]
    for mo in motions:
        if mo is None or mo.key() in out:
            continue
        a, v, g = mo.at(t)
        k = len(out)
        files = []
        for what, x in (("disp", g - g0), ("vel", v - v0), ("accel", a - a0)):
            p = tmp / f"ground{k}-{what}.txt"
            np.savetxt(p, x, fmt="%.17g")
            files.append(str(p))
        out[mo.key()] = {"index": k, "files": files, "disp": g - g0}
    return out


def build(scn: dict, dt: float, nsteps: int, tmp: Path, contact: bool = True) -> dict:
    """Build the model (domain wiped first); returns the commands issued (records as file names) and the
    driven nodes."""
    cmds = []

    def log(name, *args):
        getattr(ops, name)(*args)
        cmds.append([name, *args])

    ops.wipe()
    log("model", "basic", "-ndm", 2, "-ndf", 3)
    for bi, b in enumerate(scn["buildings"]):
        build_building(bi, b, log)
    driven = []  # (node, motion)
    for bi, b in enumerate(scn["buildings"]):
        if b["motion"] is not None:
            driven.append((ground_node(bi), b["motion"]))
    links = []
    if contact:
        for n, lk in enumerate(scn["links"]):
            name, args, _ = base.contact_material(lk["raw"], lk["m_eff"])
            t = link_tag(n)
            log("uniaxialMaterial", name, t, *args)
            if lk["kind"] == "contact":
                ni, nj = floor_node(lk["left"], lk["floors"][0]), floor_node(lk["right"], lk["floors"][1])
            else:
                fl = floor_node(lk["building"], lk["floors"][0])
                z = scn["buildings"][lk["building"]]["z"][lk["floors"][0] - 1]
                wn = wall_node(n)
                log("node", wn, 0.0, z)
                if lk["motion"] is None:
                    log("fix", wn, 1, 1, 1)
                else:
                    log("fix", wn, 0, 1, 1)
                    driven.append((wn, lk["motion"]))
                ni, nj = (fl, wn) if lk["side"] == "right" else (wn, fl)
            log("element", "zeroLength", t, ni, nj, "-mat", t, "-dir", 1)
            links.append(t)
    gdt, values, factor = scn["gm"][0], scn["gm"][1], scn["gm"][2]
    ops.timeSeries("Path", 1, "-dt", gdt, "-values", *values, "-factor", factor)
    cmds.append(["timeSeries", "Path", 1, "-dt", gdt, "-values", f"<{len(values)} values from t = 0>", "-factor", factor])
    log("pattern", "UniformExcitation", 1, 1, "-accel", 1)
    gf = {}
    if driven:
        gf = ground_files(scn, dt, nsteps, tmp)
        log("pattern", "MultipleSupport", 2)
        for key, g in gf.items():
            k = g["index"]
            for s, fn in enumerate(g["files"]):
                ops.timeSeries("Path", 100 + 3 * k + s, "-dt", dt, "-filePath", fn)
                cmds.append(["timeSeries", "Path", 100 + 3 * k + s, "-dt", dt, "-filePath",
                             f"<{['g_s - g_0', 'v_s - v_0', 'a_s - a_0'][s]} of support {key[0]} x {key[1]:g} "
                             f"delayed {key[2]:g} s, exact, every step>"])
            log("groundMotion", 10 + k, "Plain", "-disp", 100 + 3 * k, "-vel", 101 + 3 * k, "-accel", 102 + 3 * k)
        for node, mo in driven:
            log("imposedMotion", node, 1, 10 + gf[mo.key()]["index"])
    log("constraints", "Transformation")
    log("numberer", "RCM")
    log("system", "BandGeneral")
    log("test", "NormDispIncr", base.TOL, base.MAX_ITER)
    log("algorithm", "Newton")
    log("integrator", "Newmark", 0.5, 0.25)
    log("analysis", "Transient")
    return {"commands": cmds, "links": links, "driven": driven, "ground_files": gf}


def opensees_periods(b: dict) -> list[float]:
    """Periods of building b built alone in OpenSees (eigen, full generalised LAPACK)."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    bb = dict(b, motion=None)
    build_building(0, bb, lambda name, *a: getattr(ops, name)(*a), eigen_only=True)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("FullGeneral")
    d = len(b["m"]) + (2 if b["foundation"] else 0)
    lam = ops.eigen("-fullGenLapack", d)
    ops.wipe()
    return sorted((2 * math.pi / math.sqrt(x) for x in lam), reverse=True)


# --------------------------------------------------------------------------
# Runs
# --------------------------------------------------------------------------
def recorded_nodes(scn: dict) -> list[int]:
    nodes = []
    for bi, b in enumerate(scn["buildings"]):
        nodes.append(ground_node(bi))
        if b["foundation"]:
            nodes.append(foundation_node(bi))
        nodes += [floor_node(bi, f) for f in range(1, len(b["m"]) + 1)]
    return nodes


def quantity_map(scn: dict) -> tuple[np.ndarray, list[str]]:
    """T such that (per-step disps of recorded_nodes, dofs 1 and 3 each) @ T = the compared quantities:
    per building its floors' w_i (less its ground), storeys' d_j, and on a foundation u_f and theta."""
    nodes = recorded_nodes(scn)
    col = {nd: 2 * i for i, nd in enumerate(nodes)}  # dof 1 at col, dof 3 at col + 1
    names, cols = [], []
    for bi, b in enumerate(scn["buildings"]):
        n = len(b["m"])
        f = b["foundation"] is not None
        G = col[ground_node(bi)]

        def vec(terms):
            v = np.zeros(2 * len(nodes))
            for c, x in terms:
                v[c] += x
            return v

        th = [(col[foundation_node(bi)] + 1, -1.0)] if f else []  # theta = -rz (tool's sign)
        for i in range(1, n + 1):
            names.append(f"{b['name']}.floor{i}")
            cols.append(vec([(col[floor_node(bi, i)], 1.0), (G, -1.0)]))
        for j in range(1, n + 1):
            below = col[floor_node(bi, j - 1)] if j > 1 else (col[foundation_node(bi)] if f else G)
            terms = [(col[floor_node(bi, j)], 1.0), (below, -1.0)]
            if f:
                terms.append((th[0][0], -b["heights"][j - 1] * th[0][1]))
            names.append(f"{b['name']}.storey{j}")
            cols.append(vec(terms))
        if f:
            names.append(f"{b['name']}.sway")
            cols.append(vec([(col[foundation_node(bi)], 1.0), (G, -1.0)]))
            names.append(f"{b['name']}.rocking")
            cols.append(vec(th))
    return np.array(cols).T, names


class Peaks:
    """Running peak |x| per column over per-step chunks, with the time and value at the peak."""

    def __init__(self, ncol: int):
        self.peak, self.t, self.val = np.zeros(ncol), np.zeros(ncol), np.zeros(ncol)

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
    with tempfile.TemporaryDirectory(prefix="opensees-soil-") as tmp:
        tmp = Path(tmp)
        if not record:
            t0, c0 = time.perf_counter(), time.process_time()
            info = build(scn, dt, nsteps, tmp, contact)
            fallback = base.analyze(nsteps, dt)
            ops.wipe()
            return {"dt": dt, "steps": nsteps, "wall_s": time.perf_counter() - t0,
                    "cpu_s": time.process_time() - c0, "fallback_steps": fallback, "info": info}
        nodes = recorded_nodes(scn)
        T, names = quantity_map(scn)
        pk = Peaks(T.shape[1])
        per_chunk = int(round(CHUNK_S / dt))
        ends = list(range(per_chunk, nsteps, per_chunk)) + [nsteps]
        t0, c0 = time.perf_counter(), time.process_time()
        info = build(scn, dt, nsteps, tmp, contact)
        ctags = info["links"]
        driven_cols = [2 * nodes.index(nd) for nd, _ in info["driven"] if nd in nodes]
        driven_err = 0.0
        fallback, cd, cs, end_q = 0, [], [], None
        for s, n_end in enumerate(ends):
            ops.recorder("Node", "-binary", str(tmp / f"n{s}.bin"), "-time", "-node", *nodes, "-dof", 1, 3, "disp")
            if ctags:
                ops.recorder("Element", "-binary", str(tmp / f"cd{s}.bin"), "-ele", *ctags, "deformation")
                ops.recorder("Element", "-binary", str(tmp / f"cs{s}.bin"), "-ele", *ctags, "material", "1", "stress")
            fallback += base.analyze(n_end, dt)
            ops.remove("recorders")
            nrows = n_end - (ends[s - 1] if s else 0)
            x = base.read_binary_recorder(tmp / f"n{s}.bin", 1 + 2 * len(nodes)).astype(np.float64)
            (tmp / f"n{s}.bin").unlink()
            if len(x) != nrows:
                raise RuntimeError("node recorder length does not match the step count")
            tt = np.round(x[:, 0], 9)
            q = x[:, 1:] @ T
            pk.update(tt, q)
            end_q = q[-1]
            # the driven ground nodes against the exact integrals at the step times
            k0 = n_end - nrows + 1
            for (nd, mo) in info["driven"]:
                if nd in nodes:
                    want = info["ground_files"][mo.key()]["disp"][k0:n_end + 1]
                    driven_err = max(driven_err, float(np.abs(x[:, 1 + 2 * nodes.index(nd)] - want).max()))
            if ctags:
                a = base.read_binary_recorder(tmp / f"cd{s}.bin", len(ctags))
                b_ = base.read_binary_recorder(tmp / f"cs{s}.bin", len(ctags))
                if not len(a) == len(b_) == nrows:
                    raise RuntimeError("contact recorder length does not match the step count")
                cd.append(a.astype(np.float64))
                cs.append(b_.astype(np.float64))
                (tmp / f"cd{s}.bin").unlink()
                (tmp / f"cs{s}.bin").unlink()
        t_end = ops.getTime()
        ops.wipe()
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    del driven_cols
    return {"dt": dt, "steps": nsteps, "wall_s": wall, "cpu_s": cpu, "fallback_steps": fallback, "info": info,
            "names": names, "pk": pk, "end": end_q, "t_end": t_end, "driven_max_abs_error_m": driven_err,
            "cd": np.concatenate(cd) if ctags else None, "cs": np.concatenate(cs) if ctags else None}


def summarise(scn: dict, res: dict) -> dict:
    dt = res["dt"]
    out = {"dt": dt, "steps": res["steps"], "wall_s": res["wall_s"], "cpu_s": res["cpu_s"],
           "fallback_steps": res["fallback_steps"], "driven_ground_max_abs_error_m": res["driven_max_abs_error_m"],
           "buildings": [], "links": []}
    pk, names = res["pk"], res["names"]
    idx = {nm: i for i, nm in enumerate(names)}

    def row(nm):
        i = idx[nm]
        return {"peak": float(pk.peak[i]), "t": float(pk.t[i]), "at_peak": float(pk.val[i]),
                "end": float(res["end"][i])}

    for b in scn["buildings"]:
        n = len(b["m"])
        e = {"name": b["name"], "floors": [row(f"{b['name']}.floor{i}") for i in range(1, n + 1)],
             "storeys": [row(f"{b['name']}.storey{j}") for j in range(1, n + 1)]}
        for j, law in enumerate(b["storeys"]):
            if "Fy" in law:
                e["storeys"][j]["ductility"] = e["storeys"][j]["peak"] / (law["Fy"] / law["k"])
        if b["foundation"]:
            e["sway"] = row(f"{b['name']}.sway")
            e["rocking"] = row(f"{b['name']}.rocking")
        out["buildings"].append(e)
    if res["cd"] is not None:
        for k, lk in enumerate(scn["links"]):
            strain = res["cd"][:, k]
            closed = strain < -lk["gap"]
            F = 0.0 - res["cs"][:, k]
            first = inel.rising_edges(closed)
            ipk = int(np.argmax(F)) if F.max() > 0.0 else None
            out["links"].append({
                "kind": lk["kind"], "name": lk["name"], "floors": lk["floors"],
                "impacts": int(len(first)), "impacts_force": int(len(inel.rising_edges(F != 0.0))),
                "first_steps_inside_s": [float(round((i + 1) * dt, 9)) for i in first],
                "peak_force": float(F.max()),
                "t_peak_force": float(round((ipk + 1) * dt, 9)) if ipk is not None else None,
                "min_force": float(F.min()),
                "max_penetration": float(max(0.0, -(strain.min() + lk["gap"]))),
                "steps_in_contact": int(closed.sum())})
    return out


# --------------------------------------------------------------------------
# Exact linear solution without contact
# --------------------------------------------------------------------------
def exact_linear(scn: dict, b: dict, h: float = 1e-4) -> dict:
    """Peaks of |w_i|, |d_j|, |u_f|, |theta| of building b alone, linear, without contact, under its own
    support's record: exact propagation of [q, q', a, a'] over the grid h (the record linear between grid
    points: exact when the record's samples, delayed, fall on the grid)."""
    mo = b["motion"] or scn["ground"]
    if abs(mo.h / h - round(mo.h / h)) > 1e-9 or abs(mo.delay / h - round(mo.delay / h)) > 1e-9:
        raise SystemExit("h must divide the record's step and delay")
    M, C, K, r = matrices(b)
    d = len(M)
    Minv = np.linalg.inv(M)
    A = np.zeros((2 * d + 2, 2 * d + 2))
    A[:d, d:2 * d] = np.eye(d)
    A[d:2 * d, :d] = -Minv @ K
    A[d:2 * d, d:2 * d] = -Minv @ C
    A[d:2 * d, 2 * d] = -r
    A[2 * d, 2 * d + 1] = 1.0
    P = base.expm(A * h)
    N = int(round(scn["duration"] / h))
    a, _, _ = mo.at(np.arange(N + 1) * h)
    U = np.zeros((N + 1, d))
    z = np.zeros(2 * d + 2)
    for j in range(N):
        z[2 * d], z[2 * d + 1] = a[j], (a[j + 1] - a[j]) / h
        z = P @ z
        U[j + 1] = z[:d]
    n = len(b["m"])
    out = {"h": h, "floors": [float(np.abs(U[:, i]).max()) for i in range(n)],
           "storeys": [float(np.abs(U @ g).max()) for g in storey_vectors(b)]}
    if b["foundation"]:
        out["sway"] = float(np.abs(U[:, n]).max())
        out["rocking"] = float(np.abs(U[:, n + 1]).max())
    return out


def rel(a: float, b: float) -> float:
    return abs(a - b) / abs(b) if b else abs(a - b)


def check_vs_exact(scn: dict, dt: float) -> dict:
    s = summarise(scn, run(scn, dt, contact=False))
    out = {"dt": dt, "buildings": [], "max_rel_diff": 0.0}
    for b, sb in zip(scn["buildings"], s["buildings"]):
        ex = exact_linear(scn, b)
        worst = max([rel(fo["peak"], fe) for fo, fe in zip(sb["floors"], ex["floors"])]
                    + [rel(so["peak"], se) for so, se in zip(sb["storeys"], ex["storeys"])]
                    + ([rel(sb["sway"]["peak"], ex["sway"]), rel(sb["rocking"]["peak"], ex["rocking"])]
                       if b["foundation"] else []))
        out["buildings"].append({"name": b["name"], "exact": ex, "max_rel_diff": worst})
        out["max_rel_diff"] = max(out["max_rel_diff"], worst)
    return out


# --------------------------------------------------------------------------
# Convergence, tables
# --------------------------------------------------------------------------
def quantities(s: dict) -> dict:
    q = {}
    for b in s["buildings"]:
        for i, f in enumerate(b["floors"], start=1):
            q[f"{b['name']}.floor{i}.floor"] = f["peak"]
        for j, st in enumerate(b["storeys"], start=1):
            q[f"{b['name']}.storey{j}.drift"] = st["peak"]
        for k in ("sway", "rocking"):
            if k in b:
                q[f"{b['name']}.{k}"] = b[k]["peak"]
    for c in s["links"]:
        q[f"{c['name']}.floors{'-'.join(map(str, c['floors']))}.impacts"] = c["impacts"]
    return q


def convergence(runs: list) -> list:
    out = []
    for a, b in zip(runs, runs[1:]):
        qa, qb = quantities(a), quantities(b)
        groups = {}
        for k, v in qb.items():
            if k.endswith(".impacts"):
                continue
            grp = k.rsplit(".", 1)[-1]
            groups[grp] = max(groups.get(grp, 0.0), rel(qa[k], v))
        imp_a = {k: v for k, v in qa.items() if k.endswith(".impacts")}
        imp_b = {k: v for k, v in qb.items() if k.endswith(".impacts")}
        out.append({"dt_a": a["dt"], "dt_b": b["dt"], "max_rel": groups, "impacts_equal": imp_a == imp_b,
                    "impacts_a": imp_a, "impacts_b": imp_b})
    return out


def g(x, d: int = 6) -> str:
    return "-" if x is None else f"{x:.{d}g}"


def print_tables(res: dict) -> None:
    for name, entry in res["scenarios"].items():
        runs = entry["runs"]
        print(f"\n**{name}**: peak |w| of each floor (m, relative to its support), foundation sway (m) / rocking "
              f"(rad); impacts per contact element\n")
        head = ["dt (s)"]
        for b in runs[0]["buildings"]:
            head += [f"{b['name']}{i + 1}" for i in range(len(b["floors"]))]
            if "sway" in b:
                head += [f"{b['name']} sway / rocking"]
        head += ["impacts", "CPU (s)"]
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for r in runs:
            row = [f"{r['dt']:g}"]
            for b in r["buildings"]:
                row += [g(f["peak"], 7) for f in b["floors"]]
                if "sway" in b:
                    row += [f"{g(b['sway']['peak'], 6)} / {g(b['rocking']['peak'], 6)}"]
            row += ["/".join(str(c["impacts"]) for c in r["links"]), f"{r['cpu_s']:.1f}"]
            print("| " + " | ".join(row) + " |")
        conv = entry.get("convergence", [])
        if conv:
            keys = ["floor", "drift", "sway", "rocking"]
            print(f"\n{name}: largest relative change between successive dts\n")
            print("| dts | " + " | ".join(keys) + " | impacts equal |")
            print("|---|" + "---|" * (len(keys) + 1))
            for c in conv:
                print(f"| {c['dt_a']:g} -> {c['dt_b']:g} | " + " | ".join(g(c["max_rel"].get(k), 2) for k in keys)
                      + f" | {'yes' if c['impacts_equal'] else 'no'} |")
    if res.get("checks"):
        print("\nchecks:")
        for k, v in res["checks"].items():
            parts = []
            if "periods_max_rel_diff" in v:
                parts.append(f"periods OpenSees vs numpy {v['periods_max_rel_diff']:.1e}")
            if "no_contact_vs_exact" in v:
                parts.append(f"no contact vs exact (dt = {v['no_contact_vs_exact']['dt']:g}) "
                             f"{v['no_contact_vs_exact']['max_rel_diff']:.1e}")
            print(f"- {k}: " + "; ".join(parts))


def short(s: dict) -> str:
    parts = []
    for b in s["buildings"]:
        p = f"{b['name']} top {g(b['floors'][-1]['peak'])}"
        if "sway" in b:
            p += f" sway {g(b['sway']['peak'])} rock {g(b['rocking']['peak'])}"
        parts.append(p)
    if s["links"]:
        parts.append("impacts " + "/".join(str(c["impacts"]) for c in s["links"]))
    parts.append(f"driven err {s['driven_ground_max_abs_error_m']:.1e}")
    return "; ".join(parts)


def describe(scn: dict) -> dict:
    return {
        "scenario": str(scn["path"].relative_to(REPO)), "duration": scn["duration"],
        "inelastic": sorted({law["model"] for b in scn["buildings"] for law in b["storeys"]} - {"linear"}),
        "record": {"file": scn["gm"][4], "dt": scn["gm"][0], "factor": scn["gm"][2]},
        "supports": [{"name": s["name"], "delay": s["delay"], "own_record": s["own_record"], "record": s["record"],
                      "factor": s["factor"]} for s in scn["supports"].values()],
        "buildings": [{"name": b["name"], "support": b["support"], "driven": b["motion"] is not None,
                       "fixed_base_periods": b["rayleigh"]["periods"], "a0": b["rayleigh"]["a0"],
                       "a1": b["rayleigh"]["a1"], "foundation": b["foundation"],
                       "periods_numpy": numpy_periods(b)} for b in scn["buildings"]],
        "links": [{"kind": lk["kind"], "name": lk["name"], "floors": lk["floors"], "gap": lk["gap"],
                   "m_eff": lk["m_eff"], "support": lk.get("support")} for lk in scn["links"]],
        "runs": []}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scenarios", default=",".join(SCENARIOS), help="comma-separated names (scenarios-soil/NAME.toml)")
    ap.add_argument("--dts", default=",".join(f"{d:g}" for d in DEFAULT_DTS), help="time steps, s")
    ap.add_argument("--timing-repeats", type=int, default=0, help="runs without recorders at dt = 1e-4 (median) of "
                                                                  "--timing-scenario; 0 skips (bench_soil.py times)")
    ap.add_argument("--timing-scenario", default="soil-linear")
    ap.add_argument("--checks", action=argparse.BooleanOptionalAction, default=True,
                    help="OpenSees periods vs numpy; linear scenarios without contact vs the exact solution")
    ap.add_argument("--max-run-seconds", type=float, default=600.0,
                    help="skip a smaller dt when the run predicted from the last one would exceed this")
    ap.add_argument("--quick", action="store_true", help="smoke run: dt = 1e-3 only, checks at 1e-3")
    ap.add_argument("--out", default=str(HERE / "results-soil.json"))
    ap.add_argument("--table", metavar="JSON", help="print the markdown tables of a results file, run nothing")
    ap.add_argument("--merge", metavar="JSON,JSON,...", help="merge result files into --out, run nothing")
    args = ap.parse_args()
    if args.merge:
        parts = [json.loads(Path(x).read_text()) for x in args.merge.split(",")]
        out = parts[0]
        out["merged_from"] = [{"command": p_["command"], "generated": p_["generated"]} for p_ in parts]
        for p_ in parts[1:]:
            for nm, entry in p_["scenarios"].items():
                if nm in out["scenarios"]:  # the same scenario at other dts: one ladder, coarse to fine
                    runs = {r["dt"]: r for r in out["scenarios"][nm]["runs"] + entry["runs"]}
                    out["scenarios"][nm]["runs"] = [runs[d] for d in sorted(runs, reverse=True)]
                    out["scenarios"][nm]["convergence"] = convergence(out["scenarios"][nm]["runs"])
                else:
                    out["scenarios"][nm] = entry
            for key in ("checks", "timing"):
                out[key].update(p_[key])
            out["notes"] += p_["notes"]
        Path(args.out).write_text(base.to_json(out))
        print(f"wrote {args.out}")
        return
    if args.table:
        print_tables(json.loads(Path(args.table).read_text()))
        return
    names = [x.strip() for x in args.scenarios.split(",") if x.strip()]
    dts = [float(x) for x in args.dts.split(",")]
    aux_dt = 1e-4
    if args.quick:
        dts, aux_dt = [1e-3], 1e-3
    ops.logFile(os.devnull, "-noEcho")
    results = {
        "about": "OpenSeesPy peer of buildings on soil springs (sway and rocking) and of multi-support excitation "
                 "(wave passage, a support's own record), pounding; see bench/opensees/README.md, "
                 "section 'Soil, supports and floor-to-column contacts'",
        "generated": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "command": " ".join([Path(sys.argv[0]).name] + sys.argv[1:]),
        "environment": {"openseespy": base._version("openseespy"), "opensees": ops.version(),
                        "numpy": np.__version__, "python": platform.python_version(),
                        "platform": platform.platform(), "cpu": base._cpu_model(), "cpus": os.cpu_count()},
        "analysis": {"integrator": "Newmark gamma=0.5 beta=0.25", "algorithm": "Newton",
                     "test": "NormDispIncr 1e-12, max 50 iterations (fallbacks as two_sdof.py)",
                     "system": "BandGeneral", "numberer": "RCM", "constraints": "Transformation",
                     "peaks": "max |x| over every step (binary Node recorder, dofs 1 and 3)",
                     "impacts": "per contact or wall element: open -> closed transitions of strain < -gap on the "
                                "step sequence; impacts_force: of F != 0",
                     "contact force": "F = -stress (> 0 compressive)",
                     "displacements": "floors and foundation sway relative to the building's own support's ground; "
                                      "rocking theta with the tool's sign (a floor at z moves by u_f + z theta)"},
        "scenarios": {}, "checks": {}, "timing": {}, "notes": [],
    }
    scns = {nm: load_scenario(SCENARIO_DIR / f"{nm}.toml") for nm in names}
    for nm, scn in scns.items():
        entry = describe(scn)
        last = None
        for dt in dts:
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
            chk = {"periods": []}
            worst = 0.0
            for b, eb in zip(scn["buildings"], entry["buildings"]):
                tos = opensees_periods(b)
                d = max(rel(x, y) for x, y in zip(tos, eb["periods_numpy"]))
                worst = max(worst, d)
                chk["periods"].append({"name": b["name"], "opensees": tos, "numpy": eb["periods_numpy"],
                                       "max_rel_diff": d})
            chk["periods_max_rel_diff"] = worst
            print(f"  check {nm}: OpenSees periods vs numpy {worst:.1e}", file=sys.stderr, flush=True)
            if not entry["inelastic"]:
                ex = check_vs_exact(scn, aux_dt)
                chk["no_contact_vs_exact"] = ex
                print(f"  check {nm}: no contact, dt={aux_dt:g}, vs exact: {ex['max_rel_diff']:.2e}",
                      file=sys.stderr, flush=True)
            results["checks"][nm] = chk
    if args.timing_repeats > 0:
        tn = args.timing_scenario
        tscn = scns.get(tn) or load_scenario(SCENARIO_DIR / f"{tn}.toml")
        tr = [run(tscn, aux_dt, record=False) for _ in range(args.timing_repeats)]
        times, cpus = [r["wall_s"] for r in tr], [r["cpu_s"] for r in tr]
        results["timing"][tn] = {"dt": aux_dt, "steps": tr[0]["steps"], "median_s": statistics.median(times),
                                 "runs_s": times, "median_cpu_s": statistics.median(cpus), "runs_cpu_s": cpus,
                                 "what": "ops.wipe + model build + ops.analyze over the duration, no recorders"}
    print_tables(results)
    Path(args.out).write_text(base.to_json(results))
    print(f"\nwrote {args.out}")


if __name__ == "__main__":
    main()
