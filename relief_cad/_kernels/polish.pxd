# pure-Python mode: the helpers polish.py imports are called as C functions (see bezier.pxd, clip.pxd)
from relief_cad._kernels.bezier cimport _cartesian, _eval, _rounds, _segment
from relief_cad._kernels.clip cimport clip_range_kernel, fat_line_kernel

# and its own helpers, called as C functions by planar.py (noexcept: none of them can raise,
# except _coincide, which allocates)
cpdef (double, double, double) _newton(const double[:, :] HA, const double[:, :] HB, double t, double u, double[:, :] wa, double[:, :] wb, Py_ssize_t iters) noexcept nogil
cpdef (double, double, double) _closest(const double[:, :] HA, const double[:, :] HB, double t, double u, double[:, :] wa, double[:, :] wb, Py_ssize_t iters) noexcept nogil
cpdef (double, double) _point_on(const double[:, :] H, double px, double py, double tol, double[:, :] S, double[:, :] C, double[:] V, double[:] e, double[:, :] wk) noexcept nogil
cpdef double _local_dist(const double[:, :] H, double px, double py, double u, double[:, :] wk) noexcept nogil
cpdef double _angle_sin(const double[:, :] HA, const double[:, :] HB, double t, double u, double[:, :] wa, double[:, :] wb) noexcept nogil
cpdef double _local_proj(const double[:, :] H, double px, double py, double u, double[:, :] wk) noexcept nogil
cpdef bint _coincide(const double[:, :] HA, const double[:, :] HB, double ta, double ua, double tb, double ub, double tol, double[:, :] wa, double[:, :] wb, Py_ssize_t nsamp) except -1
cpdef double _end_ratio(const double[:, :] H, double t0, double t1, double[:, :] wk) noexcept nogil
cpdef double _spread(double f, double lam) noexcept nogil
