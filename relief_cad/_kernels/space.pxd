# pure-Python mode: the planar pair driver is called as a C function (see planar.pxd), not through
# Python (which turned its four memoryviews back into objects on every projection frame)
from relief_cad._kernels.planar cimport intersect_pair_kernel
# the end-point gate of the pair kernels (batch.pxd)
from relief_cad._kernels.batch cimport _ends_match
