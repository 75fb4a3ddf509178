"""pound.verify: the verification benchmarks of ``pound verify``, as dicts."""

import json
import numbers
import re

import numpy as np

from pound import _core
from pound._documents import INT_MAX, integer, real
from pound.errors import InputError


def _python_names(message):
    """`pound verify`'s option names in a message as the keyword arguments here (--k-ratio:
    k_ratio)."""
    return re.sub(r"--([a-z][a-z-]*)", lambda m: m.group(1).replace("-", "_"), message)


# The keywords of rod_impact and the type of each.
_ROD_IMPACT_KEYWORDS = {"case": str, "n": numbers.Integral, "k_ratio": numbers.Real,
                        "dt_ratio": numbers.Real, "courant": numbers.Real,
                        "duration_ratio": numbers.Real, "law": str, "eta": numbers.Real,
                        "integrator": str, "alpha": numbers.Real, "rho_inf": numbers.Real,
                        "tolerance": numbers.Real}


def _check_keywords(options):
    for name, value in options.items():
        expected = _ROD_IMPACT_KEYWORDS.get(name)
        if expected is None:
            raise TypeError(f"rod_impact() got an unexpected keyword argument '{name}' (known: "
                            f"{', '.join(_ROD_IMPACT_KEYWORDS)})")
        if not isinstance(value, expected) or isinstance(value, bool):
            kind = "a string" if expected is str else (
                "an integer" if expected is numbers.Integral else "a number")
            raise InputError("", name, f"expected {kind}, got {value!r}")
        if expected is numbers.Integral:
            options[name] = integer(value, name, -INT_MAX, INT_MAX)
        elif expected is numbers.Real:
            options[name] = real(value, name)


def rod_impact(**options):
    """Two elastic rods collide; the finite element solution against the exact wave solution
    (``pound verify rod-impact``). Keywords: case ("kawashima", "fixed-end", "area-ratio-3",
    "unequal-lengths", "rigid-wall"), n (elements per rod), k_ratio, dt_ratio, courant,
    duration_ratio, law ("gap_spring", "extended_penalty", "hard_contact"), eta, integrator,
    alpha, rho_inf, tolerance. Returns the metrics (force_l2_error, duration_error,
    separation_velocity_error, peak_force_ratio, ...) with "time_step" and the histories "time",
    "force", "exact_force", "penetration" as arrays."""
    _check_keywords(options)
    try:
        document, step, histories = _core.verify_rod_impact(options)
    except ValueError as error:
        if isinstance(error, InputError):
            raise
        raise InputError("", "", _python_names(str(error))) from None
    metrics = json.loads(document)
    metrics["time_step"] = step
    metrics.update({key: np.asarray(value) for key, value in histories.items()})
    return metrics


def restitution():
    """Two masses collide once through every impact law at e = 0.3, 0.5, 0.7, 0.9: the target
    and achieved restitution, peak force, contact time, penetration (``pound verify
    restitution --json``): {"rows": [a dict per law and target]}."""
    return json.loads(_core.verify_restitution())


def two_element():
    """Suzuki & Toi's two-element model: the program's eigenvalues against the closed forms
    (``pound verify two-element --json``): {"cases": [a dict per case with its
    relative_error]}."""
    return json.loads(_core.verify_two_element())
