"""The Python package against the command line, single runs against sweeps, and the store's promises.

The command line binary is taken from POUNDING_BIN (the test script sets it), else target/debug/pounding.
"""

import copy
import hashlib
import json
import math
import os
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import pounding

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "two-sdof.toml"
BIN = Path(os.environ.get("POUNDING_BIN", ROOT / "target" / "debug" / "pounding"))


def cli(*args, cwd=ROOT):
    return subprocess.run([str(BIN), *args], cwd=cwd, capture_output=True, text=True)


def without_label(summary):
    s = dict(summary)
    s.pop("scenario")
    return s


def headline_rows(summaries):
    """`pounding.headline` as a list of dicts, with pandas or without."""
    table = pounding.headline(summaries)
    return table if isinstance(table, list) else table.to_dict("records")


def site(summary, name):
    """The site called `name` in a summary's `sites`."""
    (found,) = [x for x in summary["sites"] if x["name"] == name]
    return found


@pytest.fixture(scope="module")
def base():
    return pounding.load_scenario(EXAMPLE)


def gaps(base, values):
    out = []
    for g in values:
        s = copy.deepcopy(base)
        s["contact"][0]["gap"] = g
        out.append(s)
    return out


def test_run_gives_the_numbers_of_the_command_line(tmp_path, base):
    o = cli("run", "examples/two-sdof.toml", "--out", str(tmp_path / "out"), "-q", "--json")
    assert o.returncode == 0, o.stderr
    expected = json.loads(o.stdout)
    # The same file by the same path: the whole summary, label included, to the last digit.
    os.chdir(ROOT)
    assert pounding.run("examples/two-sdof.toml").summary == expected
    # The same scenario as a dict.
    r = pounding.run(base)
    assert without_label(r.summary) == without_label(expected)
    assert r.summary["scenario"] == "<dict>"
    (contact,) = r.summary["sites"]
    assert (contact["kind"], contact["name"], contact["between"]) == ("contact", "left|right", ["left", "right"])
    assert contact["levels"] == [{"left": 1, "right": 1}]
    assert r.summary["buildings"][0]["heights"] == [3.0]
    # Impacts and histories against the files the command line wrote.
    header, *rows = (tmp_path / "out" / "impacts.csv").read_text().splitlines()
    assert len(r.impacts["time_s"]) == len(rows) == contact["impacts"] > 0
    # Columns by name: the file's columns are its header's, not positions to remember.
    first = dict(zip(header.split(","), rows[0].split(",")))
    for column in ("time_s", "v_i_m_per_s", "e_asked", "e_post", "peak_force_N"):
        assert r.impacts[column][0] == float(first[column]), column
    resp = np.loadtxt(tmp_path / "out" / "response.csv", delimiter=",", skiprows=1)
    h = r.histories
    assert h.time.shape == (resp.shape[0],)
    assert h.displacement["left"].shape == (resp.shape[0], 1)
    # response.csv writes 17 significant digits (`{:e}` of the shortest representation): exact.
    assert np.array_equal(h.displacement["left"][:, 0], resp[:, 2])
    assert np.array_equal(h.site_force["left|right"][:, 0], resp[:, 4])
    assert h.site_levels == {"left|right": [(1, 1)]}
    # The contacts' view of the sites: the same arrays.
    assert h.contact_force["left|right"] is h.site_force["left|right"]
    assert h.contact_floors == {"left|right": [(1, 1)]}
    assert h.wall_force == {} and h.wall_floors == {}


def test_walls_devices_and_isolators_match_the_command_line(tmp_path):
    # The bridge: two abutments (walls), two joints, two restrainers, three decks on bearings.
    o = cli("run", "examples/bridge-three-span.toml", "--out", str(tmp_path / "out"), "-q", "--json")
    assert o.returncode == 0, o.stderr
    expected = json.loads(o.stdout)
    os.chdir(ROOT)
    r = pounding.run("examples/bridge-three-span.toml")
    assert r.summary == expected
    assert [(x["kind"], x["name"]) for x in r.summary["sites"]] == [
        ("contact", "span1|span2"), ("contact", "span2|span3"), ("wall", "abutment-west"), ("wall", "abutment-east")
    ]
    west = site(r.summary, "abutment-west")
    assert (west["facing"], west["side"], west["levels"]) == ("span1", "left", [{"right": 1}])
    assert site(r.summary, "abutment-east")["levels"] == [{"left": 1}]
    assert r.summary["devices"][0]["law"] == {"model": "restrainer", "stiffness": 4.0e7, "slack": 0.02}
    assert [d["name"] for d in r.summary["devices"]] == ["restrainer-1", "restrainer-2"]
    assert r.summary["buildings"][0]["isolator"]["model"] == "bilinear"
    header = (tmp_path / "out" / "response.csv").read_text().splitlines()[0].split(",")
    resp = np.loadtxt(tmp_path / "out" / "response.csv", delimiter=",", skiprows=1)
    h = r.histories
    k = header.index("abutment-west_floor1_force_N")
    assert np.array_equal(h.site_force["abutment-west"][:, 0], resp[:, k])
    assert h.wall_force["abutment-west"] is h.site_force["abutment-west"]
    k = header.index("span2|span3_floors1-1_force_N")
    assert np.array_equal(h.site_force["span2|span3"][:, 0], resp[:, k])
    k = header.index("restrainer-2_floors1-1_force_N")
    assert np.array_equal(h.device_force["restrainer-2"][:, 0], resp[:, k])
    # A restrainer only pulls (negative: it resists the opening).
    assert h.device_force["restrainer-2"].max() <= 0.0 < -h.device_force["restrainer-2"].min()
    assert h.wall_floors == {"abutment-west": [1], "abutment-east": [1]}
    assert h.site_levels["abutment-west"] == [(None, 1)] and h.site_levels["abutment-east"] == [(1, None)]
    assert set(h.contact_force) == {"span1|span2", "span2|span3"}
    # Impacts on a wall: its name, 0 for the wall's side (blank in impacts.csv), and the layer.
    walls = r.impacts["contact"] == "abutment-west"
    assert walls.sum() == west["impacts"] > 0
    assert (r.impacts["floor_left"][walls] == 0).all() and (r.impacts["floor_right"][walls] == 1).all()
    assert set(r.impacts["layer"]) == {"direct"}
    # The headline lists the walls as it lists the contacts, from the summary's sites.
    (row,) = headline_rows([r.summary])
    for x in r.summary["sites"]:
        assert row[f"{x['name']}_impacts"] == x["impacts"]
        assert row[f"{x['name']}_peak_force_N"] == x["peak_force"]
    assert row["abutment-west_impacts"] == walls.sum()
    # Decks on bearings: no storey above them, so no drift ratio and no storey ductility (the bearings' own
    # is in the summary); the bearings' displacement is.
    for b in r.summary["buildings"]:
        assert f"{b['name']}_peak_drift_ratio" not in row and f"{b['name']}_peak_ductility" not in row
        assert row[f"{b['name']}_isolator_displacement_m"] == b["isolator"]["peak_displacement"]


