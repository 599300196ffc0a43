"""Earthquake-induced pounding of structures, from Python.

The engine is the Rust library behind the ``pounding`` command line; this package gives it numpy arrays,
dicts and pandas tables. SI units throughout (m, s, kg, N; a contact stiffness of exponent n in N/m^n).

- :func:`load_scenario` reads a scenario file (TOML) into a dict;
- :func:`run` runs one scenario (a dict or a path) and returns a :class:`Result`;
- :func:`sweep` runs many scenarios in parallel (Rust threads, the GIL released), optionally into a
  resumable SQLite store; :func:`pounding.dask.sweep` does the same on a Dask cluster;
- :func:`headline` turns summaries into a table of headline results (as ``runs.csv`` of ``pounding sweep``);
- :mod:`pounding.fit` fits contact laws to tests (restitution against impact velocity, force histories).

Bad input raises :class:`InputError` (a ``ValueError``) with the command line's one-line message.
See docs/python.md.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _pounding
from ._pounding import InputError
from . import fit

__version__ = _pounding.__version__
__all__ = ["InputError", "Result", "Histories", "load_scenario", "run", "sweep", "headline", "spectrum", "separation", "synthetic", "coherent", "ida", "fit"]

Scenario = Union[Dict[str, Any], str, "os.PathLike[str]"]


def _plain(o: Any) -> Any:
    """numpy scalars and arrays as plain Python numbers and lists (for JSON)."""
    if hasattr(o, "tolist"):
        return o.tolist()
    if hasattr(o, "item"):
        return o.item()
    raise TypeError(f"{type(o).__name__} is not a number, string, list or dict")


def _json(scenario: Dict[str, Any], what: str = "scenario") -> str:
    """A dict (a scenario, or the parameters of ``what``) as JSON text; NaN and infinity are refused as the
    schema would refuse them."""
    if not isinstance(scenario, dict):
        raise InputError(f"{what}: a dict or a path, not {type(scenario).__name__}")
    bad = _non_finite(scenario)
    if bad is not None:
        key, x = bad
        word = "nan" if math.isnan(x) else ("inf" if x > 0 else "-inf")
        raise InputError(f"{key or what} = {word} is not allowed: a finite number")
    try:
        return json.dumps(scenario, allow_nan=False, default=_plain)
    except (TypeError, ValueError) as e:
        raise InputError(f"{what}: {e}") from None
    except RecursionError:
        raise InputError(f"{what}: lists or dicts nested too deeply; allowed: the tables of docs/scenarios.md") from None


def _non_finite(v: Any, key: str = "", depth: int = 0) -> Optional[Tuple[str, float]]:
    """The first number of ``v`` that is NaN or infinite (JSON has neither), with its dotted key as scenario
    messages name keys (``building.0.masses.0``)."""
    if depth > 200:
        return None  # json.dumps says it is nested too deeply
    child = (lambda k: f"{key}.{k}" if key else str(k))
    if isinstance(v, (float, np.floating)):
        return None if math.isfinite(v) else (key, float(v))
    if isinstance(v, dict):
        items: Any = v.items()
    elif isinstance(v, (list, tuple)):
        items = enumerate(v)
    elif isinstance(v, np.ndarray) and v.dtype.kind == "f":
        items = enumerate(v.ravel().tolist())
    else:
        return None
    for k, x in items:
        found = _non_finite(x, child(k), depth + 1)
        if found is not None:
            return found
    return None


def _fspath(key: str, v: Any) -> str:
    """A path or a name given as ``key``, as text; anything else is InputError naming the key."""
    if isinstance(v, (str, os.PathLike)):
        return os.fspath(v)
    raise InputError(f"{key} = {_short(v)} is not allowed: a path or a name (str or os.PathLike)")


def _short(v: Any) -> str:
    r = repr(v)
    return r if len(r) <= 60 else r[:57] + "..."


def _flag(key: str, v: Any) -> bool:
    if isinstance(v, (bool, np.bool_)):
        return bool(v)
    raise InputError(f"{key} = {_short(v)} is not allowed: True or False")


def _number(key: str, v: Any) -> float:
    """A real number given as ``key`` (NaN and infinity are the library's to refuse, by name)."""
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating)):
        raise InputError(f"{key} = {_short(v)} is not allowed: a number")
    return float(v)


