# pure-Python mode: the pair driver and its helpers are called as C functions (see planar.pxd)
from relief_cad._kernels.planar cimport _apart, _box, _pair_core, scratch_rows
