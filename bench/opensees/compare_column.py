#!/usr/bin/env python3
"""Compare `pounding run` with the OpenSees peer of floor-to-column pounding (results-column.json).

For each scenario of scenarios-column/ runs the tool (release build, `--json`) at its default tolerance and at
1e-10 and compares with OpenSees' finest dt of the variant "point" (the tool's model: the struck column as two
massless elasticBeamColumns with the tool's point mass at the struck node) and, to show the modelling
difference, of the variant "distributed" (the column's mass spread along it). Compared: per floor the peak |u|
(summary peak_displacement), per storey the peak |drift| (peak_drift), per site the impact count (summary
sites[].impacts), and the column's demand (sites[].column: peak_force, peak_shear, peak_moment) against the
peer's element forces: the jump of the beams' shear at the struck node, and the whole end shears and moments
of the lowest and highest elements (the load at the point's part and the storey drift's, 12 EI/L^3 and
6 EI/L^2 times the drift, as the tool reports them since 2026-11-27; before, the tool reported the load's part
only and this script compared it with the beams' forces less the drift's part). Also the
column's numbers (point stiffness, point mass) against the peer's closed forms and OpenSees' statics.
Targets: peaks within 0.5 %, impact counts within one per site.

Writes compare-column.json beside this script and prints markdown tables.

    python3 bench/opensees/compare_column.py [--bin target/release/pounding] [--results results-column.json]

Needs only the Python standard library (Python >= 3.11).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
QUANTITIES = ["floor", "drift", "force", "shear", "moment"]


def ours(binary: str, scenario: Path, tol: float | None) -> dict:
    with tempfile.TemporaryDirectory() as d:
        args = [binary, "run", str(scenario), "--out", str(Path(d) / "out"), "--json", "--quiet"]
        if tol is not None:
            args += ["--tolerance", str(tol)]
        return json.loads(subprocess.run(args, check=True, capture_output=True, text=True, cwd=REPO).stdout)


def source_of(binary: str) -> dict:
    """The git checkout the binary was built in (the folder above its target/), and its HEAD commit: the tool
    may be built in a clone of its own, not in this repository."""
    b = Path(binary).resolve()
    for d in b.parents:
        if (d / ".git").exists():
            head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=d, capture_output=True, text=True).stdout.strip()
            return {"checkout": str(d), "git_head": head}
    return {}


def rel(a: float, b: float) -> float:
    return abs(a - b) / abs(b) if b else abs(a - b)


def compare(key: str, ref: dict, s: dict, tol) -> list:
    rows = []

    def add(what, q, got, want):
        rows.append({"case": key, "tolerance": tol, "what": what, "quantity": q, "ours": got, "opensees": want,
                     "rel_diff": rel(got, want) if q != "impacts" else abs(got - want)})

    for rb, sb in zip(ref["buildings"], s["buildings"]):
        assert rb["name"] == sb["name"]
        for i, f in enumerate(rb["floors"]):
            add(f"{rb['name']} floor {i + 1} peak |u| (m)", "floor", sb["peak_displacement"][i], f["peak"])
        for j, f in enumerate(rb["storeys"]):
            add(f"{rb['name']} storey {j + 1} peak |drift| (m)", "drift", sb["peak_drift"][j], f["peak"])
    sites = {x["name"]: x for x in s["sites"]}
    for rc in ref["sites"]:
        sc = sites[rc["name"]]
        col = sc["column"]
        add(f"{rc['name']} impacts", "impacts", sc["impacts"], rc["impacts"])
        add(f"{rc['name']} point force (N)", "force", col["peak_force"], rc["point_force_from_elements"]["peak"])
        for k, end in enumerate(("lower", "upper")):
            # The tool's end forces carry the load at the point and the storey's drift (since 2026-11-27):
            # the beams' whole end forces.
            add(f"{rc['name']} {end} end shear (N)", "shear", col["peak_shear"][k],
                rc["end_shear_total"][k]["peak"])
            add(f"{rc['name']} {end} end moment (N m)", "moment", col["peak_moment"][k],
                rc["end_moment_total"][k]["peak"])
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=str(REPO / "target" / "release" / "pounding"))
    ap.add_argument("--results", default=str(HERE / "results-column.json"))
    ap.add_argument("--out", default=str(HERE / "compare-column.json"))
    a = ap.parse_args()
    res = json.loads(Path(a.results).read_text())
    rows, refs, numbers, totals = [], {}, [], []
    tool_runs = {}
    for key, entry in res["scenarios"].items():
        scn_name, variant = key.split("/")
        scenario = REPO / entry["scenario"]
        ref = min(entry["runs"], key=lambda r: r["dt"])
        refs[key] = f"dt = {ref['dt']:g} s"
        for tol in [None, 1e-10]:
            if (scn_name, tol) not in tool_runs:
                tool_runs[(scn_name, tol)] = ours(a.bin, scenario, tol)
            s = tool_runs[(scn_name, tol)]
            rows += compare(key, ref, s, tol or s["tolerance"])
        if variant == "point":
            s = tool_runs[(scn_name, None)]
            sites = {x["name"]: x for x in s["sites"]}
            for c in res["checks"][scn_name]["columns"]:
                col = sites[c["name"]]["column"]
                numbers.append({"site": c["name"], "tool_stiffness": col["stiffness"],
                                "peer_k_point": c["numbers"]["k_point"],
                                "opensees_statics_k_point": c["opensees_statics"]["k_point"],
                                "tool_point_mass": col["point_mass"], "peer_point_mass": c["numbers"]["point_mass"],
                                "stiffness_rel_diff": rel(col["stiffness"], c["opensees_statics"]["k_point"]),
                                "point_mass_rel_diff": rel(col["point_mass"], c["numbers"]["point_mass"])})
            for rc in ref["sites"]:
                col = sites[rc["name"]]["column"]
                totals.append({"site": rc["name"], "tool_shear": col["peak_shear"], "tool_moment": col["peak_moment"],
                               "opensees_total_shear": [x["peak"] for x in rc["end_shear_total"]],
                               "opensees_total_moment": [x["peak"] for x in rc["end_moment_total"]],
                               "opensees_contact_part_shear": [x["peak"] for x in rc["end_shear_contact_part"]],
                               "closed_form_residual": rc["closed_form_residual"]})
    default = [r for r in rows if r["tolerance"] != 1e-10]
    tight = [r for r in rows if r["tolerance"] == 1e-10]
    summary = {}
    for key in res["scenarios"]:
        summary[key] = {}
        for q in QUANTITIES + ["impacts"]:
            sel = [r for r in default if r["case"] == key and r["quantity"] == q]
            sel_t = [r for r in tight if r["case"] == key and r["quantity"] == q]
            if sel:
                w = max(sel, key=lambda r: r["rel_diff"])
                summary[key][q] = {"max_diff_default": w["rel_diff"], "where": w["what"], "n": len(sel),
                                   "max_diff_1e-10": max(r["rel_diff"] for r in sel_t)}
    ok = {k: {"peaks_within_0.5%": all(r["rel_diff"] <= 5e-3 for r in default if r["case"] == k
                                       and r["quantity"] in QUANTITIES),
              "impacts_within_one_per_site": all(r["rel_diff"] <= 1 for r in default if r["case"] == k
                                                 and r["quantity"] == "impacts")}
          for k in res["scenarios"]}
    tool = {"version": subprocess.run([a.bin, "--version"], capture_output=True, text=True).stdout.strip()}
    tool.update(binary=a.bin, **source_of(a.bin))
    out = {"tool": tool, "opensees_reference": refs, "opensees": res["environment"], "targets_met": ok,
           "worst": summary, "column_numbers": numbers, "end_forces_total_vs_contact_part": totals, "rows": rows}
    Path(a.out).write_text(json.dumps(out, indent=1) + "\n")
    print("| case | OpenSees reference | quantity | n | largest rel. diff (default tol.) | where | at 1e-10 |")
    print("|---|---|---|---|---|---|---|")
    for key, qs in summary.items():
        for q, v in qs.items():
            f = (lambda x: f"{x:g}") if q == "impacts" else (lambda x: f"{x:.1e}")
            print(f"| {key} | {refs[key]} | {q} | {v['n']} | {f(v['max_diff_default'])} | {v['where']} | "
                  f"{f(v['max_diff_1e-10'])} |")
    print("\nimpacts per site (default tolerance): ours / OpenSees")
    for key in res["scenarios"]:
        pts = [r for r in default if r["case"] == key and r["quantity"] == "impacts"]
        print(f"- {key}: " + ", ".join(f"{r['what'].replace(' impacts', '')} {r['ours']}/{r['opensees']}" for r in pts))
    print("\ncolumn numbers: " + "; ".join(f"{n['site']}: k {n['stiffness_rel_diff']:.1e}, m_p "
                                         f"{n['point_mass_rel_diff']:.1e}" for n in numbers))
    print("end forces (lower/upper), tool | OpenSees contact part | OpenSees total (with the drift part):")
    for t in totals:
        print(f"- {t['site']}: shear {t['tool_shear'][0]:.4g}/{t['tool_shear'][1]:.4g} | "
              f"{t['opensees_contact_part_shear'][0]:.4g}/{t['opensees_contact_part_shear'][1]:.4g} | "
              f"{t['opensees_total_shear'][0]:.4g}/{t['opensees_total_shear'][1]:.4g}; moment "
              f"{t['tool_moment'][0]:.4g}/{t['tool_moment'][1]:.4g} | total {t['opensees_total_moment'][0]:.4g}/"
              f"{t['opensees_total_moment'][1]:.4g}; closed-form residual {t['closed_form_residual']:.1e}")
    print("\ntargets:", json.dumps(ok))


if __name__ == "__main__":
    main()
