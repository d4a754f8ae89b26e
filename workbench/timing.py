"""One timing helper for every benchmark: ``timeit``'s autorange, best of several repeats.

The benchmark modules (``bench_planar``, ``bench_space``, ``bench_cad``) each carried their
own loop; :func:`best_time` replaces them (the switch is left to the benchmarks' owner).
"""

from __future__ import annotations

import timeit
from collections.abc import Callable
from typing import Any

from relief_cad.errors import InvalidInputError

__all__ = ["best_time"]


def best_time(fn: Callable[[], Any], *, repeat: int = 5, per_call: int = 1) -> float:
    """Seconds per call of ``fn``: the best of ``repeat`` autoranged runs, divided by ``per_call``.

    Parameters
    ----------
    fn : callable
        Called with no argument.
    repeat : int
        Independent measurements (the minimum is kept: it is the least disturbed by the machine).
    per_call : int
        Items one call handles (e.g. pairs in a batch), to report seconds per item.

    Returns
    -------
    float
        Seconds per call (per item with ``per_call``).

    Examples
    --------
    >>> 0 < best_time(lambda: sum(range(100)), repeat=2) < 1
    True
    """
    if repeat < 1 or per_call < 1:
        raise InvalidInputError(f"expected repeat >= 1 and per_call >= 1, received {repeat} and {per_call}")
    timer = timeit.Timer(fn)
    number, _ = timer.autorange()  # enough calls for at least 0.2 s
    return min(timer.repeat(repeat=repeat, number=number)) / number / per_call
