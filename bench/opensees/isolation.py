#!/usr/bin/env python3
"""OpenSees peer: base-isolated buildings and bridge decks against walls and each other.

What it does
------------
Reads the scenario files in bench/opensees/scenarios-isolation/*.toml (the Rust
tool's format with the keys `[building.isolator]`, `[[wall]]` and `seat`),
builds each one in OpenSeesPy and integrates it over the record at several
constant time steps:

    ndm = 1, ndf = 1; u relative to the ground, positive to the right.
    Building with [building.isolator]: masses[0] is the base slab (floor 1) on
      the isolator (storey 1), a zeroLength from the building's fixed ground
      node to floor 1 with
        bilinear -> uniaxialMaterial Steel01 Fy=yield_force E0=stiffness b=post_yield_ratio
        linear   -> uniaxialMaterial Elastic stiffness
      and no viscous damping. stiffnesses[j] (0-based) is storey j+2, a linear
      zeroLength (Elastic) from floor j+1 to floor j+2 (1-based floors).
      `clearance` and the isolator `height` do not enter the model (clearance
      is reported against the peak isolator drift).
    Superstructure damping (storeys above the isolator only): Rayleigh with
      ratio damping_ratio (default 0.05) on modes 1 and 2 of the fixed-base
      superstructure (floors 2..n, floor 1 held fixed; one storey: w2 = w1),
      a0 = 2 z w1 w2 / (w1 + w2), a1 = 2 z / (w1 + w2), as explicit dashpots:
      a zeroLength Viscous (c = a1 k_j, alpha = 1) in parallel with each
      storey j >= 2, and a zeroLength Viscous (c = a0 m_i) from floor 1 (i) to
      floor i (j) for i >= 2. No `rayleigh` command, no region; the base slab
      has no other damping.
    [[wall]]: a rigid wall fixed to the ground beside building `facing`, one
      fixed node per struck floor (`floors`, default [1]); a zeroLength from
      the floor (i) to the wall node (j) for side = "right" (strain = -u,
      closes when u > gap), from the wall node (i) to the floor (j) for side =
      "left" (strain = u, closes when u < -gap).
    [[contact]]: a zeroLength from the left building's floor (i) to the right
      building's floor (j) per floor pair (strain = u_R - u_L, closes when
      u_L - u_R > gap); left/right = order of the buildings in the file.
    Contact and wall materials: two_sdof.contact_material (hertzdamp ->
      Hertzdamp Kh xiNorm = 8 (1 - e) / (5 e) -gap n = 1.5; hooke ->
      ElasticPPGap E Fy = -1e20 -gap eta = 0); m_eff (unused by these two) is
      m_L m_R / (m_L + m_R) for a contact and the floor mass for a wall.
    Record: the scenario's file (path relative to the scenario file), Path
      timeSeries (linear between samples, ground at rest at t = 0, 0 after
      the record), UniformExcitation. Newmark average acceleration, Newton,
      NormDispIncr 1e-12 m, the fallbacks of two_sdof.analyze, constant dt,
      over the scenario's duration (the record's, 20 s).

Reported per scenario and dt (JSON, default results-isolation.json): per floor
peak |u| and its time (EnvelopeNode, every step, 17 digits) and u at the end;
per storey (isolator = storey 1) peak |drift| and peak |spring force|
(EnvelopeElement); peak |isolator drift| (= peak |u| of floor 1) against the
clearance; per wall / contact (every step recorded, binary): impacts counted
on the step sequence as open -> closed transitions of penetration > 0 (the
materials' own test, strain < -gap) and of F != 0, peak and minimum force
(F = -stress > 0 compressive), largest penetration, largest opening = max of
the zeroLength strain (contact: u_R - u_L; right wall: -u; left wall: u)
against `seat`; wall-clock and CPU time of the run (with recorders). Then the
relative changes between successive dts (printed as a table) and a timing
section: build + analysis without recorders at dt = 1e-4, median of N runs,
for isolated-4. Check (--checks): isolated-4 with a linear isolator (Fy = 1e20)
and no wall against the exact solution of M u'' + C u' + K u = -M 1 a_g with
C assembled from the dashpots above (matrix-exponential propagator), which
verifies the damping mapping.

    /tmp/opensees-venv/bin/python bench/opensees/near_fault.py        # the record
    /tmp/opensees-venv/bin/python bench/opensees/isolation.py --quick --out /tmp/q.json
    nice -n 10 /tmp/opensees-venv/bin/python bench/opensees/isolation.py
    /tmp/opensees-venv/bin/python bench/opensees/isolation.py --table bench/opensees/results-isolation.json

Peer measurement only: OpenSeesPy and NumPy are never dependencies of the Rust
tool. Needs Python >= 3.11 (tomllib). See README.md, "Isolation, walls and
bridge decks".
"""

from __future__ import annotations

import argparse
import copy
import datetime
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
sys.path.insert(0, str(HERE))
import two_sdof as base  # noqa: E402  (BLAS workaround, contact materials, analysis loop, JSON)
import inelastic as inel  # noqa: E402  (fixed-base matrices and Rayleigh coefficients, envelopes)

ops = base.ops
REPO = base.REPO
SCENARIO_DIR = HERE / "scenarios-isolation"
SCENARIOS = ["block-hertzdamp", "block-hooke", "two-deck", "isolated-4"]
DEFAULT_DTS = [1e-4, 5e-5, 2e-5, 1e-5]
HUGE_FY = 1.0e20
ISOLATOR_KEYS = {"model", "stiffness", "yield_force", "post_yield_ratio", "height", "clearance"}