# Walls and devices may have any name: commas, quotes, | and letters beyond ASCII (building names are
# plainer: no commas, quotes or |).
WEST = 'mur "ouest", côté | nord'
EAST = "östliche Wand, „alt“ | ü"
DAMPER = 'amortisseur, "visqueux" | é'
TIE = "tirant | Zugglied, ß"
LEFT, RIGHT = "Bâtiment-A", "Gebäude-B"


def odd_names(gap=0.02):
    """Two buildings between two walls, a contact between them, a dashpot to the east wall and a
    restrainer across the joint; the walls and devices named with commas, quotes, | and non-ASCII letters."""
    law = {"model": "papi", "e": 0.65, "stiffness": 2.0e9, "stiffness_unit": "N/m"}
    return {
        "ground_motion": {"record": "el-centro-1940"},
        "analysis": {"duration": 10.0},
        "building": [
            {"name": LEFT, "masses": [5.0e5], "stiffnesses": [7.9e7], "heights": [3.0]},
            {"name": RIGHT, "masses": [5.0e5], "stiffnesses": [2.0e7], "heights": [3.0]},
        ],
        "contact": [{"between": [LEFT, RIGHT], "gap": gap, **law}],
        "wall": [
            {"name": WEST, "facing": LEFT, "side": "left", "gap": 0.01, **law},
            {"name": EAST, "facing": RIGHT, "side": "right", "gap": 0.02, **law},
        ],
        "device": [
            {"name": DAMPER, "between": [RIGHT, EAST], "model": "dashpot", "damping_coefficient": 1.0e5},
            {"name": TIE, "between": [LEFT, RIGHT], "model": "restrainer", "stiffness": 1.0e7, "slack": 0.01},
        ],
    }


def toml_text(scenario):
    """A scenario dict as a TOML file (tables of plain values; strings as JSON writes them, which TOML reads)."""

    def value(v):
        if isinstance(v, str):
            return json.dumps(v, ensure_ascii=False)
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return repr(v)

    lines = []
    for key, v in scenario.items():
        for table in v if isinstance(v, list) else [v]:
            lines.append(f"[[{key}]]" if isinstance(v, list) else f"[{key}]")
            lines += [f"{k} = {value(x)}" for k, x in table.items()]
    return "\n".join(lines) + "\n"


def test_walls_and_devices_with_any_name_run_and_read_back(tmp_path):
    r = pounding.run(odd_names())
    sites = r.summary["sites"]
    assert [(x["kind"], x["name"]) for x in sites] == [("contact", f"{LEFT}|{RIGHT}"), ("wall", WEST), ("wall", EAST)]
    assert (sites[1]["facing"], sites[1]["side"], sites[1]["levels"]) == (LEFT, "left", [{"right": 1}])
    assert (sites[2]["facing"], sites[2]["side"], sites[2]["levels"]) == (RIGHT, "right", [{"left": 1}])
    assert [(d["name"], d["between"]) for d in r.summary["devices"]] == [(DAMPER, [RIGHT, EAST]), (TIE, [LEFT, RIGHT])]
    assert r.summary["devices"][0]["law"] == {"model": "dashpot", "damping_coefficient": 1.0e5}
    # Each wall's impacts: in the impacts by its name, in its site's totals and in the headline.
    (row,) = headline_rows([r.summary])
    for x in sites:
        mine = r.impacts["contact"] == x["name"]
        assert mine.sum() == x["impacts"] == row[f"{x['name']}_impacts"] > 0
        assert r.impacts["peak_force_N"][mine].max() == x["peak_force"] == row[f"{x['name']}_peak_force_N"]
    west = r.impacts["contact"] == WEST
    assert (r.impacts["floor_left"][west] == 0).all() and (r.impacts["floor_right"][west] == 1).all()
    # Their histories, by the same names.
    h = r.histories
    assert set(h.site_force) == {x["name"] for x in sites}
    assert h.site_levels == {f"{LEFT}|{RIGHT}": [(1, 1)], WEST: [(None, 1)], EAST: [(1, None)]}
    assert h.wall_floors == {WEST: [1], EAST: [1]}
    assert h.site_force[WEST].shape == (len(h.time), 1) and h.site_force[WEST].max() > 0
    assert set(h.device_force) == {DAMPER, TIE}
    # The same scenario from a TOML file: the same summary, but for its label.
    path = tmp_path / "odd names.toml"
    path.write_text(toml_text(odd_names()), encoding="utf-8")
    from_file = pounding.run(path, histories=False)
    assert from_file.summary["scenario"] == str(path)
    assert without_label(from_file.summary) == without_label(r.summary)
    # Through a sweep into a store and back: every name intact, the summaries equal single runs.
    store = tmp_path / "study.sqlite"
    scenarios = [odd_names(), odd_names(gap=0.03)]
    first = pounding.sweep(scenarios, store=store, progress=False)
    assert first[0] == pounding.run(scenarios[0], histories=False).summary
    assert first[1] == pounding.run(scenarios[1], histories=False).summary
    with sqlite3.connect(store) as db:
        stored = [json.loads(t) for (t,) in db.execute("SELECT summary FROM runs ORDER BY idx")]
        (units,) = db.execute("SELECT value FROM study WHERE name = 'units'").fetchone()
    # Rows leave out the units every run shares; the study table holds them once.
    assert all("units" not in s for s in stored) and "units" in first[0]
    assert [{**s, "units": json.loads(units)} for s in stored] == first
    assert [x["name"] for x in stored[1]["sites"]] == [f"{LEFT}|{RIGHT}", WEST, EAST]
    assert pounding.sweep(scenarios, store=store, progress=False) == first
    table = headline_rows(first)
    assert [t[f"{WEST}_impacts"] for t in table] == [s["sites"][1]["impacts"] for s in first]


