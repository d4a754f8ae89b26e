"""Ctrl-C held through a block: the one home of the workbench's signal hold (no heavy imports here)."""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator

__all__ = ["sigint_held"]


@contextlib.contextmanager
def sigint_held() -> Iterator[None]:
    """Hold a Ctrl-C that comes during the block, and raise it as KeyboardInterrupt at its end.

    Two places must not be cut by one:

    * OCP's extension modules are pybind11 modules: a KeyboardInterrupt raised while one
      initialises comes back as an ``ImportError`` (which an ``except ImportError`` then swallows)
      and leaves the type registry half filled, so that every later ``import OCP`` in that process
      and in the worker processes forked from it fails ("... is already defined").
    * A local pool forks its workers when the first tasks are submitted. A KeyboardInterrupt
      raised in Python's fork handlers (``logging`` releases its lock there) is printed and
      ignored: a Ctrl-C one second into ``compare`` was lost and the run went on to the end.

    Outside the main thread (no signal handlers there) the block runs as it is.

    >>> import os
    >>> try:
    ...     with sigint_held():
    ...         os.kill(os.getpid(), signal.SIGINT)
    ...         print("the block ends")
    ... except KeyboardInterrupt:
    ...     print("then the Ctrl-C")
    the block ends
    then the Ctrl-C
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    held: list[int] = []
    old = signal.signal(signal.SIGINT, lambda signum, frame: held.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old)
    if held:
        raise KeyboardInterrupt
