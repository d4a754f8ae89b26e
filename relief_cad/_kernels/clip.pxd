# C-level declarations of clip.py's kernels (pure-Python mode: this file augments it), so that the
# other kernel modules call them as C functions (cimport), not through Python.
# noexcept: they cannot raise (no allocation; bounds checks off), so no error check per call.
cpdef (double, double, double, double, double) fat_line_kernel(const double[:, :] P, bint perpendicular) noexcept nogil
cpdef (double, double) hull_range_kernel(double[:] e) noexcept nogil
cpdef (double, double) clip_range_kernel(const double[:, :] P, const double[:] W, double nx, double ny, double c, double dmin, double dmax, double[:] e) noexcept nogil
cdef (double, double) _cone(const double[:, :] P, double err) noexcept nogil
cpdef bint cones_apart(const double[:, :] P, const double[:, :] Q, double ep=*, double eq=*) noexcept nogil
