"""The FMI 3.0 C ABI through ctypes: the shared library, and one co-simulation instance whose every
call is checked (a status other than fmi3OK/fmi3Warning raises PeriStepError with the component's log)."""
import ctypes as C
import logging
import weakref

import numpy as np

from .errors import PeriStepError

OK, WARNING, DISCARD, ERROR, FATAL = range(5)
_STATUS = ("fmi3OK", "fmi3Warning", "fmi3Discard", "fmi3Error", "fmi3Fatal")
_log = logging.getLogger("peristep")

LOG_CALLBACK = C.CFUNCTYPE(None, C.c_void_p, C.c_int, C.c_char_p, C.c_char_p)

# FMI type -> (numpy dtype, suffix of fmi3Get*/fmi3Set*); enumerations go through the Int64 functions.
NUMERIC_TYPES = {
    "Float32": (np.float32, "Float32"), "Float64": (np.float64, "Float64"),
    "Int8": (np.int8, "Int8"), "UInt8": (np.uint8, "UInt8"), "Int16": (np.int16, "Int16"),
    "UInt16": (np.uint16, "UInt16"), "Int32": (np.int32, "Int32"), "UInt32": (np.uint32, "UInt32"),
    "Int64": (np.int64, "Int64"), "UInt64": (np.uint64, "UInt64"), "Enumeration": (np.int64, "Int64"),
    "Boolean": (np.bool_, "Boolean"),
}

_VRS = C.POINTER(C.c_uint32)
_INSTANCE = C.c_void_p
_PROTOTYPES = {
    "fmi3InstantiateCoSimulation": (C.c_void_p, [C.c_char_p, C.c_char_p, C.c_char_p, C.c_bool, C.c_bool, C.c_bool,
                                                 C.c_bool, _VRS, C.c_size_t, C.c_void_p, LOG_CALLBACK, C.c_void_p]),
    "fmi3FreeInstance": (None, [_INSTANCE]),
    "fmi3EnterConfigurationMode": (C.c_int, [_INSTANCE]),
    "fmi3ExitConfigurationMode": (C.c_int, [_INSTANCE]),
    "fmi3EnterInitializationMode": (C.c_int, [_INSTANCE, C.c_bool, C.c_double, C.c_double, C.c_bool, C.c_double]),
    "fmi3ExitInitializationMode": (C.c_int, [_INSTANCE]),
    "fmi3DoStep": (C.c_int, [_INSTANCE, C.c_double, C.c_double, C.c_bool, C.POINTER(C.c_bool),
                             C.POINTER(C.c_bool), C.POINTER(C.c_bool), C.POINTER(C.c_double)]),
    "fmi3Terminate": (C.c_int, [_INSTANCE]),
    "fmi3GetFMUState": (C.c_int, [_INSTANCE, C.POINTER(C.c_void_p)]),
    "fmi3SetFMUState": (C.c_int, [_INSTANCE, C.c_void_p]),
    "fmi3FreeFMUState": (C.c_int, [_INSTANCE, C.POINTER(C.c_void_p)]),
    "fmi3SerializedFMUStateSize": (C.c_int, [_INSTANCE, C.c_void_p, C.POINTER(C.c_size_t)]),
    "fmi3SerializeFMUState": (C.c_int, [_INSTANCE, C.c_void_p, C.c_void_p, C.c_size_t]),
    "fmi3DeserializeFMUState": (C.c_int, [_INSTANCE, C.c_void_p, C.c_size_t, C.POINTER(C.c_void_p)]),
}
for _suffix in {s for _, s in NUMERIC_TYPES.values()}:
    for _verb in ("Get", "Set"):
        # The values pointer as void*: one prototype serves every element type.
        _PROTOTYPES[f"fmi3{_verb}{_suffix}"] = (C.c_int, [_INSTANCE, _VRS, C.c_size_t, C.c_void_p, C.c_size_t])


class Library:
    """The component's shared library with the fmi3 functions this package calls."""

    def __init__(self, path):
        try:
            self._dll = C.CDLL(str(path))
        except OSError as e:
            raise PeriStepError(f"cannot load {path}: {e}") from None
        for name, (restype, argtypes) in _PROTOTYPES.items():
            try:
                f = getattr(self._dll, name)
            except AttributeError:
                raise PeriStepError(f"{path} does not export {name}") from None
            f.restype, f.argtypes = restype, argtypes
            setattr(self, name[4:], f)


def _free_instance(free, handle, fatal, _callback):
    # _callback: kept alive until the component can no longer log through it.
    if not fatal[0]:  # after fmi3Fatal the standard allows no further call
        free(handle)


