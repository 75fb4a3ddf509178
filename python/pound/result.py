"""pound.Result: what pound.run returns, its histories as NumPy arrays."""

import json


def _by_item(table):
    """{id: {quantity: array, "time": array}} of a history table's "<id>.<quantity>" columns."""
    columns = dict(zip(table["columns"], table["values"]))
    time = columns.get("time")
    items = {}
    for column, values in columns.items():
        if column == "time" or "." not in column:
            continue
        item, quantity = column.rsplit(".", 1)
        entry = items.setdefault(item, {} if time is None else {"time": time})
        entry[quantity] = values
    return items


class Result:
    """The results of one run, as ``pound run`` writes them.

    - ``summary``: summary.json as a dict (statistics, per-link impacts, peak forces, work,
      the energy balance, monitors, warnings, status); ``link_summaries[id]``: its links by id;
    - ``links[id]``, ``nodes[id]``, ``elements[id]``: each a dict of quantity -> NumPy array
      (e.g. ``links["joint"]["force"]``, ``nodes["girder_1"]["u_x"]``) with its ``"time"``, from
      the model's history recorders (of those that hold the item, the one with the most samples:
      every step before a thinned copy; the first of equals);
    - ``tables[file]``: every recorder's table (histories, envelopes, spectra) as
      column -> array, named as its CSV file;
    - ``time``: the first history table's times; ``energy``: the energy terms;
      ``warnings``, ``completed``, ``failure``, ``failure_time``; ``report``: the lines
      ``pound run`` prints;
    - ``ensemble`` (with ``pound.run(ensemble=N)``, else None): ensemble.json as a dict, its
      "quantities" a list of dicts (path, unperturbed, median, p16, p84, min, max, spread,
      robust, headline); ``pandas.DataFrame(result.ensemble["quantities"])`` is a table of them.

    The arrays are read-only views of the results held by C++ (no copy). A Result pickles (to
    cross to a process pool's parent, say): its arrays go as copies, read-only again once loaded.
    """

    def __init__(self, core):
        self._core = core
        self.summary = json.loads(core.summary_json)
        self.warnings = list(core.warnings)
        self.failure = core.failure or None
        self.failure_time = core.failure_time if self.failure else None
        self.headline = core.headline
        self.report = core.report + core.ensemble_report
        self.ensemble = None if core.ensemble_json is None else json.loads(core.ensemble_json)
        self._tables = core.tables()
        self.tables = {t["file"]: self._columns(t) for t in self._tables}
        self.links, self.nodes, self.elements = {}, {}, {}
        for table in self._densest_first():
            target = {"link": self.links, "node": self.nodes, "element": self.elements}
            for item, quantities in _by_item(table).items():
                target[table["kind"]].setdefault(item, quantities)

    def __getstate__(self):
        # The C++ results stay in their process; every value read from them goes (pickle keeps
        # an array that several tables share as one).
        state = dict(self.__dict__)
        state["_core"] = None
        return state

    def __setstate__(self, state):
        self.__dict__.update(state)
        for table in self._tables:
            for values in table["values"]:
                values.flags.writeable = False

    def _densest_first(self):
        """The history tables, those with the most samples first (in recorder order among
        equals): an item or column a thinned recorder holds too is taken from the every-step one
        (a roof's peak acceleration read 24 % low from a thinned copy: audit 71)."""
        histories = [t for t in self._tables
                     if not t["envelope"] and t["kind"] != "spectrum" and "time" in t["columns"]]
        return sorted(histories, key=lambda t: -len(t["values"][t["columns"].index("time")]))

    @staticmethod
    def _columns(table):
        columns = dict(table["text_columns"])
        columns.update(zip(table["columns"], table["values"]))
        return columns

    @property
    def link_summaries(self):
        """summary["links"] by link id: impacts, peak force, penetration, impulse, work, ..."""
        return {link["id"]: link for link in self.summary.get("links", [])}

    @property
    def completed(self):
        return self.failure is None

    @property
    def energy(self):
        """The energy terms of summary.json (input, kinetic, strain, damping, links, ...)."""
        return self.summary.get("energy", {})

    @property
    def time(self):
        """The times of the first history table (None without histories)."""
        for table in self._tables:
            if not table["envelope"] and "time" in table["columns"]:
                return table["values"][table["columns"].index("time")]
        return None

    def _table(self, file):
        """A recorder's table by its file name, or a KeyError listing the names."""
        table = next((t for t in self._tables if t["file"] == file), None)
        if table is None:
            raise KeyError(f"no table {file!r}: the tables are {sorted(self.tables)} "
                           "(a file name as its CSV is written)")
        return table

    def units(self, file):
        """{column: unit} of a table, as its CSV header names them."""
        table = self._table(file)
        return dict(zip(table["columns"], table["units"] or [""] * len(table["columns"])))

    def to_pandas(self, file=None):
        """A pandas DataFrame: the history tables joined on time (columns "<id>.<quantity>", a
        column two recorders hold taken from the one with the most samples), or one table by its
        file name (an envelope or spectrum too). Needs pandas."""
        import pandas
        if file is not None:
            return pandas.DataFrame(self._columns(self._table(file)))
        frames = [pandas.DataFrame(self.tables[t["file"]]).set_index("time")
                  for t in self._densest_first()]
        if not frames:
            return pandas.DataFrame()
        frame = frames[0]
        for other in frames[1:]:
            frame = frame.join(other[[c for c in other.columns if c not in frame.columns]],
                               how="outer")
        return frame

    def __repr__(self):
        status = "completed" if self.completed else f"failed at t = {self.failure_time:g}"
        return f"<pound.Result {status}: {self.headline}>"
