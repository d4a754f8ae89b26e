"""Compiled kernels of the planar Bézier-clipping intersector and of the space relief scheme.

The modules of this package are plain Python files annotated for Cython (pure-Python mode); the
build (``pip install .`` or ``python setup.py build_ext --inplace``, a C compiler is needed)
compiles each of them to a C extension. The public, documented API lives in
:mod:`relief_cad.intersection`, :mod:`relief_cad.space` and :mod:`relief_cad.clipping`; these
kernels have no stability promise.

Modules, by concept:

- :mod:`~relief_cad._kernels.bezier`: homogeneous Bézier evaluation, subdivision, boxes, frame;
- :mod:`~relief_cad._kernels.clip`: fat lines and convex-hull clipping;
- :mod:`~relief_cad._kernels.polish`: Newton polishing, closest points, coincidence;
- :mod:`~relief_cad._kernels.certify`: double-double arithmetic and the certified polish;
- :mod:`~relief_cad._kernels.planar`: the planar pair driver;
- :mod:`~relief_cad._kernels.batch`: many pairs in one call;
- :mod:`~relief_cad._kernels.space`: the relief frame, φ, ψ, the depth check and the space driver;
- :mod:`~relief_cad._kernels.rows`: result rows to result objects (with the GIL; the one such place).

Uncompiled switch
-----------------
``RELIEF_CAD_PURE=1`` in the environment (before the first import of :mod:`relief_cad`) runs the
same ``.py`` files as plain Python (needs the ``cython`` package for its annotations; slow; for
debugging and coverage). Without it, a kernel module that is not compiled is an
:class:`ImportError` saying how to build it: there is never a silent fallback to slow code.

Data layout
-----------
A planar rational curve is passed as Cartesian control points ``P`` of shape ``(n + 1, 2)`` and
weights ``W`` of shape ``(n + 1,)``. Result rows (``RES_COLS`` columns) are
``[pair, kind, t, u, t1, u1, x, y, distance]``; space rows (``SPACE_COLS``) are
``[kind, t, u, t1, u1, x, y, z, distance]``.

>>> KIND_CROSSING, KIND_TANGENT, KIND_OVERLAP, KIND_UNRESOLVED
(0, 1, 2, 3)
"""

from __future__ import annotations

import importlib
import importlib.machinery
import importlib.util
import os
import sys
from types import ModuleType

__all__ = [
    "_space_frame",
    "COMPILED",
    "KIND_CROSSING",
    "KIND_OVERLAP",
    "KIND_TANGENT",
    "KIND_UNRESOLVED",
    "RES_COLS",
    "SPACE_COLS",
    "STATUS_ARTEFACT",
    "STATUS_OK",
    "clip_range_kernel",
    "ends_match",
    "fat_line_kernel",
    "hull_range_kernel",
    "intersect_batch_kernel",
    "intersect_one_kernel",
    "intersect_pair_kernel",
    "pack_pairs",
    "planar_pair",
    "space_pair_kernel",
    "space_pair_rows",
]

#: the compiled modules, in dependency order (``constants`` is plain Python, never compiled)
KERNEL_MODULES: tuple[str, ...] = ("rows", "bezier", "clip", "certify", "polish", "planar", "batch", "space")

PURE_ENV = "RELIEF_CAD_PURE"


def _pure_requested() -> bool:
    return os.environ.get(PURE_ENV, "").strip() not in ("", "0")


def _load_source(name: str) -> ModuleType:
    """Execute ``<name>.py`` of this package as a plain Python module (the uncompiled switch)."""
    full = f"{__name__}.{name}"
    path = os.path.join(os.path.dirname(__file__), f"{name}.py")
    spec = importlib.util.spec_from_file_location(full, path)
    if spec is None or spec.loader is None:  # pragma: no cover - the file ships with the package
        raise ImportError(f"cannot load the kernel source {path}")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[full] = mod
    spec.loader.exec_module(mod)
    return mod


def _load_compiled(name: str) -> ModuleType:
    """Import the compiled extension ``name``; an :class:`ImportError` if only the source is there."""
    full = f"{__name__}.{name}"
    mod = importlib.import_module(full)
    origin = getattr(mod, "__file__", "") or ""
    if not origin.endswith(tuple(importlib.machinery.EXTENSION_SUFFIXES)):
        del sys.modules[full]
        raise ImportError(
            f"{full} is not compiled (found {origin!r}): build the kernels with `pip install .` or "
            f"`pip install -e .` (a C compiler is needed), or set {PURE_ENV}=1 to run them as "
            "plain Python (slow, for debugging)"
        )
    return mod


def _load() -> bool:
    pure = _pure_requested()
    for name in KERNEL_MODULES:
        _load_source(name) if pure else _load_compiled(name)
    return not pure


COMPILED: bool = _load()
"""True when the compiled kernels run; False under ``RELIEF_CAD_PURE=1``."""

from .batch import ends_match, intersect_batch_kernel, intersect_one_kernel, pack_pairs, planar_pair  # noqa: E402
from .clip import clip_range_kernel, fat_line_kernel, hull_range_kernel  # noqa: E402
from .constants import (  # noqa: E402
    KIND_CROSSING,
    KIND_OVERLAP,
    KIND_TANGENT,
    KIND_UNRESOLVED,
    RES_COLS,
    SPACE_COLS,
    STATUS_ARTEFACT,
    STATUS_OK,
)
from .planar import intersect_pair_kernel  # noqa: E402
from .space import _space_frame, _space_project, space_pair_kernel, space_pair_rows  # noqa: E402,F401
