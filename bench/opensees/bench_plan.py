#!/usr/bin/env python3
"""Speed against OpenSeesPy: buildings in plan, scenario (a) (scenarios-plan/three-linear.toml).

An eccentric 3-storey building beside a 4-storey one, 9 + 12 dofs in plan, 32 linear line storeys, 6 Jankowski
contact elements, two ground components, 20 s. Both sides are timed in this one process and session,
alternately:

- the tool: the whole command `pounding run three-linear.toml --out DIR --quiet` (release build; process start,
  reading the scenario and records, the run, and writing summary.json, response.csv, impacts.csv,
  impact-loops.csv and energy.csv), wall time by time.perf_counter around subprocess.run;
- OpenSeesPy: plan.run(..., record=False) at dt = 1e-4 s: ops.wipe, model build and ops.analyze over the 20 s
  (200 000 steps) without recorders.

Accuracy of each: the largest relative difference over every floor's peak |u_x|, |u_y|, |theta| and corner
peak from OpenSees' converged run in results-plan.json (its finest dt); for the tool at its default tolerance,
for OpenSees at dt = 1e-4.

    /tmp/opensees-venv/bin/python bench/opensees/bench_plan.py [--repeat 3] [--bin target/release/pounding]

Writes bench-plan.json beside this script.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import plan  # noqa: E402  (the OpenSees peer; imports openseespy)

NAME = "three-linear"
SCENARIO = HERE / "scenarios-plan" / f"{NAME}.toml"


def peaks_os(s: dict) -> list[float]:
    out = []
    for b in s["buildings"]:
        for f in b["floors"]:
            out += [f["peak_x"], f["peak_y"], f["peak_rotation"]]
            out += [c[k] for c in f["corners"] for k in ("peak_x", "peak_y")]
    return out


def peaks_tool(s: dict) -> list[float]:
    out = []
    for b in s["buildings"]:
        p = b["plan"]
        for f in range(len(b["peak_displacement"])):
            out += [b["peak_displacement"][f], p["peak_displacement_y"][f], p["peak_rotation"][f]]
            out += [v for k in range(4) for v in (p["peak_corner_x"][f][k], p["peak_corner_y"][f][k])]
    return out


def worst(a: list[float], ref: list[float]) -> float:
    return max(abs(x - y) / abs(y) for x, y in zip(a, ref))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3, help="OpenSees runs (median); the tool runs 10 times as many")
    ap.add_argument("--bin", default=str(HERE.parents[1] / "target" / "release" / "pounding"))
    a = ap.parse_args()
    plan.ops.logFile(os.devnull, "-noEcho")
    runs = json.loads((HERE / "results-plan.json").read_text())["scenarios"][NAME]["runs"]
    ref = peaks_os(min(runs, key=lambda r: r["dt"]))
    at_1e4 = next(r for r in runs if r["dt"] == 1e-4)
    scn = plan.load_scenario(SCENARIO)
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "out"
        cmd = [a.bin, "run", SCENARIO.name, "--out", str(out), "--quiet"]
        # cwd = the scenario's folder (its [ground_motion.y] file is relative; see README.md)
        subprocess.run(cmd, check=True, cwd=SCENARIO.parent, capture_output=True)  # warm-up (file cache)
        tool_err = worst(peaks_tool(json.loads((out / "summary.json").read_text())), ref)
        t_os, t_tool = [], []
        for _ in range(a.repeat):
            t0 = time.perf_counter()
            plan.run(scn, 1e-4, record=False)
            t_os.append(time.perf_counter() - t0)
            for _ in range(10):
                t0 = time.perf_counter()
                subprocess.run(cmd, check=True, cwd=SCENARIO.parent, capture_output=True)
                t_tool.append(time.perf_counter() - t0)
        steps = json.loads((out / "summary.json").read_text())["statistics"]
    res = {
        "scenario": str(SCENARIO.relative_to(HERE.parents[1])),
        "opensees_dt": 1e-4,
        "opensees_steps": int(round(scn["duration"] / 1e-4)),
        "opensees_median_s": statistics.median(t_os),
        "opensees_runs_s": t_os,
        "pounding_command": " ".join(["pounding", "run", SCENARIO.name, "--out", "DIR", "--quiet"]),
        "pounding_median_s": statistics.median(t_tool),
        "pounding_min_s": min(t_tool),
        "pounding_runs_s": t_tool,
        "ratio_of_medians": statistics.median(t_os) / statistics.median(t_tool),
        "accuracy_vs_opensees_finest": {"pounding_default_tolerance": tool_err,
                                        "opensees_dt_1e-4": worst(peaks_os(at_1e4), ref),
                                        "reference_dt": min(r["dt"] for r in runs)},
        "pounding_statistics": steps,
        "environment": {"opensees": plan.ops.version(), "python": platform.python_version(),
                        "cpu": plan.base._cpu_model(), "cpus": os.cpu_count(), "platform": platform.platform()},
        "what": "wall time; OpenSeesPy: build + analyze at dt = 1e-4 s without recorders (plan.run(record=False)); "
                "pounding: the whole CLI command (release), writing its files; alternately, same process",
    }
    (HERE / "bench-plan.json").write_text(json.dumps(res, indent=1) + "\n")
    print(json.dumps(res, indent=1))


if __name__ == "__main__":
    main()
