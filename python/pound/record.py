"""pound.Record: a ground-acceleration record, from a file or from arrays."""

import math
import numbers

import numpy as np

from pound import _core
from pound._documents import INT_MAX, flag, integer, path_argument, real
from pound.errors import InputError


def _samples(values, name, what):
    """A 1-D float64 array of `values`, or InputError naming `what`."""
    try:
        # Complex numbers would lose their imaginary part, booleans become 0 and 1, and text be
        # parsed: none of them is a time or an acceleration.
        given = np.asarray(values)
        if given.dtype.kind in "bcSUV":
            raise TypeError(f"an array of {given.dtype} is no real number")
        array = np.asarray(given, dtype=np.float64)
    except (TypeError, ValueError, OverflowError) as error:
        raise InputError(name, what, f"expected numbers: {error}") from None
    if array.ndim != 1:
        raise InputError(name, what, f"expected a 1-D array, got shape {array.shape}")
    return array


def _scale(scale, name):
    if scale is None:
        return None
    if isinstance(scale, bool) or not isinstance(scale, numbers.Real) or \
            not math.isfinite(real(scale, "scale")) or not scale > 0:
        raise InputError(name, "scale", f"expected a positive number, got {scale!r}")
    return float(scale)


def _time_unit(value, name):
    """None (the model's unit of time), "s" or "ms"."""
    if value is not None and value not in ("s", "ms"):
        raise InputError(name, "time_unit", f"expected 's' or 'ms' (or None, the model's unit of "
                                            f"time), got {value!r}")
    return value


def _word(value, name, where):
    """A str argument (a unit, a format, a name)."""
    if not isinstance(value, str):
        raise InputError(name, where, f"expected a str, got {value!r}")
    return value


