#!/usr/bin/env python3
"""Compare `pounding run` with the OpenSees peer on the soil and multi-support scenarios (results-soil.json).

For each scenario of scenarios-soil/ ((a) soil-linear: a 3-storey and a 2-storey building on foundations over
soft soil, Jankowski contacts; (b) soil-bilinear: the same with bilinear storeys; (c) bridge-wave: two decks on
piers under wave passage, an abutment wall on the scenario's ground and one on a support with a record of its
own; (d) soil-wave: (a)'s buildings, one on springs given directly, the other on a support 0.1 s late), runs the
tool (release build, `--json`) at its default tolerance and at 1e-10 and compares with OpenSees' converged
answer (its finest dt; every law here is Elastic, Steel01 or a contact material, second order or close to it).
Compared: per floor the peak |w| relative to the building's own support (summary peak_displacement), per storey
the peak |drift| (peak_drift, the rocking left out), per foundation the peak sway and rocking (foundation.
peak_sway, peak_rocking), per contact element (contact floor pair, or wall and floor) the impact count
(impacts.csv). Also: the foundation's numbers (mass, inertia, springs, dashpots) and periods on the foundation
(foundation.flexible_periods) against the peer's formulas and numpy on the same M, K; without contact
(`--no-contact`), the linear scenarios against the exact solution (results-soil.json checks). Targets: peaks
within 0.5 %, impact counts within one per contact element, foundation numbers and periods within 1e-9.

Writes compare-soil.json beside this script and prints markdown tables.

    cargo build --release -p pounding-cli
    python3 bench/opensees/compare_soil.py [--bin target/release/pounding] [--results results-soil.json]

Needs only the Python standard library (Python >= 3.11).
"""

from __future__ import annotations

import argparse
import collections
import csv
import json
import subprocess
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
QUANTITIES = ["floor", "drift", "sway", "rocking"]
FOUNDATION_KEYS = ["mass", "inertia", "kx", "ktheta", "cx", "ctheta"]


def ours(binary: str, scenario: Path, tol: float | None, no_contact: bool = False) -> tuple[dict, dict]:
    """The tool's summary and its impacts counted per (contact, floor_left, floor_right) of impacts.csv."""
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "out"
        args = [binary, "run", str(scenario), "--out", str(out), "--json", "--quiet"]
        if tol is not None:
            args += ["--tolerance", str(tol)]
        if no_contact:
            args.append("--no-contact")
        s = json.loads(subprocess.run(args, check=True, capture_output=True, text=True, cwd=REPO).stdout)
        counts = collections.Counter()
        with open(out / "impacts.csv", newline="") as f:
            for r in csv.DictReader(f):
                counts[(r["contact"], r["floor_left"], r["floor_right"])] += 1
    return s, counts


def link_key(lk: dict, side: str | None) -> tuple:
    """impacts.csv's key of an OpenSees contact element: (name, floor_left, floor_right); a wall on the left of
    its building has the building's floor on the right, and the reverse."""
    if lk["kind"] == "contact":
        return (lk["name"], str(lk["floors"][0]), str(lk["floors"][1]))
    f = str(lk["floors"][0])
    return (lk["name"], "", f) if side == "left" else (lk["name"], f, "")


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


def wall_sides(scenario: Path) -> dict:
    import tomllib
    raw = tomllib.loads(scenario.read_text())
    return {w["name"]: w["side"] for w in raw.get("wall", [])}


def compare(name: str, ref: dict, s: dict, counts: collections.Counter, sides: dict, tol) -> list:
    rows = []

    def add(what, quantity, got, want):
        rows.append({"scenario": name, "tolerance": tol, "what": what, "quantity": quantity,
                     "ours": got, "opensees": want, "rel_diff": rel(got, want)})

    for rb, sb in zip(ref["buildings"], s["buildings"]):
        if rb["name"] != sb["name"]:
            raise SystemExit(f"{name}: building order differs: {rb['name']} / {sb['name']}")
        for i, f in enumerate(rb["floors"]):
            add(f"{rb['name']} floor {i + 1} peak |w| (m)", "floor", sb["peak_displacement"][i], f["peak"])
        for j, st in enumerate(rb["storeys"]):
            add(f"{rb['name']} storey {j + 1} peak |drift| (m)", "drift", sb["peak_drift"][j], st["peak"])
        if "sway" in rb:
            fd = sb["foundation"]
            add(f"{rb['name']} foundation peak |sway| (m)", "sway", fd["peak_sway"], rb["sway"]["peak"])
            add(f"{rb['name']} foundation peak |rocking| (rad)", "rocking", fd["peak_rocking"], rb["rocking"]["peak"])
    known = set()
    for lk in ref["links"]:
        key = link_key(lk, sides.get(lk["name"]))
        known.add(key)
        n = counts.get(key, 0)
        rows.append({"scenario": name, "tolerance": tol, "quantity": "impacts",
                     "what": f"{lk['kind']} {lk['name']} floors {'-'.join(map(str, lk['floors']))} impacts",
                     "ours": n, "opensees": lk["impacts"], "rel_diff": abs(n - lk["impacts"])})
    for key, n in counts.items():
        if key not in known:
            rows.append({"scenario": name, "tolerance": tol, "quantity": "impacts", "what": f"{key} impacts (not in OpenSees)",
                         "ours": n, "opensees": 0, "rel_diff": n})
    return rows