def test_histories_close_the_energy_balance(base):
    h = pounding.run(base).histories
    e = h.energy
    residual = e["input"] - sum(e[k] for k in ("kinetic", "strain", "structural_damping", "hysteretic", "contact"))
    scale = max(np.max(np.abs(v)) for v in e.values())
    # The run's own balance error (summary) bounds the residual at every sample.
    assert np.max(np.abs(residual)) / scale < 1e-5
    assert h.displacement["left"].flags.writeable


def test_summary_only_run_has_the_same_summary(base):
    full = pounding.run(base)
    lean = pounding.run(base, histories=False)
    assert lean.histories is None
    assert lean.summary == full.summary


def test_impacts_frame_is_a_dataframe(base):
    pd = pytest.importorskip("pandas")
    f = pounding.run(base).impacts_frame()
    assert isinstance(f, pd.DataFrame)
    assert list(f.columns)[:4] == ["time_s", "contact", "floor_left", "floor_right"]
    assert f["contact"].iloc[0] == "left|right"


def test_bad_input_raises_the_command_lines_message(tmp_path, base):
    bad = EXAMPLE.read_text().replace("gap = 0.02", "gap = -0.02")
    path = tmp_path / "bad.toml"
    path.write_text(bad)
    o = cli("run", str(path), "--out", str(tmp_path / "out"))
    assert o.returncode == 2
    with pytest.raises(pounding.InputError) as e:
        pounding.run(path)
    assert o.stderr.strip() == f"error: {e.value}"
    assert isinstance(e.value, ValueError)
    # A dict names the key by its dotted path.
    d = copy.deepcopy(base)
    d["contact"][0]["gap"] = -0.02
    with pytest.raises(pounding.InputError, match=r"^contact\.0\.gap: gap = -0\.02 is not allowed: gap >= 0 \(m\)$"):
        pounding.run(d)
    d = copy.deepcopy(base)
    d["contact"][0]["gapp"] = 1
    with pytest.raises(pounding.InputError, match=r"^contact\.0\.gapp: unknown field `gapp`"):
        pounding.run(d)
    d = copy.deepcopy(base)
    d["contact"][0]["k" * 5000] = 1
    with pytest.raises(pounding.InputError, match=r"^contact\.0: unknown field `k{56}\.\.\.` \(5000 characters\), expected one of `between`, .*, \.\.\. \(\d+ in all\)$"):
        pounding.run(d)
    d = copy.deepcopy(base)
    d["building"][0]["masses"] = [float("nan")]
    with pytest.raises(pounding.InputError, match=r"^building\.0\.masses\.0 = nan is not allowed: a finite number$"):
        pounding.run(d)
    d = copy.deepcopy(base)
    d["ground_motion"]["scale"] = float("-inf")
    with pytest.raises(pounding.InputError, match=r"^ground_motion\.scale = -inf is not allowed: a finite number$"):
        pounding.run(d)


def test_a_sweep_equals_single_runs_in_input_order(base):
    scenarios = gaps(base, [0.05, 0.0, 0.01, 0.02])
    scenarios.append({"ground_motion": {"record": "kobe"}})
    out = pounding.sweep(scenarios, workers=2, progress=False)
    for s, o in zip(scenarios[:4], out[:4]):
        assert o == pounding.run(s, histories=False).summary
    assert out[4] == {
        "error": 'ground_motion.record: record = "kobe" is not a built-in record: el-centro-1940, synthetic-SEED (SEED 0, 1, 2, ...) (for a file, use file = "path")'
    }
    table = pounding.headline(out)
    assert list(table["left|right_peak_force_N"][:4]) == [o["sites"][0]["peak_force"] for o in out[:4]]
    assert list(table["left|right_impacts"][:4]) == [o["sites"][0]["impacts"] for o in out[:4]]
    assert table["error"][4] == out[4]["error"] and table["error"][:4].isna().all()


def test_headline_reads_summaries_as_the_library_does(base):
    summary = pounding.run(base, histories=False).summary
    (row,) = headline_rows([summary])
    assert isinstance(row["left|right_impacts"], int) and isinstance(row["steps"], int)
    assert row["left|right_impacts"] == summary["sites"][0]["impacts"]
    assert row["left_peak_drift_ratio"] == summary["buildings"][0]["peak_drift_ratio"][0]
    # A summary of the old shape (contacts and walls apart, buildings without heights) is not one.
    old = copy.deepcopy(summary)
    old["contacts"], old["walls"] = old.pop("sites"), []
    for b in old["buildings"]:
        b.pop("heights")
    with pytest.raises(pounding.InputError, match=r"^summary\.buildings\.0: missing field `heights`$"):
        pounding.headline([old])
    wrong = copy.deepcopy(summary)
    wrong["sites"][0]["kind"] = "bridge"
    with pytest.raises(pounding.InputError, match=r"^summary\.sites\.0: unknown variant `bridge`, expected `contact` or `wall`$"):
        pounding.headline([wrong])


def without_units(summary):
    """A summary as a study store's row holds it: without the units every run shares."""
    return {k: v for k, v in summary.items() if k != "units"}


def test_the_store_resumes_and_refuses_another_study(tmp_path, base):
    store = tmp_path / "study.sqlite"
    scenarios = gaps(base, [0.0, 0.01, 0.02])
    first = pounding.sweep(scenarios[:2] + [{"ground_motion": {}}], store=store, progress=False)
    assert "error" in first[2]
    # Another list of scenarios is another study: refused, the store untouched.
    before = hashlib.sha256(store.read_bytes()).hexdigest()
    with pytest.raises(pounding.InputError, match="written by a different study"):
        pounding.sweep(scenarios, store=store, progress=False)
    assert hashlib.sha256(store.read_bytes()).hexdigest() == before
    with sqlite3.connect(store) as db:
        rows = db.execute("SELECT key, status, summary, error FROM runs ORDER BY idx").fetchall()
    assert [r[1] for r in rows] == ["ok", "ok", "error"]
    assert json.loads(rows[0][2]) == without_units(first[0])
    assert rows[2][3].startswith("[ground_motion] needs exactly one of")