class Record:
    """A ground-acceleration record, uniformly sampled.

    ``Record(times_or_dt, accelerations, units="g")`` takes the time step (a number) or the
    sample times (an array, uniform), and the accelerations in ``units``: "g", "m/s2", "cm/s2" or
    "model" (the model's own units). The times are in ``time_unit``, "s" or "ms", or without it
    in the unit of time of the model the record drives. ``Record.from_file`` reads the files
    ``pound run --motion`` reads, its times (and ``dt``) in seconds as the file's. Given to
    :func:`pound.run`, it replaces the model's first excitation's record (its
    direction and supports stay); with ``scale`` it is multiplied by that factor instead of the
    model's scaling, without it the model's scaling (factor, target PGA or Sa) applies to it.
    """

    def __init__(self, times_or_dt, accelerations, units="g", *, name="<array>", scale=None,
                 time_unit=None):
        self.name = _word(name, "", "name")
        self.units = _word(units, name, "units")
        self.time_unit = _time_unit(time_unit, self.name)
        self.scale = _scale(scale, name)
        self.path = None
        self._values = _samples(accelerations, name, "accelerations")
        if isinstance(times_or_dt, bool):
            raise InputError(name, "times_or_dt",
                             f"expected a time step or times, got {times_or_dt}")
        if isinstance(times_or_dt, numbers.Real):
            self._given_step, self._times = real(times_or_dt, "times_or_dt"), np.empty(0)
        else:
            self._given_step, self._times = None, _samples(times_or_dt, name, "times")
        self.time_step = _core.check_samples(name, self._values, self._given_step, self._times,
                                             units)
        self._values.flags.writeable = False

    @classmethod
    def from_file(cls, path, units="g", column=None, scale=None, *, dt=None, time_column=False,
                  format="auto"):
        """Reads a PEER .AT2 file or a columns file, as ``pound run --motion`` does: ``column``
        (from 1; default 1, or 2 with ``time_column``), ``dt`` for a columns file that does not
        state it, ``format`` "auto", "at2" or "columns"."""
        path = path_argument(path, "path", "a record file's path")
        time_column = flag(time_column, "time_column")
        units, format = _word(units, path, "units"), _word(format, path, "format")
        dt = None if dt is None else real(dt, "dt")
        if dt is not None and not (math.isfinite(dt) and dt > 0.0):
            raise InputError(path, "dt", f"expected a time step > 0, got {dt}")
        column = column if column is not None else (2 if time_column else 1)
        record = cls.__new__(cls)
        column = integer(column, "column", -INT_MAX, INT_MAX)
        name, step, values, sha1, read_as = _core.read_record(path, format, units, column, dt,
                                                              time_column)
        record.name, record.units, record.path = name, units, path
        record.time_unit = "s"  # a file's times, and dt beside it
        record.scale = _scale(scale, path)
        record.time_step, record.sha1, record.format = step, sha1, read_as
        record._column, record._dt, record._time_column = column, dt, time_column
        record._values = np.asarray(values)
        record._values.flags.writeable = False
        return record

    @property
    def accelerations(self):
        """The samples in the record's units, times ``scale`` when given."""
        return self._values if self.scale is None else self._values * self.scale

    @property
    def times(self):
        """The time of each sample, from 0."""
        return np.arange(len(self._values)) * self.time_step

    @property
    def duration(self):
        return (len(self._values) - 1) * self.time_step

    @property
    def peak(self):
        """The largest |acceleration|, in the record's units (``scale`` applied)."""
        return float(np.max(np.abs(self.accelerations)))

    @property
    def _second(self):
        """One second in the record's unit of time (seconds unless its time_unit is "ms")."""
        return 1000.0 if self.time_unit == "ms" else 1.0

    def _periods(self, periods):
        """The periods asked, or the default 40 from 0.02 s to 10 s, in the record's unit."""
        if periods is None:
            return np.asarray(_core.default_spectrum_periods()) * self._second
        return _samples(np.atleast_1d(periods), self.name, "periods")

    def spectrum(self, periods=None, damping=0.05):
        """Pseudo-spectral acceleration Sa = w^2 max|u| of a linear oscillator at each period, in
        the record's unit of time (default: 40 log-spaced from 0.02 s to 10 s), exact for the
        linearly interpolated record (Nigam & Jennings) and its free vibration after the last
        sample, in the record's units. Returns {"periods", "sa"} arrays. A record of arrays in
        a millisecond model's time wants ``time_unit="ms"`` for these defaults."""
        periods = self._periods(periods)
        sa = _core.spectrum(self.name, self.time_step, self.accelerations, periods,
                            real(damping, "damping"), self._second)
        return {"periods": periods, "sa": np.asarray(sa)}

    def pair_spectrum(self, second, periods=None, damping=0.05, rotation=0.0):
        """The intensity measures of this record and ``second``, the same station's other
        horizontal component (90 degrees from this one, on the same time grid and in the same
        units): each component's Sa, their geometric mean, and the orientation-independent RotD50
        and RotD100 (Boore 2010: the median and the largest over the directions 0..179 degrees of
        the peak oscillator response to the pair), as ``pound spectrum --pair``. ``rotation``
        [degrees] turns the pair's axes first (the components' Sa change, RotD50 does not).
        Returns arrays {"periods", "sa1", "sa2", "geometric_mean", "rotd50", "rotd100"} in the
        records' units and "rotd100_angle" in degrees from this component towards ``second``."""
        if not isinstance(second, Record):
            raise InputError(self.name, "second", f"expected a pound.Record, got {second!r}")
        if second.units != self.units:
            raise InputError(second.name, "units",
                             f"the pair's components must be in one unit, got {self.units!r} "
                             f"and {second.units!r}")
        if isinstance(rotation, bool) or not isinstance(rotation, numbers.Real):
            raise InputError(second.name, "rotation", f"expected an angle, got {rotation!r}")
        rotation, damping = real(rotation, "rotation"), real(damping, "damping")
        if second.time_unit != self.time_unit:
            raise InputError(second.name, "time_unit",
                             f"the pair's components must be in one unit of time, got "
                             f"{self.time_unit!r} and {second.time_unit!r}")
        periods = self._periods(periods)
        result = _core.pair_spectrum(self.name, self.time_step, self.accelerations, second.name,
                                     second.time_step, second.accelerations, periods,
                                     damping, rotation, self._second)
        return {"periods": periods, **{key: np.asarray(value) for key, value in result.items()}}

    def _motion(self):
        """The record as _core.run takes it."""
        motion = {"name": self.name, "units": self.units, "scale": self.scale,
                  "second": None if self.time_unit is None else self._second}
        if self.path is None:
            motion.update(accelerations=self._values, times=self._times,
                          time_step=self._given_step)
        else:
            motion.update(path=self.path, column=self._column, time_step=self._dt,
                          time_column=self._time_column)
        return motion

    def __repr__(self):
        unit = self.time_unit or "(the model's unit of time)"
        return (f"pound.Record({self.name!r}, {len(self._values)} samples, dt = "
                f"{self.time_step:g} {unit}, units {self.units!r})")
