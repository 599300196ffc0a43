"""Issue 28's peer: a fixed-step central-difference code (numba; and the same in Rust, bench/peer/cd-rust) for the
two-SDOF El Centro pair with Hooke and Kelvin-Voigt contacts, against the `pounding` tool, in one session.

    python3 -m venv /tmp/peer-venv && /tmp/peer-venv/bin/pip install numba numpy
    cargo build --release -p pounding-cli                                  # the tool (or --bin PATH)
    cargo build --release --manifest-path bench/peer/cd-rust/Cargo.toml    # the Rust peer (optional)
    nice -n 10 /tmp/peer-venv/bin/python bench/peer/central_difference.py [--bin target/release/pounding] \
        [--repeat 5] [--runs 10000] [--json bench/peer/central-difference.json]
    .../python bench/peer/central_difference.py --tables bench/peer/central-difference.json   # Markdown tables
    .../python bench/peer/central_difference.py --gap-ladder --json gap-ladder.json   # accuracy over all gaps per dt

The tool, the Rust peer and numba run as children or in this process at the priority the script was started
with (nice the whole script, not its children: a nested nice would hand the tool less CPU than numba gets).

What it does (bench/peer/README.md, "Central-difference peer (issue 28)"):
 1. the tool's converged answer (--tolerance 1e-10) and its default-tolerance answer for a few gaps per model;
 2. the peer on a ladder of dt: relative errors of the peak displacements of both buildings, of the peak
    contact force and the impact count against the converged answer; the largest dt from which on (every finer
    dt too) each criterion holds; time per run and ns per degree of freedom and step at each dt;
 3. 10,000 runs with gaps evenly spaced over [0, 0.1) m per model: the peer (numba 1 and 2 threads, Rust 1 and
    2 threads) at the dt each criterion needs, and `pounding sweep` (1 and 2 workers), interleaved round by
    round, wall and CPU seconds, medians and spread; and the peer's accuracy over all 10,000 gaps against the
    tool's converged sweep (how many runs hold each criterion).
"""

import argparse
import csv
import json
import math
import os
import platform
import resource
import shutil
import sqlite3
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numba
import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(HERE))
import cd_kernel as cd  # noqa: E402

RECORD = ROOT / "crates" / "pounding" / "data" / "elcentro1940_ns.csv"
SCENARIOS = {"hooke": ROOT / "bench" / "opensees" / "scenarios" / "hooke.toml",
             "kelvin-voigt": ROOT / "bench" / "opensees" / "scenarios" / "kelvin-voigt.toml"}
LADDER = [2e-2, 1e-2, 5e-3, 4e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5, 5e-6]
GAPS = [0.0, 0.005, 0.01, 0.02, 0.03, 0.05, 0.07, 0.1]
M1 = M2 = 5.0e5
K1, K2 = 7.8957e7, 1.9739e7
ZETA = 0.05
KC = 2.0e9
E = 0.65


def pair(model):
    c1 = 2 * ZETA * math.sqrt(K1 * M1)
    c2 = 2 * ZETA * math.sqrt(K2 * M2)
    meff = M1 * M2 / (M1 + M2)
    cc = 0.0 if model == "hooke" else 2 * cd.kv_zeta(E) * math.sqrt(KC * meff)
    return (M1, K1, c1, M2, K2, c2), cc


def rel(a, b):
    return abs(a - b) / abs(b) if b != 0 else (0.0 if a == 0 else math.inf)


# ---------------------------------------------------------------- the tool

