#!/usr/bin/env python3
"""Exit 0 when one process may read another's memory with process_vm_readv (Linux cross-memory
attach, CMA), as OpenMPI's shared-memory transport does for its single-copy messages; else 1.

A sibling test: the child reads its parent's memory (MPI ranks are siblings, not one another's
ancestors: Yama's ptrace_scope 1 refuses that unless the target allows it, which OpenMPI asks with
prctl(PR_SET_PTRACER); a seccomp profile or ptrace_scope 2-3 refuses it outright)."""
import ctypes
import os
import sys


class IoVec(ctypes.Structure):
    _fields_ = [("base", ctypes.c_void_p), ("len", ctypes.c_size_t)]


def main():
    libc = ctypes.CDLL(None, use_errno=True)
    try:
        readv = libc.process_vm_readv
    except AttributeError:
        return 1
    readv.argtypes = [ctypes.c_int, ctypes.POINTER(IoVec), ctypes.c_ulong,
                      ctypes.POINTER(IoVec), ctypes.c_ulong, ctypes.c_ulong]
    readv.restype = ctypes.c_ssize_t
    PR_SET_PTRACER, PR_SET_PTRACER_ANY = 0x59616D61, ctypes.c_ulong(-1)
    libc.prctl(PR_SET_PTRACER, PR_SET_PTRACER_ANY, 0, 0, 0)  # as OpenMPI does; fails harmlessly
    src = ctypes.create_string_buffer(b"zcube-cma", 16)
    pid = os.fork()
    if pid == 0:
        dst = ctypes.create_string_buffer(16)
        local = IoVec(ctypes.cast(dst, ctypes.c_void_p), 16)
        remote = IoVec(ctypes.cast(src, ctypes.c_void_p), 16)
        n = readv(os.getppid(), ctypes.byref(local), 1, ctypes.byref(remote), 1, 0)
        os._exit(0 if n == 16 and dst.value == b"zcube-cma" else 1)
    _, status = os.waitpid(pid, 0)
    return 0 if os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