# --------------------------------------------------------------------------
# Record and scenario
# --------------------------------------------------------------------------
def load_record(gm: dict, scenario_path: Path) -> tuple[float, list[float], float, float, str]:
    """(dt, values from t = 0 in the record's units, factor to m/s^2, duration, path).
    A time-acc file as the Rust tool reads it: `#`/`%` comments and blank lines
    skipped, non-numeric lines before the data are a header, fields split on
    commas, semicolons or whitespace, uniform steps. A record whose first sample
    is at t = dt gets the ground-at-rest value 0 at t = 0 prepended."""
    if "record" in gm:
        path = base.BUILTIN_RECORDS[gm["record"]]
    else:
        path = Path(gm["file"])
        if not path.is_absolute():
            path = (scenario_path.parent / path).resolve()
        if gm.get("format", "time-acc") != "time-acc":
            raise SystemExit(f"{scenario_path}: only time-acc records are supported here")
    t, a = [], []
    for line in Path(path).read_text().splitlines():
        s = line.strip()
        if not s or s[0] in "#%":
            continue
        toks = [x for x in re.split(r"[\s,;]+", s) if x]
        try:
            vals = [float(x) for x in toks]
        except ValueError:
            if t:
                raise SystemExit(f"{path}: non-numeric line after the data: {line!r}")
            continue  # header
        if len(vals) != 2:
            raise SystemExit(f"{path}: expected 2 columns: {line!r}")
        t.append(vals[0])
        a.append(vals[1])
    t, a = np.array(t), np.array(a)
    dt = float(t[1] - t[0])
    if np.max(np.abs(t - (t[0] + dt * np.arange(len(t))))) > 1e-3 * dt:
        raise SystemExit(f"{path}: uneven time step")
    values = [float(x) for x in a]
    if abs(t[0]) < 1e-3 * dt:
        pass
    elif abs(t[0] - dt) < 1e-3 * dt:
        values = [0.0] + values
    else:
        raise SystemExit(f"{path}: first sample at t = {t[0]} is neither 0 nor dt")
    factor = base.UNIT_FACTORS[gm.get("units", "g")] * float(gm.get("scale", 1.0))
    rel = str(Path(path).resolve().relative_to(REPO)) if Path(path).resolve().is_relative_to(REPO) else str(path)
    return dt, values, factor, float(t[-1]), rel


def load_scenario(path: Path) -> dict:
    with open(path, "rb") as f:
        raw = tomllib.load(f)
    return expand(raw, path)


def expand(raw: dict, path: Path) -> dict:
    blds = []
    for b in raw["building"]:
        name, m = b["name"], [float(x) for x in b["masses"]]
        iso = b.get("isolator")
        if iso is None:
            raise SystemExit(f"{path}: building {name!r} has no [building.isolator]; this peer "
                             "handles isolated buildings and decks only (fixed-base: inelastic.py)")
        extra = set(iso) - ISOLATOR_KEYS
        if extra:
            raise SystemExit(f"{path}: building {name!r}: isolator keys {sorted(extra)} not handled "
                             "(no isolator damping in this peer)")
        k = [float(x) for x in b.get("stiffnesses", [])]
        if len(k) != len(m) - 1 or len(b.get("heights", [])) != len(m) - 1:
            raise SystemExit(f"{path}: building {name!r}: with an isolator, stiffnesses and heights "
                             "list the storeys above it (len(masses) - 1 entries)")
        if iso["model"] not in ("bilinear", "linear"):
            raise SystemExit(f"{path}: isolator model {iso['model']!r} not handled")
        isolator = {"model": iso["model"], "k": float(iso["stiffness"])}
        if iso["model"] == "bilinear":
            isolator.update(Fy=float(iso["yield_force"]), b=float(iso.get("post_yield_ratio", 0.0)))
        zeta = float(b.get("damping_ratio", 0.05))
        super_ray = None
        if k:  # fixed-base superstructure: floors 2..n on floor 1 held fixed
            super_ray = inel.rayleigh({"m": m[1:], "storeys": [{"k": x} for x in k], "zeta": zeta})
        z_floors = float(iso.get("height", 0.0)) + np.concatenate(([0.0], np.cumsum(b.get("heights", []))))
        blds.append({"name": name, "m": m, "k_super": k, "isolator": isolator, "zeta": zeta,
                     "clearance": float(iso["clearance"]) if "clearance" in iso else None,
                     "rayleigh": super_ray, "z": z_floors.tolist()})
    index = {b["name"]: i for i, b in enumerate(blds)}
    links = []  # contacts, then walls, in file order
    for c in raw.get("contact", []):
        i, j = sorted(index[x] for x in c["between"])
        L, R = blds[i], blds[j]
        if "floors" in c:
            pairs = [tuple(int(x) for x in p) for p in c["floors"]]
        else:  # every pair of floors at the same height (within 1 mm)
            pairs = [(a + 1, bb + 1) for a in range(len(L["z"])) for bb in range(len(R["z"]))
                     if abs(L["z"][a] - R["z"][bb]) <= 1e-3]
        for fl, fr in pairs:
            links.append({"kind": "contact", "name": f"{L['name']}|{R['name']}", "left": i, "right": j,
                          "floors": [fl, fr], "gap": float(c["gap"]), "raw": c,
                          "seat": float(c["seat"]) if "seat" in c else None,
                          "m_eff": L["m"][fl - 1] * R["m"][fr - 1] / (L["m"][fl - 1] + R["m"][fr - 1])})
    for w in raw.get("wall", []):
        bi = index[w["facing"]]
        if w["side"] not in ("left", "right"):
            raise SystemExit(f"{path}: wall side {w['side']!r}")
        for f in w.get("floors", [1]):
            links.append({"kind": "wall", "name": w.get("name", f"wall-{w['facing']}"), "building": bi,
                          "side": w["side"], "floors": [int(f)], "gap": float(w["gap"]), "raw": w,
                          "seat": float(w["seat"]) if "seat" in w else None, "m_eff": blds[bi]["m"][int(f) - 1]})
    gm = load_record(raw["ground_motion"], path)
    duration = float(raw.get("analysis", {}).get("duration", gm[3]))
    return {"path": path, "raw": raw, "buildings": blds, "links": links, "gm": gm, "duration": duration}


