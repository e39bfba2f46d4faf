"""The process environment the host sets for the component (user guide, section 11)."""
import os


def _openblas_kernels():
    """OpenBLAS kernels for this CPU's vector units (the host's choice, host/process_settings.hpp):
    Debian 12's OpenBLAS falls back to slow SSE3 kernels on CPU models it does not know."""
    try:
        with open("/proc/cpuinfo") as f:
            flags = next((line.split(":", 1)[1].split() for line in f if line.startswith("flags")), [])
            f.seek(0)
            amd = "AuthenticAMD" in f.read()
    except OSError:
        return None
    if {"avx512f", "avx512bw", "avx512dq", "avx512vl", "avx512cd"} <= set(flags):
        return "SkylakeX"
    if {"avx2", "fma"} <= set(flags):
        return "Zen" if amd else "Haswell"
    return None


def prefer():
    """Sets each variable the user has not: libgomp and OpenBLAS read them when they are loaded, which
    numpy may do first (it loads OpenBLAS), so this runs when peristep is imported, before numpy is.
    GLIBC_TUNABLES is read at process start: only the sample workers get it."""
    for name, value in (("OMP_WAIT_POLICY", "passive"), ("OPENBLAS_THREAD_TIMEOUT", "4"),
                        ("OPENBLAS_CORETYPE", _openblas_kernels())):
        if value and name not in os.environ:
            os.environ[name] = value
