#!/usr/bin/env python3
"""Compare `pounding run` with the OpenSees peer on the buildings-in-plan scenarios (results-plan.json).

For each scenario of scenarios-plan/ (an eccentric 3-storey building beside a 4-storey one, linear and
bilinear lines, Jankowski contacts along x; an eccentric 6-storey building with a 4-storey one north of it,
linear and Bouc-Wen lines, Hertzdamp contacts along y; both ground components), runs the tool (release build,
`--json`) at its default tolerance and at 1e-10 and compares with OpenSees' converged answer: its finest dt
for Elastic and Steel01 lines, and for BoucWen (first order in dt, inelastic.py's finding) the Richardson
extrapolation with p = 1 from its two finest dts, q1 + (q1 - q2) h1 / (h2 - h1). Compared: per floor the peak
|u_x|, |u_y| of the mass centre and the peak |theta|; per floor and corner the peak |u_x|, |u_y|; per line
and storey the peak |drift|; per contact element (floor pair and point) the impact count (impacts.csv); the
periods of the modes in plan (summary.json plan.modes against numpy on the same M, K) and the modes the
damping is fixed on. Without contact (`--no-contact`), the linear scenarios against the exact solution
(results-plan.json checks). Targets: peaks within 0.5 %, impact counts within one per point, periods 1e-6.

Writes compare-plan.json beside this script and prints markdown tables.

    cargo build --release -p pounding-cli
    python3 bench/opensees/compare_plan.py [--bin target/release/pounding] [--results results-plan.json]

Needs only the Python standard library (Python >= 3.11).
"""

from __future__ import annotations

import argparse
import collections
import csv
import json
import re
import subprocess
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
QUANTITIES = ["x", "y", "rotation", "corner x", "corner y", "line drift"]


def ours(binary: str, scenario: Path, tol: float | None, no_contact: bool = False) -> tuple[dict, dict]:
    """The tool's summary and its impacts counted per (contact, floor_left, floor_right, x, y)."""
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "out"
        args = [binary, "run", str(scenario), "--out", str(out), "--json", "--quiet"]
        if tol is not None:
            args += ["--tolerance", str(tol)]
        if no_contact:
            args.append("--no-contact")
        # cwd = the scenario's folder: the tool resolves a relative [ground_motion.y] file against the working
        # directory (only ground_motion.file is made relative to the scenario file; see the README).
        s = json.loads(subprocess.run(args, check=True, capture_output=True, text=True,
                                      cwd=scenario.parent).stdout)
        counts = collections.Counter()
        with open(out / "impacts.csv", newline="") as f:
            for r in csv.DictReader(f):
                key = (r["contact"], int(r["floor_left"]), int(r["floor_right"]),
                       round(float(r["point_x_m"]), 6), round(float(r["point_y_m"]), 6))
                counts[key] += 1
    return s, counts


def variant(scenario: Path, tension_allow: bool, min_impact_velocity: float | None, d: Path) -> Path:
    """A copy of the scenario (record files made absolute) with hertzdamp's tension allowed and/or another
    [analysis] min_impact_velocity: the diagnostics of the differences (README, "Buildings in plan")."""
    lines = []
    for ln in scenario.read_text().splitlines():
        m = re.match(r'^(file\s*=\s*")([^"]+)(".*)$', ln)
        if m and not Path(m.group(2)).is_absolute():
            ln = m.group(1) + str((scenario.parent / m.group(2)).resolve()) + m.group(3)
        lines.append(ln)
        if tension_allow and re.match(r'^model\s*=\s*"hertzdamp"', ln):
            lines.append('tension = "allow"')
        if min_impact_velocity is not None and ln.strip() == "[analysis]":
            lines.append(f"min_impact_velocity = {min_impact_velocity}")
    out = d / scenario.name
    out.write_text("\n".join(lines) + "\n")
    return out


