"""pound.Model: a model file or dict, read and checked as ``pound run`` reads it."""

import json
import os

import numpy as np

from pound import _core
from pound._documents import INT_MAX, integer, to_json


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
        path = os.fspath(path)
        _core.validate_model(None, path)
        return cls(None, path)

    @classmethod
    def from_dict(cls, model, *, name="<dict>", folder=None):
        """A model given as a dict of the model format. Errors name it ``name``; its records are
        found relative to ``folder`` (default: the working directory)."""
        path = name if folder is None else os.path.join(os.fspath(folder), name)
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

    def _arguments(self):
        return self._text, self._path

    def __repr__(self):
        return f"pound.Model({self._path!r})"