def _items(key: str, v: Any, what: str) -> list:
    """The items of an iterable given as ``key`` (a string or a dict is not a list of ``what``)."""
    if isinstance(v, (str, bytes, dict, os.PathLike)) or not hasattr(v, "__iter__"):
        raise InputError(f"{key} = {_short(v)} is not allowed: a list (or other iterable) of {what}")
    return list(v)


def _workers(v: Any) -> int:
    """``workers``: None (every core) or a whole number (its range is the library's to check)."""
    if v is None:
        return os.cpu_count() or 1
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)):
        raise InputError(f"workers = {_short(v)} is not allowed: a whole number (default: the number of cores)")
    most = _pounding.max_workers()
    if not 1 <= v <= most:
        raise InputError(f"workers = {v} is not allowed: 1 to {most} (16 per core on this machine; default: the number of cores)")
    return int(v)


def load_scenario(path: Union[str, "os.PathLike[str]"]) -> Dict[str, Any]:
    """The scenario file at ``path`` (TOML, see docs/scenarios.md) as a dict, ready to change and run.

    A relative record ``file`` is made absolute, so the dict runs from any folder. Raises InputError for a
    file that cannot be read or is not valid TOML (the content is validated when it runs).
    """
    return json.loads(_pounding.load_scenario(_fspath("path", path)))


def _array(d: Dict[str, Any]) -> np.ndarray:
    return np.frombuffer(d["data"], dtype="<f8").reshape(d["shape"])


@dataclass
class Histories:
    """Histories at the output interval, SI units.

    - ``time`` (s) and ``ground_acceleration`` (m/s^2): arrays of the samples;
    - ``displacement`` (m, relative to the ground), ``absolute_acceleration`` (m/s^2) and ``storey_shear``
      (N): for each building by name, an array of samples x floors (floor or storey 1 first);
    - ``site_force`` (N): for each contact site by name (a contact ``"left|right"`` or a wall's name, as in
      ``summary["sites"]``), an array of samples x levels, in the order of ``site_levels``: each level's
      ``(left, right)`` floors, from 1, ``None`` on a wall's side (with a bumper, the layer's and the hard
      law's force together);
    - ``contact_force`` and ``contact_floors``, ``wall_force`` and ``wall_floors``: the same arrays for the
      contacts between neighbours (floor pairs) and for the walls (the floor facing the wall) alone;
    - ``device_force`` (N, positive pushing apart): for each device by name, samples x floor pairs, in the
      order of ``device_floors``;
    - ``energy`` (J): ``input``, ``kinetic``, ``strain``, ``structural_damping``, ``hysteretic``, ``contact``;
    - buildings in plan: ``displacement_y`` (m) and ``rotation`` (rad, counterclockwise) of each floor's mass
      centre, for each building in plan by name (samples x floors; ``displacement`` and the others then hold
      its mass centres along x), and ``ground_acceleration_y`` (m/s^2; empty unless the ground shakes along y);
    - buildings on a foundation: ``foundation``, for each by name, samples x 2: its sway (m) and rocking (rad).
    """

    time: np.ndarray
    ground_acceleration: np.ndarray
    displacement: Dict[str, np.ndarray]
    absolute_acceleration: Dict[str, np.ndarray]
    storey_shear: Dict[str, np.ndarray]
    site_force: Dict[str, np.ndarray]
    site_levels: Dict[str, List[Tuple[Optional[int], Optional[int]]]]
    contact_force: Dict[str, np.ndarray]
    contact_floors: Dict[str, List[Tuple[int, int]]]
    wall_force: Dict[str, np.ndarray]
    wall_floors: Dict[str, List[int]]
    device_force: Dict[str, np.ndarray]
    device_floors: Dict[str, List[tuple]]
    energy: Dict[str, np.ndarray]
    displacement_y: Dict[str, np.ndarray]
    rotation: Dict[str, np.ndarray]
    ground_acceleration_y: np.ndarray
    foundation: Dict[str, np.ndarray]