def reference(entry: dict) -> tuple[dict, str]:
    """OpenSees' converged run: the finest dt, or for Bouc-Wen lines the p = 1 extrapolation."""
    runs = sorted(entry["runs"], key=lambda r: r["dt"])
    fine = runs[0]
    if "bouc-wen" not in entry["inelastic"] or len(runs) < 2:
        return fine, f"dt = {fine['dt']:g} s"
    coarse = runs[1]
    h1, h2 = fine["dt"], coarse["dt"]
    w = h1 / (h2 - h1)
    ref = json.loads(json.dumps(fine))

    def ext(a, b):
        return a + (a - b) * w

    for bf, bc, br in zip(fine["buildings"], coarse["buildings"], ref["buildings"]):
        for ff, fc, fr in zip(bf["floors"], bc["floors"], br["floors"]):
            for k in ("peak_x", "peak_y", "peak_rotation"):
                fr[k] = ext(ff[k], fc[k])
            for cf, cc, cr in zip(ff["corners"], fc["corners"], fr["corners"]):
                for k in ("peak_x", "peak_y"):
                    cr[k] = ext(cf[k], cc[k])
        for lf, lc, lr in zip(bf["lines"], bc["lines"], br["lines"]):
            for sf, sc, sr in zip(lf["storeys"], lc["storeys"], lr["storeys"]):
                sr["peak_drift"] = ext(sf["peak_drift"], sc["peak_drift"])
    return ref, f"Richardson p = 1 from dt = {h1:g} and {h2:g} s"


def rel(a: float, b: float) -> float:
    return abs(a - b) / abs(b) if b else abs(a - b)


def compare(name: str, scn_path: Path, entry: dict, ref: dict, s: dict, counts: collections.Counter, tol) -> list:
    rows = []

    def add(what, quantity, got, want):
        rows.append({"scenario": name, "tolerance": tol, "what": what, "quantity": quantity,
                     "ours": got, "opensees": want, "rel_diff": rel(got, want)})

    for rb, sb in zip(ref["buildings"], s["buildings"]):
        p = sb["plan"]
        for f, rf in enumerate(rb["floors"]):
            nm = f"{rb['name']} floor {f + 1}"
            add(f"{nm} peak |u_x| (m)", "x", sb["peak_displacement"][f], rf["peak_x"])
            add(f"{nm} peak |u_y| (m)", "y", p["peak_displacement_y"][f], rf["peak_y"])
            add(f"{nm} peak |theta| (rad)", "rotation", p["peak_rotation"][f], rf["peak_rotation"])
            for k, rc in enumerate(rf["corners"]):
                add(f"{nm} corner {k + 1} peak |u_x| (m)", "corner x", p["peak_corner_x"][f][k], rc["peak_x"])
                add(f"{nm} corner {k + 1} peak |u_y| (m)", "corner y", p["peak_corner_y"][f][k], rc["peak_y"])
        for li, (rl, sl) in enumerate(zip(rb["lines"], p["lines"])):
            for st in rl["storeys"]:
                add(f"{rb['name']} line {li + 1} ({rl['direction']} at {rl['at']:g}) storey {st['storey']} peak |drift| (m)",
                    "line drift", sl["peak_drift"][st["storey"] - 1], st["peak_drift"])
    for c in ref["contacts"]:
        key = (c["site"], c["floors"][0], c["floors"][1], round(c["point"][0], 6), round(c["point"][1], 6))
        n = counts.get(key, 0)
        rows.append({"scenario": name, "tolerance": tol, "quantity": "impacts",
                     "what": f"{c['site']} floors {c['floors'][0]}-{c['floors'][1]} at ({c['point'][0]:g}, {c['point'][1]:g}) impacts",
                     "ours": n, "opensees": c["impacts"], "rel_diff": abs(n - c["impacts"])})
    known = {(c["site"], c["floors"][0], c["floors"][1], round(c["point"][0], 6), round(c["point"][1], 6))
             for c in ref["contacts"]}
    for key, n in counts.items():
        if key not in known:
            rows.append({"scenario": name, "tolerance": tol, "quantity": "impacts", "what": f"{key} impacts (not in OpenSees)",
                         "ours": n, "opensees": 0, "rel_diff": n})
    return rows


