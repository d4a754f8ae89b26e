# pure-Python mode: the helpers planar.py imports are called as C functions (see bezier.pxd, clip.pxd,
# polish.pxd, certify.pxd)
from relief_cad._kernels.bezier cimport _cartesian, _curve_box_update, _eval, _frame, _homog_into, _segment
from relief_cad._kernels.certify cimport _polish_dd, _side_dd
from relief_cad._kernels.clip cimport clip_range_kernel, cones_apart, fat_line_kernel
from relief_cad._kernels.polish cimport _angle_sin, _closest, _coincide, _local_dist, _local_proj, _newton, _point_on

# the pair driver without the GIL and its helpers, called as C functions by batch.py (cpdef: the
# uncompiled switch imports them as Python functions)
cpdef (double, double, double, double) _box(const double[:, :] P) noexcept nogil
cpdef bint _apart(const double[:, :] PA, const double[:, :] PB, double tol) noexcept nogil
cpdef Py_ssize_t scratch_rows(Py_ssize_t ma, Py_ssize_t mb) noexcept nogil
cpdef Py_ssize_t _pair_core(const double[:, :] PA, const double[:] WA, const double[:, :] PB, const double[:] WB, double tol, long long budget, double pair, double[:, :] scratch, double[:, :] rv, Py_ssize_t nres) except -1 nogil
# the pair driver with the GIL (space.py calls it through Python)
cpdef tuple intersect_pair_kernel(const double[:, :] PA, const double[:] WA, const double[:, :] PB, const double[:] WB, double tol, long long budget, double pair, object res, Py_ssize_t nres)
