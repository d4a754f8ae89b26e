# pure-Python mode: the pair driver is called as a C function (see planar.pxd)
from relief_cad._kernels.planar cimport intersect_pair_kernel