def test_a_store_grows_into_a_study_that_holds_all_its_runs(tmp_path, base):
    store = tmp_path / "study.sqlite"
    scenarios = gaps(base, [0.0, 0.01, 0.02])
    first = pounding.sweep([scenarios[0], scenarios[2]], store=store, progress=False)
    with sqlite3.connect(store) as db:
        before = dict(db.execute("SELECT key, finished FROM runs").fetchall())
    # A new gap between them: the two stored runs are kept as they were, the new one added, each at its place.
    grown = pounding.sweep(scenarios, store=store, progress=False)
    assert [grown[0], grown[2]] == first
    with sqlite3.connect(store) as db:
        rows = db.execute("SELECT key, idx, finished FROM runs ORDER BY idx").fetchall()
    assert [r[1] for r in rows] == [0, 1, 2]
    assert {r[0]: r[2] for r in rows if r[0] in before} == before
    # A list without one of the stored runs is another study's: refused.
    with pytest.raises(pounding.InputError, match="a store grows only into a study with all its runs"):
        pounding.sweep(scenarios[1:], store=store, progress=False)


RESUME_SCRIPT = """
import copy, sys, pounding
base = pounding.load_scenario(sys.argv[1])
scenarios = []
for i in range(int(sys.argv[3])):
    s = copy.deepcopy(base)
    s["contact"][0]["gap"] = 0.0005 * i
    scenarios.append(s)
out = pounding.sweep(scenarios, workers=1, store=sys.argv[2], progress=False)
print(sum("error" in o for o in out))
"""


def test_a_sweep_killed_with_sigkill_resumes_with_every_run_once(tmp_path):
    store = tmp_path / "study.sqlite"
    script = tmp_path / "sweep.py"
    script.write_text(RESUME_SCRIPT)
    n = 120
    args = [sys.executable, str(script), str(EXAMPLE), str(store), str(n)]
    p = subprocess.Popen(args)
    deadline = time.time() + 120
    done = 0
    while time.time() < deadline and p.poll() is None:
        time.sleep(0.02)
        if not store.exists():
            continue
        try:
            with sqlite3.connect(f"file:{store}?mode=ro", uri=True, timeout=0.1) as db:
                done = db.execute("SELECT count(*) FROM runs").fetchone()[0]
        except sqlite3.Error:
            continue
        if done >= 10:
            break
    assert p.poll() is None, "the sweep ended before it could be killed: make it longer"
    p.send_signal(signal.SIGKILL)
    p.wait()
    with sqlite3.connect(store) as db:
        before = dict(db.execute("SELECT key, finished FROM runs").fetchall())
    assert 10 <= len(before) < n
    o = subprocess.run(args, capture_output=True, text=True)
    assert o.returncode == 0, o.stderr
    assert o.stdout.strip() == "0"
    with sqlite3.connect(store) as db:
        rows = db.execute("SELECT key, idx, finished, summary FROM runs ORDER BY idx").fetchall()
    # Every run exactly once, in study order, and the runs finished before the kill were not run again.
    assert len(rows) == n and len({r[0] for r in rows}) == n
    assert [r[1] for r in rows] == list(range(n))
    assert all(before[k] == f for k, _, f, _ in rows if k in before)
    # The results equal a sweep that was never interrupted.
    base = pounding.load_scenario(EXAMPLE)
    fresh = pounding.sweep(gaps(base, [0.0005 * i for i in range(n)]), progress=False)
    assert [json.loads(r[3]) for r in rows] == [without_units(f) for f in fresh]


def test_dask_sweep_on_a_local_cluster_equals_the_local_sweep(tmp_path, base):
    distributed = pytest.importorskip("dask.distributed")
    import pounding.dask

    scenarios = gaps(base, [0.0, 0.005, 0.01, 0.02, 0.03, 0.05])
    scenarios.append({"ground_motion": {"record": "el-centro-1940"}, "building": []})
    local = pounding.sweep(scenarios, progress=False)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            store = tmp_path / "dask.sqlite"
            remote = pounding.dask.sweep(scenarios, client, store=store, chunk=2)
            assert remote == local
            # Resumed from its store: nothing to run, the same results.
            assert pounding.dask.sweep(scenarios, client, store=store) == local
            # A stored summary that does not read as one (here, the old shape) is run again and replaced,
            # as the local sweep does.
            with sqlite3.connect(store) as db:
                db.execute("UPDATE runs SET summary = ? WHERE idx = 1", (json.dumps({"contacts": []}),))
            assert pounding.dask.sweep(scenarios, client, store=store) == local
            with sqlite3.connect(store) as db:
                (text,) = db.execute("SELECT summary FROM runs WHERE idx = 1").fetchone()
            assert json.loads(text) == without_units(local[1])
    with sqlite3.connect(store) as db:
        assert db.execute("SELECT count(*) FROM runs").fetchone()[0] == len(scenarios)
    # The local sweep reads the store the cluster wrote.
    assert pounding.sweep(scenarios, store=store, progress=False) == local


@pytest.mark.parametrize("name", ["gap_sweep.py", "dask_sweep.py"])
def test_the_python_examples_run(tmp_path, name):
    pytest.importorskip("matplotlib" if name == "gap_sweep.py" else "dask.distributed")
    out = tmp_path / ("gap.png" if name == "gap_sweep.py" else "dask.sqlite")
    o = subprocess.run(
        [sys.executable, str(ROOT / "examples" / "python" / name), str(out)],
        capture_output=True, text=True, timeout=300,
    )
    assert o.returncode == 0, o.stderr
    assert out.exists() and out.stat().st_size > 0
    if name == "dask_sweep.py":
        # Every run once in the store, each a success (equality with the local sweep: the Dask test above).
        with sqlite3.connect(out) as db:
            status = [r[0] for r in db.execute("SELECT status FROM runs")]
        assert status == ["ok"] * 20


def test_spectrum_gives_the_numbers_of_the_command_line():
    o = cli("record", "spectrum", "el-centro-1940", "--damping", "0.02", "--periods", "0.3,1,2.5", "--json")
    assert o.returncode == 0, o.stderr
    expected = json.loads(o.stdout)
    s = pounding.spectrum("el-centro-1940", damping=0.02, periods=[0.3, 1.0, 2.5])
    for k in ("sd", "psv", "psa"):
        assert s[k].tolist() == expected[k]
    with pytest.raises(pounding.InputError, match="damping = 1 is not allowed"):
        pounding.spectrum(damping=1.0, periods=[1.0])