def _histories(h: Dict[str, Any], sites: List[Dict[str, Any]]) -> Histories:
    """The histories the extension gives, with the contacts' and the walls' views of the sites' forces (the
    same arrays, by each site's ``kind`` in the summary)."""
    force = {k: _array(v) for k, v in h["site_force"].items()}
    levels = {k: [tuple(l) for l in v] for k, v in h["site_levels"].items()}
    walls = {s["name"] for s in sites if s["kind"] == "wall"}
    return Histories(
        time=np.frombuffer(h["time"], dtype="<f8"),
        ground_acceleration=np.frombuffer(h["ground_acceleration"], dtype="<f8"),
        displacement={k: _array(v) for k, v in h["displacement"].items()},
        absolute_acceleration={k: _array(v) for k, v in h["absolute_acceleration"].items()},
        storey_shear={k: _array(v) for k, v in h["storey_shear"].items()},
        site_force=force,
        site_levels=levels,
        contact_force={k: v for k, v in force.items() if k not in walls},
        contact_floors={k: v for k, v in levels.items() if k not in walls},
        wall_force={k: v for k, v in force.items() if k in walls},
        wall_floors={k: [l if l is not None else r for l, r in v] for k, v in levels.items() if k in walls},
        device_force={k: _array(v) for k, v in h["device_force"].items()},
        device_floors={k: [tuple(p) for p in v] for k, v in h["device_floors"].items()},
        energy={k: np.frombuffer(v, dtype="<f8") for k, v in h["energy"].items()},
        displacement_y={k: _array(v) for k, v in h["displacement_y"].items()},
        rotation={k: _array(v) for k, v in h["rotation"].items()},
        ground_acceleration_y=np.frombuffer(h["ground_acceleration_y"], dtype="<f8"),
        foundation={k: _array(v) for k, v in h["foundation"].items()},
    )


class Result:
    """One run: ``summary`` (a dict, the content of ``summary.json``: its ``sites`` list the contacts and the
    walls alike, each with its ``kind``), ``impacts`` (columns as numpy arrays: ``time_s``, ``contact`` (the
    site's name: a contact ``"left|right"`` or a wall's name), ``floor_left``, ``floor_right`` (0 on a
    wall's side), ``layer`` (``direct``, ``bumper``, or ``consumed``: the hard law behind a consumed bumper),
    ``v_i_m_per_s``, ``e_asked`` (the e its law was built to deliver between free bodies: the contact's e, or
    its table or damping constant at v_i; NaN for an elastic law), ``e_post`` (NaN where an impact gave none), ``peak_force_N``, ``time_of_peak_force_s``,
    ``duration_s``, ``dissipated_energy_J``, ``max_penetration_m``, ``ended``, ``resting``, ``point_x_m`` and
    ``point_y_m`` (between buildings in plan, the impact's point at rest; NaN in one line)) and
    ``histories`` (a :class:`Histories`, or None for a run without them)."""

    def __init__(self, raw: Dict[str, Any]):
        self.summary: Dict[str, Any] = json.loads(raw["summary"])
        imp = raw["impacts"]
        self.impacts: Dict[str, np.ndarray] = {}
        for k, v in imp.items():
            if k in ("contact", "layer"):
                self.impacts[k] = np.asarray(v, dtype=object)
            elif k in ("floor_left", "floor_right"):
                self.impacts[k] = np.asarray(v, dtype=np.int64)
            elif k in ("ended", "resting"):
                self.impacts[k] = np.asarray(v, dtype=bool)
            else:
                self.impacts[k] = np.asarray(v, dtype=np.float64)
        h = raw["histories"]
        self.histories: Optional[Histories] = None if h is None else _histories(h, self.summary["sites"])

    def impacts_frame(self):
        """The impacts as a pandas DataFrame (needs pandas)."""
        import pandas as pd

        return pd.DataFrame(self.impacts)

    def __repr__(self) -> str:
        n = len(self.impacts["time_s"])
        return f"<pounding.Result {self.summary['scenario']}: {n} impacts>"


def run(scenario: Scenario, histories: bool = True) -> Result:
    """Runs one scenario: a dict (the schema of docs/scenarios.md) or the path of a scenario file.

    With ``histories=False`` only the summary and the impacts are kept (faster, little memory). The GIL is
    released while the analysis runs. Raises InputError with the command line's message for bad input.
    """
    histories = _flag("histories", histories)
    if isinstance(scenario, (str, os.PathLike)):
        raw = _pounding.run(path=os.fspath(scenario), histories=histories)
    else:
        raw = _pounding.run(scenario=_json(scenario), histories=histories)
    return Result(raw)


def _outcome(ok: bool, text: str) -> Dict[str, Any]:
    return json.loads(text) if ok else {"error": text}


