"""Buildings in plan against the same buildings in one line (issue 26), in one session, interleaved round by
round, with the analysis timer of bench/rust (`Scenario::run_with`, histories in memory, no files):

  - `line`: a 3-storey and a 2-storey shear building in one line, 20 mm apart, El Centro, hertzdamp contact;
  - `plan-symmetric`: the same buildings in plan (symmetric plans, lines along x through the mass centres
    carrying the storeys, lines along y at the edges), the same record along x, one contact point on the
    line of the mass centres: the same motion, three times the degrees of freedom;
  - `plan-eccentric`: the same masses and stiffnesses in eccentric plans (mass centres off the middle, lines
    along x unequal), shaken along x and along y, contact points at both ends of the façades' overlap.

Prints the medians and the ratios plan / line as a Markdown table, and JSON (--json FILE). Target (issue 26): a
two-building planar run at most 4 times the cost of the same buildings in one line.

    python3 bench/plan/bench.py [--rounds 9] [--repeat 20] [--json out.json]
"""

import argparse
import json
import statistics
import subprocess
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BENCH = ROOT / "bench" / "rust"

MA, KA = [4.0e5, 4.0e5, 3.0e5], [3.2e8, 2.8e8, 2.0e8]
MB, KB = [6.0e5, 5.0e5], [1.2e8, 1.0e8]
HEAD = """[ground_motion]
record = "el-centro-1940"
{y}
[analysis]
duration = 20.0
"""
CONTACT = """[[contact]]
between = ["A", "B"]
model = "hertzdamp"
stiffness = 2.0e10
stiffness_unit = "N/m^1.5"
e = 0.65
{extra}
"""


def toml_list(xs):
    return "[" + ", ".join(repr(float(x)) for x in xs) + "]"


def in_line():
    out = HEAD.format(y="")
    for name, m, k in (("A", MA, KA), ("B", MB, KB)):
        out += f'[[building]]\nname = "{name}"\nmasses = {toml_list(m)}\nstiffnesses = {toml_list(k)}\nheights = {toml_list([3.0] * len(m))}\n\n'
    return out + CONTACT.format(extra="gap = 0.02")


def in_plan(eccentric):
    out = HEAD.format(y='[ground_motion.y]\nrecord = "synthetic-1"\nscale = 0.7' if eccentric else "")
    plans = (("A", MA, KA, (20.0, 12.0), (0.0, 0.0), (13.0, 6.0)), ("B", MB, KB, (16.0, 16.0), (20.02, -2.0), (8.0, 8.0)))
    for name, m, k, (a, b), (x0, y0), c in plans:
        out += f'[[building]]\nname = "{name}"\nmasses = {toml_list(m)}\nheights = {toml_list([3.0] * len(m))}\n'
        out += f"[building.plan]\nsize = [{a}, {b}]\nposition = [{x0}, {y0}]\n"
        if eccentric:
            out += f"mass_centre = [{c[0]}, {c[1]}]\n"
            lines = [("x", 0.0, [0.6 * x for x in k]), ("x", b, [0.4 * x for x in k]),
                     ("y", 0.0, [1.0 * x for x in k]), ("y", a, [0.6 * x for x in k])]
        else:
            lines = [("x", b / 2, k), ("y", 0.0, [0.8 * x for x in k]), ("y", a, [0.8 * x for x in k])]
        for d, at, ks in lines:
            out += f'[[building.line]]\ndirection = "{d}"\nat = {at}\nstiffnesses = {toml_list(ks)}\n'
        out += "\n"
    # A: mass centres on y = 6; B's at y = -2 + 8 = 6: one point on their line, or both ends of the overlap.
    return out + CONTACT.format(extra="" if eccentric else "points = [6.0]")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rounds", type=int, default=9)
    ap.add_argument("--repeat", type=int, default=20)
    ap.add_argument("--json")
    a = ap.parse_args()
    subprocess.run(["cargo", "build", "--release", "-q", "--manifest-path", str(BENCH / "Cargo.toml"),
                    "--bin", "analysis-time"], cwd=ROOT, check=True)
    timer = BENCH / "target" / "release" / "analysis-time"
    with tempfile.TemporaryDirectory() as tmp:
        files = {"line": in_line(), "plan-symmetric": in_plan(False), "plan-eccentric": in_plan(True)}
        paths = {}
        for name, text in files.items():
            paths[name] = Path(tmp) / f"{name}.toml"
            paths[name].write_text(text)
        times = {n: [] for n in files}
        steps = {}
        for _ in range(a.rounds):
            out = subprocess.run([str(timer), "--repeat", str(a.repeat), *map(str, paths.values())],
                                 check=True, capture_output=True, text=True).stdout
            for line in out.splitlines():
                j = json.loads(line)
                name = Path(j["file"]).stem
                times[name].append(j["median_s"])
                steps[name] = j["steps"]
    med = {n: statistics.median(t) for n, t in times.items()}
    rows = [{"scenario": n, "median_s": med[n], "steps": steps[n], "ratio_to_line": med[n] / med["line"]}
            for n in files]
    print("| scenario | analysis, median | steps | ratio to the buildings in one line |")
    print("|---|---|---|---|")
    for r in rows:
        print(f"| {r['scenario']} | {1e3 * r['median_s']:.2f} ms | {r['steps']} | {r['ratio_to_line']:.2f} |")
    if a.json:
        Path(a.json).write_text(json.dumps({"rounds": a.rounds, "repeat": a.repeat, "rows": rows}, indent=1) + "\n")


if __name__ == "__main__":
    main()
