"""The one home of the workbench's Ctrl-C handling (no heavy imports here).

A Ctrl-C is held through a block (:func:`sigint_held`), kept when it comes while a finalizer runs
(:func:`ctrl_c_in_finalizers_kept`), and stops a command until the command is done
(:func:`ctrl_c_until_done`).
"""

from __future__ import annotations

import contextlib
import signal
import sys
import threading
from collections.abc import Iterator
from typing import Any

__all__ = [
    "command_done", "ctrl_c_in_finalizers_kept", "ctrl_c_until_done", "raise_kept_ctrl_c", "sigint_held",
]

_KEPT: list[int] = []  # Ctrl-Cs that came while a finalizer ran (see ctrl_c_in_finalizers_kept)
_DONE = [False]  # the command's work is done (see ctrl_c_until_done)


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


@contextlib.contextmanager
def ctrl_c_in_finalizers_kept() -> Iterator[None]:
    """Keep a Ctrl-C that comes while a finalizer runs, silently, for :func:`raise_kept_ctrl_c`.

    Python raises a Ctrl-C in whatever Python code runs when it comes. In a finalizer (a
    ``__del__``, a weakref callback) the KeyboardInterrupt cannot reach the code around it:
    Python prints "Exception ignored in ..." with its traceback and goes on. compare's progress
    bar is freed as the run returns: a Ctrl-C just after the work was done printed a traceback
    from tqdm's ``__del__``, and one coming there mid-run was lost. Within this block such a
    Ctrl-C prints nothing and is kept; any other exception of a finalizer is reported as before.

    >>> class Bar:
    ...     def __del__(self):  # what a Ctrl-C that comes while the finalizer runs raises there
    ...         raise KeyboardInterrupt
    >>> with ctrl_c_in_finalizers_kept():
    ...     bar = Bar()
    ...     del bar  # its finalizer runs here
    ...     try:
    ...         raise_kept_ctrl_c()
    ...     except KeyboardInterrupt:
    ...         print("raised where the loop checks")
    raised where the loop checks
    """
    before = sys.unraisablehook

    def hook(info: Any) -> None:
        if isinstance(info.exc_value, KeyboardInterrupt):
            _KEPT.append(signal.SIGINT)
        else:
            before(info)

    _KEPT.clear()
    sys.unraisablehook = hook
    try:
        yield
    finally:
        sys.unraisablehook = before


def raise_kept_ctrl_c() -> None:
    """Raise KeyboardInterrupt if a finalizer got a Ctrl-C (:func:`ctrl_c_in_finalizers_kept`), once."""
    if _KEPT:
        _KEPT.clear()
        raise KeyboardInterrupt


def command_done() -> None:
    """Mark the command's work done: from here a Ctrl-C has nothing to stop (:func:`ctrl_c_until_done`)."""
    _DONE[0] = True


def _interrupt_until_done(signum: int, frame: Any) -> None:
    if not _DONE[0]:
        raise KeyboardInterrupt


@contextlib.contextmanager
def ctrl_c_until_done() -> Iterator[None]:
    """A Ctrl-C stops the command until :func:`command_done`; from then on it is ignored.

    The command calls :func:`command_done` inside its own ``try`` that handles a Ctrl-C, so no
    Ctrl-C falls between the two: one before is the command's, one after is dropped, even one
    already pending. (Ignoring it once the command had returned left a few instructions between
    its end and the ignoring, where a Ctrl-C raised a KeyboardInterrupt with a traceback and
    exit status -2.) At the end of the block Ctrl-C is ignored for good: Python's shutdown would
    give it back its default action, killing the process and hiding the exit status.

    >>> import os
    >>> before = signal.getsignal(signal.SIGINT)
    >>> with ctrl_c_until_done():
    ...     command_done()
    ...     os.kill(os.getpid(), signal.SIGINT)  # nothing left to stop: nothing raised
    ...     print("finished")
    finished
    >>> signal.getsignal(signal.SIGINT) is signal.SIG_IGN
    True
    >>> _ = signal.signal(signal.SIGINT, before)
    """
    _DONE[0] = False
    signal.signal(signal.SIGINT, _interrupt_until_done)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, signal.SIG_IGN)
