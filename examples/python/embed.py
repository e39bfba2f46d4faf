"""How to run:   python3 examples/python/embed.py <path to PeriStep.so>
                 (needs numpy; the library is build/component/fmi/PeriStep.so, or
                 binaries/x86_64-linux/PeriStep.so inside an unpacked PeriStep.fmu)
What it shows:   PeriStep driven from Python through its FMI 3.0 C ABI with ctypes alone: a small loop
                 over the random coordinate xi of Test 1 (one instance, fmi3Reset between samples),
                 reading the fields damage and ux as 2D numpy arrays [ny][nx] and the error against
                 the manufactured solution. This is the skeleton of a sampling loop in a script.
"""
import ctypes as C
import sys

import numpy as np

# Value references and the instantiation token, from api/peristep.h.
TOKEN = b"{8c4f2b7e-3d91-4a6c-b5e0-7f12a9d3c648}"
VR_NX, VR_NY, VR_XI, VR_POISSON_RATIO = 1, 2, 19, 14
VR_LOAD_FACTOR, VR_UX, VR_DAMAGE, VR_ERROR_L2 = 30, 40, 42, 56
FMI3_OK = 0
NX, NY = 17, 17

LOGGER = C.CFUNCTYPE(None, C.c_void_p, C.c_int, C.c_char_p, C.c_char_p)


@LOGGER
def log_message(_env, status, category, message):
    print(f"PeriStep [{(category or b'').decode()}, status {status}]: {(message or b'').decode()}", file=sys.stderr)


class PeriStep:
    """1. The library and the fmi3 functions used here, with their C signatures."""

    def __init__(self, path):
        self.lib = C.CDLL(path)
        vr_array, size = C.POINTER(C.c_uint32), C.c_size_t
        self._declare("fmi3InstantiateCoSimulation", C.c_void_p,
                      [C.c_char_p, C.c_char_p, C.c_char_p, C.c_bool, C.c_bool, C.c_bool, C.c_bool,
                       vr_array, size, C.c_void_p, LOGGER, C.c_void_p])
        for name in ("fmi3EnterConfigurationMode", "fmi3ExitConfigurationMode", "fmi3ExitInitializationMode",
                     "fmi3Terminate", "fmi3Reset"):
            self._declare(name, C.c_int, [C.c_void_p])
        self._declare("fmi3FreeInstance", None, [C.c_void_p])
        self._declare("fmi3EnterInitializationMode", C.c_int,
                      [C.c_void_p, C.c_bool, C.c_double, C.c_double, C.c_bool, C.c_double])
        self._declare("fmi3SetUInt64", C.c_int, [C.c_void_p, vr_array, size, C.POINTER(C.c_uint64), size])
        self._declare("fmi3SetInt64", C.c_int, [C.c_void_p, vr_array, size, C.POINTER(C.c_int64), size])
        self._declare("fmi3SetFloat64", C.c_int, [C.c_void_p, vr_array, size, C.POINTER(C.c_double), size])
        self._declare("fmi3GetFloat64", C.c_int, [C.c_void_p, vr_array, size, C.POINTER(C.c_double), size])
        self._declare("fmi3DoStep", C.c_int,
                      [C.c_void_p, C.c_double, C.c_double, C.c_bool, C.POINTER(C.c_bool), C.POINTER(C.c_bool),
                       C.POINTER(C.c_bool), C.POINTER(C.c_double)])

    def instantiate(self, name):
        """A co-simulation instance that logs to stderr; name is the instance's name (bytes)."""
        instance = self.InstantiateCoSimulation(name, TOKEN, None, False, True, False, False, None, 0, None,
                                                log_message, None)
        if not instance:
            raise RuntimeError("instantiation failed")
        return instance

    def step(self, instance, time, step_size):
        """fmi3DoStep from `time` over `step_size`; the event flags and the last time are not needed here."""
        flags = [C.c_bool() for _ in range(3)]
        last_time = C.c_double()
        self.DoStep(instance, time, step_size, True, *[C.byref(f) for f in flags], C.byref(last_time))

    def _declare(self, name, restype, argtypes):
        f = getattr(self.lib, name)
        f.restype, f.argtypes = restype, argtypes
        # Every status-returning call is checked: a failure stops the script with the function's name.
        if restype is C.c_int:
            def checked(*args, _f=f, _name=name):
                status = _f(*args)
                if status != FMI3_OK:
                    raise RuntimeError(f"{_name} returned status {status}")
            setattr(self, name[4:], checked)
        else:
            setattr(self, name[4:], f)


def refs(*vrs):
    return (C.c_uint32 * len(vrs))(*vrs)


def set_float64(fmu, instance, vr, values):
    values = np.ascontiguousarray(values, dtype=np.float64)
    fmu.SetFloat64(instance, refs(vr), 1, values.ctypes.data_as(C.POINTER(C.c_double)), values.size)


def get_float64(fmu, instance, vr, shape):
    """A variable as a numpy array of the given shape: fields come back as images [ny][nx]."""
    out = np.empty(shape, dtype=np.float64)
    fmu.GetFloat64(instance, refs(vr), 1, out.ctypes.data_as(C.POINTER(C.c_double)), out.size)
    return out


def main(path):
    fmu = PeriStep(path)
    # 2. One instance serves every sample: fmi3Reset brings it back to its start values.
    instance = fmu.instantiate(b"embed.py")
    print(f"{'xi':>6} {'errorL2 [m]':>12} {'max |ux| [m]':>13} {'max damage':>11}")
    try:
        for k, xi in enumerate([-2.0, -1.0, 0.0, 1.0, 2.0]):
            if k > 0:
                fmu.Reset(instance)
            # 3. The grid (structural parameters, Configuration Mode), then parameters.
            fmu.EnterConfigurationMode(instance)
            grid = (C.c_uint64 * 2)(NX, NY)
            fmu.SetUInt64(instance, refs(VR_NX, VR_NY), 2, grid, 2)
            fmu.ExitConfigurationMode(instance)
            set_float64(fmu, instance, VR_POISSON_RATIO, [0.3])
            set_float64(fmu, instance, VR_XI, [xi])
            # 4. Initialize, 5. one step at full load.
            fmu.EnterInitializationMode(instance, False, 0.0, 0.0, True, 1.0)
            fmu.ExitInitializationMode(instance)
            set_float64(fmu, instance, VR_LOAD_FACTOR, [1.0])
            fmu.step(instance, 0.0, 1.0)
            # 6. Fields as 2D arrays: row j is y_j, column i is x_i.
            ux = get_float64(fmu, instance, VR_UX, (NY, NX))
            damage = get_float64(fmu, instance, VR_DAMAGE, (NY, NX))
            error = get_float64(fmu, instance, VR_ERROR_L2, (1,))[0]
            print(f"{xi:6.1f} {error:12.4e} {np.abs(ux).max():13.4e} {damage.max():11.3g}")
            if not (np.isfinite(error) and error > 0 and np.isfinite(ux).all() and ux.shape == (NY, NX)):
                raise RuntimeError(f"unexpected outputs at xi = {xi}")
            fmu.Terminate(instance)
    finally:
        # 7. Release the instance whatever happened.
        fmu.FreeInstance(instance)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(f"usage: {sys.argv[0]} <path to PeriStep.so>")
    main(sys.argv[1])
