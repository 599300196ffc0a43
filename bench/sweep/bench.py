"""Sweep benchmark (issue 11): 10,000 summary-only runs of the two-SDOF El Centro example (gaps 0 to 0.1 m),
from the command line and from Python, on 1 and 2 threads, with and without the store; and Python's cost per
single run against the run itself. Wall times, best of --repeat, all in one session.

    cargo build --release && .venv/bin/pip install ./crates/pounding-py
    .venv/bin/python bench/sweep/bench.py [--runs 10000] [--repeat 3]
"""

import argparse
import copy
import os
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

import pounding

ROOT = Path(__file__).resolve().parents[2]
BIN = ROOT / "target" / "release" / "pounding"


def best(f, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=10_000)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    n = a.runs
    gaps = [0.1 * i / n for i in range(n)]
    base = pounding.load_scenario(ROOT / "examples" / "two-sdof.toml")
    scenarios = []
    for g in gaps:
        s = copy.deepcopy(base)
        s["contact"][0]["gap"] = g
        scenarios.append(s)
    tmp = Path(tempfile.mkdtemp())
    study = tmp / "study.toml"
    study.write_text(
        f"scenario = {str(ROOT / 'examples' / 'two-sdof.toml')!r}\n[axes]\n"
        f"contact.0.gap = [{', '.join(repr(g) for g in gaps)}]\n"
    )

    def cli(workers):
        def go():
            out = tmp / f"cli{workers}"
            shutil.rmtree(out, ignore_errors=True)
            subprocess.run([str(BIN), "sweep", str(study), "--out", str(out), "--workers", str(workers), "-q"],
                           check=True, stdout=subprocess.DEVNULL)
        return go

    def py(workers, store):
        def go():
            path = None
            if store:
                path = tmp / f"py{workers}.sqlite"
                for suffix in ("", "-wal", "-shm"):
                    Path(str(path) + suffix).unlink(missing_ok=True)
            out = pounding.sweep(scenarios, workers=workers, store=path, progress=False)
            assert not any("error" in o for o in out)
        return go

    rows = []
    for name, f in [
        ("cli, 1 thread, store", cli(1)),
        ("cli, 2 threads, store", cli(2)),
        ("python, 1 thread, no store", py(1, False)),
        ("python, 1 thread, store", py(1, True)),
        ("python, 2 threads, no store", py(2, False)),
        ("python, 2 threads, store", py(2, True)),
    ]:
        t = best(f, a.repeat)
        rows.append((name, t))
        print(f"{name:30s} {t:7.2f} s  ({1e3 * t / n:.3f} ms per run)", flush=True)
    d = dict(rows)
    # Python's cost per single run: pounding.run in a loop against the same runs inside one sweep on 1 thread.
    m = min(n, 1000)
    single = best(lambda: [pounding.run(s, histories=False) for s in scenarios[:m]], a.repeat) / m
    inside = best(lambda: pounding.sweep(scenarios[:m], workers=1, progress=False), a.repeat) / m
    print(f"{'pounding.run per run':30s} {1e3 * single:.3f} ms; in a 1-thread sweep {1e3 * inside:.3f} ms")
    print()
    print(f"speed-up on 2 threads: cli {d['cli, 1 thread, store'] / d['cli, 2 threads, store']:.2f}, "
          f"python {d['python, 1 thread, no store'] / d['python, 2 threads, no store']:.2f}")
    print(f"store overhead: 1 thread {d['python, 1 thread, store'] / d['python, 1 thread, no store'] - 1:+.1%}, "
          f"2 threads {d['python, 2 threads, store'] / d['python, 2 threads, no store'] - 1:+.1%}")
    print(f"python against cli (2 threads, store): {d['python, 2 threads, store'] / d['cli, 2 threads, store']:.3f}")
    print(f"pounding.run per call against the run in a sweep: {single / inside - 1:+.1%}")
    shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
