"""The same sweep on a Dask cluster: here a LocalCluster of two worker processes, which stands for any
dask.distributed cluster (pass its scheduler address to Client instead). Results are committed to an SQLite
store on this machine as chunks return; run it again and it resumes from the store.

    python examples/python/dask_sweep.py [STORE.sqlite]

Needs dask[distributed] (pip install "dask[distributed]") besides pounding.
"""

import copy
import sys
from pathlib import Path

from dask.distributed import Client, LocalCluster

import pounding
import pounding.dask

HERE = Path(__file__).resolve().parent
store = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("out/dask-sweep.sqlite")


def main():
    base = pounding.load_scenario(HERE.parent / "two-sdof.toml")
    scenarios = []
    for scale in [0.5, 1.0, 1.5, 2.0]:
        for gap in [0.0, 0.01, 0.02, 0.04, 0.08]:
            s = copy.deepcopy(base)
            s["ground_motion"]["scale"] = scale
            s["contact"][0]["gap"] = gap
            scenarios.append(s)
    store.parent.mkdir(parents=True, exist_ok=True)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            workers = len(client.nthreads())
            summaries = pounding.dask.sweep(scenarios, client, store=store)
    table = pounding.headline(summaries)
    table.insert(0, "scale", [s["ground_motion"]["scale"] for s in scenarios])
    table.insert(1, "gap_m", [s["contact"][0]["gap"] for s in scenarios])
    cols = ["scale", "gap_m", "left|right_impacts", "left|right_peak_force_N", "right_peak_drift_ratio"]
    print(table[cols].to_string(index=False))
    print(f"{len(summaries)} runs on {workers} workers; store: {store}")


if __name__ == "__main__":  # worker processes import this file: the cluster starts here only
    main()
