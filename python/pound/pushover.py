"""The result of a static pushover (``pound pushover``): the capacity curve and its summary."""

import json


class Pushover:
    """A capacity curve, as ``pound pushover`` writes it.

    - ``curve``: column -> NumPy array: ``displacement`` (of the control node), ``base_shear``
      (the load factor, the pattern's loads summing to 1 along the push), ``iterations`` and the
      deformation of every yielding link (``<id>.deformation``, a coupled bearing's
      ``<id>.deformation_1``, ...);
    - ``summary``: pushover.json as a dict (initial stiffness, final slope, first yield, peak
      base shear, the displacement reached, status);
    - ``report``: the lines ``pound pushover`` prints; ``completed``: whether the control node
      reached the target, and if not ``stopped`` says why (a mechanism).
    """

    def __init__(self, columns, arrays, document, report, stopped):
        self.curve = dict(zip(columns, arrays))
        self.summary = json.loads(document)
        self.report = report
        self.stopped = stopped or None

    @property
    def completed(self):
        return self.stopped is None

    def to_pandas(self):
        """The curve as a pandas DataFrame. Needs pandas."""
        import pandas
        return pandas.DataFrame(self.curve)

    def __repr__(self):
        peak = self.summary["peak_base_shear"]
        status = "completed" if self.completed else "stopped"
        return (f"<pound.Pushover {status}: reached {self.summary['reached']:g}, "
                f"peak base shear {peak:g}>")