def test_spectrum_knows_every_built_in_record_from_the_library(tmp_path, monkeypatch):
    periods = [0.2, 0.5, 1.0, 2.0]
    o = cli("record", "spectrum", "synthetic-3", "--periods", "0.2,0.5,1,2", "--json")
    assert o.returncode == 0, o.stderr
    expected = json.loads(o.stdout)
    # A file of that name in the working folder changes nothing: a built-in name is a built-in record, as
    # for the command line.
    monkeypatch.chdir(tmp_path)
    (tmp_path / "synthetic-3").write_text("not a record\n")
    s = pounding.spectrum("synthetic-3", periods=periods)
    for k in ("sd", "psv", "psa"):
        assert s[k].tolist() == expected[k]
    # It is synthetic(3) with its defaults: the same spectrum from that record written to a file.
    rec = pounding.synthetic(3)
    f = tmp_path / "s3.txt"
    np.savetxt(f, rec["acceleration"], fmt="%.17e")
    from_file = pounding.spectrum(f, periods=periods, format="values", dt=rec["dt"], units="m/s2")
    assert np.allclose(from_file["sd"], s["sd"], rtol=1e-12, atol=0)
    # Another seed is another record.
    assert not np.allclose(pounding.spectrum("synthetic-4", periods=periods)["sd"], s["sd"], rtol=1e-3)
    # Not a built-in name (a leading zero): a file, which is missing; the message lists the built-ins.
    with pytest.raises(pounding.InputError, match=r"synthetic-03.*built-in records: el-centro-1940, synthetic-SEED"):
        pounding.spectrum("synthetic-03", periods=periods)
    with pytest.raises(pounding.InputError, match=r"^format and dt apply to a record file"):
        pounding.spectrum("synthetic-3", periods=periods, format="values", dt=0.01)
    with pytest.raises(pounding.InputError, match=r'^units = "gg" is not allowed: one of g, m/s2'):
        pounding.spectrum("el-centro-1940", periods=periods, units="gg")
    # A built-in record carries its units: units given for it are refused, not ignored.
    with pytest.raises(pounding.InputError, match=r'built-in record "el-centro-1940" carries its own'):
        pounding.spectrum("el-centro-1940", periods=periods, units="m/s2")


def test_separation_gives_the_numbers_of_the_command_line(base):
    o = cli("separation", "examples/three-vs-eight-storey.toml", "--json")
    assert o.returncode == 0, o.stderr
    expected = json.loads(o.stdout)
    os.chdir(ROOT)
    assert pounding.separation("examples/three-vs-eight-storey.toml") == expected
    levels = expected["pairs"][0]["levels"]
    assert [l["floors"] for l in levels] == [[1, 1], [2, 2], [3, 3]]
    # Over a suite: each record, then the statistics.
    two = pounding.separation(base, records=["el-centro-1940", "el-centro-1940"], aligned_factor=0.7)
    assert len(two["records"]) == 2
    gap = two["records"][0]["pairs"][0]["levels"][0]["required_gap"]
    assert two["statistics"]["pairs"][0]["levels"][0]["required_gap"] == {"mean": gap, "median": gap, "p84": gap}
    with pytest.raises(pounding.InputError, match="aligned_factor = 2 is not allowed"):
        pounding.separation(base, aligned_factor=2.0)


def test_synthetic_records_are_those_of_the_command_line(tmp_path):
    out = tmp_path / "s.csv"
    o = cli("record", "synth", "--seed", "5", "--out", str(out), "--pga", "2.5", "--filter", "kanai-tajimi")
    assert o.returncode == 0, o.stderr
    data = np.loadtxt(out, delimiter=",", comments="#", skiprows=3)
    s = pounding.synthetic(5, pga=2.5, filter="kanai-tajimi")
    # Accelerations to the last bit (written with 17 digits); times as the file rounds them (12 digits).
    assert np.array_equal(s["acceleration"], data[:, 1])
    assert np.allclose(s["time"], data[:, 0], rtol=1e-12, atol=0)
    assert np.max(np.abs(s["acceleration"])) == pytest.approx(2.5, rel=1e-15)
    # The file runs as a scenario's record.
    d = pounding.load_scenario(EXAMPLE)
    d["ground_motion"] = {"file": str(out), "units": "m/s2"}
    assert pounding.run(d, histories=False).summary["record"]["pga"] == pytest.approx(2.5, rel=1e-15)
    with pytest.raises(pounding.InputError, match="zg = 1.5 is not allowed"):
        pounding.synthetic(1, zg=1.5)


def test_synthetic_reads_its_parameters_as_the_library_does(tmp_path):
    # The defaults are the library's (SyntheticParams), which the command line's record synth also uses.
    out = tmp_path / "s.csv"
    o = cli("record", "synth", "--seed", "9", "--out", str(out))
    assert o.returncode == 0, o.stderr
    data = np.loadtxt(out, delimiter=",", comments="#", skiprows=3)
    s = pounding.synthetic(9)
    assert np.array_equal(s["acceleration"], data[:, 1])
    assert (s["dt"], len(s["acceleration"])) == (0.01, 2000)
    assert np.max(np.abs(s["acceleration"])) == pytest.approx(3.0, rel=1e-15)
    # A parameter given as None keeps its default; one given changes the record.
    assert np.array_equal(pounding.synthetic(9, pga=None, filter=None)["acceleration"], s["acceleration"])
    assert not np.array_equal(pounding.synthetic(9, wg=10.0)["acceleration"], s["acceleration"])
    # Each mistake names its key, the value where there is one, and what is allowed.
    bad = [
        (dict(foo=3), r"^foo: unknown field `foo`, expected one of `filter`, `wg`, `zg`, `wf`, `zf`, `duration`, `dt`, `t1`, `t2`, `decay`, `pga`$"),
        (dict(pgaa=2.0), r"^pgaa: unknown field `pgaa` \(did you mean `pga`\?\), expected one of"),
        (dict(filter="clough-penzein"), r'^filter = "clough-penzein" is not allowed \(did you mean "clough-penzien"\?\): one of kanai-tajimi, clough-penzien$'),
        (dict(wg="fast"), r'^wg: invalid type: string "fast", expected f64$'),
        (dict(dt=float("nan")), r"^dt = nan is not allowed: a finite number$"),
    ]
    for kw, message in bad:
        with pytest.raises(pounding.InputError, match=message):
            pounding.synthetic(1, **kw)
    for seed in (-1, 2**64, 1.5, "7"):
        with pytest.raises(pounding.InputError, match=r"^seed = .* is not allowed: a whole number from 0 to 2\^64 - 1$"):
            pounding.synthetic(seed)


