# pure-Python mode: one pair's result list, called as a C function by batch.py on its scratch rows
# (cpdef: Python callers and the uncompiled switch call it as a Python function)
cpdef tuple rows_to_list(const double[:, :] rows, double tol)
