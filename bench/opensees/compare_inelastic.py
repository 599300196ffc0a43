#!/usr/bin/env python3
"""Compare `pounding run` with the OpenSees peer on the inelastic scenarios (results-inelastic.json).

For each scenario of scenarios-inelastic/, with and without contact, over the record (31.18 s) and with free
vibration to 45 s, runs the tool (release build, `--json`) at its default tolerance and at 1e-10, and compares
with OpenSees' converged answer: the finest dt (5e-6 s) for Steel01, and for BoucWen (first order in dt) the
Richardson extrapolation 2 q(5e-6) - q(1e-5). Reports per floor the peak |u| (relative difference), the
displacement at the end (difference over the floor's peak), per storey the peak force (relative), and the
impact counts. Writes compare-inelastic.json beside this script and prints a markdown table.

    cargo build --release
    python3 bench/opensees/compare_inelastic.py [--bin target/release/pounding]

Needs only the Python standard library (tomllib: Python >= 3.11).
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]


def opensees_reference(runs: list[dict], window: str, bouc_wen: bool) -> dict:
    """Per building: floors' peak and end displacement, storeys' peak force; contacts' impacts."""
    by_dt = {r["dt"]: r[window] for r in runs}
    fine = by_dt[min(by_dt)]
    coarse = by_dt.get(1e-5)

    def value(get):
        q = get(fine)
        if bouc_wen and coarse is not None:
            return 2.0 * q - get(coarse)
        return q

    # OpenSees counts per floor pair; the tool per contact (all its floor pairs).
    out = {"buildings": [], "impacts": [sum(c["impacts_gap"] for c in fine["contacts"])] if fine["contacts"] else []}
    for b, bf in enumerate(fine["buildings"]):
        floors = [
            {
                "peak_u": value(lambda w, b=b, f=f: w["buildings"][b]["floors"][f]["peak_u"]),
                "end_u": value(lambda w, b=b, f=f: w["buildings"][b]["floors"][f]["residual_u"]),
            }
            for f in range(len(bf["floors"]))
        ]
        storeys = [
            value(lambda w, b=b, j=j: w["buildings"][b]["storeys"][j]["peak_force"])
            for j in range(len(bf["storeys"]))
        ]
        out["buildings"].append({"name": bf["name"], "floors": floors, "peak_force": storeys})
    return out


def ours(binary: str, scenario: Path, contact: bool, duration: float | None, tol: float | None) -> dict:
    text = scenario.read_text()
    if not contact:
        text = text.split("[[contact]]")[0]
    if duration is not None:
        if re.search(r"^duration\s*=", text, re.M):
            text = re.sub(r"^duration\s*=.*$", f"duration = {duration}", text, flags=re.M)
        else:
            text = text.replace("[analysis]\n", f"[analysis]\nduration = {duration}\n")
    with tempfile.TemporaryDirectory() as d:
        f = Path(d) / "s.toml"
        f.write_text(text)
        args = [binary, "run", str(f), "--out", str(Path(d) / "out"), "--json", "--quiet"]
        if tol is not None:
            args += ["--tolerance", str(tol)]
        return json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=str(REPO / "target" / "release" / "pounding"))
    a = ap.parse_args()
    ref = json.loads((HERE / "results-inelastic.json").read_text())
    rows, worst = [], {"peak": 0.0, "end_over_peak": 0.0, "force": 0.0, "impacts": 0}
    for name, sc in ref["scenarios"].items():
        scenario = REPO / sc["scenario"]
        bouc_wen = "bouc-wen" in scenario.read_text()
        for contact, key in [(True, "contact"), (False, "no-contact")]:
            for window, duration in [("record", None), ("long", sc["long_duration"])]:
                os_ref = opensees_reference(sc[key], window, bouc_wen)
                for tol in [None, 1e-10]:
                    s = ours(a.bin, scenario, contact, duration, tol)
                    impacts = [c["impacts"] for c in s["sites"] if c["kind"] == "contact"]
                    for b, (rb, sb) in enumerate(zip(os_ref["buildings"], s["buildings"])):
                        for f, rf in enumerate(rb["floors"]):
                            peak = sb["peak_displacement"][f]
                            end = sb["residual_displacement"][f]
                            d_peak = abs(peak - rf["peak_u"]) / rf["peak_u"]
                            d_end = abs(end - rf["end_u"]) / rf["peak_u"]
                            d_force = abs(sb["peak_storey_shear"][f] - rb["peak_force"][f]) / rb["peak_force"][f]
                            rows.append({
                                "scenario": name, "contact": contact, "window": window,
                                "tolerance": tol or s["tolerance"], "building": rb["name"], "floor": f + 1,
                                "peak_u": peak, "peak_u_opensees": rf["peak_u"], "peak_rel_diff": d_peak,
                                "end_u": end, "end_u_opensees": rf["end_u"], "end_diff_over_peak": d_end,
                                "peak_force": sb["peak_storey_shear"][f], "peak_force_opensees": rb["peak_force"][f],
                                "force_rel_diff": d_force,
                                "impacts": impacts, "impacts_opensees": os_ref["impacts"],
                            })
                            if tol is None:
                                worst["peak"] = max(worst["peak"], d_peak)
                                worst["end_over_peak"] = max(worst["end_over_peak"], d_end)
                                worst["force"] = max(worst["force"], d_force)
                    if tol is None and contact:
                        worst["impacts"] = max(
                            [worst["impacts"]] + [abs(x - y) for x, y in zip(impacts, os_ref["impacts"])]
                        )
    (HERE / "compare-inelastic.json").write_text(json.dumps({"worst_at_default_tolerance": worst, "rows": rows}, indent=1) + "\n")
    print("| scenario | contact | window | building | floor | peak \\|u\\| ours (m) | OpenSees | rel. diff | end u ours (m) | OpenSees | diff / peak | peak storey force rel. diff | impacts ours / OpenSees |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if r["tolerance"] != 1e-10 and (r["floor"] == 1 or r["building"] == "8-storey" and r["floor"] == 8 or r["building"] == "3-storey" and r["floor"] == 3):
            print(f"| {r['scenario']} | {'yes' if r['contact'] else 'no'} | {r['window']} | {r['building']} | {r['floor']} | "
                  f"{r['peak_u']:.6g} | {r['peak_u_opensees']:.6g} | {r['peak_rel_diff']:.1e} | {r['end_u']:.6g} | "
                  f"{r['end_u_opensees']:.6g} | {r['end_diff_over_peak']:.1e} | {r['force_rel_diff']:.1e} | "
                  f"{'/'.join(map(str, r['impacts']))} / {'/'.join(map(str, r['impacts_opensees']))} |")
    print("\nworst at the default tolerance:", json.dumps(worst))
    tight = [r for r in rows if r["tolerance"] == 1e-10]
    print("worst at 1e-10:", json.dumps({
        "peak": max(r["peak_rel_diff"] for r in tight),
        "end_over_peak": max(r["end_diff_over_peak"] for r in tight),
        "force": max(r["force_rel_diff"] for r in tight),
    }))


if __name__ == "__main__":
    main()