def test_ida_fits_agree_with_scipy_on_the_same_data(tmp_path):
    pd = pytest.importorskip("pandas")
    optimize = pytest.importorskip("scipy.optimize")
    stats = pytest.importorskip("scipy.stats")
    res = pounding.ida(ROOT / "examples" / "studies" / "ida.toml", tmp_path / "ida", progress=False)
    runs, frag = res["runs"], res["fragility"]
    assert isinstance(runs, pd.DataFrame) and len(runs) == 300
    levels = np.sort(runs["intensity_m_per_s2"].unique())
    for ls, exceeded in [
        ("pounding", runs["pounding"] > 0.5),
        ("drift_ratio.right > 0.02", runs["right_peak_drift_ratio"] > 0.02),
        ("peak_force > 2e7", runs["peak_force_N"] > 2e7),
    ]:
        n = np.array([np.sum(runs["intensity_m_per_s2"] == x) for x in levels])
        z = np.array([np.sum(exceeded[runs["intensity_m_per_s2"] == x]) for x in levels])

        def nll(p):
            u = (np.log(levels) - p[0]) / np.exp(p[1])
            return -np.sum(z * stats.norm.logcdf(u) + (n - z) * stats.norm.logsf(u))

        fit = optimize.minimize(nll, [np.log(np.median(levels)), np.log(0.4)], method="Nelder-Mead",
                                options={"xatol": 1e-12, "fatol": 1e-14, "maxiter": 20000})
        row = frag[(frag["limit_state"] == ls) & (frag["method"] == "stripes")].iloc[0]
        assert row["median_m_per_s2"] == pytest.approx(np.exp(fit.x[0]), rel=1e-6), ls
        assert row["beta"] == pytest.approx(np.exp(fit.x[1]), rel=1e-6), ls
        # IDA: the first level at which each record exceeds; censored at the top level if it never does.
        first, censored = [], 0
        for _, g in runs.assign(ex=exceeded).groupby("record"):
            hit = g.sort_values("intensity_m_per_s2").loc[lambda d: d["ex"], "intensity_m_per_s2"]
            if len(hit):
                first.append(hit.iloc[0])
            else:
                censored += 1
        logs = np.log(first)
        row = frag[(frag["limit_state"] == ls) & (frag["method"] == "ida")].iloc[0]
        if censored == 0:
            assert row["median_m_per_s2"] == pytest.approx(np.exp(logs.mean()), rel=1e-12), ls
            assert row["beta"] == pytest.approx(logs.std(), rel=1e-12), ls
        else:
            top = np.log(levels[-1])

            def cnll(p):
                return -np.sum(stats.norm.logpdf(logs, p[0], np.exp(p[1]))) - censored * stats.norm.logsf(top, p[0], np.exp(p[1]))

            c = optimize.minimize(cnll, [logs.mean(), np.log(logs.std())], method="Nelder-Mead",
                                  options={"xatol": 1e-12, "fatol": 1e-14, "maxiter": 20000})
            assert row["median_m_per_s2"] == pytest.approx(np.exp(c.x[0]), rel=1e-6), ls
            assert row["beta"] == pytest.approx(np.exp(c.x[1]), rel=1e-6), ls


def test_bad_arguments_raise_input_error_naming_them(base, tmp_path):
    # Each call with an argument of the wrong type or range: InputError naming the argument, nothing written.
    store = tmp_path / "study.sqlite"
    deep = [1.0]
    for _ in range(100_000):
        deep = [deep]
    calls = [
        (lambda: pounding.spectrum(None), "record = None"),
        (lambda: pounding.load_scenario(None), "path = None"),
        (lambda: pounding.sweep([base], workers=2**64, progress=False), f"workers = {2**64}"),
        (lambda: pounding.sweep([base], workers="2", progress=False), "workers = '2'"),
        (lambda: pounding.sweep([base], workers=10**6, store=store, progress=False), "workers = 1000000"),
        (lambda: pounding.run(base, histories="no"), "histories = 'no'"),
        (lambda: pounding.separation(base, records="el-centro-1940"), "records = 'el-centro-1940'"),
        (lambda: pounding.sweep(base, progress=False), "scenarios = {"),
        (lambda: pounding.synthetic(-1), "seed = -1"),
        (lambda: pounding.synthetic(1, filter=5), "filter"),
        (lambda: pounding.ida(tmp_path / "ida.toml", tmp_path / "out", workers=True), "workers = True"),
        # A list where a table belongs: refused, not read by position; nested past Python's recursion limit.
        (lambda: pounding.run({**base, "analysis": [1.0, 0.01]}), "analysis is a list"),
        (lambda: pounding.run({**base, "analysis": deep}), "nested too deeply"),
        (lambda: pounding.sweep([{**base, "ground_motion": deep}], progress=False), "nested too deeply"),
    ]
    for call, needle in calls:
        with pytest.raises(pounding.InputError) as e:
            call()
        assert needle in str(e.value), str(e.value)
        assert "\n" not in str(e.value) and len(str(e.value)) < 300
    assert not store.exists()
    assert not (tmp_path / "out").exists()


def test_ctrl_c_stops_long_calls_within_half_a_second(base):
    # Each call takes seconds; SIGINT 0.3 s in must end it with KeyboardInterrupt within 0.5 s.
    tall = copy.deepcopy(base)  # two buildings of 150 storeys: seconds of analysis
    for b in tall["building"]:
        b["masses"] = b["masses"] * 150
        b["stiffnesses"] = [b["stiffnesses"][0] * 150] * 150
        b["heights"] = [3.0] * 150
    suite = [f"synthetic-{i}" for i in range(1, 4000)]  # about 5 s
    calls = {
        "spectrum": lambda: pounding.spectrum("el-centro-1940", periods=[1e-3] * 790),
        "separation": lambda: pounding.separation(base, records=suite),
        "run": lambda: pounding.run(tall, histories=False),
    }
    # A shell starts background jobs with SIGINT ignored, and Python then keeps it so: the test's own handler.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        _press_ctrl_c_during(calls)
    finally:
        signal.signal(signal.SIGINT, previous)


def _press_ctrl_c_during(calls):
    import threading

    for name, call in calls.items():
        timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
        t0 = time.monotonic()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            call()
        late = time.monotonic() - t0 - 0.3
        timer.join()
        assert late < 0.5, f"{name}: stopped {late:.2f} s after Ctrl-C"


