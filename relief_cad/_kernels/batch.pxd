# pure-Python mode: the pair driver and its helpers are called as C functions (see planar.pxd)
from relief_cad._kernels.planar cimport _apart, _box, _pair_core, scratch_rows
# one pair's result list, made on the kernel's scratch rows as a C call (see rows.pxd)
from relief_cad._kernels.rows cimport rows_to_list
# the end-point gate, called by the space kernel as a C function (see space.pxd)
cpdef bint _ends_match(const double[:, :] PA, const double[:, :] PB, double lim) noexcept
# the one-pair entry, called by planar_pair as a C function and by Python callers
cpdef object intersect_one_kernel(const double[:, :] PA, const double[:] WA, const double[:, :] PB, const double[:] WB, double tol, long long budget, double ends_lim=*, bint listed=*)
