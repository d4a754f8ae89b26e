"""Build of relief_cad's compiled kernels (Cython, pure-Python mode); metadata is in pyproject.toml.

``RELIEF_CAD_SANITIZE=1`` builds a checked variant: Cython bounds and wraparound checks on, and
the C code compiled with AddressSanitizer and UndefinedBehaviorSanitizer (run it with
``LD_PRELOAD=$(gcc -print-file-name=libasan.so)``); ``RELIEF_CAD_SANITIZE=bounds`` turns on only
the Cython checks (no C sanitizers, no preload needed).
"""

from __future__ import annotations

import os
import tempfile

import numpy
from Cython.Build import cythonize
from Cython.Compiler import Options
from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

MODULES = ("rows", "bezier", "clip", "certify", "polish", "planar", "batch", "space")
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

# the modules that make numpy arrays through numpy's C API (built against numpy 2 headers, which
# run on numpy 1.x too: NumPy's default target API is older than the oldest numpy we accept)
NUMPY_C_API = ("rows",)

extensions = [
    Extension(f"relief_cad._kernels.{name}", [f"relief_cad/_kernels/{name}.py"],
              extra_compile_args=CFLAGS, extra_link_args=LDFLAGS,
              **({"include_dirs": [numpy.get_include()],
                  "define_macros": [("NPY_NO_DEPRECATED_API", "NPY_1_7_API_VERSION")]}
                 if name in NUMPY_C_API else {}))
    for name in MODULES
]

# Cython zeroes every memoryview slice a function holds (88 bytes each) on entry; x86 GCC does it
# with one `rep stos` per slice, about 30 cycles of start-up each (a tenth of a small pair's
# kernel time in the pair driver). Plain stores instead, where the compiler takes the option
# (gcc on x86; it changes no arithmetic, so no bits)
PLAIN_STORES = "-mstringop-strategy=unrolled_loop"


def _accepts(compiler: object, flag: str) -> bool:
    """True when ``compiler`` (a setuptools compiler) compiles a C file with ``flag``."""
    with tempfile.TemporaryDirectory() as tmp:
        src = os.path.join(tmp, "probe.c")
        with open(src, "w") as f:
            f.write("int main(void) { return 0; }\n")
        try:
            compiler.compile([src], output_dir=tmp, extra_postargs=[flag, "-Werror"])  # type: ignore[attr-defined]
        except Exception:  # noqa: BLE001 - any failure means: not this flag
            return False
    return True


class BuildExt(build_ext):
    """``build_ext`` adding :data:`PLAIN_STORES` when the compiler accepts it."""

    def build_extensions(self) -> None:
        """Probe the compiler once, then build every extension."""
        if _accepts(self.compiler, PLAIN_STORES):
            for ext in self.extensions:
                ext.extra_compile_args = [*ext.extra_compile_args, PLAIN_STORES]
        super().build_extensions()


setup(ext_modules=cythonize(extensions, compiler_directives=DIRECTIVES, quiet=True),
      cmdclass={"build_ext": BuildExt})