def foundation_check(name: str, entry: dict, s: dict) -> list:
    out = []
    for eb, sb in zip(entry["buildings"], s["buildings"]):
        if not eb["foundation"]:
            continue
        fd = sb["foundation"]
        numbers = {k: rel(fd[k], eb["foundation"][k]) for k in FOUNDATION_KEYS}
        per = max(rel(a, b) for a, b in zip(fd["flexible_periods"], eb["periods_numpy"]))
        out.append({"scenario": name, "building": eb["name"], "numbers_rel_diff": numbers,
                    "numbers_max_rel_diff": max(numbers.values()), "tool": {k: fd[k] for k in FOUNDATION_KEYS},
                    "periods_tool": fd["flexible_periods"], "periods_numpy": eb["periods_numpy"],
                    "periods_max_rel_diff": per, "n_periods": [len(fd["flexible_periods"]), len(eb["periods_numpy"])]})
    return out


def no_contact_check(name: str, chk: dict, s: dict) -> dict:
    worst = {q: 0.0 for q in QUANTITIES}
    for eb, sb in zip(chk["buildings"], s["buildings"]):
        ex = eb["exact"]
        for i, x in enumerate(ex["floors"]):
            worst["floor"] = max(worst["floor"], rel(sb["peak_displacement"][i], x))
        for j, x in enumerate(ex["storeys"]):
            worst["drift"] = max(worst["drift"], rel(sb["peak_drift"][j], x))
        if "sway" in ex:
            worst["sway"] = max(worst["sway"], rel(sb["foundation"]["peak_sway"], ex["sway"]))
            worst["rocking"] = max(worst["rocking"], rel(sb["foundation"]["peak_rocking"], ex["rocking"]))
    return {"scenario": name, "tool_no_contact_vs_exact": worst, "opensees_no_contact_vs_exact": chk["max_rel_diff"],
            "opensees_dt": chk["dt"], "exact_grid_s": chk["buildings"][0]["exact"]["h"]}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=str(REPO / "target" / "release" / "pounding"))
    ap.add_argument("--results", default=str(HERE / "results-soil.json"))
    ap.add_argument("--out", default=str(HERE / "compare-soil.json"))
    a = ap.parse_args()
    res = json.loads(Path(a.results).read_text())
    rows, founds, nocontact, refs = [], [], [], {}
    for name, entry in res["scenarios"].items():
        scenario = REPO / entry["scenario"]
        sides = wall_sides(scenario)
        ref = min(entry["runs"], key=lambda r: r["dt"])
        refs[name] = f"dt = {ref['dt']:g} s"
        for tol in [None, 1e-10]:
            s, counts = ours(a.bin, scenario, tol)
            t = tol or s["tolerance"]
            rows += compare(name, ref, s, counts, sides, t)
            if tol is None:
                founds += foundation_check(name, entry, s)
                tot_o = sum(counts.values())
                tot_p = sum(lk["impacts"] for lk in ref["links"])
                rows.append({"scenario": name, "tolerance": t, "quantity": "impacts total", "what": "impacts, all elements",
                             "ours": tot_o, "opensees": tot_p, "rel_diff": abs(tot_o - tot_p)})
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
    ok = {
        "peaks_within_0.5%": all(r["rel_diff"] <= 5e-3 for r in default if r["quantity"] in QUANTITIES),
        "impacts_within_one_per_element": all(r["rel_diff"] <= 1 for r in default if r["quantity"] == "impacts"),
        "foundation_numbers_within_1e-9": all(f["numbers_max_rel_diff"] <= 1e-9 for f in founds),
        "periods_within_1e-9": all(f["periods_max_rel_diff"] <= 1e-9 for f in founds),
    }
    tool = {"version": subprocess.run([a.bin, "--version"], capture_output=True, text=True).stdout.strip()}
    tool.update(binary=a.bin, **source_of(a.bin))
    out = {"tool": tool, "opensees_reference": refs, "opensees": res["environment"], "targets_met": ok,
           "worst": summary, "foundations": founds, "no_contact_vs_exact": nocontact, "rows": rows}
    Path(a.out).write_text(json.dumps(out, indent=1) + "\n")

    print("| scenario | OpenSees reference | quantity | n | largest rel. diff (default tol.) | where | at 1e-10 |")
    print("|---|---|---|---|---|---|---|")
    for name, qs in summary.items():
        for q, v in qs.items():
            fmt = (lambda x: f"{x:g}") if q.startswith("impacts") else (lambda x: f"{x:.1e}")
            print(f"| {name} | {refs[name]} | {q} | {v['n']} | {fmt(v['max_diff_default'])} | {v['where']} | "
                  f"{fmt(v['max_diff_1e-10']) if v['max_diff_1e-10'] is not None else '-'} |")
    print("\nimpacts per contact element (default tolerance): ours / OpenSees")
    for name in res["scenarios"]:
        pts = [r for r in default if r["scenario"] == name and r["quantity"] == "impacts"]
        print(f"- {name}: " + ", ".join(f"{r['what'].replace(' impacts', '')} {r['ours']}/{r['opensees']}" for r in pts))
    print("\nfoundations: " + "; ".join(f"{f['scenario']} {f['building']}: numbers {f['numbers_max_rel_diff']:.1e}, "
                                       f"periods {f['periods_max_rel_diff']:.1e}" for f in founds))
    for n in nocontact:
        print(f"no contact vs exact ({n['scenario']}): tool {json.dumps({k: float(f'{v:.2e}') for k, v in n['tool_no_contact_vs_exact'].items()})}, "
              f"OpenSees dt = {n['opensees_dt']:g} {n['opensees_no_contact_vs_exact']:.1e}")
    print("\ntargets:", json.dumps(ok))


if __name__ == "__main__":
    main()