def sweep(
    scenarios: Iterable[Scenario],
    workers: Optional[int] = None,
    store: Optional[Union[str, "os.PathLike[str]"]] = None,
    progress: bool = True,
) -> List[Dict[str, Any]]:
    """Runs every scenario (dicts or paths) in parallel on ``workers`` Rust threads (default: every core) with
    the GIL released, keeping summaries only; returns their summaries in input order. A scenario that fails
    (bad input, an analysis that fails) gives ``{"error": "one-line message"}`` and does not stop the sweep.

    With ``store="study.sqlite"`` every finished run is committed to that SQLite store as it finishes (table
    ``runs``: ``key``, ``idx``, ``status``, ``summary``, ``error``, ``seconds``, ``finished``, ``digest``): started again
    with the same scenarios, the sweep runs only what is missing. A store written by other scenarios raises
    InputError and is left untouched. ``progress`` prints one updating line on stderr; Ctrl-C stops the sweep
    (finished runs stay in the store) and raises KeyboardInterrupt.
    """
    texts, labels = _texts(scenarios)
    n = _workers(workers)
    out = _pounding.sweep_runs(
        texts, labels, n, None if store is None else _fspath("store", store), _flag("progress", progress)
    )
    return [_outcome(ok, text) for _, ok, text in out]


def _texts(scenarios: Iterable[Scenario]):
    """JSON texts and labels of scenarios given as dicts or paths."""
    texts, labels = [], []
    for s in _items("scenarios", scenarios, "scenarios, dicts or paths"):
        if isinstance(s, (str, os.PathLike)):
            d = load_scenario(s)
            labels.append(os.fspath(s))
        else:
            d = s
            labels.append("<dict>")
        texts.append(_json(d))
    return texts, labels


def headline(summaries: Iterable[Dict[str, Any]]):
    """One row per summary of headline results (the record's PGA, each building's peak displacement and drift
    ratio, each site's impacts, peak force and penetration (contacts and walls alike, by the site's name),
    the balance error, the steps; units in the column names) and an ``error`` column: a pandas DataFrame if
    pandas is installed, else a list of dicts. A summary that is not one (of another version, say) raises
    InputError naming the key that does not fit."""
    rows = []
    for s in _items("summaries", summaries, "summaries (dicts)"):
        if not isinstance(s, dict):
            raise InputError(f"summaries: {_short(s)} is not allowed: a summary (a dict, as sweep gives)")
        if "error" in s and "buildings" not in s:
            rows.append({"error": s["error"]})
        else:
            row = dict(_pounding.headline(json.dumps(s)))
            row["error"] = None
            rows.append(row)
    try:
        import pandas as pd
    except ImportError:
        return rows
    return pd.DataFrame(rows)


def spectrum(
    record: Union[str, "os.PathLike[str]"] = "el-centro-1940",
    damping: float = 0.05,
    periods: Optional[Iterable[float]] = None,
    format: Optional[str] = None,
    dt: Optional[float] = None,
    units: Optional[str] = None,
    scale: float = 1.0,
) -> Dict[str, Any]:
    """The elastic response spectrum of a record (a built-in record's name, such as ``"el-centro-1940"`` or
    ``"synthetic-3"``, else a file; ``format``, ``dt``, ``units`` and
    ``scale`` as in a scenario's ``[ground_motion]``; ``units`` unset: what the file states, else g; none for a
    built-in) for oscillators of damping ratio ``damping`` at
    ``periods`` (s; default 100 from 0.02 to 10 s, evenly spaced in log), by the exact piecewise-linear
    solution with peaks located between samples: a dict of ``damping``, ``periods`` (s), ``sd`` (m), ``psv``
    (m/s) and ``psa`` (m/s^2), numpy arrays; the numbers of ``pounding record spectrum --json``."""
    if periods is None:
        p = np.geomspace(0.02, 10.0, 100)
    else:
        p = np.asarray([_number("periods", t) for t in _items("periods", periods, "periods (s)")], dtype=np.float64)
    for key, v in (("format", format), ("units", units)):
        if v is not None and not isinstance(v, str):
            raise InputError(f"{key} = {_short(v)} is not allowed: a name (str) or None")
    # Whether the source is a built-in record or a file is the library's to say (as for the command line).
    sd, psv, psa = _pounding.spectrum(
        _fspath("record", record),
        _number("damping", damping),
        p.tolist(),
        format=format,
        dt=None if dt is None else _number("dt", dt),
        units=units,
        scale=_number("scale", scale),
    )
    return {"damping": float(damping), "periods": p, "sd": np.asarray(sd), "psv": np.asarray(psv), "psa": np.asarray(psa)}


