"""Contact laws fitted to tests, as ``pounding fit`` does on the command line (docs/contact-models.md
section 2.8). Each function returns a dict: ``parameters`` under their scenario key names (paste them into a
scenario's contact), ``std_errors`` and ``units`` by the same keys, ``also`` (what is not a scenario key:
``yield_velocity`` m/s, ``touch_time`` s), the residual (``rms_residual`` in ``residual_unit``,
``normalised_residual``), ``scenario`` (the lines to paste) and ``curve`` (the fitted curve, two numpy arrays).

Data are a path to a two-column text file (a header line and ``#`` comments allowed), or pairs: a list of
``(x, y)``, an array of shape (n, 2), or a pandas DataFrame of two columns.
"""

from __future__ import annotations

import json
import math
import os
from typing import Any, Dict, Optional

import numpy as np

from . import _pounding
from ._pounding import InputError

__all__ = ["restitution", "force_history"]


def _data(data: Any, what: str):
    """``(points, path)``: a path as text, or the pairs as a list of float tuples."""
    if isinstance(data, (str, os.PathLike)):
        return None, os.fspath(data)
    try:
        a = np.asarray(data, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(f"data = {type(data).__name__} is not allowed: a path, or pairs ({what})") from None
    if a.ndim != 2 or a.shape[1] != 2:
        raise InputError(f"data of shape {a.shape} is not allowed: pairs, shape (n, 2) ({what})")
    return [(float(x), float(y)) for x, y in a], None


def _number(key: str, v: Any) -> Optional[float]:
    if v is None:
        return None
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating)):
        raise InputError(f"{key} = {v!r:.60} is not allowed: a number")
    return float(v)


def _report(text: str, x, y, names) -> Dict[str, Any]:
    r = json.loads(text)
    r["curve"] = {names[0]: np.asarray(x), names[1]: np.asarray(y)}
    return r


def restitution(
    data: Any,
    model: str,
    rows: Optional[int] = None,
    monotone: bool = False,
    radius: Optional[float] = None,
    k: Optional[float] = None,
    m1: Optional[float] = None,
    m2: float = math.inf,
) -> Dict[str, Any]:
    """Fits measured ``(v_i, e)`` pairs (v_i in m/s): for a model of the Hunt-Crossley family its
    ``damping_constant`` (s/m), for ``"thornton"`` its yield velocity (and with ``radius`` m, ``k`` N/m^1.5
    and ``m1`` kg its ``yield_pressure``), for another damped model one ``e``, and for ``"table"`` the table
    ``e(v_i)`` itself (at most ``rows`` rows; non-increasing if ``monotone``). ``curve``: ``v_i``, ``e``."""
    if not isinstance(model, str):
        raise InputError(f"model = {model!r:.60} is not allowed: a model's name or \"table\"")
    if rows is not None and (isinstance(rows, bool) or not isinstance(rows, (int, np.integer))):
        raise InputError(f"rows = {rows!r:.60} is not allowed: a whole number")
    if not isinstance(monotone, (bool, np.bool_)):
        raise InputError(f"monotone = {monotone!r:.60} is not allowed: True or False")
    points, path = _data(data, "v_i in m/s, then e")
    text, x, y = _pounding.fit_restitution(
        model, points=points, path=path, rows=None if rows is None else int(rows), monotone=bool(monotone),
        radius=_number("radius", radius), k=_number("k", k), m1=_number("m1", m1), m2=_number("m2", m2),
    )
    return _report(text, x, y, ("v_i", "e"))


def force_history(
    data: Any,
    model: str,
    m1: float,
    v: float,
    m2: float = math.inf,
    n: Optional[float] = None,
    damping_constant: bool = False,
    radius: Optional[float] = None,
) -> Dict[str, Any]:
    """Fits the force history of one impact (``(t, F)`` pairs, s and N, any time origin) of a body of mass
    ``m1`` (kg) striking one of ``m2`` (kg; ``math.inf`` a rigid slab) at ``v`` (m/s): the model's
    ``stiffness`` (N/m^n), ``exponent`` (unless held at ``n``) and damping (``e``, or with
    ``damping_constant=True`` a material ``damping_constant`` in s/m, or ``thornton``'s ``yield_pressure`` in
    Pa, given its ``radius`` in m), with the touch time. ``curve``: ``time``, ``force``."""
    if not isinstance(model, str):
        raise InputError(f"model = {model!r:.60} is not allowed: a model's name")
    if not isinstance(damping_constant, (bool, np.bool_)):
        raise InputError(f"damping_constant = {damping_constant!r:.60} is not allowed: True or False")
    points, path = _data(data, "time in s, then force in N")
    text, x, y = _pounding.fit_force_history(
        model, _number("m1", m1), _number("v", v), data=points, path=path, m2=_number("m2", m2),
        n=_number("n", n), damping_constant=bool(damping_constant), radius=_number("radius", radius),
    )
    return _report(text, x, y, ("time", "force"))
