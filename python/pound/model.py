"""pound.Model: a model file or dict, read and checked as ``pound run`` reads it."""

import json
import os

import numpy as np

from pound import _core
from pound._documents import INT_MAX, flag, integer, path_argument, real, to_json
from pound.errors import AnalysisError, InputError
from pound.pushover import Pushover


class Model:
    """A model (docs/model_format.md), checked whole when it is made: every error the ``pound``
    program reports (types, ranges, references, records that cannot be read) is raised here as
    :class:`pound.InputError` with the file and JSON path.

    Make one with :meth:`from_file` or :meth:`from_dict`; it is then run with :func:`pound.run`.
    """

    def __init__(self, text, path):
        # Private: use from_file or from_dict.
        self._text = text
        self._path = path

    @classmethod
    def from_file(cls, path):
        """Reads the model file at ``path``; its records are found relative to its folder."""
        path = path_argument(path, "path", "a model file's path")
        _core.validate_model(None, path)
        return cls(None, path)

    @classmethod
    def from_dict(cls, model, *, name="<dict>", folder=None):
        """A model given as a dict of the model format. Errors name it ``name``; its records are
        found relative to ``folder`` (default: the working directory)."""
        if not isinstance(name, str):
            raise InputError("", "name", f"expected a str, got {type(name).__name__}")
        path = name if folder is None else os.path.join(path_argument(folder, "folder"), name)
        text = to_json(model, path)
        _core.validate_model(text, path)
        return cls(text, path)

    @property
    def path(self):
        """The file the model came from, or its name when it came from a dict."""
        return self._path

    def to_dict(self):
        """The model as given (its generators not expanded)."""
        if self._text is not None:
            return json.loads(self._text)
        with open(self._path, encoding="utf-8") as file:
            return json.load(file)

    def expand(self):
        """The model with every generator replaced by what it generates (``pound expand``)."""
        return json.loads(_core.expand_model(self._text, self._path))

    def check(self):
        """The checks before a run (``pound check --json``): DOFs, periods, stable steps, each
        contact link's stiffness, k-ratio, contact duration, and the warnings."""
        return json.loads(_core.check_model(self._text, self._path))

    def modes(self, count=12):
        """The first ``count`` modes (``pound modes --json``): a dict with "modes" (period,
        frequency, effective mass ratios), "shapes" (an array, a row per free DOF, a column per
        mode, largest component +1) and "dofs" (each row's label, e.g. "girder_1.u_x")."""
        document, shapes, labels = _core.model_modes(self._text, self._path,
                                                     integer(count, "count", 1, INT_MAX))
        modes = json.loads(document)
        modes["shapes"] = np.asarray(shapes)
        modes["dofs"] = list(labels)
        return modes

    def pushover(self, node, to, *, direction="x", pattern="point", increments=100, out=None,
                 check=True):
        """A static pushover (``pound pushover``): the model's constant loads first (its
        records left out), then a lateral load pattern grown until ``node`` has moved ``to``
        along ``direction`` (x or y), in ``increments`` equal steps (halved where Newton does
        not converge). ``pattern``: a point load at the node ("point"), the masses times a
        uniform acceleration ("mass") or times their height above the lowest node
        ("triangular"), scaled so that the load factor is the base shear. With ``out``,
        pushover.csv and pushover.json are written there. Returns a :class:`pound.Pushover`;
        a push that cannot reach ``to`` (a mechanism) raises :class:`pound.AnalysisError` with
        the curve up to there as ``error.result``, unless ``check=False``, which returns it."""
        if not isinstance(node, str):
            raise InputError(self._path, "node", f"expected a node id, got {node!r}")
        for name, value in (("direction", direction), ("pattern", pattern)):
            if not isinstance(value, str):
                raise InputError(self._path, name, f"expected a string, got {value!r}")
        push = Pushover(*_core.model_pushover(
            self._text, self._path, node, real(to, "to"), direction, pattern,
            integer(increments, "increments", 1, INT_MAX),
            None if out is None else path_argument(out, "out", "a folder")))
        if flag(check, "check") and not push.completed:
            raise AnalysisError(None, push.stopped, push)
        return push

    def _arguments(self):
        return self._text, self._path

    def __repr__(self):
        return f"pound.Model({self._path!r})"