def tool_summary(binary, model, gap, tolerance, work):
    """summary.json of one run of the scenario with this gap (None: the file's) and tolerance (None: default)."""
    text = SCENARIOS[model].read_text()
    if gap is not None:
        text = text.replace("gap = 0.02", f"gap = {gap!r}")
        assert f"gap = {gap!r}" in text
    scen = work / f"{model}-{gap}.toml"
    scen.write_text(text)
    out = work / f"out-{model}-{gap}-{tolerance}"
    cmd = [str(binary), "run", str(scen), "--out", str(out), "-q"]
    if tolerance is not None:
        cmd += ["--tolerance", repr(tolerance)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    s = json.loads((out / "summary.json").read_text())
    shutil.rmtree(out)
    return s


def headline(s):
    b = s["buildings"]
    site = s["sites"][0]
    return {"peak_u1": b[0]["peak_displacement"][0], "peak_u2": b[1]["peak_displacement"][0],
            "peak_force": site["peak_force"], "impacts": site["impacts"], "steps": s["statistics"]["steps"]}


def timed(cmd):
    """(wall s, CPU s of the child: user + sys)."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)


def study_file(work, model, gaps, tolerance=None):
    p = work / f"study-{model}-{len(gaps)}-{tolerance}.toml"
    text = f"scenario = {str(SCENARIOS[model])!r}\n[axes]\n"
    if tolerance is not None:
        text += f"analysis.tolerance = [{tolerance!r}]\n"
    text += f"contact.0.gap = [{', '.join(repr(g) for g in gaps)}]\n"
    p.write_text(text)
    return p


def sweep_results(out):
    """Per run, in run order: the headline of each run's summary in the store."""
    con = sqlite3.connect(out / "study.sqlite")
    cols = [r[1] for r in con.execute("PRAGMA table_info(runs)")]
    key = "idx" if "idx" in cols else cols[0]
    scol = next(c for c in ("summary", "summary_json", "result") if c in cols)
    rows = con.execute(f"SELECT {key}, {scol} FROM runs ORDER BY {key}").fetchall()
    con.close()
    return [headline(json.loads(r[1])) for r in rows]


# ---------------------------------------------------------------- the peer

def peer_time(acc, nsub, dt, p, gap, cc, target_s=0.3, min_n=3):
    """Median seconds of one run, single-threaded (many runs when they are short)."""
    cd.run(acc, nsub, dt, *p, gap, KC, cc)
    t0 = time.perf_counter()
    cd.run(acc, nsub, dt, *p, gap, KC, cc)
    one = time.perf_counter() - t0
    n = max(min_n, min(200, int(target_s / max(one, 1e-6))))
    ts = []
    for _ in range(n):
        t0 = time.perf_counter()
        cd.run(acc, nsub, dt, *p, gap, KC, cc)
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts)