def variant_linear_no_walls(scn: dict) -> dict:
    """The same scenario with every isolator Steel01 at Fy = 1e20 (linear) and no wall or contact."""
    s = copy.deepcopy(scn)
    for b in s["buildings"]:
        if b["isolator"]["model"] == "bilinear":
            b["isolator"]["Fy"] = HUGE_FY
    s["links"] = []
    return s


# --------------------------------------------------------------------------
# OpenSees model
# --------------------------------------------------------------------------
def node_tag(b: int, floor: int) -> int:
    return 1000 * (b + 1) + floor          # floor 0 = the building's ground node


def storey_tag(b: int, j: int) -> int:
    return 1000 * (b + 1) + j              # storey j (1 = isolator): element and spring material


def storey_dashpot_tag(b: int, j: int) -> int:
    return 1000 * (b + 1) + 300 + j        # a1 k_j dashpot in parallel with storey j >= 2


def mass_dashpot_tag(b: int, i: int) -> int:
    return 1000 * (b + 1) + 600 + i        # a0 m_i dashpot from floor 1 to floor i >= 2


def link_tag(n: int) -> int:
    return 100000 + n                      # element and material of link n (contacts, then walls)


def wall_node_tag(n: int) -> int:
    return 200000 + n


def build(scn: dict) -> dict:
    """Build the model (domain wiped first); returns the commands issued (except
    the record's values) and the tags to record."""
    log = []

    def cmd(name, *args):
        getattr(ops, name)(*args)
        log.append([name, *args])

    gm_dt, gm_values, gm_factor, _, _ = scn["gm"]
    ops.wipe()
    cmd("model", "basic", "-ndm", 1, "-ndf", 1)
    floors, storeys = [], []
    for bi, b in enumerate(scn["buildings"]):
        n = len(b["m"])
        cmd("node", node_tag(bi, 0), 0.0)
        cmd("fix", node_tag(bi, 0), 1)
        for f, m in enumerate(b["m"], start=1):
            cmd("node", node_tag(bi, f), 0.0)
            cmd("mass", node_tag(bi, f), m)
            floors.append(node_tag(bi, f))
        iso, tag = b["isolator"], storey_tag(bi, 1)
        if iso["model"] == "bilinear":  # Steel01 Fy E0 b (a1..a4 defaults: no isotropic hardening)
            cmd("uniaxialMaterial", "Steel01", tag, iso["Fy"], iso["k"], iso["b"])
        else:
            cmd("uniaxialMaterial", "Elastic", tag, iso["k"])
        cmd("element", "zeroLength", tag, node_tag(bi, 0), node_tag(bi, 1), "-mat", tag, "-dir", 1)
        storeys.append(tag)
        ray = b["rayleigh"]
        for j in range(2, n + 1):  # storey j joins floor j-1 to floor j; k_super[j-2]
            tag, k = storey_tag(bi, j), b["k_super"][j - 2]
            cmd("uniaxialMaterial", "Elastic", tag, k)
            cmd("element", "zeroLength", tag, node_tag(bi, j - 1), node_tag(bi, j), "-mat", tag, "-dir", 1)
            storeys.append(tag)
            ctag = storey_dashpot_tag(bi, j)
            cmd("uniaxialMaterial", "Viscous", ctag, ray["a1"] * k, 1.0)
            cmd("element", "zeroLength", ctag, node_tag(bi, j - 1), node_tag(bi, j), "-mat", ctag, "-dir", 1)
        for i in range(2, n + 1):
            ctag = mass_dashpot_tag(bi, i)
            cmd("uniaxialMaterial", "Viscous", ctag, ray["a0"] * b["m"][i - 1], 1.0)
            cmd("element", "zeroLength", ctag, node_tag(bi, 1), node_tag(bi, i), "-mat", ctag, "-dir", 1)
    links = []
    for n, lk in enumerate(scn["links"]):
        name, args, _ = base.contact_material(lk["raw"], lk["m_eff"])
        tag = link_tag(n)
        cmd("uniaxialMaterial", name, tag, *args)
        if lk["kind"] == "contact":
            ni, nj = node_tag(lk["left"], lk["floors"][0]), node_tag(lk["right"], lk["floors"][1])
        else:
            floor, wall = node_tag(lk["building"], lk["floors"][0]), wall_node_tag(n)
            cmd("node", wall, 0.0)
            cmd("fix", wall, 1)
            ni, nj = (floor, wall) if lk["side"] == "right" else (wall, floor)
        cmd("element", "zeroLength", tag, ni, nj, "-mat", tag, "-dir", 1)
        links.append(tag)
    ops.timeSeries("Path", 1, "-dt", gm_dt, "-values", *gm_values, "-factor", gm_factor)
    log.append(["timeSeries", "Path", 1, "-dt", gm_dt, "-values", f"<{len(gm_values)} values from t = 0>",
                "-factor", gm_factor])
    cmd("pattern", "UniformExcitation", 1, 1, "-accel", 1)
    cmd("constraints", "Plain")
    cmd("numberer", "Plain")
    cmd("system", "BandGeneral")  # bit-identical to FullGeneral here (checked), slightly faster
    cmd("test", "NormDispIncr", base.TOL, base.MAX_ITER)
    cmd("algorithm", "Newton")
    cmd("integrator", "Newmark", 0.5, 0.25)
    cmd("analysis", "Transient")
    return {"floors": floors, "storeys": storeys, "links": links, "commands": log}


