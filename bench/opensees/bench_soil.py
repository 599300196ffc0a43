#!/usr/bin/env python3
"""Speed against OpenSeesPy: soil-structure interaction, scenario (a) (scenarios-soil/soil-linear.toml).

A 3-storey building on a rectangular mat and a 2-storey building on a disk over soft soil (5 + 4 dofs: floors,
sway and rocking), linear storeys, two Jankowski contact elements, El Centro, 20 s. Both sides are timed in this
one process and session, alternately:

- the tool: the whole command `pounding run soil-linear.toml --out DIR --quiet` (release build; process start,
  reading the scenario, the run, and writing summary.json, response.csv, impacts.csv, impact-loops.csv and
  energy.csv), wall time by time.perf_counter around subprocess.run;
- OpenSeesPy: soil.run(..., record=False) at dt = 1e-4 s: ops.wipe, model build and ops.analyze over the 20 s
  (200 000 steps) without recorders.

Wall times of both, and CPU times (OpenSeesPy: this process's; the tool: the child's user + sys time from
getrusage), the CPU ratio being the steadier figure on a loaded machine. Accuracy of each: the largest relative difference over every floor's peak |w|, storey's peak drift and
foundation's peak sway and rocking from OpenSees' converged run in results-soil.json (its finest dt); for the
tool at its default tolerance, for OpenSees at dt = 1e-4.

    nice -n 10 /tmp/opensees-venv/bin/python bench/opensees/bench_soil.py [--repeat 3] [--bin target/release/pounding]

Writes bench-soil.json beside this script.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import soil  # noqa: E402  (the OpenSees peer; imports openseespy)

NAME = "soil-linear"
SCENARIO = HERE / "scenarios-soil" / f"{NAME}.toml"


def peaks_os(s: dict) -> list[float]:
    out = []
    for b in s["buildings"]:
        out += [f["peak"] for f in b["floors"]] + [x["peak"] for x in b["storeys"]]
        if "sway" in b:
            out += [b["sway"]["peak"], b["rocking"]["peak"]]
    return out


def peaks_tool(s: dict) -> list[float]:
    out = []
    for b in s["buildings"]:
        out += list(b["peak_displacement"]) + list(b["peak_drift"])
        if b.get("foundation"):
            out += [b["foundation"]["peak_sway"], b["foundation"]["peak_rocking"]]
    return out


def worst(a: list[float], ref: list[float]) -> float:
    return max(abs(x - y) / abs(y) for x, y in zip(a, ref))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3, help="OpenSees runs (median); the tool runs 10 times as many")
    ap.add_argument("--bin", default=str(HERE.parents[1] / "target" / "release" / "pounding"))
    a = ap.parse_args()
    soil.ops.logFile(os.devnull, "-noEcho")
    runs = json.loads((HERE / "results-soil.json").read_text())["scenarios"][NAME]["runs"]
    ref = peaks_os(min(runs, key=lambda r: r["dt"]))
    at_1e4 = next(r for r in runs if r["dt"] == 1e-4)
    scn = soil.load_scenario(SCENARIO)
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "out"
        cmd = [a.bin, "run", str(SCENARIO), "--out", str(out), "--quiet"]
        subprocess.run(cmd, check=True, capture_output=True)  # warm-up (file cache)
        tool_err = worst(peaks_tool(json.loads((out / "summary.json").read_text())), ref)
        t_os, cpu_os, t_tool, cpu_tool = [], [], [], []
        for _ in range(a.repeat):
            r = soil.run(scn, 1e-4, record=False)
            t_os.append(r["wall_s"])
            cpu_os.append(r["cpu_s"])
            for _ in range(10):
                r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
                t0 = time.perf_counter()
                subprocess.run(cmd, check=True, capture_output=True)
                t_tool.append(time.perf_counter() - t0)
                r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpu_tool.append((r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime))
        stats = json.loads((out / "summary.json").read_text())["statistics"]
    res = {
        "scenario": str(SCENARIO.relative_to(HERE.parents[1])),
        "opensees_dt": 1e-4,
        "opensees_steps": int(round(scn["duration"] / 1e-4)),
        "opensees_median_s": statistics.median(t_os),
        "opensees_runs_s": t_os,
        "opensees_median_cpu_s": statistics.median(cpu_os),
        "pounding_command": "pounding run soil-linear.toml --out DIR --quiet",
        "pounding_median_s": statistics.median(t_tool),
        "pounding_min_s": min(t_tool),
        "pounding_runs_s": t_tool,
        "pounding_median_cpu_s": statistics.median(cpu_tool),
        "pounding_runs_cpu_s": cpu_tool,
        "ratio_of_medians": statistics.median(t_os) / statistics.median(t_tool),
        "ratio_of_cpu_medians": statistics.median(cpu_os) / statistics.median(cpu_tool),
        "accuracy_vs_opensees_finest": {"pounding_default_tolerance": tool_err,
                                        "opensees_dt_1e-4": worst(peaks_os(at_1e4), ref),
                                        "reference_dt": min(r["dt"] for r in runs)},
        "pounding_statistics": stats,
        "environment": {"opensees": soil.ops.version(), "python": platform.python_version(),
                        "cpu": soil.base._cpu_model(), "cpus": os.cpu_count(), "platform": platform.platform()},
        "what": "wall time (and CPU: the process's for OpenSeesPy, the child's user + sys for pounding); OpenSeesPy: build + analyze at dt = 1e-4 s without recorders (soil.run(record=False)); "
                "pounding: the whole CLI command (release), writing its files; alternately, same process",
    }
    (HERE / "bench-soil.json").write_text(json.dumps(res, indent=1) + "\n")
    print(json.dumps(res, indent=1))


if __name__ == "__main__":
    main()
