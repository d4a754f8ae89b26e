# pure-Python mode: bezier's _eval is called as a C function (see bezier.pxd)
from relief_cad._kernels.bezier cimport _eval
