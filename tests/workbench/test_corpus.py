"""Corpus files: reproducible families, shared topology kept, bad input named."""

from __future__ import annotations

import gzip

import pytest
from OCP.TopExp import TopExp
from OCP.TopoDS import TopoDS_Vertex
from relief_cad_workbench.corpus import (
    CONIC_KINDS,
    RANDOM_FAMILIES,
    CorpusError,
    Item,
    brep_text,
    conic_family,
    random_family,
    read_corpus,
    read_shape,
    step_family,
    write_corpus,
)

from relief_cad.cad.occt import unique_edges

from ._pairs import segment


@pytest.mark.parametrize("family", RANDOM_FAMILIES)
def test_random_families_are_seeded_and_reproducible(family):
    first = [i.to_json() for i in random_family(family, 3, seed=11)]
    again = [i.to_json() for i in random_family(family, 3, seed=11)]
    other = [i.to_json() for i in random_family(family, 3, seed=12)]
    assert first == again and first != other
    for line in first:
        (item,) = [i for i in read_corpus_lines([line])]
        a, b = item.shapes()
        assert unique_edges(a) and unique_edges(b)


def test_conic_family_is_seeded_and_relief_cad_is_right_on_its_well_posed_kinds():
    # circles, an ellipse and a circle, a line and a conic in contact, a spline through an arc's
    # span joint and a line through a periodic spline's seam: the kinds where this family found
    # wrong answers (f3fc0da, 2d92697). Splines on a circle and near-misses within tol are
    # contacts whose truth depends on the rule for tol (overlap or points), left out here
    from relief_cad.cad.compare import compare

    first = [i.to_json() for i in conic_family(14, seed=5)]
    assert first == [i.to_json() for i in conic_family(14, seed=5)]
    assert first != [i.to_json() for i in conic_family(14, seed=6)]
    items = read_corpus_lines(first)
    assert [i.meta["kind"] for i in items] == list(CONIC_KINDS) * 2
    for item in items:
        if item.meta["kind"] in ("spline-on-circle", "near-miss"):
            continue
        a, b = item.shapes()
        c = compare(a, b)
        assert c.errors == {} and c.score()["occt_right"] == 0 and c.score()["neither"] == 0, (item.id, c)


def read_corpus_lines(lines, tmp=None):
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "c.jsonl"
        p.write_text("\n".join(lines) + "\n")
        return list(read_corpus(p))


def test_step_pairs_keep_their_shared_vertices_and_broken_files_are_named(tmp_path):
    from relief_cad_workbench.corpus import bundled_step_dir

    broken = tmp_path / "broken.step"
    broken.write_text("ISO-10303-21;\nnot really")
    items = list(step_family([bundled_step_dir(), broken], 6))
    errors = [i for i in items if isinstance(i, CorpusError)]
    assert len(errors) == 1 and "OCCT cannot read this STEP file" in str(errors[0]) and "broken.step" in str(errors[0])
    shared = 0
    for it in items:
        if isinstance(it, Item):
            a, b = it.shapes()
            shared += TopExp.CommonVertex_s(unique_edges(a)[0], unique_edges(b)[0], TopoDS_Vertex())
    assert shared >= 1  # neighbouring edges of a face still share their vertex after the round trip


def test_corrupt_lines_and_files_are_reported_per_item(tmp_path):
    good = Item("ok-1", "cubic", brep_text(segment((0, 0, 0), (1, 0, 0))), brep_text(segment((0, 1, 0), (1, 0, 0))))
    path = tmp_path / "c.jsonl.gz"
    write_corpus(path, [good])
    with gzip.open(path, "at") as f:
        f.write("not json\n")
        f.write('{"id": "x", "a": 3}\n')
    out = list(read_corpus(path))
    assert isinstance(out[0], Item) and out[0].id == "ok-1"
    assert [type(x) for x in out[1:]] == [CorpusError, CorpusError]
    assert "line 2" in str(out[1]) and "line 3" in str(out[2])
    truncated = tmp_path / "t.jsonl.gz"
    truncated.write_bytes(path.read_bytes()[:-12])
    tail = list(read_corpus(truncated))
    assert isinstance(tail[-1], CorpusError)
    with pytest.raises(CorpusError, match="unreadable BREP|holds no shape"):
        read_shape("DBRep_DrawableShape\nnonsense")
    with pytest.raises(CorpusError, match="does not exist"):
        list(read_corpus(tmp_path / "missing.jsonl"))