def largest_ok(rows, ok):
    """The largest dt of the ladder from which on every finer dt holds `ok` (None if not even the finest)."""
    best = None
    for r in sorted(rows, key=lambda r: r["dt"]):
        if ok(r):
            best = r["dt"]
        else:
            break
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default=str(ROOT / "target" / "release" / "pounding"))
    ap.add_argument("--rust", default=str(HERE / "cd-rust" / "target" / "release" / "cd-peer"))
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--runs", type=int, default=10_000)
    ap.add_argument("--skip-throughput", action="store_true")
    ap.add_argument("--quick", action="store_true", help="smoke run: one gap, three dt")
    ap.add_argument("--json")
    ap.add_argument("--gap-ladder", action="store_true",
                    help="only: the peer's accuracy over all --runs gaps at each dt of GAP_LADDER (not timed)")
    ap.add_argument("--tables", metavar="JSON", help="print the Markdown tables of a results file and stop")
    a = ap.parse_args()
    if a.tables:
        tables(json.loads(Path(a.tables).read_text()))
        return
    if a.gap_ladder:
        work = Path(tempfile.mkdtemp(prefix="cd-peer-"))
        try:
            res = gap_ladder(a, Path(a.bin), work)
        finally:
            shutil.rmtree(work, ignore_errors=True)
        if a.json:
            Path(a.json).write_text(json.dumps(res, indent=1) + "\n")
        return
    if a.quick:
        GAPS[:] = [0.02]
        LADDER[:] = [1e-3, 1e-4, 5e-5]
    binary = Path(a.bin)
    rust = Path(a.rust) if Path(a.rust).exists() else None
    work = Path(tempfile.mkdtemp(prefix="cd-peer-"))
    rec_dt, acc = cd.load_el_centro(RECORD)
    result = {"machine": machine_info(binary), "ladder": LADDER, "gaps": GAPS, "models": {}}
    try:
        # ---- 1 and 2: accuracy ladder per model and gap
        for model in SCENARIOS:
            p, cc = pair(model)
            m = result["models"][model] = {"cc": cc, "gaps": {}}
            for gap in GAPS:
                ref = headline(tool_summary(binary, model, gap, 1e-10, work))
                dflt = headline(tool_summary(binary, model, gap, None, work))
                rows = []
                for dt in LADDER:
                    nsub = int(round(rec_dt / dt))
                    u1, u2, f, n = cd.run(acc, nsub, rec_dt / nsub, *p, gap, KC, cc)
                    t = peer_time(acc, nsub, rec_dt / nsub, p, gap, cc)
                    steps = (len(acc) - 1) * nsub
                    rows.append({"dt": dt, "peak_u1": u1, "peak_u2": u2, "peak_force": f, "impacts": int(n),
                                 "err_u": max(rel(u1, ref["peak_u1"]), rel(u2, ref["peak_u2"])),
                                 "err_f": rel(f, ref["peak_force"]) if ref["impacts"] or f else 0.0,
                                 "run_s": t, "ns_per_dof_step": 1e9 * t / (2 * steps)})
                def crit(tol_f):
                    return lambda r: r["err_u"] <= 1e-3 and r["err_f"] <= tol_f and r["impacts"] == ref["impacts"]
                g = {"tool_converged": ref, "tool_default": dflt,
                     "tool_default_err_u": max(rel(dflt["peak_u1"], ref["peak_u1"]), rel(dflt["peak_u2"], ref["peak_u2"])),
                     "tool_default_err_f": rel(dflt["peak_force"], ref["peak_force"]) if ref["impacts"] else 0.0,
                     "rows": rows,
                     "dt_peaks": largest_ok(rows, lambda r: r["err_u"] <= 1e-3),
                     "dt_peaks_force1pc_impacts": largest_ok(rows, crit(1e-2)),
                     "dt_peaks_force01pc_impacts": largest_ok(rows, crit(1e-3))}
                m["gaps"][repr(gap)] = g
                print(f"{model:13s} gap {gap:<6} tool: {ref['impacts']:3d} impacts, F {ref['peak_force']:.6e}, "
                      f"default tol err u {g['tool_default_err_u']:.1e} F {g['tool_default_err_f']:.1e}", flush=True)
                for r in rows:
                    print(f"    dt {r['dt']:.0e}: err u {r['err_u']:.2e}  err F {r['err_f']:.2e}  impacts "
                          f"{r['impacts']:3d}  {1e3 * r['run_s']:8.3f} ms/run  {r['ns_per_dof_step']:.2f} ns/dof-step",
                          flush=True)
                print(f"    largest dt: peaks {g['dt_peaks']}, +F 1 % + impacts {g['dt_peaks_force1pc_impacts']}, "
                      f"+F 0.1 % + impacts {g['dt_peaks_force01pc_impacts']}", flush=True)
            worst = {}
            for k in ("dt_peaks", "dt_peaks_force1pc_impacts", "dt_peaks_force01pc_impacts"):
                vals = [g[k] for g in m["gaps"].values()]
                worst[k] = None if any(v is None for v in vals) else min(vals)
            m["dt_worst_over_gaps"] = worst
            print(f"{model}: dt over all gaps: {worst}", flush=True)
        if not a.skip_throughput:
            result["throughput"] = throughput(a, binary, rust, work, rec_dt, acc, result)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if a.json:
        Path(a.json).write_text(json.dumps(result, indent=1) + "\n")


