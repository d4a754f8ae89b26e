"""The one thread pool of the batch paths: kept alive between calls, results in order.

The batch kernels release the GIL, so chunks of pairs run at once on threads. Starting and
joining a :class:`~concurrent.futures.ThreadPoolExecutor` on every call cost about 1 ms on a
2-core machine (a sixth of 2,000 random cubic pairs); the pool here is made once per process and
per number of workers, and made again in a child process after a ``fork`` (whose copy of the
pool has no threads).

>>> run_ordered(lambda k: k * k, [1, 2, 3], workers=2)
[1, 4, 9]
"""

from __future__ import annotations

import os
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor, wait
from typing import TypeVar

__all__ = ["run_ordered"]

T = TypeVar("T")
R = TypeVar("R")

_POOLS: dict[int, ThreadPoolExecutor] = {}
_OWNER = [os.getpid()]  # the process whose threads the pools hold
_LOCK = threading.Lock()
_PREFIX = "relief_cad-pool"  # the pool's thread names


def _pool(workers: int) -> ThreadPoolExecutor:
    """The live pool of ``workers`` threads of this process (made on first use)."""
    with _LOCK:
        if _OWNER[0] != os.getpid():  # a forked child: the parent's threads are not here
            _POOLS.clear()
            _OWNER[0] = os.getpid()
        pool = _POOLS.get(workers)
        if pool is None:
            pool = _POOLS[workers] = ThreadPoolExecutor(max_workers=workers, thread_name_prefix=_PREFIX)
        return pool


def run_ordered(fn: Callable[[T], R], items: Sequence[T], workers: int) -> list[R]:
    """``[fn(x) for x in items]``, run on up to ``workers`` threads of the kept pool.

    One item, or one worker, runs here without a pool, and so does a call from a task of the pool
    (its threads would wait on tasks queued behind their own). Otherwise every item is submitted and
    the results are read in order once all have run, so an exception is that of the first item,
    in order, that raised, and no task is left running behind it.
    """
    if workers <= 1 or len(items) <= 1 or threading.current_thread().name.startswith(_PREFIX):
        return [fn(x) for x in items]  # (in a task of the pool: here, not waiting on the pool itself)
    futures = [_pool(min(workers, len(items))).submit(fn, x) for x in items]
    wait(futures)  # every task to its end, even behind one that raised
    return [f.result() for f in futures]
