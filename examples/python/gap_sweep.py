"""Peak pounding force against the gap between the two buildings of examples/two-sdof.toml, for two contact
models, under El Centro at two intensities: 2 x 2 x 41 = 164 runs, in parallel, about a second.

    python examples/python/gap_sweep.py [OUT.png]

Needs matplotlib (pip install matplotlib) besides pounding.
"""

import copy
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no window
import matplotlib.pyplot as plt
import numpy as np

import pounding

HERE = Path(__file__).resolve().parent
out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("out/gap-sweep.png")

base = pounding.load_scenario(HERE.parent / "two-sdof.toml")
gaps = np.linspace(0.0, 0.10, 41)  # m
models = ["papi", "kelvin-voigt"]  # both of exponent 1, like the example's stiffness (N/m)
scales = [1.0, 1.5]

scenarios, keys = [], []
for model in models:
    for scale in scales:
        for gap in gaps:
            s = copy.deepcopy(base)
            s["contact"][0]["model"] = model
            s["ground_motion"]["scale"] = scale
            s["contact"][0]["gap"] = float(gap)
            scenarios.append(s)
            keys.append((model, scale))

summaries = pounding.sweep(scenarios)
failed = [s["error"] for s in summaries if "error" in s]
if failed:
    sys.exit(f"{len(failed)} runs failed, the first: {failed[0]}")

fig, ax = plt.subplots(figsize=(7, 4.2), layout="constrained")
colours = {"papi": "#1f5fa8", "kelvin-voigt": "#d1495b"}
styles = {1.0: "-", 1.5: "--"}
for model in models:
    for scale in scales:
        force = [s["sites"][0]["peak_force"] / 1e6 for s, k in zip(summaries, keys) if k == (model, scale)]
        ax.plot(gaps * 1e3, force, styles[scale], color=colours[model], label=f"{model}, El Centro x {scale}")
ax.set_xlabel("gap at rest (mm)")
ax.set_ylabel("peak contact force (MN)")
ax.set_title("Two SDOF buildings (T = 0.5 s and 1.0 s): peak force against gap")
ax.grid(alpha=0.3)
ax.legend(frameon=False)
out.parent.mkdir(parents=True, exist_ok=True)
fig.savefig(out, dpi=120)
print(f"{len(summaries)} runs; wrote {out}")