def throughput(a, binary, rust, work, rec_dt, acc, result):
    n = a.runs
    gaps = np.array([0.1 * i / n for i in range(n)])
    out = {"runs": n, "models": {}}
    for model in SCENARIOS:
        p, cc = pair(model)
        mres = out["models"][model] = {}
        # the tool's converged answer for every gap, once (not timed), for the peer's accuracy over all gaps
        ref_out = work / f"ref-{model}"
        subprocess.run([str(binary), "sweep", str(study_file(work, model, [float(g) for g in gaps], 1e-10)), "--out", str(ref_out),
                        "-q"], check=True, stdout=subprocess.DEVNULL)
        ref = sweep_results(ref_out)
        shutil.rmtree(ref_out)
        dts = result["models"][model]["dt_worst_over_gaps"]
        cases = []
        for crit in ("dt_peaks", "dt_peaks_force1pc_impacts", "dt_peaks_force01pc_impacts"):
            dt = dts[crit]
            if dt is None or any(c[1] == dt for c in cases):
                continue
            cases.append((crit, dt))
        # accuracy over the 10,000 gaps
        acc_rows = {}
        for crit, dt in cases:
            nsub = int(round(rec_dt / dt))
            r = cd.sweep(acc, nsub, rec_dt / nsub, *p, gaps, KC, cc)
            rows = [{"peak_u1": r[i, 0], "peak_u2": r[i, 1], "peak_force": r[i, 2], "impacts": int(r[i, 3])}
                    for i in range(n)]
            acc_rows[repr(dt)] = {"criterion": crit, **over_gaps(rows, ref)}
            print(f"{model} dt {dt:.0e} ({crit}) over {n} gaps: {acc_rows[repr(dt)]}", flush=True)
        mres["accuracy_over_gaps"] = acc_rows
        mres["tool_converged_impacts_total"] = int(sum(r["impacts"] for r in ref))
        # timings, interleaved round by round
        study = study_file(work, model, [float(g) for g in gaps])
        loose = study_file(work, model, [float(g) for g in gaps], 1e-4)
        samples = {}

        def add(name, wall, cpu):
            samples.setdefault(name, {"wall": [], "cpu": []})
            samples[name]["wall"].append(wall)
            samples[name]["cpu"].append(cpu)

        for crit, dt in cases:  # compile and warm
            nsub = int(round(rec_dt / dt))
            cd.sweep(acc, nsub, rec_dt / nsub, *p, gaps[:4], KC, cc)
        for rnd in range(a.repeat):
            for workers, st, label in ((1, study, ""), (2, study, ""), (2, loose, ", tolerance 1e-4")):
                o = work / f"sweep-{model}-{workers}"
                shutil.rmtree(o, ignore_errors=True)
                w, c = timed([str(binary), "sweep", str(st), "--out", str(o),
                              "--workers", str(workers), "-q"])
                add(f"tool{label}, {workers} worker{'s' if workers > 1 else ''}", w, c)
                if rnd == 0:  # the tool's own accuracy over the gaps, at its default tolerance and at 1e-4
                    k = "tool_accuracy_over_gaps" + label.replace(", tolerance ", "_tol_")
                    mres[k] = over_gaps(sweep_results(o), ref)
                    print(f"{model} {k}: {mres[k]}", flush=True)
                shutil.rmtree(o, ignore_errors=True)
            for crit, dt in cases:
                nsub = int(round(rec_dt / dt))
                for threads in (1, 2):
                    numba.set_num_threads(threads)
                    c0 = time.process_time()
                    t0 = time.perf_counter()
                    cd.sweep(acc, nsub, rec_dt / nsub, *p, gaps, KC, cc)
                    add(f"numba dt {dt:.0e}, {threads} thread{'s' if threads > 1 else ''}",
                        time.perf_counter() - t0, time.process_time() - c0)
                    if rust:
                        w, c = timed([str(rust), "sweep", "--model", model, "--dt", repr(dt),
                                      "--runs", str(n), "--threads", str(threads)])
                        add(f"rust dt {dt:.0e}, {threads} thread{'s' if threads > 1 else ''}", w, c)
            print(f"{model}: round {rnd + 1}/{a.repeat} done", flush=True)
        numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
        table = {}
        for name, s in samples.items():
            table[name] = {"wall_median_s": statistics.median(s["wall"]), "wall_min_s": min(s["wall"]),
                           "wall_max_s": max(s["wall"]), "cpu_median_s": statistics.median(s["cpu"]),
                           "wall_s": s["wall"], "cpu_s": s["cpu"]}
        mres["timings"] = table
        t2 = table["tool, 2 workers"]["wall_median_s"]
        t1 = table["tool, 1 worker"]["wall_median_s"]
        print(f"\n{model}: 10,000 runs (median wall s [min-max], median CPU s; ratio tool/this at equal threads)")
        for name, t in table.items():
            ref_t = t2 if "2 " in name.split(",")[-1] else t1
            t["tool_over_this"] = ref_t / t["wall_median_s"]
            print(f"  {name:28s} {t['wall_median_s']:8.3f} [{t['wall_min_s']:.3f}-{t['wall_max_s']:.3f}] "
                  f"cpu {t['cpu_median_s']:8.3f}  tool/this {t['tool_over_this']:7.2f}", flush=True)
    return out