def test_arguments_of_every_type_raise_input_error_or_work(base, tmp_path):
    # Seeded: each public function with one argument replaced by a value of another type or range; the call
    # returns or raises InputError, never another exception, and never writes where it was refused.
    import random

    rng = random.Random(int(os.environ.get("POUNDING_FUZZ_SEED", "0")))
    hostile = [None, True, -1, 0, 2**64, 1.5, float("nan"), float("inf"), "x", b"x", [], {}, [[1.0]], {"a": 1},
               object(), ["el-centro-1940"], "el-centro-1940", tmp_path]
    calls = {
        "run": (pounding.run, [base], {"histories": False}),
        "sweep": (pounding.sweep, [[base]], {"workers": 1, "progress": False}),
        "separation": (pounding.separation, [base], {"records": None, "aligned_factor": None}),
        "spectrum": (pounding.spectrum, ["el-centro-1940"], {"damping": 0.05, "periods": [0.5, 1.0]}),
        "synthetic": (pounding.synthetic, [1], {"duration": 5.0}),
        "load_scenario": (pounding.load_scenario, [EXAMPLE], {}),
        "headline": (pounding.headline, [[]], {}),
    }
    cases = int(os.environ.get("POUNDING_FUZZ_CASES", "60"))
    for case in range(cases):
        name = rng.choice(sorted(calls))
        f, args, kwargs = calls[name]
        args, kwargs = list(args), dict(kwargs)
        slots = [("arg", i) for i in range(len(args))] + [("kw", k) for k in kwargs]
        kind, slot = rng.choice(slots)
        value = rng.choice(hostile)
        if kind == "arg":
            args[slot] = value
        else:
            kwargs[slot] = value
        try:
            f(*args, **kwargs)
        except pounding.InputError as e:
            assert "\n" not in str(e) and len(str(e)) < 300, f"case {case} {name}: {e}"
        except Exception as e:  # noqa: BLE001 - the point of the test
            raise AssertionError(f"case {case}: {name}({slot} = {value!r}) raised {type(e).__name__}: {e}")


def test_fits_give_the_numbers_of_the_command_line():
    rest = ROOT / "data" / "contact-tests" / "restitution-synthetic.csv"
    o = cli("fit", "restitution", str(rest), "--model", "hunt-crossley", "--json")
    assert o.returncode == 0, o.stderr
    expected = json.loads(o.stdout)
    # From the file, and from the same pairs as an array: the command line's report, and its curve.
    r = pounding.fit.restitution(rest, "hunt-crossley")
    pts = np.loadtxt(rest, delimiter=",", comments="#", skiprows=3)
    a = pounding.fit.restitution(pts, "hunt-crossley")
    for got in (r, a):
        curve = got.pop("curve")
        assert got == expected
    c = expected["parameters"]["damping_constant"]
    # The curve: e = 1 at rest, falling with v_i, and at each v_i the root of the defining relation
    # chi - ln(1 + chi) = -chi e - ln(1 - chi e), chi = c v_i (next-physics.md section 1).
    assert curve["e"][0] == 1.0 and np.all(np.diff(curve["e"]) < 0)
    chi = c * curve["v_i"][1:]
    y = chi * curve["e"][1:]
    assert np.allclose(chi - np.log1p(chi), -y - np.log1p(-y), rtol=1e-9, atol=1e-14)
    assert c == pytest.approx(0.3, abs=3 * expected["std_errors"]["damping_constant"])
    hist = ROOT / "data" / "contact-tests" / "force-history-synthetic.csv"
    args = ("--m1", "10.0531", "--v", "3.13", "--n", "1.5", "--damping-constant")
    o = cli("fit", "force-history", str(hist), "--model", "hunt-crossley", *args, "--json")
    assert o.returncode == 0, o.stderr
    h = pounding.fit.force_history(hist, "hunt-crossley", m1=10.0531, v=3.13, n=1.5, damping_constant=True)
    h.pop("curve")
    assert h == json.loads(o.stdout)
    with pytest.raises(pounding.InputError, match="at least 5 samples"):
        pounding.fit.force_history([(0.0, 1.0)], "papi", m1=1.0, v=1.0)
    with pytest.raises(pounding.InputError, match="shape"):
        pounding.fit.restitution([1.0, 2.0, 3.0], "papi")
    # A data file that cannot be read is InputError, as a scenario file that cannot be read is (exit 2).
    with pytest.raises(pounding.InputError, match=r"^cannot read data file .*absent\.csv: No such file"):
        pounding.fit.restitution("absent.csv", "hunt-crossley")
    with pytest.raises(pounding.InputError, match=r"^cannot read data file /dev/zero: not a regular file"):
        pounding.fit.restitution("/dev/zero", "hunt-crossley")


def test_separation_probability_codes_and_risk_match_the_command_line(tmp_path):
    base = pounding.load_scenario(EXAMPLE)
    # Random vibration: the command line's numbers, key for key.
    o = cli("separation", str(EXAMPLE), "--white-noise", "0.01", "--duration", "20", "--target-probability", "0.1", "--json")
    assert o.returncode == 0, o.stderr
    r = pounding.separation(base, white_noise=0.01, duration=20.0, target_probability=0.1)
    expected = json.loads(o.stdout)
    assert r["pairs"] == expected["pairs"]
    assert r["pairs"][0]["levels"][0]["nu0"] == pytest.approx(1.1513, rel=1e-3)
    # A code under a flat spectrum: 5.5 x sqrt(d1^2 + d2^2) with d = Sa / w^2.
    code = {"name": "asce7-22", "cd": 5.5, "design_spectrum": [[0.0, 2.0], [10.0, 2.0]]}
    c = pounding.separation(base, code=code)
    level = c["pairs"][0]["levels"][0]
    periods = [b["periods"][0] for b in pounding.run(base, histories=False).summary["buildings"]]
    d = [2.0 / (2 * np.pi / t) ** 2 for t in periods]
    assert level["code_required_gap"] == pytest.approx(5.5 * np.hypot(*d), rel=1e-9)
    # A suite's fit is the lognormal MLE of its records' gaps.
    s = pounding.separation(base, records=["synthetic-1", "synthetic-2", "synthetic-3"], target_probability=0.2)
    gaps = np.array([rec["pairs"][0]["levels"][0]["required_gap"] for rec in s["records"]])
    fit = s["statistics"]["pairs"][0]["levels"][0]["fit"]
    assert fit["median"] == pytest.approx(np.exp(np.mean(np.log(gaps))), rel=1e-12)
    assert fit["dispersion"] == pytest.approx(np.std(np.log(gaps)), rel=1e-12)
    # The hazard as a dict: a frequency that falls with the gap.
    curve = [[x, 1e-3 * x ** -2.5] for x in np.geomspace(0.1, 10.0, 30)]
    h = pounding.separation(base, records=["synthetic-1", "synthetic-2"], hazard={"curve": curve, "levels": [1.0, 2.0], "target_rate": 1e-3})
    f = h["pairs"][0]["levels"][0]["curve"]["annual_frequency"]
    assert all(b <= a * (1 + 1e-9) for a, b in zip(f, f[1:]))
    with pytest.raises(pounding.InputError, match="duration is required"):
        pounding.separation(base, white_noise=0.01)
    with pytest.raises(pounding.InputError, match="cd is required"):
        pounding.separation(base, code={"name": "asce7-22"})


