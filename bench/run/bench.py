"""Whole-command benchmark (issue 21): for every example, in one session and interleaved round by round,
  - the analysis alone at this commit (`analysis-time`: `Scenario::run_with`, histories in memory, no files),
  - the analysis alone at an older commit (`--old COMMIT`: the same timer built in a git worktree of it),
  - the whole `pounding run EXAMPLE --out DIR -q` (process start, reading, analysis, every file, the rename).
Prints medians over the rounds and the ratios new/old analysis and whole command/analysis, as a Markdown table
(docs/performance.md) and as JSON (--json FILE).

    python3 bench/run/bench.py [--old 8feb6e7] [--rounds 15] [--json out.json]

Needs only the Rust toolchain and Python 3. Wall times; the machine may be shared, so read the ratios.
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BENCH = ROOT / "bench" / "rust"


def build_new():
    subprocess.run(["cargo", "build", "--release", "-q", "--bin", "pounding"], cwd=ROOT, check=True)
    subprocess.run(["cargo", "build", "--release", "-q", "--manifest-path", str(BENCH / "Cargo.toml"),
                    "--bin", "analysis-time"], cwd=ROOT, check=True)
    return ROOT / "target" / "release" / "pounding", BENCH / "target" / "release" / "analysis-time"


def build_old(commit, work):
    """The analysis timer built against `commit`: a worktree of it with this commit's bench crate copied in."""
    tree = work / "old-tree"
    subprocess.run(["git", "worktree", "add", "-f", "--detach", str(tree), commit], cwd=ROOT, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for name in ("Cargo.toml", "Cargo.lock", "analysis_time.rs"):
        shutil.copy(BENCH / name, tree / "bench" / "rust" / name)
    target = work / "old-target"
    subprocess.run(["cargo", "build", "--release", "-q", "--manifest-path", str(tree / "bench" / "rust" / "Cargo.toml"),
                    "--bin", "analysis-time"], cwd=tree, check=True,
                   env={**os.environ, "CARGO_TARGET_DIR": str(target)})
    return tree, target / "release" / "analysis-time"


def analysis(timer, files, repeat):
    """Median seconds of the analysis alone per file (the timer repeats each in one process)."""
    out = subprocess.run([str(timer), "--repeat", str(repeat), *map(str, files)], check=True,
                         capture_output=True, text=True).stdout
    return {Path(j["file"]).name: (j["median_s"], j["steps"]) for j in map(json.loads, out.splitlines())}


def whole(binary, file, out, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run([str(binary), "run", str(file), "--out", str(out), "-q"], check=True,
                       stdout=subprocess.DEVNULL)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--old", help="commit to compare the analysis against (e.g. 8feb6e7)")
    ap.add_argument("--rounds", type=int, default=15)
    ap.add_argument("--repeat", type=int, default=5, help="runs per measurement within a round")
    ap.add_argument("--json")
    a = ap.parse_args()
    files = sorted((ROOT / "examples").glob("*.toml"))
    binary, timer = build_new()
    work = Path(tempfile.mkdtemp(prefix="pounding-bench-"))
    tree = None
    try:
        old_timer = None
        if a.old:
            tree, old_timer = build_old(a.old, work)
        samples = {f.name: {"new": [], "old": [], "whole": []} for f in files}
        steps = {}
        for r in range(a.rounds):
            new = analysis(timer, files, a.repeat)
            old = analysis(old_timer, files, a.repeat) if old_timer else {}
            for f in files:
                s = samples[f.name]
                s["new"].append(new[f.name][0])
                steps[f.name] = new[f.name][1]
                if old:
                    s["old"].append(old[f.name][0])
                    if old[f.name][1] != new[f.name][1]:
                        print(f"note: {f.name} takes {old[f.name][1]} steps at {a.old}, {new[f.name][1]} now")
                s["whole"].append(whole(binary, f, work / "out", a.repeat))
            print(f"round {r + 1}/{a.rounds}", flush=True)
        rows = []
        for f in files:
            s = samples[f.name]
            med = {k: statistics.median(v) for k, v in s.items() if v}
            row = {"example": f.name, "steps": steps[f.name],
                   "analysis_ms": med["new"] * 1e3, "whole_ms": med["whole"] * 1e3,
                   "whole_over_analysis": med["whole"] / med["new"]}
            if "old" in med:
                # the ratio of medians and the median of per-round ratios (which cancels slow drifts)
                row["old_analysis_ms"] = med["old"] * 1e3
                row["new_over_old"] = med["new"] / med["old"]
                row["new_over_old_paired"] = statistics.median(n / o for n, o in zip(s["new"], s["old"]))
            rows.append(row)
        old_cols = " old analysis (ms) | new/old (medians) | new/old (paired) |" if a.old else ""
        print(f"\n| example | steps | analysis (ms) |{old_cols} whole run (ms) | whole/analysis |")
        print("|---|---|---|" + ("---|---|---|" if a.old else "") + "---|---|")
        for row in rows:
            o = (f" {row['old_analysis_ms']:.2f} | {row['new_over_old']:.3f} | {row['new_over_old_paired']:.3f} |"
                 if a.old else "")
            print(f"| {row['example']} | {row['steps']} | {row['analysis_ms']:.2f} |{o} {row['whole_ms']:.2f} | "
                  f"{row['whole_over_analysis']:.2f} |")
        if a.json:
            Path(a.json).write_text(json.dumps({"old": a.old, "rounds": a.rounds, "repeat": a.repeat,
                                                "rows": rows}, indent=1) + "\n")
    finally:
        if tree:
            subprocess.run(["git", "worktree", "remove", "--force", str(tree)], cwd=ROOT,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