def separation(
    scenario: Scenario,
    records: Optional[Iterable[Union[str, "os.PathLike[str]"]]] = None,
    aligned_factor: Optional[float] = None,
    target_probability: Optional[float] = None,
    white_noise: Optional[float] = None,
    duration: Optional[float] = None,
    filter: Optional[Dict[str, Any]] = None,
    clumping: str = "poisson",
    code: Optional[Dict[str, Any]] = None,
    hazard: Optional[Dict[str, Any]] = None,
) -> Dict[str, Any]:
    """The required separation of each pair of neighbours at each contact level, from a run without contact,
    against the ABS, SRSS and DDC rules (docs/separation.md): the JSON of ``pounding separation --json`` as a
    dict. ``scenario`` is a dict or a path; ``records`` (built-in names or files) replace its record, one run
    each, and add the mean, median and 84th percentile over them, and the probability that a record pounds
    (a lognormal fit and the records' fraction); ``aligned_factor`` (Eurocode 8: 0.7) multiplies the rules
    where the floors are at the same height; ``target_probability`` asks the gap for a probability.

    ``white_noise`` (S0, m^2/s^3, two-sided) with ``duration`` (s): the probability of pounding under a
    stationary random ground acceleration instead of records, through ``filter`` (a dict: ``kind``
    ``"kanai-tajimi"`` or ``"clough-penzien"``, ``wg``, ``zg``, ``wf``, ``zf``) if given, crossings counted by
    ``clumping`` (``"poisson"`` or ``"vanmarcke"``).

    ``code``: a dict with ``name`` (``"asce7-22"``, ``"en1998-1"``, ``"is1893-2016"``, ``"gb50011-2010"``), its
    parameters (``cd``, ``ie``; ``q``, ``qd``; ``r``; ``intensity``, ``system``) and ``design_spectrum`` (rows
    ``[T s, Sa m/s^2]``) or ``spectrum`` (``{"shape": "asce7-22", "sds", "sd1", "tl"}`` with ``r``, or
    ``{"shape": "en1998-1", "ag", "ground_type", "spectrum_type"}`` with ``q``).

    ``hazard``: a dict with ``curve`` (rows ``[IM m/s^2, annual rate 1/yr]``), ``levels`` (m/s^2; the records
    scaled to each), ``measure`` (``"sa"`` or ``"pga"``), ``building``, ``damping``, ``target_rate`` (1/yr) or
    ``design_life`` (yr, with ``target_probability``): the mean annual frequency of pounding against the gap."""
    if isinstance(records, (str, bytes, os.PathLike)):
        raise InputError(f"records = {_short(records)} is not allowed: a list of records (write [{_short(records)}])")
    recs = [] if records is None else [_fspath("records", r) for r in _items("records", records, "records")]
    if aligned_factor is not None:
        aligned_factor = _number("aligned_factor", aligned_factor)
    options: Dict[str, Any] = {}
    if target_probability is not None:
        options["target_probability"] = _number("target_probability", target_probability)
    if white_noise is not None:
        if duration is None:
            raise InputError("duration is required with white_noise: how long the stationary motion lasts, s")
        wn: Dict[str, Any] = {"s0": _number("white_noise", white_noise), "duration": _number("duration", duration), "clumping": clumping}
        if filter is not None:
            if not isinstance(filter, dict):
                raise InputError(f"filter = {_short(filter)} is not allowed: a dict with kind, wg, zg (wf, zf)")
            wn["filter"] = filter
        options["white_noise"] = wn
    elif duration is not None or filter is not None:
        raise InputError("duration and filter are not allowed without white_noise")
    for key, value in (("code", code), ("hazard", hazard)):
        if value is not None:
            if not isinstance(value, dict):
                raise InputError(f"{key} = {_short(value)} is not allowed: a dict (see help(pounding.separation))")
            options[key] = value
    text = _json(options, "options")
    if isinstance(scenario, (str, os.PathLike)):
        out = _pounding.separation(path=os.fspath(scenario), records=recs, aligned_factor=aligned_factor, options=text)
    else:
        out = _pounding.separation(scenario=_json(scenario), records=recs, aligned_factor=aligned_factor, options=text)
    return json.loads(out)