def modes_check(name: str, entry: dict, s: dict) -> dict:
    out = {"scenario": name, "buildings": []}
    for eb, sb in zip(entry["buildings"], s["buildings"]):
        tool = [m["period"] for m in sb["plan"]["modes"]]
        d = max(rel(a, b) for a, b in zip(tool, eb["periods"]))
        out["buildings"].append({"name": eb["name"], "periods_tool": tool, "periods_numpy": eb["periods"],
                                 "max_rel_diff": d, "damping_modes_tool": sb["plan"]["damping_modes"],
                                 "damping_modes_peer": eb["damping_modes"],
                                 "damping_modes_equal": list(sb["plan"]["damping_modes"]) == list(eb["damping_modes"])})
    return out


def no_contact_check(name: str, chk: dict, s: dict) -> dict:
    worst = {"x": 0.0, "y": 0.0, "rotation": 0.0, "corner": 0.0}
    for eb, sb in zip(chk["buildings"], s["buildings"]):
        p = sb["plan"]
        for f, fe in enumerate(eb["exact"]["floors"]):
            worst["x"] = max(worst["x"], rel(sb["peak_displacement"][f], fe["peak_x"]))
            worst["y"] = max(worst["y"], rel(p["peak_displacement_y"][f], fe["peak_y"]))
            worst["rotation"] = max(worst["rotation"], rel(p["peak_rotation"][f], fe["peak_rotation"]))
            for k, ce in enumerate(fe["corners"]):
                worst["corner"] = max(worst["corner"], rel(p["peak_corner_x"][f][k], ce["peak_x"]),
                                      rel(p["peak_corner_y"][f][k], ce["peak_y"]))
    return {"scenario": name, "tool_no_contact_vs_exact": worst,
            "opensees_no_contact_vs_exact": chk["max_rel_diff"], "opensees_dt": chk["dt"],
            "exact_grid_s": chk["buildings"][0]["exact"]["h"]}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=str(REPO / "target" / "release" / "pounding"))
    ap.add_argument("--results", default=str(HERE / "results-plan.json"))
    ap.add_argument("--out", default=str(HERE / "compare-plan.json"))
    a = ap.parse_args()
    res = json.loads(Path(a.results).read_text())
    rows, modes, nocontact, refs, diagnostics = [], [], [], {}, []
    for name, entry in res["scenarios"].items():
        scenario = REPO / entry["scenario"]
        ref, how = reference(entry)
        refs[name] = how
        for tol in [None, 1e-10]:
            s, counts = ours(a.bin, scenario, tol)
            t = tol or s["tolerance"]
            rows += compare(name, scenario, entry, ref, s, counts, t)
            if tol is None:
                modes.append(modes_check(name, entry, s))
                rows.append({"scenario": name, "tolerance": t, "quantity": "impacts total", "what": "impacts, all points",
                             "ours": sum(x["impacts"] for x in s["sites"]),
                             "opensees": sum(c["impacts"] for c in ref["contacts"]),
                             "rel_diff": abs(sum(x["impacts"] for x in s["sites"]) - sum(c["impacts"] for c in ref["contacts"]))})
        if '"hertzdamp"' in scenario.read_text():
            for allow, vmin in [(True, None), (False, 1e-4), (True, 1e-4)]:
                with tempfile.TemporaryDirectory() as d:
                    s, counts = ours(a.bin, variant(scenario, allow, vmin, Path(d)), 1e-10)
                w = {}
                for r in compare(name, scenario, entry, ref, s, counts, 1e-10):
                    w[r["quantity"]] = max(w.get(r["quantity"], 0.0), r["rel_diff"])
                diagnostics.append({"scenario": name, "tension": "allow" if allow else "clamp (default)",
                                    "min_impact_velocity": vmin or "1e-3 (default)", "tolerance": 1e-10, "worst": w})
        chk = res.get("checks", {}).get(name, {}).get("no_contact_vs_exact")
        if chk:
            s, _ = ours(a.bin, scenario, None, no_contact=True)
            nocontact.append(no_contact_check(name, chk, s))
    default = [r for r in rows if r["tolerance"] != 1e-10]
    tight = [r for r in rows if r["tolerance"] == 1e-10]
    summary = {}
    for name in res["scenarios"]:
        summary[name] = {}
        for q in QUANTITIES + ["impacts", "impacts total"]:
            sel = [r for r in default if r["scenario"] == name and r["quantity"] == q]
            sel_t = [r for r in tight if r["scenario"] == name and r["quantity"] == q]
            if not sel:
                continue
            w = max(sel, key=lambda r: r["rel_diff"])
            summary[name][q] = {"max_diff_default": w["rel_diff"], "where": w["what"],
                                "max_diff_1e-10": max(r["rel_diff"] for r in sel_t) if sel_t else None, "n": len(sel)}
        summary[name]["impacts ours/opensees"] = [
            next(r["ours"] for r in default if r["scenario"] == name and r["quantity"] == "impacts total"),
            next(r["opensees"] for r in default if r["scenario"] == name and r["quantity"] == "impacts total")]
    ok = {
        "peaks_within_0.5%": all(r["rel_diff"] <= 5e-3 for r in default if r["quantity"] in QUANTITIES),
        "impacts_within_one_per_point": all(r["rel_diff"] <= 1 for r in default if r["quantity"] == "impacts"),
        "periods_within_1e-6": all(b["max_rel_diff"] <= 1e-6 for m in modes for b in m["buildings"]),
        "damping_modes_equal": all(b["damping_modes_equal"] for m in modes for b in m["buildings"]),
    }
    tool = {"version": subprocess.run([a.bin, "--version"], capture_output=True, text=True).stdout.strip()}
    try:
        tool["git_head"] = subprocess.run(["git", "rev-parse", "HEAD"], cwd=REPO, capture_output=True,
                                          text=True).stdout.strip()
    except OSError:
        pass
    out = {"tool": tool, "opensees_reference": refs, "opensees": res["environment"], "targets_met": ok, "worst": summary,
           "modes": modes, "no_contact_vs_exact": nocontact, "diagnostics": diagnostics, "rows": rows}
    Path(a.out).write_text(json.dumps(out, indent=1) + "\n")

    print("| scenario | OpenSees reference | quantity | n | largest rel. diff (default tol.) | where | at 1e-10 |")
    print("|---|---|---|---|---|---|---|")
    for name, qs in summary.items():
        for q, v in qs.items():
            if q == "impacts ours/opensees":
                continue
            fmt = (lambda x: f"{x:g}") if q.startswith("impacts") else (lambda x: f"{x:.1e}")
            print(f"| {name} | {refs[name]} | {q} | {v['n']} | {fmt(v['max_diff_default'])} | {v['where']} | "
                  f"{fmt(v['max_diff_1e-10']) if v['max_diff_1e-10'] is not None else '-'} |")
    print("\nimpacts per point (default tolerance): ours / OpenSees")
    for name in res["scenarios"]:
        pts = [r for r in default if r["scenario"] == name and r["quantity"] == "impacts"]
        print(f"- {name}: " + ", ".join(f"{r['what'].split(' floors ')[1].replace(' impacts', '')} {r['ours']}/{r['opensees']}"
                                        for r in pts if r["ours"] or r["opensees"])
              + f"; total {summary[name]['impacts ours/opensees'][0]}/{summary[name]['impacts ours/opensees'][1]}")
    print("\nmodes:", "; ".join(f"{m['scenario']} {b['name']}: periods {b['max_rel_diff']:.1e}, damping modes "
                               f"{b['damping_modes_tool']} / {b['damping_modes_peer']}" for m in modes for b in m["buildings"]))
    for n in nocontact:
        print(f"no contact vs exact ({n['scenario']}): tool {json.dumps({k: float(f'{v:.2e}') for k, v in n['tool_no_contact_vs_exact'].items()})}, "
              f"OpenSees dt = {n['opensees_dt']:g} {n['opensees_no_contact_vs_exact']:.1e}")
    print("\ndiagnostics (tool at 1e-10 with hertzdamp's tension allowed as in OpenSees, and/or a lower "
          "min_impact_velocity; largest relative differences):")
    for dg in diagnostics:
        print(f"- {dg['scenario']}, tension {dg['tension']}, min_impact_velocity {dg['min_impact_velocity']}: "
              + ", ".join(f"{k} {v:.1e}" for k, v in dg["worst"].items() if not k.startswith("impacts"))
              + f"; impacts per point within {max(v for k, v in dg['worst'].items() if k == 'impacts'):g}")
    print("\ntargets:", json.dumps(ok))


if __name__ == "__main__":
    main()
