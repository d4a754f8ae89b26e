"""Result rows to result objects: the one place where kernel rows become Python objects.

Both kernels write one row per result: the planar kernels ``[pair, kind, t, u, t1, u1, x, y,
distance]`` (``RES_COLS``), the space kernel ``[kind, t, u, t1, u1, x, y, z, distance]``
(``SPACE_COLS``): after the planar pair column the two layouts agree, and a point's coordinates
run up to column 8. This module turns them into :class:`~relief_cad.results.Intersection`,
:class:`~relief_cad.results.Overlap` and :class:`~relief_cad.results.ParameterBox` objects.

It is compiled like the kernels (the loop over rows is the hot part of every small call), but it
holds the GIL throughout and knows no kernel: it reads the rows and calls the result classes.
Compiled, a point's array is made through numpy's C API (:func:`_coords`: about 0.2 us, against
1.3 us for numpy's Python calls that view a row and make it read-only).

>>> import numpy as np
>>> rows = np.array([[0.0, 0.0, 0.5, 0.25, 0.5, 0.25, 1.0, 2.0, 0.0]])
>>> res, final = rows_to_list(rows, 1e-9)
>>> res[0].t, res[0].u, res[0].point.tolist(), res[0].kind, res.tol_used, final
(0.5, 0.25, [1.0, 2.0], 'crossing', 1e-09, True)
"""

from __future__ import annotations

import cython

if cython.compiled:
    from cython.cimports.cpython.object import PyObject_GenericSetAttr as _store
    from cython.cimports.numpy import (
        NPY_ARRAY_WRITEABLE,
        NPY_DOUBLE,
        PyArray_CLEARFLAGS,
        PyArray_DATA,
        PyArray_SimpleNew,
        import_array,
        ndarray,
        npy_intp,
    )

    import_array()
else:
    import numpy as np

    _store = object.__setattr__  # the frozen dataclasses' own way round their __setattr__

from ..results import Intersection, IntersectionList, Overlap, ParameterBox, Result
from .constants import KIND_CROSSING, KIND_OVERLAP, KIND_TANGENT

_KIND_NAMES = ("crossing", "tangent")  # by kind code
_CROSSING = cython.declare(cython.int, KIND_CROSSING)  # C copies for the loop
_TANGENT = cython.declare(cython.int, KIND_TANGENT)
_OVERLAP = cython.declare(cython.int, KIND_OVERLAP)


def distribute(rows, items: list, boxes: list, planar: cython.bint, looks: list = None) -> None:
    """Append the result object of each row of ``rows``, in order, to the lists of its pair.

    ``rows`` (r, 9) float64: planar rows (``planar`` True; column 0 indexes ``items`` and
    ``boxes``, lists of lists) or space rows of one pair (``planar`` False; ``items[0]`` and
    ``boxes[0]`` take them). A point's coordinates are its own new read-only array
    (:func:`_coords`). The objects are built without the frozen dataclasses' ``__init__``
    (three guarded ``setattr`` each): their fields are stored as ``object.__setattr__`` stores
    them (the C call, compiled), so they compare, hash and print as if built by hand.

    ``looks`` (a list, or None) gets the index of each pair with a row that
    :func:`relief_cad.contacts.needs_refining` may not pass as it is, once: a box, a contact that
    is not a crossing, or a crossing at an end of either curve. The pairs not listed need no look.

    >>> import numpy as np
    >>> items, boxes, looks = [[], []], [[], []], []
    >>> distribute(np.array([[1.0, 2.0, 0.1, 0.2, 0.3, 0.4, 0.0, 0.0, 0.0],
    ...                      [1.0, 3.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0]]), items, boxes, True, looks)
    >>> items[1], boxes[1], looks
    ([Overlap(t=(0.1, 0.3), u=(0.2, 0.4), kind='overlap')],
     [ParameterBox(t0=0.0, t1=1.0, u0=0.0, u1=1.0)], [1])
    """
    _fill(rows, items, boxes, planar, looks)


@cython.cfunc
def _fill(R: cython.const[cython.double][:, :], items: list, boxes: list, planar: cython.bint,
          looks: object) -> cython.void:
    """:func:`distribute`'s loop on a typed view of the rows (C callers pass theirs: no new view).

    ``looks``: a list or None.
    """
    if not cython.compiled:  # plain Python reads the rows as Python floats, as compiled (not numpy's)
        R = R.astype(object)
    i: cython.Py_ssize_t
    c: cython.Py_ssize_t = 1 if planar else 0  # the kind's column
    k: cython.Py_ssize_t = 0
    last: cython.Py_ssize_t = -1  # the last pair put in looks
    kind: cython.int
    for i in range(R.shape[0]):
        if planar:
            k = cython.cast(cython.Py_ssize_t, R[i, 0])
        kind = cython.cast(cython.int, R[i, c])
        if kind == _CROSSING or kind == _TANGENT:
            cython.cast(list, items[k]).append(_point(R[i, c + 1], R[i, c + 2], _coords(R, i, c + 5),
                                                      _KIND_NAMES[kind], R[i, 8]))
        elif kind == _OVERLAP:
            cython.cast(list, items[k]).append(_overlap((R[i, c + 1], R[i, c + 3]),
                                                        (R[i, c + 2], R[i, c + 4])))
        else:
            cython.cast(list, boxes[k]).append(_box(R[i, c + 1], R[i, c + 3], R[i, c + 2], R[i, c + 4]))
        if looks is not None and k != last and not (
                kind == _CROSSING and _inner(R[i, c + 1]) and _inner(R[i, c + 2])):
            cython.cast(list, looks).append(k)
            last = k