def synthetic(seed: int, **params: Any) -> Dict[str, Any]:
    """A synthetic ground motion from ``seed`` (a whole number from 0 to 2^64 - 1): filtered white noise
    under a time envelope, scaled to a PGA, exactly ``pounding record synth`` and the built-in record
    ``"synthetic-SEED"`` with the defaults (docs/separation.md). Parameters (SI units), each read by the
    library with its default (a parameter given as None keeps its default): ``filter`` (``"clough-penzien"``
    or ``"kanai-tajimi"``), ``wg``, ``zg``, ``wf``, ``zf`` (rad/s and ratios), ``duration``, ``dt``, ``t1``,
    ``t2`` (s), ``decay`` (1/s), ``pga`` (m/s^2); an unknown one raises InputError. Returns ``dt`` (s),
    ``t0`` (s), ``time`` (s) and ``acceleration`` (m/s^2, numpy)."""
    given = {k: v for k, v in params.items() if v is not None}
    dt, t0, acc = _pounding.synthetic(seed, _json(given, "synthetic"))
    a = np.asarray(acc)
    return {"dt": dt, "t0": t0, "time": t0 + dt * np.arange(len(a)), "acceleration": a}


def coherent(
    seed: int,
    positions: Sequence[float],
    model: str,
    record: Optional[Union[str, "os.PathLike[str]"]] = None,
    units: Optional[str] = None,
    window: float = 2.0,
    low_cut: float = 0.1,
    **params: Any,
) -> Dict[str, Any]:
    """Records at supports along a line that lose coherence with distance, exactly ``pounding record
    coherent`` (docs/structures.md): ``positions`` (m), ``model`` ``"luco-wong"`` (give ``alpha``, s/m) or
    ``"harichandran-vanmarcke"`` (``A``, ``a``, ``k`` in m, ``f0`` in Hz, ``b``; defaults SMART-1 event 20).
    Generated from the spectrum's parameters of :func:`synthetic` (the first support's PGA is ``pga``; one
    factor scales all), or, with ``record`` (a built-in record's name or a file; ``units`` as in a scenario's
    ``[ground_motion]``), conditioned on that record: it stays at the first position, the others get its
    Fourier amplitudes and the model's coherency with it, their random parts under its envelope (moving RMS
    over ``window`` s; 0 for none) and holding nothing below ``low_cut`` Hz (0 for no cut). Returns ``dt`` (s), ``t0`` (s), ``time`` (s) and ``acceleration``: one
    numpy array per support (m/s^2)."""
    keys = {"alpha", "A", "a", "k", "f0", "b"}
    given = {k: v for k, v in params.items() if v is not None}
    coh = {"model": model, **{k: given.pop(k) for k in list(given) if k in keys}}
    if units is not None and not isinstance(units, str):
        raise InputError(f"units = {_short(units)} is not allowed: a name (str) or None")
    dt, t0, accs = _pounding.coherent(
        seed,
        [float(x) for x in positions],
        _json(coh, "coherency"),
        _json(given, "coherent"),
        record=None if record is None else _fspath("record", record),
        units=units,
        window=_number("window", window),
        low_cut=_number("low_cut", low_cut),
    )
    arrays = [np.asarray(a) for a in accs]
    return {"dt": dt, "t0": t0, "time": t0 + dt * np.arange(len(arrays[0])), "acceleration": arrays}


def ida(
    study: Union[str, "os.PathLike[str]"],
    out: Union[str, "os.PathLike[str]"],
    workers: Optional[int] = None,
    progress: bool = True,
) -> Dict[str, Any]:
    """Runs the IDA study file ``study`` (docs/ida.md) into the folder ``out``, exactly as ``pounding ida``
    does (a resumable store, runs.csv, fragility.csv), and returns a dict: ``runs`` and ``fragility`` as
    pandas DataFrames (lists of dicts without pandas) and ``result``, the JSON summary (measure, levels,
    records and their intensities, the fits)."""
    n = _workers(workers)
    result = json.loads(_pounding.ida(_fspath("study", study), _fspath("out", out), n, _flag("progress", progress)))
    folder = Path(os.fspath(out))
    try:
        import pandas as pd

        runs = pd.read_csv(folder / "runs.csv")
        fragility = pd.read_csv(folder / "fragility.csv")
    except ImportError:
        import csv

        runs = list(csv.DictReader(open(folder / "runs.csv")))
        fragility = list(csv.DictReader(open(folder / "fragility.csv")))
    return {"runs": runs, "fragility": fragility, "result": result}
