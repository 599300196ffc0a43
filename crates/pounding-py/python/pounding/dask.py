"""Sweeps on a ``dask.distributed`` cluster: the same results as :func:`pounding.sweep`, with runs spread over
the cluster's workers in chunks and every result committed to the store on the client.

Every worker needs the ``pounding`` package, and any record file a scenario names at the same path.
"""

from __future__ import annotations

import os
import sys
import time
from typing import Any, Dict, Iterable, List, Optional, Union

from . import InputError, Scenario, _fspath, _outcome, _pounding, _texts


def _run_chunk(texts: List[str], labels: List[str]) -> List[tuple]:
    """Runs a chunk of scenarios on one worker, one thread (the cluster gives the parallelism):
    ``(key, ok, summary JSON or error message, seconds)`` per run."""
    out = []
    for text, label in zip(texts, labels):
        t0 = time.perf_counter()
        ((key, ok, result),) = _pounding.sweep_runs([text], [label], 1, None, False)
        out.append((key, ok, result, time.perf_counter() - t0))
    return out


def sweep(
    scenarios: Iterable[Scenario],
    client,
    store: Optional[Union[str, "os.PathLike[str]"]] = None,
    chunk: Optional[int] = None,
    progress: bool = True,
) -> List[Dict[str, Any]]:
    """Runs every scenario (dicts or paths) on the cluster of ``client`` (a ``dask.distributed.Client``) and
    returns their summaries in input order, exactly as :func:`pounding.sweep` does (a failed run gives
    ``{"error": message}``). Runs go to the workers in chunks of ``chunk`` (default: about four chunks per
    worker thread, at most 1000 runs each); with ``store``, each chunk's runs are committed on the client as the
    chunk returns, so an interrupted sweep resumes from the store, and a store of other scenarios raises
    InputError, untouched; a store of earlier scenarios that are all among these grows into theirs.
    ``progress`` prints one updating line on stderr as chunks return (runs done, failed, from the store, time
    left), as :func:`pounding.sweep` does.
    """
    from dask.distributed import as_completed

    # Every argument checked before the store is touched.
    if chunk is not None and (isinstance(chunk, bool) or not isinstance(chunk, int) or chunk < 1):
        raise InputError(f"chunk = {chunk!r} is not allowed: a whole number of runs per task, at least 1")
    if not isinstance(progress, bool):
        raise InputError(f"progress = {progress!r} is not allowed: True or False")
    texts, labels = _texts(scenarios)
    keys, study = _pounding.keys(texts)
    st = None if store is None else _pounding.Store(_fspath("store", store), study, keys)
    outcomes: Dict[str, tuple] = {}
    if st is not None:
        for key, ok, text in st.finished():
            outcomes[key] = (ok, text)
    # One run per distinct key not yet in the store, in study order.
    todo, seen = [], set(outcomes)
    for i, k in enumerate(keys):
        if k not in seen:
            seen.add(k)
            todo.append(i)
    if todo:
        threads = sum(client.nthreads().values()) or 1
        size = chunk if chunk is not None else max(1, min(1000, len(todo) // (4 * threads) or 1))
        chunks = [todo[i : i + size] for i in range(0, len(todo), size)]
        futures = [
            client.submit(_run_chunk, [texts[i] for i in c], [labels[i] for i in c], pure=False)
            for c in chunks
        ]
        index = {f.key: c for f, c in zip(futures, chunks)}
        line = _Progress(len(todo), len(keys) - len(todo), progress)
        for fut, result in as_completed(futures, with_results=True):
            c = index[fut.key]
            rows = [(key, i, ok, text, secs) for i, (key, ok, text, secs) in zip(c, result)]
            if st is not None:
                st.commit(rows)
            for key, _, ok, text, _ in rows:
                outcomes[key] = (ok, text)
            line.show(len(rows), sum(1 for r in rows if not r[2]))
        line.end()
    return [_outcome(*outcomes[k]) for k in keys]


class _Progress:
    """One updating line on stderr: runs done of the total, failed, taken from the store, time left."""

    def __init__(self, todo: int, stored: int, shown: bool):
        self.todo, self.stored, self.shown = todo, stored, shown
        self.done = self.failed = 0
        self.t0 = time.perf_counter()

    def show(self, done: int, failed: int) -> None:
        self.done += done
        self.failed += failed
        if not self.shown:
            return
        elapsed = time.perf_counter() - self.t0
        left = (self.todo - self.done) * elapsed / max(self.done, 1)
        sys.stderr.write(
            f"\rpounding dask sweep: {self.done + self.stored}/{self.todo + self.stored} runs, {self.failed} failed, "
            f"{self.stored} from the store, {elapsed:.1f} s, about {left:.0f} s left   "
        )
        sys.stderr.flush()

    def end(self) -> None:
        if self.shown:
            sys.stderr.write("\n")
