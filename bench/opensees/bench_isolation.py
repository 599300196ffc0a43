#!/usr/bin/env python3
"""Speed against OpenSeesPy (issue 13): an isolated building against its moat wall under a near-fault record.

The scenario is scenarios-isolation/isolated-4.toml (a base slab and three floors on a bilinear isolator, a
Hertzdamp moat wall, the near-fault record of records/near-fault.txt, 20 s). Both sides are timed in this one
process and session, alternately, as the work a study repeats: OpenSeesPy builds the model and runs it at
dt = 1e-4 s without recorders (isolation.run(..., record=False)); pounding runs the scenario dict without
histories (pounding.run(..., histories=False): it still locates every event and keeps every peak, impact and
the energy balance). The accuracy of each is its largest relative difference from OpenSees at dt = 2e-6 s
(results-isolation.json) over the floors' peak |u| and the wall's peak force.

    /tmp/opensees-venv/bin/pip install openseespy numpy ./crates/pounding-py
    /tmp/opensees-venv/bin/python bench/opensees/bench_isolation.py [--repeat 5]

Writes bench-isolation.json beside this script.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import isolation  # noqa: E402  (the OpenSees peer; imports openseespy)
import pounding  # noqa: E402

SCENARIO = HERE / "scenarios-isolation" / "isolated-4.toml"


def errors(floors: list[float], force: float, ref: dict) -> float:
    """Largest relative difference from the converged OpenSees run `ref`."""
    out = [abs(u - f["peak_u"]) / f["peak_u"] for u, f in zip(floors, ref["buildings"][0]["floors"])]
    out.append(abs(force - ref["links"][0]["peak_force"]) / ref["links"][0]["peak_force"])
    return max(out)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=5, help="OpenSees runs (median); pounding runs 20 times as many")
    a = ap.parse_args()
    ref_all = json.loads((HERE / "results-isolation.json").read_text())["scenarios"]["isolated-4"]["runs"]
    ref = min(ref_all, key=lambda r: r["dt"])
    at_1e4 = next(r for r in ref_all if r["dt"] == 1e-4)
    scn = isolation.load_scenario(SCENARIO)
    doc = pounding.load_scenario(SCENARIO)
    r = pounding.run(doc, histories=False)  # warm-up, and its accuracy
    ours_err = errors(r.summary["buildings"][0]["peak_displacement"], next(w for w in r.summary["sites"] if w["kind"] == "wall")["peak_force"], ref)
    os_err = errors([f["peak_u"] for f in at_1e4["buildings"][0]["floors"]], at_1e4["links"][0]["peak_force"], ref)
    t_os, t_ours = [], []
    for _ in range(a.repeat):
        t0 = time.perf_counter()
        isolation.run(scn, 1e-4, record=False)
        t_os.append(time.perf_counter() - t0)
        for _ in range(20):
            t0 = time.perf_counter()
            pounding.run(doc, histories=False)
            t_ours.append(time.perf_counter() - t0)
    out = {
        "scenario": str(SCENARIO.relative_to(HERE.parents[1])),
        "opensees_dt": 1e-4,
        "opensees_median_s": statistics.median(t_os),
        "opensees_runs_s": t_os,
        "pounding_median_s": statistics.median(t_ours),
        "pounding_min_s": min(t_ours),
        "ratio_of_medians": statistics.median(t_os) / statistics.median(t_ours),
        "accuracy_vs_opensees_2e-6": {"pounding_default_tolerance": ours_err, "opensees_dt_1e-4": os_err},
        "pounding_steps": r.summary["statistics"]["steps"],
        "what": "OpenSeesPy: build + analyze at dt = 1e-4 s without recorders; pounding: pounding.run(dict, histories=False), same process, alternately",
    }
    (HERE / "bench-isolation.json").write_text(json.dumps(out, indent=1) + "\n")
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