GAP_LADDER = {"hooke": [2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5], "kelvin-voigt": [2e-4, 1e-4, 5e-5, 2e-5, 1e-5]}


def gap_ladder(a, binary, work):
    """The peer's accuracy over all gaps at each dt (numba, all threads), against the tool's converged sweep."""
    rec_dt, acc = cd.load_el_centro(RECORD)
    n = a.runs
    gaps = np.array([0.1 * i / n for i in range(n)])
    res = {"runs": n, "models": {}}
    for model, dts in GAP_LADDER.items():
        p, cc = pair(model)
        o = work / f"ref-{model}"
        subprocess.run([str(binary), "sweep", str(study_file(work, model, [float(g) for g in gaps], 1e-10)),
                        "--out", str(o), "-q"], check=True, stdout=subprocess.DEVNULL)
        ref = sweep_results(o)
        shutil.rmtree(o)
        res["models"][model] = {}
        for dt in dts:
            nsub = int(round(rec_dt / dt))
            r = cd.sweep(acc, nsub, rec_dt / nsub, *p, gaps, KC, cc)
            rows = [{"peak_u1": r[i, 0], "peak_u2": r[i, 1], "peak_force": r[i, 2], "impacts": int(r[i, 3])}
                    for i in range(n)]
            res["models"][model][repr(dt)] = v = over_gaps(rows, ref)
            print(f"{model} dt {dt:g}: peaks {100 * v['frac_peaks_01pc']:.2f} %, F 0.1 % {100 * v['frac_force_01pc']:.2f} %, "
                  f"F 1 % {100 * v['frac_force_1pc']:.2f} %, impacts {100 * v['frac_impacts_equal']:.2f} %, "
                  f"all {100 * v['frac_all_01pc']:.2f} %, worst u {v['max_err_u']:.1e} F {v['max_err_f']:.1e}", flush=True)
    return res


def over_gaps(rows, ref):
    """How many runs hold each criterion against the converged answer."""
    eu = np.array([max(rel(r["peak_u1"], f["peak_u1"]), rel(r["peak_u2"], f["peak_u2"])) for r, f in zip(rows, ref)])
    ef = np.array([rel(r["peak_force"], f["peak_force"]) if f["impacts"] else 0.0 for r, f in zip(rows, ref)])
    same = np.array([r["impacts"] == f["impacts"] for r, f in zip(rows, ref)])
    return {"frac_peaks_01pc": float(np.mean(eu <= 1e-3)), "max_err_u": float(eu.max()),
            "median_err_u": float(np.median(eu)), "frac_force_1pc": float(np.mean(ef <= 1e-2)),
            "frac_force_01pc": float(np.mean(ef <= 1e-3)), "max_err_f": float(ef.max()),
            "median_err_f": float(np.median(ef)), "frac_impacts_equal": float(same.mean()),
            "frac_all_01pc": float(np.mean((eu <= 1e-3) & (ef <= 1e-3) & same)),
            "frac_all_1pc_force": float(np.mean((eu <= 1e-3) & (ef <= 1e-2) & same))}