@cython.cfunc
@cython.inline
def _inner(x: cython.double) -> cython.bint:
    """True when a parameter is not an end (0 or 1) of its curve."""
    return x != 0.0 and x != 1.0


@cython.cfunc
def _coords(R: cython.const[cython.double][:, :], i: cython.Py_ssize_t,
            first: cython.Py_ssize_t) -> object:
    """Columns ``first`` to 7 of row ``i`` of ``R``: a point, as a new read-only float64 array."""
    if not cython.compiled:  # plain Python: numpy's own calls
        a = np.array(R[i, first:8], dtype=np.float64)
        a.flags.writeable = False
        return a
    n: npy_intp = 8 - first
    out: ndarray = PyArray_SimpleNew(1, cython.address(n), NPY_DOUBLE)
    p: cython.p_double = cython.cast(cython.p_double, PyArray_DATA(out))
    j: cython.Py_ssize_t
    for j in range(n):
        p[j] = R[i, first + j]
    PyArray_CLEARFLAGS(out, NPY_ARRAY_WRITEABLE)
    return out


@cython.cfunc
def _point(t: cython.double, u: cython.double, point: object, kind: object,
           distance: cython.double) -> object:
    """An :class:`Intersection` with these fields (stored as ``object.__setattr__`` does)."""
    obj = Intersection.__new__(Intersection)
    _store(obj, "t", t)
    _store(obj, "u", u)
    _store(obj, "point", point)
    _store(obj, "kind", kind)
    _store(obj, "distance", distance)
    return obj


@cython.cfunc
def _overlap(t: tuple, u: tuple) -> object:
    """An :class:`Overlap` with these fields (stored as ``object.__setattr__`` does)."""
    obj = Overlap.__new__(Overlap)
    _store(obj, "t", t)
    _store(obj, "u", u)
    _store(obj, "kind", "overlap")
    return obj


@cython.cfunc
def _box(t0: cython.double, t1: cython.double, u0: cython.double, u1: cython.double) -> object:
    """A :class:`ParameterBox` with these fields (stored as ``object.__setattr__`` does)."""
    obj = ParameterBox.__new__(ParameterBox)
    _store(obj, "t0", t0)
    _store(obj, "t1", t1)
    _store(obj, "u0", u0)
    _store(obj, "u1", u1)
    return obj


def rows_to_list(rows: cython.const[cython.double][:, :],
                 tol: cython.double) -> tuple[IntersectionList, bool]:
    """``(results, final)``: the :class:`IntersectionList` of one planar pair's rows; whether it is final.

    ``tol_used`` is ``tol``. The kernel gives a pair's points and overlaps in the order of their
    ``t`` (a point's ``t``, an overlap's first ``t``; stable), then its unresolved boxes: the
    order of the list. ``final`` is True when no row needs a look (see :func:`distribute`): no
    box is open and :func:`relief_cad.contacts.needs_refining` would pass it. Compiled,
    :func:`relief_cad._kernels.batch.planar_pair` calls it as a C function on the kernel's
    scratch rows (a typed view: no copy of the rows, no new view of them).

    >>> import numpy as np
    >>> res, final = rows_to_list(np.empty((0, 9)), 1e-9)
    >>> len(res), res.tol_used, final
    (0, 1e-09, True)
    """
    out = IntersectionList.__new__(IntersectionList)  # filled here: its ``__init__`` copies
    out.tol_used = tol
    out.unresolved = ()
    if rows.shape[0] == 0:
        return out, True
    boxes: list = []
    looks: list = []
    _fill(rows, [out], [boxes], True, looks)  # compiled: the view as it came, no new one
    if boxes:
        out.unresolved = tuple(boxes)
    return out, not looks


def batch_lists(rows, tols) -> tuple[list[IntersectionList], list[int]]:
    """``(lists, looks)``: the :class:`IntersectionList` of each pair of a batch's planar rows.

    ``tols`` (p,) float64 holds each pair's tolerance (its list's ``tol_used``); column 0 of
    ``rows`` indexes it. ``looks`` lists the pairs that need a look (see :func:`distribute`),
    in order; the other lists are final.

    >>> import numpy as np
    >>> lists, looks = batch_lists(np.array([[1.0, 0.0, 0.5, 0.5, 0.5, 0.5, 1.0, 1.0, 0.0]]),
    ...                            np.array([1e-9, 2e-9]))
    >>> [len(x) for x in lists], lists[1].tol_used, looks
    ([0, 1], 2e-09, [])
    """
    T: cython.const[cython.double][:] = tols
    j: cython.Py_ssize_t
    n: cython.Py_ssize_t = T.shape[0]
    lists: list = []
    boxes: list = []
    for j in range(n):
        out = IntersectionList.__new__(IntersectionList)
        out.tol_used = float(T[j])  # a Python float in the uncompiled mode too
        out.unresolved = ()
        lists.append(out)
        boxes.append([])
    looks: list = []
    _fill(rows, lists, boxes, True, looks)
    for j in looks:
        if boxes[j]:
            lists[j].unresolved = tuple(boxes[j])
    return lists, looks


def space_results(rows) -> tuple[list[Result], list[ParameterBox]]:
    """``(items, boxes)``: the result objects of one space pair's rows, in the rows' order.

    >>> import numpy as np
    >>> items, boxes = space_results(np.array([[1.0, 0.5, 0.5, 0.5, 0.5, 1.0, 2.0, 3.0, 1e-12]]))
    >>> items[0].kind, items[0].point.tolist(), items[0].distance, boxes
    ('tangent', [1.0, 2.0, 3.0], 1e-12, [])
    """
    items: list = []
    boxes: list = []
    _fill(rows, [items], [boxes], False, None)
    return items, boxes
