"""Build of relief_cad's compiled kernels (Cython, pure-Python mode); metadata is in pyproject.toml.

``RELIEF_CAD_SANITIZE=1`` builds a checked variant: Cython bounds and wraparound checks on, and
the C code compiled with AddressSanitizer and UndefinedBehaviorSanitizer (run it with
``LD_PRELOAD=$(gcc -print-file-name=libasan.so)``); ``RELIEF_CAD_SANITIZE=bounds`` turns on only
the Cython checks (no C sanitizers, no preload needed).
"""

from __future__ import annotations

import os

from Cython.Build import cythonize
from Cython.Compiler import Options
from setuptools import Extension, setup

MODULES = ("bezier", "clip", "certify", "polish", "planar", "batch", "space")
SANITIZE = os.environ.get("RELIEF_CAD_SANITIZE", "").strip().lower()

# -O3, never -ffast-math; no contraction into FMA: every run and every compiler gives the same bits
CFLAGS = ["-O3", "-fno-fast-math", "-ffp-contract=off"]
LDFLAGS: list[str] = []
if SANITIZE not in ("", "0", "bounds"):
    CFLAGS += ["-O1", "-g", "-fno-omit-frame-pointer", "-fsanitize=address,undefined",
               "-fno-sanitize-recover=undefined"]
    LDFLAGS += ["-fsanitize=address,undefined"]

DIRECTIVES = {
    "language_level": 3,
    "boundscheck": bool(SANITIZE and SANITIZE != "0"),
    "wraparound": bool(SANITIZE and SANITIZE != "0"),
    "initializedcheck": bool(SANITIZE and SANITIZE != "0"),
    "cdivision": True,  # IEEE division (inf/nan), as numpy: no ZeroDivisionError inside kernels
    "infer_types": True,
    "embedsignature": True,
}

# every memoryview of the kernels has 1 or 2 dimensions: Cython's slice struct keeps its shape,
# strides and suboffsets for this many (default 8: 208 bytes per slice, zeroed on entry to each
# function for every view it holds; the pair driver holds 43). 3 is the least Cython accepts for
# 2 dimensions
Options.buffer_max_dims = 3

extensions = [
    Extension(f"relief_cad._kernels.{name}", [f"relief_cad/_kernels/{name}.py"],
              extra_compile_args=CFLAGS, extra_link_args=LDFLAGS)
    for name in MODULES
]

setup(ext_modules=cythonize(extensions, compiler_directives=DIRECTIVES, quiet=True))
