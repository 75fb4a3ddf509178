"""Dicts to the JSON text the C++ readers take, with errors that name where a value is wrong."""

import json
import math
import numbers
import os

import numpy as np

from pound.errors import InputError


def _plain(value, name, path):
    """The value with NumPy scalars and arrays as Python numbers and lists, checked finite."""
    if isinstance(value, dict):
        plain = {}
        for key, item in value.items():
            if not isinstance(key, str):
                raise InputError(name, path or "/", f"a key that is not a string: {key!r}")
            plain[key] = _plain(item, name, f"{path}/{key}")
        return plain
    if hasattr(value, "tolist") and not isinstance(value, (str, bytes)):
        value = value.tolist()  # NumPy arrays and scalars
    if isinstance(value, (list, tuple)):
        return [_plain(item, name, f"{path}/{k}") for k, item in enumerate(value)]
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, os.PathLike):  # a pathlib.Path in "models" or a record's "file"
        return os.fspath(value)
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        if not math.isfinite(value):
            raise InputError(name, path, f"expected a finite number, got {value}")
        return float(value)
    raise InputError(name, path, f"expected a JSON value (number, string, bool, None, list or "
                                 f"dict), got {type(value).__name__}")


def integer(value, where, minimum=None, maximum=None):
    """An integer argument (Python or NumPy) as int; a float is refused, not cut (max_steps=3.5
    would run 3 steps), as the program refuses --max-steps 3.5; so is a bool, and with `minimum`
    or `maximum` one outside them (the C++ type's range: pybind11 would raise a TypeError)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise InputError("", where, f"expected an integer, got {value!r}")
    whole = int(value)  # NumPy compares np.uint64(2**63) with 2**63 - 1 as float64: equal
    if minimum is not None and whole < minimum:
        raise InputError("", where, f"expected an integer >= {minimum}, got {value!r}")
    if maximum is not None and whole > maximum:
        raise InputError("", where, f"expected an integer <= {maximum}, got {value!r}")
    return whole


def real(value, where):
    """A real number argument (Python or NumPy) as float; a bool, a string or an integer past a
    double's range is refused. Its range is checked where it is used, as the program checks the
    option."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InputError("", where, f"expected a number, got {value!r}")
    try:
        return float(value)
    except OverflowError:
        raise InputError("", where, f"expected a number, got one past a double's range: {value}")


def flag(value, where):
    """A True/False argument (Python or NumPy): resume="no" would resume."""
    if not isinstance(value, (bool, np.bool_)):
        raise InputError("", where, f"expected True or False, got {value!r}")
    return bool(value)


def path_argument(value, where, what="a path"):
    """A path argument (str or os.PathLike) as str, never empty."""
    if not isinstance(value, (str, os.PathLike)):
        raise InputError("", where, f"expected {what} (a str or a pathlib.Path), got "
                                    f"{type(value).__name__}")
    path = os.fspath(value)
    if not isinstance(path, str) or path == "":
        raise InputError("", where, f"expected {what}, got {value!r}")
    return path


INT_MAX = 2**31 - 1  # a C++ int's
LONG_MAX = 2**63 - 1  # a C++ long's


def seconds(value, where):
    """A number of seconds >= 0 (0: no limit), as the program refuses --time-limit -1 or nan."""
    number = real(value, where)
    if not number >= 0.0 or not math.isfinite(number):
        raise InputError("", where, f"expected a number of seconds >= 0, got {value!r}")
    return number


def to_json(document, name):
    """JSON text of a dict for the readers of model and set files; `name` names it in errors."""
    if not isinstance(document, dict):
        raise InputError(name, "", f"expected a dict, got {type(document).__name__}")
    return json.dumps(_plain(document, name, ""))
