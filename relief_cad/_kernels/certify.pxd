# pure-Python mode: bezier's _eval is called as a C function (see bezier.pxd)
from relief_cad._kernels.bezier cimport _eval, _rounds

# the certified polish, called as a C function by planar.py (noexcept: it cannot raise)
cpdef (double, double, bint) _polish_dd(const double[:, :] HA, const double[:, :] HB, double t, double u, double[:, :] wa, double[:, :] wb, double[:, :] da, double[:, :] db, Py_ssize_t steps) noexcept nogil
cpdef double _side_dd(const double[:, :] HA, const double[:, :] HB, double t, double u, double[:, :] wb, double[:, :] da, double[:, :] db) noexcept nogil
