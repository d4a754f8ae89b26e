"""Hypothesis strategies for random rational Bézier curves."""

from __future__ import annotations

import numpy as np
from hypothesis import strategies as st

from relief_cad import RationalBezier

coords = st.floats(min_value=-10.0, max_value=10.0, allow_nan=False, allow_infinity=False)
weights = st.floats(min_value=0.2, max_value=5.0)


@st.composite
def curves(draw: st.DrawFn, dim: int | None = None, min_degree: int = 1, max_degree: int = 8,
           rational: bool = True) -> RationalBezier:
    d = draw(st.sampled_from([2, 3])) if dim is None else dim
    n = draw(st.integers(min_degree, max_degree))
    pts = np.array(draw(st.lists(st.lists(coords, min_size=d, max_size=d), min_size=n + 1, max_size=n + 1)))
    w = None
    if rational and draw(st.booleans()):
        w = np.array(draw(st.lists(weights, min_size=n + 1, max_size=n + 1)))
    return RationalBezier(pts, w)


spans = st.floats(min_value=0.05, max_value=20.0).filter(lambda k: abs(k - 1.0) > 1e-3)
params = st.floats(min_value=0.0, max_value=1.0)
