# C-level declarations of the hot helpers of bezier.py (pure-Python mode: this file augments it),
# so that the other kernel modules call them as C functions (cimport), not through Python.
# noexcept: they cannot raise (no allocation; bounds checks off), so no error check per call.
cpdef void _rounds(const double[:, :] H, double t, double[:, :] B) noexcept nogil
cpdef void _segment(const double[:, :] H, double t0, double t1, double[:, :] out) noexcept nogil
cpdef (double, double, double, double) _cartesian(double[:, :] S, double[:, :] P, double[:] W) noexcept nogil
cpdef (double, double, double, double, double, double) _eval(const double[:, :] H, double t, double[:, :] wk) noexcept nogil
cpdef (double, double, double) _frame(const double[:, :] PA, const double[:, :] PB) noexcept nogil
cpdef void _curve_box_update(const double[:, :] P, const double[:] W, double[:] box, double[:, :] wk) noexcept nogil
cpdef object _homog(const double[:, :] P, const double[:] W, double cx, double cy, double scale)
cpdef void _homog_into(const double[:, :] P, const double[:] W, double cx, double cy, double scale, double[:, :] H) noexcept nogil