def tables(res):
    """The Markdown tables of bench/peer/README.md from a results file."""
    fmt = lambda dt: "–" if dt is None else f"{dt:g}"
    print("| model | gap (m) | tool: impacts | largest dt: peaks 0.1 % | + force 1 % + impacts | "
          "+ force 0.1 % + impacts |")
    print("|---|---|---|---|---|---|")
    for model, m in res["models"].items():
        for gap, g in m["gaps"].items():
            print(f"| {model} | {gap} | {g['tool_converged']['impacts']} | {fmt(g['dt_peaks'])} | "
                  f"{fmt(g['dt_peaks_force1pc_impacts'])} | {fmt(g['dt_peaks_force01pc_impacts'])} |")
        w = m["dt_worst_over_gaps"]
        print(f"| **{model}** | **all** | | **{fmt(w['dt_peaks'])}** | **{fmt(w['dt_peaks_force1pc_impacts'])}** | "
              f"**{fmt(w['dt_peaks_force01pc_impacts'])}** |")
    print()
    print("| model | dt (s) | steps | worst peak error over the 8 gaps | worst force error | impacts equal | "
          "ms per run (median over gaps) | ns per dof-step |")
    print("|---|---|---|---|---|---|---|---|")
    for model, m in res["models"].items():
        gs = list(m["gaps"].values())
        for i, dt in enumerate(res["ladder"]):
            rows = [g["rows"][i] for g in gs]
            eq = sum(r["impacts"] == g["tool_converged"]["impacts"] for r, g in zip(rows, gs))
            steps = round(31.18 / dt)
            print(f"| {model} | {dt:g} | {steps} | {max(r['err_u'] for r in rows):.1e} | "
                  f"{max(r['err_f'] for r in rows):.1e} | {eq}/{len(rows)} | "
                  f"{1e3 * statistics.median(r['run_s'] for r in rows):.3f} | "
                  f"{statistics.median(r['ns_per_dof_step'] for r in rows):.2f} |")
    if "throughput" not in res:
        return
    th = res["throughput"]
    print()
    print(f"| model | how | 10,000 runs: wall s, median [min–max] | CPU s | per run, ms (wall x threads / runs) | "
          f"tool / this (same threads) |")
    print("|---|---|---|---|---|---|")
    for model, m in th["models"].items():
        for name, t in m["timings"].items():
            thr = 2 if "2 " in name.split(",")[-1] else 1
            print(f"| {model} | {name} | {t['wall_median_s']:.3f} [{t['wall_min_s']:.3f}–{t['wall_max_s']:.3f}] | "
                  f"{t['cpu_median_s']:.3f} | {1e3 * t['wall_median_s'] * thr / th['runs']:.3f} | "
                  f"{t['tool_over_this']:.2f} |")
    print()
    print("| model | who | dt / tolerance | runs with peaks within 0.1 % | force within 0.1 % | force within 1 % | "
          "impacts equal | all three (0.1 %) | worst peak error | worst force error |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for model, m in th["models"].items():
        items = [("peer", f"dt {dt}", v) for dt, v in m["accuracy_over_gaps"].items()]
        items += [("tool", k.replace("tool_accuracy_over_gaps", "default").replace("default_tol_", ""), m[k])
                  for k in m if k.startswith("tool_accuracy_over_gaps")]
        for who, what, v in items:
            print(f"| {model} | {who} | {what} | {100 * v['frac_peaks_01pc']:.2f} % | {100 * v['frac_force_01pc']:.2f} % | "
                  f"{100 * v['frac_force_1pc']:.2f} % | {100 * v['frac_impacts_equal']:.2f} % | "
                  f"{100 * v['frac_all_01pc']:.2f} % | {v['max_err_u']:.1e} | {v['max_err_f']:.1e} |")


def machine_info(binary):
    def cmd(c):
        try:
            return subprocess.run(c, capture_output=True, text=True, check=True).stdout.strip()
        except Exception as exc:  # noqa: BLE001
            return f"({exc})"
    lscpu = cmd(["lscpu"])
    model = next((l.split(":", 1)[1].strip() for l in lscpu.splitlines() if l.startswith("Model name")), "?")
    return {"cpu": model, "cores": os.cpu_count(), "python": platform.python_version(), "numpy": np.__version__,
            "numba": numba.__version__, "rustc": cmd(["rustc", "--version"]),
            "pounding": cmd([str(binary), "--version"]),
            "commit": cmd(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"]),
            "date": time.strftime("%Y-%m-%d %H:%M %Z")}


if __name__ == "__main__":
    main()
