# C-level declarations of the hot helpers of bezier.py (pure-Python mode: this file augments it),
# so that the other kernel modules call them as C functions (cimport), not through Python.
cpdef void _segment(const double[:, :] H, double t0, double t1, double[:, :] out)
cpdef (double, double, double, double) _cartesian(double[:, :] S, double[:, :] P, double[:] W)
cpdef (double, double, double, double, double, double) _eval(const double[:, :] H, double t, double[:, :] wk)
