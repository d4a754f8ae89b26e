"""``bench arrange`` on a small case: the row it reports, on real OCCT edges against General Fuse."""

from __future__ import annotations

import math

from relief_cad_workbench.bench_arrange import _case, _fillets, _floor_calls, _ocp_floor


def test_a_small_filleted_sketch_gives_general_fuses_counts_valid_and_connected() -> None:
    row = _case("fillets", 20, lambda: _fillets(20))
    assert row["edges"] == 20 and row["valid"] and row["connected"]
    assert (row["relief_E"], row["relief_V"]) == (row["occt_E"], row["occt_V"]) and row["verdict"] == "same"
    assert row["relief_E"] > row["edges"]  # the rectangles and circles cross: edges were cut
    assert math.isclose(row["speedup"], row["occt_s"] / row["relief_s"])
    assert 0.0 < row["ocp_floor_s"] < math.inf
    assert math.isclose(row["speedup_bound"], row["occt_s"] / row["ocp_floor_s"])


def test_the_ocp_floor_makes_the_vertices_and_edges_it_counts() -> None:
    from OCP.BRep import BRep_Tool
    from OCP.TopAbs import TopAbs_VERTEX
    from OCP.TopExp import TopExp

    from relief_cad.cad._compat import IndexedMapOfShape
    from relief_cad.cad.ocp import make_compound

    edges = _fillets(20)
    vertices, made = _floor_calls(edges, 57, 31)()
    assert len(vertices) == 31 and len(made) == 57
    ranges = [BRep_Tool.Range_s(e) for e in edges]
    for k, e in enumerate(made):  # on its input edge's curve, within that edge's range
        lo, hi = BRep_Tool.Range_s(e)
        a, b = ranges[k // 3]  # 57 pieces of 20 edges: three from each, in order
        assert min(a, b) <= lo < hi <= max(a, b)
    shared = IndexedMapOfShape()
    TopExp.MapShapes_s(make_compound(made), TopAbs_VERTEX, shared)
    assert shared.Extent() == 31  # the edges share the vertices made, none more
    assert _ocp_floor(edges, 57, 31, 1) > 0.0
