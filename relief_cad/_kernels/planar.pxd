# pure-Python mode: the helpers planar.py imports are called as C functions (see bezier.pxd, clip.pxd)
from relief_cad._kernels.bezier cimport _cartesian, _eval, _segment
from relief_cad._kernels.clip cimport clip_range_kernel, fat_line_kernel
