"""The one assertion of the public functions' input tests: a bad call raises exactly the right error."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from relief_cad.errors import InputTypeError, InvalidInputError, ReliefCadError


def refused(call: Callable[[], Any], error: type[Exception], *words: str) -> None:
    """``call()`` raises exactly ``error``, a ReliefCadError and its built-in, naming ``words``."""
    with pytest.raises(error) as info:
        call()
    exc = info.value
    assert type(exc) is error, (type(exc), exc)
    assert isinstance(exc, ReliefCadError)
    if issubclass(error, InputTypeError):
        assert isinstance(exc, TypeError)
    if issubclass(error, InvalidInputError):
        assert isinstance(exc, ValueError)
    for word in words:
        assert word in str(exc), (word, str(exc))