def test_buildings_in_plan_run_as_on_the_command_line(tmp_path):
    """A scenario of buildings in plan (two ground components, a contact from the façades) as a file and as a
    dict: the command line's summary, its impacts' points, and the histories of y and rotation."""
    path = ROOT / "examples" / "plan-eccentric.toml"
    o = cli("run", str(path), "--out", str(tmp_path / "out"), "-q", "--json")
    assert o.returncode == 0, o.stderr
    expected = json.loads(o.stdout)
    scenario = pounding.load_scenario(path)
    r = pounding.run(scenario)
    assert without_label(r.summary) == without_label(expected)
    plan = r.summary["buildings"][0]["plan"]
    assert len(plan["modes"]) == 3 * r.summary["buildings"][0]["storeys"]
    assert r.summary["record_y"]["dt"] == r.summary["record"]["dt"]
    h = r.histories
    n = h.time.shape[0]
    assert h.displacement_y["eccentric"].shape == (n, 4) and h.rotation["neighbour"].shape == (n, 3)
    assert h.ground_acceleration_y.shape == (n,)
    # The largest sampled rotation is at most the located peak.
    top = np.abs(h.rotation["eccentric"][:, 3]).max()
    assert 0 < top <= plan["peak_rotation"][3] * (1 + 1e-12)
    # Each impact's point is one of its site's points.
    points = {tuple(p) for p in r.summary["sites"][0]["points"]}
    assert len(r.impacts["time_s"]) > 0
    for x, y in zip(r.impacts["point_x_m"], r.impacts["point_y_m"]):
        assert (x, y) in points


def test_a_structure_from_matrices_runs_from_a_file_a_dict_and_numpy_rows(tmp_path):
    """A building given by its stiffness matrix (a Matrix Market file beside the scenario): the command line's
    summary from the file, from the dict `load_scenario` gives (the matrix put in as rows), from a dict naming
    the file from the working folder, and from rows of a numpy array; the white-noise separation on it."""
    path = ROOT / "examples" / "condensed-frame.toml"
    o = cli("run", str(path), "--out", str(tmp_path / "out"), "-q", "--json")
    assert o.returncode == 0, o.stderr
    expected = without_label(json.loads(o.stdout))
    assert expected["buildings"][0]["matrices"]["dofs"] == 4
    scenario = pounding.load_scenario(path)
    rows = scenario["building"][0]["stiffness_matrix"]
    assert len(rows) == 4 and all(len(r) == 4 for r in rows)
    assert without_label(pounding.run(scenario).summary) == expected
    named = copy.deepcopy(scenario)
    named["building"][0]["stiffness_matrix"] = str(ROOT / "examples" / "condensed-frame-K.mtx")
    assert without_label(pounding.run(named).summary) == expected
    dense = copy.deepcopy(scenario)
    dense["building"][0]["stiffness_matrix"] = np.array(rows).tolist()
    assert without_label(pounding.run(dense).summary) == expected
    bad = copy.deepcopy(scenario)
    bad["building"][0]["stiffness_matrix"][0][1] *= 2
    with pytest.raises(pounding.InputError, match="stiffness_matrix.*symmetric"):
        pounding.run(bad)
    sep = pounding.separation(scenario, white_noise=0.01, duration=10.0)
    assert 0 < sep["pairs"][0]["levels"][0]["probability"] < 1


def test_coherent_records_are_the_command_lines(tmp_path):
    """pounding.coherent gives the numbers `pounding record coherent` writes, for both models; bad input raises
    InputError naming the parameter."""
    for model, extra_cli, extra_py in [
        ("luco-wong", ["--alpha", "2.5e-4"], {"alpha": 2.5e-4}),
        ("harichandran-vanmarcke", ["--hv-k", "4000"], {"k": 4000.0}),
    ]:
        out = tmp_path / model
        o = cli("record", "coherent", "--seed", "5", "--positions", "0,60,150", "--model", model, *extra_cli, "--out", str(out))
        assert o.returncode == 0, o.stderr
        r = pounding.coherent(5, [0, 60, 150], model, **extra_py)
        assert len(r["acceleration"]) == 3
        for j, a in enumerate(r["acceleration"]):
            rows = np.loadtxt(out / f"support-{j + 1}.csv", delimiter=",", comments="#", skiprows=3)
            assert np.allclose(rows[:, 1], a, rtol=1e-15, atol=0)
    with pytest.raises(pounding.InputError, match="alpha is required"):
        pounding.coherent(1, [0, 10], "luco-wong")
    with pytest.raises(pounding.InputError, match="model"):
        pounding.coherent(1, [0, 10], "gauss")


def test_records_conditioned_on_a_record_are_the_command_lines(tmp_path):
    """pounding.coherent(record=...) gives the numbers `pounding record coherent --record` writes; the record
    stays at the first support; a record with a spectrum's parameters, or a negative window, raises InputError
    naming them."""
    out = tmp_path / "conditioned"
    o = cli(
        "record", "coherent", "--seed", "4", "--positions", "0,100", "--model", "luco-wong", "--alpha", "3e-4",
        "--record", "el-centro-1940", "--window", "1.5", "--out", str(out),
    )
    assert o.returncode == 0, o.stderr
    r = pounding.coherent(4, [0, 100], "luco-wong", alpha=3e-4, record="el-centro-1940", window=1.5)
    for j, a in enumerate(r["acceleration"]):
        rows = np.loadtxt(out / f"support-{j + 1}.csv", delimiter=",", comments="#", skiprows=3)
        assert np.allclose(rows[:, 1], a, rtol=1e-15, atol=0)
        assert np.allclose(rows[:, 0], r["time"], rtol=1e-12, atol=0)
    assert not np.array_equal(r["acceleration"][0], r["acceleration"][1])
    with pytest.raises(pounding.InputError, match="record"):
        pounding.coherent(1, [0, 10], "luco-wong", alpha=2e-4, record="el-centro-1940", pga=2.0)
    with pytest.raises(pounding.InputError, match="window"):
        pounding.coherent(1, [0, 10], "luco-wong", alpha=2e-4, record="el-centro-1940", window=-1.0)
