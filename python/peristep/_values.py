"""Python values <-> the flat arrays of the C ABI, checked against a variable's type and shape."""
import math

import numpy as np

from .errors import PeriStepError

_INTEGER_TYPES = {"Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32", "Int64", "UInt64"}


def shape_text(variable, shape):
    """'(ny = 9, nx = 17)' for messages."""
    return "(" + ", ".join(f"{d} = {n}" if isinstance(d, str) else str(n)
                           for d, n in zip(variable.dimensions, shape)) + ")"


def to_flat(md, variable, value, shape):
    """The value as the flat array fmi3Set* takes; PeriStepError naming the variable when its type or
    shape is wrong. Enumerations take item names."""
    if variable.type == "Enumeration":
        value = np.vectorize(lambda item: md.item_value(variable, item), otypes=[np.int64])(np.asarray(value, object))
    array = np.asarray(value)
    if array.shape != tuple(shape):
        raise PeriStepError(f"{variable.name}: expected shape {shape_text(variable, shape)}, got {array.shape}")
    kind = array.dtype.kind
    if variable.type in _INTEGER_TYPES or variable.type == "Enumeration":
        if kind == "f" and np.all(np.isfinite(array)) and np.all(array == np.round(array)):
            array = array.astype(np.int64)  # 3.0 means 3
        if array.dtype.kind not in "iu" and not (array.dtype.kind == "b" and variable.type != "Enumeration"):
            raise PeriStepError(f"{variable.name} is an {variable.type}: expected integers, got {value!r}")
        if variable.type.startswith("UInt") and np.any(array < 0):
            raise PeriStepError(f"{variable.name} is an {variable.type}: negative values are not allowed")
    elif variable.type == "Boolean":
        if kind not in "bi":
            raise PeriStepError(f"{variable.name} is a Boolean: expected True or False, got {value!r}")
    elif kind not in "biuf":
        raise PeriStepError(f"{variable.name} is a {variable.type}: expected numbers, got {value!r}")
    return array.ravel()


def from_flat(md, variable, values, shape):
    """A scalar as float/int/bool/str (enumeration item name), an array reshaped to its declared shape."""
    if variable.type == "Enumeration":
        values = np.array([md.item_name(variable, int(v)) for v in values], dtype=object)
    if not shape:
        v = values[0]
        return v if isinstance(v, str) else v.item()
    return values.reshape(shape)


def elements(shape):
    return math.prod(shape)
