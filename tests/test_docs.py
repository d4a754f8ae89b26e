"""Every public name has a docstring with a runnable example (the examples run as doctests)."""

from __future__ import annotations

import importlib
import inspect

import pytest

from tests._env import needs_cadquery

MODULES = [
    "relief_cad",
    "relief_cad.curves",
    "relief_cad.errors",
    "relief_cad.relief",
    "relief_cad.results",
    "relief_cad.space",
    "relief_cad.intersection",
    "relief_cad.clipping",
    "relief_cad.tolerances",
    "relief_cad.cad",
    "relief_cad.cad.api",
    "relief_cad.cad.ocp",
    "relief_cad.cad.results",
    "relief_cad.cad.compare",
    "relief_cad.cad.occt",
    "relief_cad.cad.build123d",
    pytest.param("relief_cad.cad.cadquery", marks=needs_cadquery),
    "relief_cad.cad._compat",
    "relief_cad.cad._checks",
    "relief_cad.cad.topology",
    "relief_cad.cad.flavour",
    "relief_cad.cad.curvetypes",
    "relief_cad.cad.exact",
    "relief_cad.cad.arbiter",
    "relief_cad.cad.render",
]


def public_objects(module_name: str) -> list[tuple[str, object]]:
    module = importlib.import_module(module_name)
    out: list[tuple[str, object]] = [(module_name, module)]
    for name in getattr(module, "__all__", []):
        obj = getattr(module, name)
        if not (inspect.isclass(obj) or inspect.isfunction(obj)) or getattr(obj, "__module__", None) != module_name:
            continue
        out.append((f"{module_name}.{name}", obj))
        if inspect.isclass(obj):
            for attr, value in vars(obj).items():
                if not attr.startswith("_") and (isinstance(value, property) or inspect.isfunction(value)):
                    out.append((f"{module_name}.{name}.{attr}", value))
    return out


@pytest.mark.parametrize("module_name", MODULES)
def test_every_public_name_has_an_example(module_name: str) -> None:
    missing = [qual for qual, obj in public_objects(module_name) if ">>>" not in (inspect.getdoc(obj) or "")]
    assert not missing, f"public names without a '>>>' example: {missing}"