class Instance:
    """One co-simulation instance. Every call goes through ``_call``, which collects what the component
    logged while it ran."""

    def __init__(self, library, token, name, resource_path=None):
        self.lib = library
        self._messages = messages = []

        def log(_env, status, category, message):
            # Called from inside an fmi3 call: it must not raise back into C.
            try:
                messages.append((status, (category or b"").decode(errors="replace"),
                                 (message or b"").decode(errors="replace")))
            except Exception:
                pass

        self._callback = LOG_CALLBACK(log)
        self._fatal = [False]
        handle = library.InstantiateCoSimulation(
            name.encode(), token.encode(), resource_path.encode() if resource_path else None, False, True, False,
            False, None, 0, None, self._callback, None)
        if not handle:
            self._raise("fmi3InstantiateCoSimulation", ERROR)
        self.handle = handle
        self._finalizer = weakref.finalize(self, _free_instance, library.FreeInstance, handle, self._fatal,
                                           self._callback)

    def free(self):
        self._finalizer()

    @property
    def alive(self):
        return self._finalizer.alive

    def _raise(self, function, status):
        messages = [m for s, _, m in self._messages if s != OK]
        self._messages.clear()
        prefix = function + ": "  # the component names the call itself; said once is enough
        messages = [m[len(prefix):] if m.startswith(prefix) else m for m in messages]
        raise PeriStepError(f"{function} returned {_STATUS[status] if 0 <= status < 5 else status}",
                            messages or ["(the component logged no message)"])

    def _call(self, function, *args):
        if not self.alive:
            raise PeriStepError(f"{function}: the instance has been freed")
        self._messages.clear()
        status = getattr(self.lib, function[4:])(self.handle, *args)
        if status == FATAL:
            self._fatal[0] = True
        if status not in (OK, WARNING):
            self._raise(function, status)
        for s, category, message in self._messages:
            if s != OK:
                _log.warning("%s [%s] %s", _STATUS[s] if 0 <= s < 5 else s, category, message)
        self._messages.clear()

    def enter_configuration_mode(self):
        self._call("fmi3EnterConfigurationMode")

    def exit_configuration_mode(self):
        self._call("fmi3ExitConfigurationMode")

    def enter_initialization_mode(self, start_time, stop_time=None):
        self._call("fmi3EnterInitializationMode", False, 0.0, start_time, stop_time is not None,
                   0.0 if stop_time is None else stop_time)

    def exit_initialization_mode(self):
        self._call("fmi3ExitInitializationMode")

    def do_step(self, time, step):
        """One fmi3DoStep; returns the component's terminateSimulation flag."""
        flags = [C.c_bool() for _ in range(3)]
        last = C.c_double()
        self._call("fmi3DoStep", time, step, True, *(C.byref(f) for f in flags), C.byref(last))
        return bool(flags[1].value)

    def terminate(self):
        self._call("fmi3Terminate")

    def set(self, variable, values):
        """Writes a flat array of values (already of the variable's length) to one variable."""
        dtype, suffix = self._type(variable)
        data = np.ascontiguousarray(values, dtype=dtype)
        vr = C.c_uint32(variable.value_reference)
        self._call(f"fmi3Set{suffix}", C.byref(vr), 1, data.ctypes.data, data.size)

    def get(self, variable, count):
        """A flat array of the variable's ``count`` values."""
        dtype, suffix = self._type(variable)
        out = np.empty(count, dtype=dtype)
        vr = C.c_uint32(variable.value_reference)
        self._call(f"fmi3Get{suffix}", C.byref(vr), 1, out.ctypes.data, count)
        return out

    @staticmethod
    def _type(variable):
        try:
            return NUMERIC_TYPES[variable.type]
        except KeyError:
            raise PeriStepError(f"{variable.name}: variables of type {variable.type} are not supported") from None

    def get_state(self):
        state = C.c_void_p()
        self._call("fmi3GetFMUState", C.byref(state))
        return state.value

    def set_state(self, state):
        self._call("fmi3SetFMUState", state)

    def free_state(self, state):
        self._call("fmi3FreeFMUState", C.byref(C.c_void_p(state)))

    def serialize_state(self, state):
        size = C.c_size_t()
        self._call("fmi3SerializedFMUStateSize", state, C.byref(size))
        buffer = (C.c_uint8 * size.value)()
        self._call("fmi3SerializeFMUState", state, buffer, size.value)
        return bytes(buffer)

    def deserialize_state(self, data):
        buffer = (C.c_uint8 * len(data)).from_buffer_copy(data)
        state = C.c_void_p()
        self._call("fmi3DeserializeFMUState", buffer, len(data), C.byref(state))
        return state.value