def run(scn: dict, dt: float, record: bool = True) -> dict:
    nsteps = int(round(scn["duration"] / dt))
    if abs(nsteps * dt - scn["duration"]) > 1e-9:
        raise SystemExit(f"dt = {dt} does not divide the duration {scn['duration']}")
    with tempfile.TemporaryDirectory(prefix="opensees-isolation-") as tmp:
        tmp = Path(tmp)
        t0, c0 = time.perf_counter(), time.process_time()
        info = build(scn)
        if record:
            ops.recorder("EnvelopeNode", "-file", str(tmp / "en.txt"), "-precision", 17, "-time",
                         "-node", *info["floors"], "-dof", 1, "disp")
            ops.recorder("EnvelopeElement", "-file", str(tmp / "ed.txt"), "-precision", 17, "-time",
                         "-ele", *info["storeys"], "deformation")
            ops.recorder("EnvelopeElement", "-file", str(tmp / "es.txt"), "-precision", 17, "-time",
                         "-ele", *info["storeys"], "material", "1", "stress")
            if info["links"]:
                ops.recorder("Element", "-binary", str(tmp / "cd.bin"), "-ele", *info["links"], "deformation")
                ops.recorder("Element", "-binary", str(tmp / "cs.bin"), "-ele", *info["links"],
                             "material", "1", "stress")
        fallback = base.analyze(nsteps, dt)
        u_end = [ops.nodeDisp(t, 1) for t in info["floors"]]
        ops.wipe()  # closes and flushes the recorders
        out = {"dt": dt, "steps": nsteps, "wall_s": time.perf_counter() - t0,
               "cpu_s": time.process_time() - c0, "fallback_steps": fallback, "info": info, "u_end": u_end}
        if record:
            out["en"] = inel.read_envelope(tmp / "en.txt")
            out["ed"] = inel.read_envelope(tmp / "ed.txt")
            out["es"] = inel.read_envelope(tmp / "es.txt")
            if info["links"]:
                out["cd"] = base.read_binary_recorder(tmp / "cd.bin", len(info["links"]))
                out["cs"] = base.read_binary_recorder(tmp / "cs.bin", len(info["links"]))
                if not len(out["cd"]) == len(out["cs"]) == nsteps:
                    raise RuntimeError("link recorder length does not match the step count")
    return out


# --------------------------------------------------------------------------
# Post-processing
# --------------------------------------------------------------------------
def peak(env: dict, c: int) -> dict:
    v = env["max"][c] if env["max"][c] >= -env["min"][c] else env["min"][c]
    return {"peak": float(env["abs"][c]), "t": float(round(env["tabs"][c], 9)), "at_peak": float(v)}


def summarise(scn: dict, res: dict) -> dict:
    dt = res["dt"]
    out = {"dt": dt, "steps": res["steps"], "wall_s": res["wall_s"], "cpu_s": res["cpu_s"],
           "fallback_steps": res["fallback_steps"], "buildings": [], "links": []}
    col = 0
    for bi, b in enumerate(scn["buildings"]):
        n = len(b["m"])
        floors = []
        for f in range(n):
            p = peak(res["en"], col + f)
            e = res["en"]
            floors.append({"floor": f + 1, "peak_u": p["peak"], "t": p["t"], "u_at_peak": p["at_peak"],
                           "u_max": float(e["max"][col + f]), "t_u_max": float(round(e["tmax"][col + f], 9)),
                           "u_min": float(e["min"][col + f]), "t_u_min": float(round(e["tmin"][col + f], 9)),
                           "u_end": float(res["u_end"][col + f])})
        storeys = []
        for j in range(n):
            d, F = peak(res["ed"], col + j), peak(res["es"], col + j)
            storeys.append({"storey": j + 1, "kind": "isolator" if j == 0 else "linear",
                            "peak_drift": d["peak"], "t_peak_drift": d["t"],
                            "peak_force": F["peak"], "t_peak_force": F["t"]})
        iso = {"peak_drift": floors[0]["peak_u"], "t": floors[0]["t"], "drift_at_peak": floors[0]["u_at_peak"],
               "residual_drift": floors[0]["u_end"], "peak_force": storeys[0]["peak_force"],
               "clearance": b["clearance"]}
        if b["isolator"]["model"] == "bilinear":
            iso["ductility"] = iso["peak_drift"] / (b["isolator"]["Fy"] / b["isolator"]["k"])
        if b["clearance"] is not None:
            iso["exceeds_clearance"] = bool(iso["peak_drift"] > b["clearance"])
        out["buildings"].append({"name": b["name"], "floors": floors, "storeys": storeys, "isolator": iso})
        col += n
    for n, lk in enumerate(scn["links"]):
        s = res["cd"][:, n]                 # zeroLength strain: u_j - u_i
        closed = s < -lk["gap"]             # the materials' own test (penetration > 0)
        F = 0.0 - res["cs"][:, n]           # > 0 compressive; 0.0 - x: no -0.0 when open
        ipk, iop = int(np.argmax(F)), int(np.argmax(s))
        on = inel.rising_edges(closed)
        off = np.nonzero(~closed & np.concatenate(([False], closed[:-1])))[0]
        per_impact = []  # first step inside (time), first step outside again (time), peak force of the impact
        for k in on:
            later = off[off > k]
            j = int(later[0]) if len(later) else len(F)
            per_impact.append([float(round((k + 1) * dt, 9)),
                               float(round((j + 1) * dt, 9)) if j < len(F) else None, float(F[k:j].max())])
        row = {"kind": lk["kind"], "name": lk["name"], "floors": lk["floors"], "gap": lk["gap"],
               "model": lk["raw"]["model"],
               "impacts": int(len(on)),
               "impacts_force": int(len(inel.rising_edges(F != 0.0))),
               "peak_force": float(F[ipk]), "t_peak_force": float(round((ipk + 1) * dt, 9)) if F[ipk] > 0 else None,
               "min_force": float(F.min()),
               "max_penetration": float(max(0.0, -s.min() - lk["gap"])),
               "steps_in_contact": int(closed.sum()), "closed_at_end": bool(closed[-1]),
               "largest_opening": float(s[iop]), "t_largest_opening": float(round((iop + 1) * dt, 9)),
               "seat": lk["seat"],
               "impact_columns": ["t_first_inside", "t_first_outside", "peak_force"], "impact_list": per_impact}
        if lk["kind"] == "contact":
            row["between"] = [scn["buildings"][lk["left"]]["name"], scn["buildings"][lk["right"]]["name"]]
            row["opening"] = "u_R - u_L"
        else:
            row["facing"] = scn["buildings"][lk["building"]]["name"]
            row["side"] = lk["side"]
            row["opening"] = "-u" if lk["side"] == "right" else "u"
        if lk["seat"] is not None:
            row["opening_exceeds_seat"] = bool(row["largest_opening"] > lk["seat"])
        out["links"].append(row)
    return out


