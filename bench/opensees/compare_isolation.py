#!/usr/bin/env python3
"""Compare `pounding run` with the OpenSees peer on the isolation scenarios (results-isolation.json).

For each scenario of scenarios-isolation/ (an isolated block on a bilinear isolator against a rigid moat wall,
Hertzdamp and ElasticPPGap; a two-deck joint with an abutment; a four-floor isolated building against its moat
wall), runs the tool (release build, `--json`) at its default tolerance and at 1e-10, and compares with
OpenSees at its finest time step (2e-6 s; Newmark average acceleration, second order in dt, and the
convergence table of results-isolation.json shows how far from converged it is): per floor the peak |u|, per
wall and joint the impact count, the peak force and the largest opening. Writes compare-isolation.json
beside this script and prints a markdown table.

    cargo build --release
    python3 bench/opensees/compare_isolation.py [--bin target/release/pounding]

Needs only the Python standard library.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]


def ours(binary: str, scenario: Path, tol: float | None) -> dict:
    with tempfile.TemporaryDirectory() as d:
        args = [binary, "run", str(scenario), "--out", str(Path(d) / "out"), "--json", "--quiet"]
        if tol is not None:
            args += ["--tolerance", str(tol)]
        return json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)


def sites(summary: dict) -> dict:
    """Walls and joints of a summary by the peer's names (`left|right` for a joint)."""
    return {s["name"]: s for s in summary["sites"]}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=str(REPO / "target" / "release" / "pounding"))
    a = ap.parse_args()
    ref = json.loads((HERE / "results-isolation.json").read_text())
    rows = []
    worst = {"peak_u": 0.0, "peak_force": 0.0, "opening": 0.0, "impacts": 0}
    for name, sc in ref["scenarios"].items():
        fine = min(sc["runs"], key=lambda r: r["dt"])
        scenario = HERE / "scenarios-isolation" / f"{name}.toml"
        for tol in [None, 1e-10]:
            s = ours(a.bin, scenario, tol)
            default = tol is None
            for b, rb in enumerate(fine["buildings"]):
                for f, rf in enumerate(rb["floors"]):
                    got = s["buildings"][b]["peak_displacement"][f]
                    d = abs(got - rf["peak_u"]) / rf["peak_u"]
                    rows.append({"scenario": name, "tolerance": tol or s["tolerance"], "what": f"{rb['name']} floor {f + 1} peak |u| (m)",
                                 "ours": got, "opensees": rf["peak_u"], "rel_diff": d})
                    if default:
                        worst["peak_u"] = max(worst["peak_u"], d)
            mine = sites(s)
            for link in fine["links"]:
                c = mine[link["name"]]
                # OpenSees counts impacts on the step sequence; ours are located touches.
                n = c["impacts"] + c.get("consumed", 0)
                rows.append({"scenario": name, "tolerance": tol or s["tolerance"], "what": f"{link['name']} impacts",
                             "ours": n, "opensees": link["impacts"], "rel_diff": abs(n - link["impacts"])})
                for key, theirs, mine_v in [
                    ("peak force (N)", link["peak_force"], c["peak_force"]),
                    ("largest opening (m)", link["largest_opening"], max(c["max_opening"])),
                ]:
                    d = abs(mine_v - theirs) / theirs if theirs else abs(mine_v)
                    rows.append({"scenario": name, "tolerance": tol or s["tolerance"], "what": f"{link['name']} {key}",
                                 "ours": mine_v, "opensees": theirs, "rel_diff": d})
                    if default:
                        k = "peak_force" if key.startswith("peak") else "opening"
                        worst[k] = max(worst[k], d)
                if default:
                    worst["impacts"] = max(worst["impacts"], abs(n - link["impacts"]))
    out = {"opensees_dt": min(r["dt"] for sc in ref["scenarios"].values() for r in sc["runs"]),
           "worst_at_default_tolerance": worst, "rows": rows}
    (HERE / "compare-isolation.json").write_text(json.dumps(out, indent=1) + "\n")
    print("| scenario | quantity | ours (default tolerance) | ours (1e-10) | OpenSees (dt = 2e-6 s) | rel. diff (default) |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        if r["tolerance"] == 1e-10:
            continue
        tight = next(x for x in rows if x["scenario"] == r["scenario"] and x["what"] == r["what"] and x["tolerance"] == 1e-10)
        fmt = (lambda v: str(v)) if isinstance(r["ours"], int) else (lambda v: f"{v:.7g}")
        diff = str(r["rel_diff"]) if isinstance(r["ours"], int) else f"{r['rel_diff']:.1e}"
        print(f"| {r['scenario']} | {r['what']} | {fmt(r['ours'])} | {fmt(tight['ours'])} | {fmt(r['opensees'])} | {diff} |")
    print("\nworst at the default tolerance:", json.dumps(worst))


if __name__ == "__main__":
    main()