def rel(a: float, b: float) -> float:
    return abs(a - b) / abs(b) if b != 0 else (0.0 if a == 0 else math.inf)


def convergence(runs: list[dict]) -> list[dict]:
    """Relative change of every peak between successive dts (x(dt_a) vs x(dt_b), relative to x(dt_b))."""
    rows = []
    for ra, rb in zip(runs[:-1], runs[1:]):
        floors = [rel(fa["peak_u"], fb["peak_u"]) for ba, bb in zip(ra["buildings"], rb["buildings"])
                  for fa, fb in zip(ba["floors"], bb["floors"])]
        uend = [abs(fa["u_end"] - fb["u_end"]) / fb["peak_u"] for ba, bb in zip(ra["buildings"], rb["buildings"])
                for fa, fb in zip(ba["floors"], bb["floors"])]
        sforce = [rel(sa["peak_force"], sb["peak_force"]) for ba, bb in zip(ra["buildings"], rb["buildings"])
                  for sa, sb in zip(ba["storeys"], bb["storeys"])]
        lf = [rel(la["peak_force"], lb["peak_force"]) for la, lb in zip(ra["links"], rb["links"])
              if lb["peak_force"] > 0]
        lo = [rel(la["largest_opening"], lb["largest_opening"]) for la, lb in zip(ra["links"], rb["links"])]
        rows.append({"dt_a": ra["dt"], "dt_b": rb["dt"],
                     "max_rel_peak_u": max(floors), "rel_peak_u": floors,
                     "max_u_end_change_over_peak": max(uend),
                     "max_rel_storey_force": max(sforce),
                     "rel_link_peak_force": lf, "rel_largest_opening": lo,
                     "max_rel_link_peak_force": max(lf) if lf else None,
                     "impacts_a": [x["impacts"] for x in ra["links"]],
                     "impacts_b": [x["impacts"] for x in rb["links"]],
                     "impacts_equal": [x["impacts"] for x in ra["links"]] == [x["impacts"] for x in rb["links"]]})
        if rows[-1]["impacts_equal"]:  # largest shift of an impact's first step inside, s
            rows[-1]["max_impact_time_shift_s"] = max(
                [abs(ia[0] - ib[0]) for la, lb in zip(ra["links"], rb["links"])
                 for ia, ib in zip(la["impact_list"], lb["impact_list"])], default=0.0)
    return rows


# --------------------------------------------------------------------------
# Check: linear isolator, no walls, against the exact linear solution
# --------------------------------------------------------------------------
def assemble(b: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """M, C, K of an isolated building with a linear isolator (floors 1..n, u relative to the ground),
    C from the dashpots exactly as build() places them."""
    n = len(b["m"])
    M = np.diag(b["m"])
    K = np.zeros((n, n))
    C = np.zeros((n, n))

    def spring(A, i, j, k):  # 0-based floors; i = -1 is the ground
        A[j, j] += k
        if i >= 0:
            A[i, i] += k
            A[i, j] -= k
            A[j, i] -= k
    spring(K, -1, 0, b["isolator"]["k"])
    for j in range(1, n):
        k = b["k_super"][j - 1]
        spring(K, j - 1, j, k)
        spring(C, j - 1, j, b["rayleigh"]["a1"] * k)
        spring(C, 0, j, b["rayleigh"]["a0"] * b["m"][j])
    return M, C, K


def exact_linear(M, C, K, gm, t_end: float, h: float = 1e-5) -> dict:
    """Peak |u| per floor (on a grid h) of M u'' + C u' + K u = -M 1 a_g, a_g piecewise linear
    through the samples, at rest at t = 0: exact propagation of [u, u', a_g, a_g']."""
    gm_dt, values, factor = gm[0], gm[1], gm[2]
    ag = [factor * v for v in values]
    n = len(M)
    powers = inel.propagator(M, C, K, gm_dt, h)
    rows = powers[:, :n, :]
    z = np.zeros(2 * n + 2)
    pk, tk = np.zeros(n), np.zeros(n)
    for j in range(int(round(t_end / gm_dt))):
        z[2 * n], z[2 * n + 1] = (ag[j], (ag[j + 1] - ag[j]) / gm_dt) if j + 1 < len(ag) else (0.0, 0.0)
        u = rows @ z
        i = np.argmax(np.abs(u), axis=0)
        v = np.abs(u[i, np.arange(n)])
        better = v > pk
        pk[better] = v[better]
        tk[better] = j * gm_dt + (i[better] + 1) * h
        z = powers[-1] @ z
    return {"peak_u": pk.tolist(), "t_peak_u": np.round(tk, 9).tolist(), "u_end": z[:n].tolist()}


def damping_check(scn: dict, dt: float) -> dict:
    lin = variant_linear_no_walls(scn)
    s = summarise(lin, run(lin, dt))
    out = {"dt": dt, "what": "every isolator Steel01 with Fy = 1e20, no walls or contacts, vs the exact "
                             "linear solution with C assembled from the dashpots (grid 1e-5 s)", "buildings": []}
    worst = 0.0
    for b, sb in zip(lin["buildings"], s["buildings"]):
        M, C, K = assemble(b)
        ex = exact_linear(M, C, K, lin["gm"], lin["duration"])
        w, V = np.linalg.eig(np.linalg.solve(M, K))
        # modal damping ratios of the whole (isolated) building, for information
        Phi = V[:, np.argsort(w)]
        wn = np.sqrt(np.sort(w.real))
        zeta = [float((Phi[:, r] @ C @ Phi[:, r]) / (2 * wn[r] * (Phi[:, r] @ M @ Phi[:, r])))
                for r in range(len(wn))]
        diffs = [rel(f["peak_u"], e) for f, e in zip(sb["floors"], ex["peak_u"])]
        worst = max(worst, *diffs)
        out["buildings"].append({"name": b["name"], "exact_peak_u": ex["peak_u"], "exact_t_peak_u": ex["t_peak_u"],
                                 "opensees_peak_u": [f["peak_u"] for f in sb["floors"]],
                                 "opensees_t_peak_u": [f["t"] for f in sb["floors"]], "rel_diff": diffs,
                                 "periods_isolated_linear": [float(2 * math.pi / x) for x in wn],
                                 "modal_damping_isolated_linear": zeta,
                                 "rayleigh_fixed_base": b["rayleigh"]})
    out["max_rel_diff_peak_u"] = worst
    return out


# --------------------------------------------------------------------------
# Tables
# --------------------------------------------------------------------------
def g(x, d: int = 6) -> str:
    return "-" if x is None else f"{x:.{d}g}"


def print_tables(res: dict) -> None:
    """Markdown tables (the README's) from a results dict."""
    for name, entry in res["scenarios"].items():
        runs = entry["runs"]
        print(f"\n**{name}** (peak |u| per floor in m; impacts / peak force (N) / largest opening (m) "
              f"per link; CPU s of the run)\n")
        head = ["dt (s)"]
        for b in runs[0]["buildings"]:
            head += [f"{b['name']} fl {f['floor']}" for f in b["floors"]]
        for lk in runs[0]["links"]:
            head += [f"{lk['name']} fl {'/'.join(map(str, lk['floors']))}: impacts", "peak F", "opening"]
        head += ["CPU (s)"]
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for r in runs:
            row = [f"{r['dt']:g}"]
            for b in r["buildings"]:
                row += [g(f["peak_u"], 7) for f in b["floors"]]
            for lk in r["links"]:
                row += [str(lk["impacts"]), g(lk["peak_force"], 7), g(lk["largest_opening"], 7)]
            row += [f"{r['cpu_s']:.1f}"]
            print("| " + " | ".join(row) + " |")
        conv = entry.get("convergence", [])
        if conv:
            print(f"\n{name}: relative change between successive dts (max over floors / storey forces "
                  f"/ link forces / openings; impacts equal)\n")
            print("| dts | peak \\|u\\| | u end / peak | storey force | link peak F | opening | impacts equal "
                  "| impact time shift (s) |")
            print("|---|---|---|---|---|---|---|---|")
            for c in conv:
                print(f"| {c['dt_a']:g} -> {c['dt_b']:g} | {g(c['max_rel_peak_u'], 2)} | "
                      f"{g(c['max_u_end_change_over_peak'], 2)} | "
                      f"{g(c['max_rel_storey_force'], 2)} | {g(c['max_rel_link_peak_force'], 2)} | "
                      f"{g(max(c['rel_largest_opening']) if c['rel_largest_opening'] else None, 2)} | "
                      f"{'yes' if c['impacts_equal'] else 'no ' + str(c['impacts_a']) + ' vs ' + str(c['impacts_b'])} | "
                      f"{g(c.get('max_impact_time_shift_s'), 2)} |")
        r = runs[-1]
        print(f"\n{name}, dt = {r['dt']:g}:")
        for b in r["buildings"]:
            iso = b["isolator"]
            print(f"- {b['name']}: " + "; ".join(
                f"fl {f['floor']} peak |u| {g(f['peak_u'], 7)} m at {f['t']:.5f} s (max {g(f['u_max'], 7)} at "
                f"{f['t_u_max']:.5f}, min {g(f['u_min'], 7)} at {f['t_u_min']:.5f}, end {g(f['u_end'], 7)})"
                for f in b["floors"])
                  + f"; isolator: peak drift {g(iso['peak_drift'], 7)} m (clearance {g(iso['clearance'])}, "
                  f"ductility {g(iso.get('ductility'), 4)}), peak force {g(iso['peak_force'], 7)} N, "
                  f"drift at the end {g(iso['residual_drift'], 5)} m")
        for lk in r["links"]:
            where = (f"contact {lk['between'][0]}|{lk['between'][1]}" if lk["kind"] == "contact"
                     else f"wall {lk['name']} ({lk['side']} of {lk['facing']})")
            print(f"- {where} floors {lk['floors']}, gap {g(lk['gap'])} m: {lk['impacts']} impacts "
                  f"({lk['impacts_force']} by force), peak force {g(lk['peak_force'], 7)} N at "
                  f"{g(lk['t_peak_force'], 8)} s, min force {g(lk['min_force'])}, max penetration "
                  f"{g(lk['max_penetration'], 5)} m, largest opening {g(lk['largest_opening'], 7)} m at "
                  f"{g(lk['t_largest_opening'], 8)} s (seat {g(lk['seat'])}); impacts (first step inside, "
                  f"peak F): " + ", ".join(f"{i[0]:.5f} s {g(i[2], 5)} N" for i in lk["impact_list"]))


def print_converged_table(res: dict) -> None:
    """One markdown table: every reported peak at the smallest dt of each scenario, and its relative
    change from the second-smallest dt, from 1e-5 and from 1e-4 (when run)."""
    print("\n| scenario | quantity | value at the smallest dt | vs the next dt | vs 1e-5 | vs 1e-4 |")
    print("|---|---|---|---|---|---|")
    for name, entry in res["scenarios"].items():
        runs = entry["runs"]
        a = runs[-1]
        others = [runs[-2] if len(runs) > 1 else None,
                  next((r for r in runs if abs(r["dt"] - 1e-5) < 1e-15 and r is not a), None),
                  next((r for r in runs if abs(r["dt"] - 1e-4) < 1e-15 and r is not a), None)]
        rows = []  # (label, getter, significant digits; 0 = integer)
        for bi, b in enumerate(a["buildings"]):
            for fi, f in enumerate(b["floors"]):
                def fl(k, bi=bi, fi=fi):
                    return lambda r: r["buildings"][bi]["floors"][fi][k]
                nm = f"{b['name']} floor {f['floor']}"
                rows += [(f"{nm}: peak \\|u\\| (m) at {f['t']:.4f} s", fl("peak_u"), 7),
                         (f"{nm}: max u (m) at {f['t_u_max']:.4f} s", fl("u_max"), 7),
                         (f"{nm}: min u (m) at {f['t_u_min']:.4f} s", fl("u_min"), 7),
                         (f"{nm}: u at {res['scenarios'][name]['duration']:g} s (m)", fl("u_end"), 6)]
            for si, st in enumerate(b["storeys"]):
                lab = "isolator" if si == 0 else f"storey {si + 1}"
                rows.append((f"{b['name']} {lab}: peak \\|force\\| (N) at {st['t_peak_force']:.4f} s",
                             lambda r, bi=bi, si=si: r["buildings"][bi]["storeys"][si]["peak_force"], 7))
        for li, lk in enumerate(a["links"]):
            nm = (f"contact {lk['between'][0]}\\|{lk['between'][1]}" if lk["kind"] == "contact"
                  else f"wall {lk['name']} ({lk['side']})")
            def li_(k, li=li):
                return lambda r: r["links"][li][k]
            rows += [(f"{nm}: impacts", li_("impacts"), 0),
                     (f"{nm}: peak force (N) at {g(lk['t_peak_force'], 7)} s", li_("peak_force"), 7),
                     (f"{nm}: max penetration (m)", li_("max_penetration"), 6),
                     (f"{nm}: largest opening (m) at {lk['t_largest_opening']:.4f} s (seat {g(lk['seat'])})",
                      li_("largest_opening"), 7)]
        for lab, get, digits in rows:
            v = get(a)
            cells = []
            for o in others:
                if o is None:
                    cells.append("-")
                elif digits == 0:
                    cells.append("same" if get(o) == v else str(get(o)))
                else:
                    cells.append(f"{rel(get(o), v):.1e}")
            val = str(v) if digits == 0 else g(v, digits)
            print(f"| {name} (dt {a['dt']:g}) | {lab} | {val} | " + " | ".join(cells) + " |")


# --------------------------------------------------------------------------
# Main
# --------------------------------------------------------------------------
def short(s: dict) -> str:
    parts = []
    for b in s["buildings"]:
        parts.append(f"{b['name']}: |u|max " + "/".join(g(f["peak_u"]) for f in b["floors"]))
    for lk in s["links"]:
        parts.append(f"{lk['name']}: {lk['impacts']} imp, F {g(lk['peak_force'])}, open {g(lk['largest_opening'])}")
    return "; ".join(parts)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scenarios", default=",".join(SCENARIOS),
                    help="comma-separated scenario names (scenarios-isolation/NAME.toml)")
    ap.add_argument("--dts", default=",".join(f"{d:g}" for d in DEFAULT_DTS), help="time steps, s")
    ap.add_argument("--timing-repeats", type=int, default=3,
                    help="build+analysis runs without recorders at dt = 1e-4 (median) of --timing-scenario; 0 skips")
    ap.add_argument("--timing-scenario", default="isolated-4")
    ap.add_argument("--checks", action=argparse.BooleanOptionalAction, default=True,
                    help="linear isolator without walls vs the exact solution (isolated-4, dt = 1e-4)")
    ap.add_argument("--max-run-seconds", type=float, default=300.0,
                    help="skip a smaller dt when the run predicted from the last one would exceed this")
    ap.add_argument("--quick", action="store_true",
                    help="smoke run: first scenario only, dt = 1e-3; timing (1 run) and check at dt = 1e-3")
    ap.add_argument("--out", default=str(HERE / "results-isolation.json"))
    ap.add_argument("--table", metavar="JSON", help="print the README's markdown tables from a results file, "
                                                    "run nothing")
    args = ap.parse_args()
    if args.table:
        res = json.loads(Path(args.table).read_text())
        print_tables(res)
        print_converged_table(res)
        return
    names = [x.strip() for x in args.scenarios.split(",") if x.strip()]
    dts = [float(x) for x in args.dts.split(",")]
    repeats, aux_dt = args.timing_repeats, 1e-4
    if args.quick:
        names, dts, repeats, aux_dt = names[:1], [1e-3], min(repeats, 1), 1e-3

    ops.logFile(os.devnull, "-noEcho")  # silence the per-impact messages of the contact materials
    results = {
        "about": "OpenSeesPy peer of base-isolated buildings and bridge decks with walls and contacts; "
                 "see bench/opensees/README.md, section 'Isolation, walls and bridge decks (isolation.py)'",
        "generated": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "command": " ".join([Path(sys.argv[0]).name] + sys.argv[1:]),
        "environment": {"openseespy": base._version("openseespy"), "opensees": ops.version(),
                        "numpy": np.__version__, "python": platform.python_version(),
                        "platform": platform.platform(), "cpu": base._cpu_model(), "cpus": os.cpu_count()},
        "analysis": {"integrator": "Newmark gamma=0.5 beta=0.25", "algorithm": "Newton",
                     "test": "NormDispIncr 1e-12 m, max 50 iterations (fallbacks as two_sdof.py)",
                     "system": "BandGeneral", "numberer": "Plain", "constraints": "Plain",
                     "peaks": "max |x| over every step (EnvelopeNode/EnvelopeElement, 17 digits; links: every "
                              "step recorded)",
                     "impacts": "open -> closed transitions of penetration > 0 (zeroLength strain < -gap) on the "
                                "step sequence; impacts_force: of F != 0",
                     "contact force": "F = -stress (> 0 compressive)",
                     "largest_opening": "max over steps of the link's zeroLength strain: contact u_R - u_L, "
                                        "right wall -u, left wall u",
                     "convergence": "relative change x(dt_a) vs x(dt_b), relative to x(dt_b)"},
        "scenarios": {}, "checks": {}, "timing": {}, "notes": [],
    }
    scns = {name: load_scenario(SCENARIO_DIR / f"{name}.toml") for name in names}
    for name, scn in scns.items():
        gm = scn["gm"]
        entry = {"scenario": str((SCENARIO_DIR / f"{name}.toml").relative_to(REPO)),
                 "record": {"file": gm[4], "dt": gm[0], "samples_from_t0": len(gm[1]),
                            "pga_m_s2": max(abs(x) for x in gm[1]) * gm[2]},
                 "duration": scn["duration"],
                 "superstructure_rayleigh": {b["name"]: b["rayleigh"] for b in scn["buildings"] if b["rayleigh"]},
                 "runs": []}
        last = None
        for dt in dts:
            if last is not None:
                predicted = last["wall_s"] * last["dt"] / dt
                if predicted > args.max_run_seconds:
                    note = f"{name}: dt = {dt:g} skipped (predicted {predicted:.0f} s > {args.max_run_seconds:g} s)"
                    results["notes"].append(note)
                    print(note, file=sys.stderr)
                    continue
            res = run(scn, dt)
            entry.setdefault("opensees_commands", res["info"]["commands"])
            s = summarise(scn, res)
            entry["runs"].append(s)
            last = s
            print(f"  {name} dt={dt:g} ({s['wall_s']:.1f} s, fallback steps {s['fallback_steps']}): {short(s)}",
                  file=sys.stderr, flush=True)
        entry["convergence"] = convergence(entry["runs"])
        results["scenarios"][name] = entry

    if args.checks:
        cname = args.timing_scenario
        cscn = scns.get(cname) or load_scenario(SCENARIO_DIR / f"{cname}.toml")
        chk = damping_check(cscn, aux_dt)
        results["checks"][f"{cname}_linear_no_walls_vs_exact"] = chk
        print(f"  check {cname}: linear isolator, no walls, dt={aux_dt:g}: max rel diff of peak |u| vs exact "
              f"{chk['max_rel_diff_peak_u']:.2e}", file=sys.stderr, flush=True)

    if repeats > 0:
        tname = args.timing_scenario
        tscn = scns.get(tname) or load_scenario(SCENARIO_DIR / f"{tname}.toml")
        tr = [run(tscn, aux_dt, record=False) for _ in range(repeats)]
        times, cpus = [r["wall_s"] for r in tr], [r["cpu_s"] for r in tr]
        results["timing"][tname] = {
            "dt": aux_dt, "steps": tr[0]["steps"], "median_s": statistics.median(times), "runs_s": times,
            "median_cpu_s": statistics.median(cpus), "runs_cpu_s": cpus,
            "fallback_steps": [r["fallback_steps"] for r in tr],
            "what": "ops.wipe + model build + ops.analyze over the record (one call), no recorders"}
        print(f"  timing {tname} dt={aux_dt:g}: median {statistics.median(times):.3f} s wall, "
              f"{statistics.median(cpus):.3f} s CPU of {len(times)}", file=sys.stderr, flush=True)

    print_tables(results)
    print_converged_table(results)
    Path(args.out).write_text(base.to_json(results))
    print(f"\nwrote {args.out}")


if __name__ == "__main__":
    main()
