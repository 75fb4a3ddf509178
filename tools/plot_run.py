#!/usr/bin/env python3
"""Plots the results of `pound run` as PNG figures next to them.

usage: python3 tools/plot_run.py DIR [--dpi 120]

DIR is the --out folder of `pound run` (summary.json and the CSV or .npy time histories). Written into
DIR, each when its data is there (one line printed per file):
  link_forces.png        force history of every link (compression +, tension -)
  force_penetration.png  force against penetration per link (impact, restrainer, spring loops)
  joint_openings.png     joint opening histories (joints.csv), seat width dashed
  drift_envelopes.png    peak storey drift ratio against height (in 3-D a panel per direction, the
                         largest plan corner dashed), pier drift ratio and ductility
  energy.png             energy components (energy.csv) and the balance error
  displacements.png      u_x histories of the recorded nodes
  accelerations.png      their absolute accelerations a_abs_x (node recorders write them)
  plan_motion.png        3-D runs only: per recorded node with u_x, u_y and u_rz, its path in
                         plan (u_y against u_x) and its rotation u_rz about z against time
  floor_spectra.png      floor response spectra Sa(T) of spectrum recorders, one panel per
                         damping ratio
  ensemble.png           with ensemble.json (`pound run --ensemble N`): the spread over the
                         perturbed copies of the peaks damage is judged by, least robust first
  report.html            one self-contained page for people: the run's facts, warnings, the
                         excitations the model names, the tables of summary.json, the
                         ensemble's spread and every figure above (inlined)
Figures with more links, joints or nodes than fit on a page continue in link_forces_2.png, ...
CSV files are recognised by their columns, not their names. Axes name the units summary.json
gives (its "units": the model's units block), "model units" where it names none.

Needs matplotlib (Debian: python3-matplotlib, installed by tools/install_dependencies.sh).
Run it with the interpreter that has it; if `python3` is another one (pyenv, a venv) without
matplotlib, the script starts itself again with /usr/bin/python3 when that one exists.

Exit codes: 0 ok, 1 usage error or matplotlib missing, 2 bad input (no summary.json, a
malformed summary or CSV; message names the file), 4 a figure could not be written.
"""

import json
import math
import os
import sys
from array import array

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_common import (InputError, check_column_names, check_folder, check_width,  # noqa: E402
                         csv_reader, folder_parser, import_matplotlib, not_a_number, read_json,
                         run_plots, save_png, strip_header, units_of)
from run_report_html import write_report  # noqa: E402

PROG = "plot_run.py"
REEXEC_MARK = "POUND_PLOT_RUN_REEXEC"

PER_PAGE = 8          # subplots (rows of plan_motion.png) per page of the per-item figures
NODES_PER_AXES = 10   # node histories overlaid in one subplot of displacements.png
LINK_QUANTITIES = ("force", "penetration", "tangential_force", "slide")
NODE_QUANTITIES = ("u_x", "a_abs_x", "u_y", "u_rz")   # the node columns a figure reads
SPACE_ONLY_QUANTITIES = ("u_z", "u_rx", "u_ry")      # node directions only a 3-D scene has
ENERGY_TERMS = ("kinetic", "strain", "damping", "links")
ENSEMBLE_SHOWN = 24


def load_ensemble(folder):
    """The headline quantities of ensemble.json (those damage is judged by, as pound marks them),
    or None without the file."""
    path = os.path.join(folder, "ensemble.json")
    if not os.path.isfile(path):
        return None
    ensemble = read_json(path)
    quantities = ensemble.get("quantities") if isinstance(ensemble, dict) else None
    if not isinstance(quantities, list) or not all(isinstance(q, dict) for q in quantities):
        raise InputError(f"{path}: expected an object with a list of \"quantities\"")
    shown = []
    for q in quantities:
        values = [number(q, key) for key in ("unperturbed", "median", "p16", "p84", "min", "max",
                                             "spread")]
        if not isinstance(q.get("path"), str) or any(v is None for v in values):
            raise InputError(f"{path}: every quantity needs a path and its numbers")
        if q.get("headline") is True:
            shown.append(q)
    for q in shown:  # pound's verdict (band and the unperturbed run's place); older files: band
        if not isinstance(q.get("robust"), bool):
            q["robust"] = q["spread"] <= (number(ensemble, "robust_spread") or 0.05)
    return {"path": path, "quantities": shown, "copies": ensemble.get("copies"),
            "perturbation": ensemble.get("perturbation"),
            "perturbed": ensemble.get("perturbed") if isinstance(ensemble.get("perturbed"), str)
            else "the records",
            "failed": number(ensemble, "failed") or 0,
            "robust_spread": number(ensemble, "robust_spread") or 0.05}


def ensemble_words(ensemble):
    """How many copies completed, of how many, and what was perturbed: for titles and notes."""
    copies, failed = ensemble.get("copies"), int(ensemble.get("failed") or 0)
    counted = f"{copies} copies" if not failed else f"{copies - failed} of {copies} copies ({failed} failed, left out)"
    return f"{counted}, {ensemble['perturbed']} scaled by 1 ± k·{ensemble['perturbation']:g}"


# ----------------------------------------------------------------------------------------------
# Input

def load_summary(folder):
    check_folder(folder)
    path = os.path.join(folder, "summary.json")
    if not os.path.isfile(path):
        raise InputError(f"{folder}: no summary.json here (is it the --out folder of `pound run`?)")
    summary = read_json(path)
    if not isinstance(summary, dict):
        raise InputError(f"{path}: expected a JSON object at the top level")
    summary["__path__"] = path
    return summary


def summary_items(summary, key):
    """summary[key] as a list of objects ([] when absent)."""
    value = summary.get(key)
    if value is None:
        return []
    if not isinstance(value, list) or not all(isinstance(item, dict) for item in value):
        raise InputError(f"{summary['__path__']}: \"{key}\" must be a list of objects")
    return value


def summary_object(summary, key):
    value = summary.get(key)
    if value is None:
        return {}
    if not isinstance(value, dict):
        raise InputError(f"{summary['__path__']}: \"{key}\" must be an object")
    return value


def number(item, key):
    """item[key] as a float, or None when absent or not a number."""
    value = item.get(key)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    return float(value)


def split_column(name):
    """'girder_1.u_x' -> ('girder_1', 'u_x'); ids may themselves contain dots."""
    owner, dot, quantity = name.rpartition(".")
    return (owner, quantity) if dot else (None, name)


def is_node_quantity(quantity):
    return len(quantity) >= 3 and quantity[0] in "uva" and quantity[1] == "_"


class History:
    """One CSV time history: its header, then the columns that are plotted, as float arrays."""

    def __init__(self, path, header):
        self.path = path
        self.columns = header
        self.index = {name: i for i, name in enumerate(header)}
        self.values = {}
        self.rows = 0

    def kinds(self):
        kinds = set()
        for name in self.columns[1:]:
            owner, quantity = split_column(name)
            if owner is None:
                if quantity in ENERGY_TERMS or quantity == "input":
                    kinds.add("energy")
            elif quantity in LINK_QUANTITIES:
                kinds.add("link")
            elif quantity == "opening":
                kinds.add("joint")
            elif is_node_quantity(quantity):
                kinds.add("node")
        return kinds

    def wanted(self):
        """Names of the columns a figure uses (others are checked for shape only)."""
        names = ["time"]
        for name in self.columns[1:]:
            owner, quantity = split_column(name)
            if owner is None:
                if quantity in ENERGY_TERMS or quantity in ("input", "initial"):
                    names.append(name)
            elif quantity in LINK_QUANTITIES or quantity in ("opening",) + NODE_QUANTITIES:
                names.append(name)
        return names

    def load(self, numpy):
        names = self.wanted()
        indices = [self.index[name] for name in names]
        arrays = [array("d") for _ in names]
        width = len(self.columns)
        with csv_reader(self.path) as reader:
            next(reader)
            for row in reader:
                if not row:
                    continue
                check_width(self.path, reader.line_num, row, width)
                try:
                    for values, i in zip(arrays, indices):
                        values.append(float(row[i]))
                except ValueError:
                    bad = next(i for i in indices if not is_float(row[i]))
                    raise not_a_number(self.path, reader.line_num, self.columns[bad],
                                       row[bad]) from None
        self.values = {name: numpy.frombuffer(values, dtype=float) if len(values) else
                       numpy.zeros(0) for name, values in zip(names, arrays)}
        self.rows = len(arrays[0])

    def time(self):
        return self.values["time"]


def is_float(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def read_npy_history(path, numpy):
    """A recorder's .npy (a structured array of float64 columns), as a History; None if not one."""
    try:
        data = numpy.load(path, allow_pickle=False)
    except (ValueError, OSError) as error:
        raise InputError(f"{path}: not a NumPy .npy file: {error}") from None
    names = data.dtype.names
    if names and names[0] in ("period", "quantity"):  # a spectrum (read_spectra) or an envelope
        return None
    if not names or names[0] != "time":
        sys.stderr.write(f"note: {path}: not a structured array starting with 'time', not a pound "
                         "history: skipped\n")
        return None
    history = History(path, list(names))
    history.values = {name: numpy.asarray(data[name], dtype=float) for name in history.wanted()}
    history.rows = len(data)
    return history


def read_histories(folder, numpy):
    """Every CSV (or .npy) of the folder whose first column is time, its plotted columns loaded."""
    histories = []
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if name.lower().endswith(".npy") and os.path.isfile(path):
            history = read_npy_history(path, numpy)
            if history is not None and history.kinds() and history.rows > 0:
                histories.append(history)
            continue
        if not name.lower().endswith(".csv") or not os.path.isfile(path):
            continue
        with csv_reader(path) as reader:
            header = strip_header(path, next(reader, None))
        if header[0] in ("period", "quantity"):  # a spectrum or an envelope: read_spectra's
            continue
        if header[0] != "time":
            sys.stderr.write(f"note: {path}: first column is not 'time', not a pound history: skipped\n")
            continue
        check_column_names(path, header)
        history = History(path, header)
        if not history.kinds():
            continue
        history.load(numpy)
        if history.rows == 0:
            sys.stderr.write(f"note: {path}: header only, no rows: skipped\n")
            continue
        histories.append(history)
    return histories


def read_spectra(folder, numpy):
    """The spectrum recorders' tables (first column 'period'): [(path, periods, {column: Sa})]."""
    spectra = []
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if not os.path.isfile(path):
            continue
        if name.lower().endswith(".npy"):
            try:
                data = numpy.load(path, allow_pickle=False)
            except (ValueError, OSError):
                continue  # read_histories reports it
            if not data.dtype.names or data.dtype.names[0] != "period":
                continue
            spectra.append((path, numpy.asarray(data["period"], dtype=float),
                            {c: numpy.asarray(data[c], dtype=float)
                             for c in data.dtype.names[1:]}))
            continue
        if not name.lower().endswith(".csv"):
            continue
        with csv_reader(path) as reader:
            header = strip_header(path, next(reader, None))
            if header[0] != "period":
                continue
            rows = []
            for row in reader:
                if not row:
                    continue
                check_width(path, reader.line_num, row, len(header))
                bad = next((i for i, cell in enumerate(row) if not is_float(cell)), None)
                if bad is not None:
                    raise not_a_number(path, reader.line_num, header[bad], row[bad])
                rows.append([float(cell) for cell in row])
        table = numpy.array(rows, dtype=float).reshape(len(rows), len(header))
        spectra.append((path, table[:, 0], {c: table[:, i] for i, c in enumerate(header)
                                            if i > 0}))
    return spectra


def spectrum_column(name):
    """'roof.sa_x_5%' -> ('roof', 'x', '5%'); None for another column."""
    owner, quantity = split_column(name)
    parts = quantity.split("_")
    if owner is None or len(parts) != 3 or parts[0] != "sa" or not parts[2].endswith("%"):
        return None
    return owner, parts[1], parts[2]


def scene_in_space(summary, histories, folder):
    """Whether the run's scene is 3-D (the model's "dimension": 3), where a node's u_x and u_y
    are a path in plan and u_rz a rotation about the vertical z.

    The node columns alone cannot tell: a node of a plane (2-D) frame records u_x, u_y (there
    the vertical) and u_rz (its in-plane rotation), the very columns of a 3-D rigid floor
    (u_x, u_y and u_rz at its mass centre), with the same units, and summary.json names no
    dimension. Any one of these is a 3-D scene, each impossible in a plane one:
      - a node column u_z, u_rx or u_ry in a history (directions a plane scene does not have);
      - in summary.json, an excitation with a "pair" (two horizontal components: 3-D only),
        a storey with "peak_twist" (a floor plan's corners) or a joint with
        "peak_plan_rotation" (both written in 3-D scenes only);
      - the model file summary.json names, where it can still be read (as given, or from
        DIR, as report.html looks for it), says "dimension": 3.
    None of them (a 3-D scene excited along one axis, without plan-corner storeys, joints or
    out-of-plane columns, whose model file has moved): taken as plane, no plan figure."""
    for history in histories:
        for name in history.columns[1:]:
            owner, quantity = split_column(name)
            if owner is not None and quantity in SPACE_ONLY_QUANTITIES:
                return True
    marks = (("excitations", "pair"), ("storeys", "peak_twist"), ("joints", "peak_plan_rotation"))
    for key, mark in marks:
        items = summary.get(key)
        if isinstance(items, list) and any(isinstance(i, dict) and mark in i for i in items):
            return True
    model = summary.get("model")
    if not isinstance(model, str) or not model:
        return False
    for path in (model, os.path.join(folder, model)):
        if os.path.isfile(path):
            try:
                with open(path, encoding="utf-8") as file:
                    spec = json.load(file)
            except (OSError, ValueError, RecursionError):
                return False  # not ours to judge: pound read it when it ran
            return isinstance(spec, dict) and spec.get("dimension") == 3
    return False


# ----------------------------------------------------------------------------------------------
# Figures

def fmt(value):
    return "n/a" if value is None else f"{value:.4g}"


class Plotter:
    def __init__(self, folder, summary, dpi, figure_class, numpy):
        self.folder = folder
        self.summary = summary
        self.dpi = dpi
        self.Figure = figure_class
        self.np = numpy
        from matplotlib.ticker import MaxNLocator
        self.MaxNLocator = MaxNLocator
        model = summary.get("model")
        self.model = (os.path.splitext(os.path.basename(model))[0] if isinstance(model, str) and model
                      else os.path.basename(os.path.abspath(folder)))
        if summary.get("status") == "failed":
            self.model += f" (analysis failed at t = {fmt(number(summary, 'failure_time'))})"
        self.written = []
        self.units = units_of(summary)
        self.time_label = f"time [{self.units['time']}]"

    def figure(self, count, columns, row_height, width=11.0):
        rows = max(1, math.ceil(count / columns))
        fig = self.Figure(figsize=(width, 1.2 + row_height * rows))
        axes = fig.subplots(rows, columns, squeeze=False).ravel()
        for ax in axes[count:]:
            ax.set_visible(False)
        return fig, axes[:count]

    def save(self, fig, name, title):
        # 0.1 inch below the top edge (matplotlib's y = 0.98 of a 5-inch figure): at a fraction
        # of a tall page's height the title would sink onto the first row's titles, for
        # tight_layout keeps the same room above them whatever the height
        fig.suptitle(f"{title}: {self.model}", y=1.0 - 0.1 / fig.get_figheight())
        path = os.path.join(self.folder, name)
        save_png(fig, path, self.dpi)
        print(path)
        self.written.append(path)

    @staticmethod
    def pages(items):
        return [items[i:i + PER_PAGE] for i in range(0, len(items), PER_PAGE)]

    @staticmethod
    def page_name(base, page):
        return f"{base}.png" if page == 0 else f"{base}_{page + 1}.png"

    # -- links ----------------------------------------------------------------------------------

    def link_series(self, histories):
        """{link id: {quantity: (time, values)}}, in the summary's link order, first file wins."""
        series = {}
        for history in histories:
            for name in history.columns[1:]:
                owner, quantity = split_column(name)
                if owner is not None and quantity in LINK_QUANTITIES:
                    series.setdefault(owner, {}).setdefault(
                        quantity, (history.time(), history.values[name]))
        order = [str(link.get("id")) for link in summary_items(self.summary, "links")]
        ids = [i for i in order if i in series] + [i for i in series if i not in order]
        return [(i, series[i]) for i in ids]

    def link_summaries(self):
        return {str(link.get("id")): link for link in summary_items(self.summary, "links")}

    def link_title(self, link_id, info):
        if info.get("seated"):  # a bearing under the weight: its force is its share of it
            impacts = number(info, "impacts") or 1
            lifted = f"lifted off {impacts - 1:g} time(s)" if impacts > 1 else "never lifted off"
            return (f"{link_id}\nseated bearing, peak normal force "
                    f"{fmt(number(info, 'peak_force') or 0.0)}, {lifted}")
        parts = []
        peak_force, peak_tension = number(info, "peak_force"), number(info, "peak_tension")
        if peak_force is not None and (peak_force > 0.0 or not peak_tension):
            parts.append(f"peak force {fmt(peak_force)}")
        if peak_tension:
            parts.append(f"peak tension {fmt(peak_tension)}")
        impacts = number(info, "impacts")
        if impacts is not None:
            taut = peak_tension and not peak_force
            parts.append(f"{'taut' if taut else 'impacts'}: {impacts:g}")
        return f"{link_id}\n" + ", ".join(parts) if parts else link_id

    def plot_link_forces(self, links):
        summaries = self.link_summaries()
        for page, items in enumerate(self.pages(links)):
            columns = 1 if len(items) <= 4 else 2
            fig, axes = self.figure(len(items), columns, 2.3)
            for ax, (link_id, data) in zip(axes, items):
                if "force" in data:
                    ax.plot(*data["force"], lw=0.8, color="C0", label="normal force")
                if "tangential_force" in data:
                    ax.plot(*data["tangential_force"], lw=0.8, color="C1", label="tangential force")
                    ax.legend(loc="best", fontsize="small")
                ax.axhline(0.0, color="0.6", lw=0.5)
                ax.set_title(self.link_title(link_id, summaries.get(link_id, {})), fontsize="medium")
                ax.set_xlabel(self.time_label)
                if summaries.get(link_id, {}).get("rotational"):
                    ax.set_ylabel(f"moment\n[{self.units['moment']}]")
                else:
                    ax.set_ylabel(f"force (compression +)\n[{self.units['force']}]")
                ax.grid(alpha=0.3)
            self.save(fig, self.page_name("link_forces", page), "Link force histories")

    def contact_window(self, x, force):
        """x limits around the part of a loop where the link carries force (None: all of it)."""
        np = self.np
        active = (force != 0.0) & np.isfinite(force) & np.isfinite(x)
        if not active.any():
            return None
        low, high = float(x[active].min()), float(x[active].max())
        finite = x[np.isfinite(x)]
        span = high - low
        if span <= 0.0:
            span = max(abs(high), 1e-12)
        # a quarter of the engaged range of free travel each side, then a small margin
        low = max(low - 0.25 * span, float(finite.min())) - 0.04 * span
        high = min(high + 0.25 * span, float(finite.max())) + 0.04 * span
        return low, high

    def plot_force_penetration(self, links):
        summaries = self.link_summaries()
        panels = []
        for link_id, data in links:
            if "force" in data and "penetration" in data:
                panels.append((link_id, data["penetration"][1], data["force"][1], "normal"))
            if "tangential_force" in data and "slide" in data:
                panels.append((link_id, data["slide"][1], data["tangential_force"][1], "tangential"))
        for page, items in enumerate(self.pages(panels)):
            columns = min(3, len(items))
            fig, axes = self.figure(len(items), columns, 3.2)
            for ax, (link_id, x, force, kind) in zip(axes, items):
                rigid = kind == "normal" and summaries.get(link_id, {}).get("law") == "hard_contact"
                if rigid:
                    # A hard contact's forces are impulses over a step (at the step's start under
                    # central difference, where the gap is still open): lines between samples
                    # would draw a stiffness it does not have.
                    engaged = force != 0.0
                    ax.vlines(x[engaged], 0.0, force[engaged], lw=0.8, color="C0")
                    ax.plot(x[engaged], force[engaged], "o", ms=3, color="C0")
                else:
                    ax.plot(x, force, lw=0.8, color="C0" if kind == "normal" else "C1")
                ax.axhline(0.0, color="0.6", lw=0.5)
                ax.axvline(0.0, color="0.6", lw=0.5)
                window = self.contact_window(x, force)
                if window:
                    ax.set_xlim(*window)
                if kind == "normal" and summaries.get(link_id, {}).get("rotational"):
                    title = self.link_title(link_id, summaries.get(link_id, {}))
                    ax.set_xlabel(f"rotation [{self.units['angle']}]")
                    ax.set_ylabel(f"moment [{self.units['moment']}]")
                elif kind == "normal":
                    title = self.link_title(link_id, summaries.get(link_id, {}))
                    ax.set_xlabel(f"penetration (closing +) [{self.units['length']}]")
                    ax.set_ylabel(f"force (compression +) [{self.units['force']}]")
                else:
                    title = f"{link_id}\nfriction: tangential force against slide"
                    ax.set_xlabel(f"slide [{self.units['length']}]")
                    ax.set_ylabel(f"tangential force [{self.units['force']}]")
                if window is None:
                    title += " (never engaged)"
                ax.xaxis.set_major_locator(self.MaxNLocator(4, steps=[1, 2, 5, 10]))
                ax.set_title(title, fontsize="medium")
                ax.grid(alpha=0.3)
            self.save(fig, self.page_name("force_penetration", page),
                      "Force against penetration (zoomed on engagement)")

    # -- joints ---------------------------------------------------------------------------------

    def plot_joint_openings(self, histories):
        series = {}
        for history in histories:
            for name in history.columns[1:]:
                owner, quantity = split_column(name)
                if owner is not None and quantity == "opening":
                    series.setdefault(owner, (history.time(), history.values[name]))
        if not series:
            return
        joints = {str(j.get("id")): j for j in summary_items(self.summary, "joints")}
        ids = [i for i in joints if i in series] + [i for i in series if i not in joints]
        for page, items in enumerate(self.pages(ids)):
            columns = 1 if len(items) <= 4 else 2
            fig, axes = self.figure(len(items), columns, 2.3)
            for ax, joint_id in zip(axes, items):
                info = joints.get(joint_id, {})
                ax.plot(*series[joint_id], lw=0.8, color="C0", label="opening")
                ax.axhline(0.0, color="0.6", lw=0.5)
                seat = number(info, "seat_width")
                if seat is not None:
                    ax.axhline(seat, color="C3", ls="--", lw=1.0, label=f"seat width {fmt(seat)}")
                    ax.legend(loc="best", fontsize="small")
                parts = [f"peak opening {fmt(number(info, 'peak_opening'))}"] if info else []
                if number(info, "peak_closing") is not None:
                    parts.append(f"peak closing {fmt(number(info, 'peak_closing'))}")
                if number(info, "unseating_margin") is not None:
                    parts.append(f"unseating margin {fmt(number(info, 'unseating_margin'))}")
                ax.set_title(f"{joint_id}\n" + ", ".join(parts) if parts else joint_id,
                             fontsize="medium")
                ax.set_xlabel(self.time_label)
                ax.set_ylabel(f"opening [{self.units['length']}]")
                ax.grid(alpha=0.3)
            self.save(fig, self.page_name("joint_openings", page), "Joint opening histories")

    # -- drifts ---------------------------------------------------------------------------------

    def plot_drift_envelopes(self):
        storeys = summary_items(self.summary, "storeys")
        piers = [p for p in summary_items(self.summary, "piers")
                 if number(p, "drift_ratio") is not None or number(p, "ductility") is not None]
        storeys = [s for s in storeys if number(s, "drift_ratio") is not None]
        has_ductility = any(number(p, "ductility") is not None for p in piers)
        # 3-D buildings: a panel per drift direction (the summary's "direction", x unless given).
        directions = sorted({str(s.get("direction", "x")) for s in storeys})
        panels = [("storeys", d) for d in directions] + \
                 ([("pier drift", None)] if piers else []) + \
                 ([("pier ductility", None)] if has_ductility else [])
        if not panels:
            return
        fig, axes = self.figure(len(panels), len(panels), 4.6, width=max(6.0, 4.8 * len(panels)))
        for ax, (panel, direction) in zip(axes, panels):
            if panel == "storeys":
                self.storey_profile(
                    ax, [s for s in storeys if str(s.get("direction", "x")) == direction],
                    direction if len(directions) > 1 or direction != "x" else None)
            elif panel == "pier drift":
                self.pier_bars(ax, piers, "drift_ratio", "peak drift ratio [-]", "Pier drift ratio")
            else:
                self.pier_bars(ax, piers, "ductility", "displacement ductility [-]", "Pier ductility")
                ax.axhline(1.0, color="C3", ls="--", lw=1.0, label="yield (ductility 1)")
                ax.legend(loc="best", fontsize="small")
        self.save(fig, "drift_envelopes.png", "Drift envelopes")

    def storey_profile(self, ax, storeys, direction=None):
        """Each building's peak drift ratio over its height; in 3-D (storeys with a
        corner_drift_ratio) its plan corners' largest too, dashed."""
        buildings = {}
        for storey in storeys:
            buildings.setdefault(str(storey.get("building", "")), []).append(storey)
        use_heights = all(number(s, "height") is not None and number(s, "height") > 0 for s in storeys)
        for k, (building, items) in enumerate(buildings.items()):
            if all(number(s, "storey") is not None for s in items):
                items = sorted(items, key=lambda s: number(s, "storey"))
            xs, corners, ys, level = [], [], [], 0.0
            for position, storey in enumerate(items):
                ratio = number(storey, "drift_ratio")
                corner = number(storey, "corner_drift_ratio")
                step = number(storey, "height") if use_heights else 1.0
                xs += [ratio, ratio]
                corners += [math.nan if corner is None else corner] * 2
                ys += [level, level + step]
                level += step
            ax.plot(xs, ys, lw=1.5, color=f"C{k % 10}",
                    label=(building + (" (mass centre)" if direction else "")) or None)
            ax.plot(xs[::2], [(a + b) / 2 for a, b in zip(ys[::2], ys[1::2])], "o", ms=3,
                    color=f"C{k % 10}")
            if any(not math.isnan(c) for c in corners):
                ax.plot(corners, ys, lw=1.2, ls="--", color=f"C{k % 10}",
                        label=f"{building} (largest corner)")
        ax.set_xlim(left=0.0)
        ax.set_ylim(bottom=0.0)
        ax.set_xlabel("peak storey drift ratio [-]")
        ax.set_ylabel(f"height [{self.units['length']}]" if use_heights else "storey")
        ax.set_title("Storey drift ratio envelopes" + (f" along {direction}" if direction else ""),
                     fontsize="medium")
        if any(buildings):
            ax.legend(loc="best", fontsize="small")
        ax.grid(alpha=0.3)

    def pier_bars(self, ax, piers, key, label, title):
        names = [str(p.get("id")) for p in piers]
        values = [number(p, key) for p in piers]
        values = [math.nan if v is None else v for v in values]
        ax.bar(range(len(names)), values, color="C0")
        ax.set_xticks(range(len(names)))
        ax.set_xticklabels(names, rotation=45 if len(names) > 6 else 0,
                           ha="right" if len(names) > 6 else "center")
        ax.set_xlabel("pier")
        ax.set_ylabel(label)
        ax.set_title(title, fontsize="medium")
        ax.grid(alpha=0.3, axis="y")

    # -- energy ---------------------------------------------------------------------------------

    def plot_energy(self, histories):
        np = self.np
        history = next((h for h in histories if "energy" in h.kinds()
                        and all(term in h.values for term in ENERGY_TERMS)), None)
        if history is None:
            return
        t = history.time()
        terms = [history.values[term] for term in ENERGY_TERMS]
        energy = summary_object(self.summary, "energy")
        input_work = history.values.get("input", np.zeros_like(t))
        if "initial" in history.values:
            initial = history.values["initial"]
        elif number(energy, "initial") is not None:
            initial = np.full_like(t, number(energy, "initial"))
        else:  # the energy in the model at the first recorded instant
            initial = np.full_like(t, terms[0][0] + terms[1][0] + terms[2][0] + terms[3][0] - input_work[0])
        supplied = initial + input_work
        stored = terms[0] + terms[1] + terms[2] + terms[3]
        scale = np.maximum.reduce([np.abs(term) for term in terms + [input_work, initial]])
        with np.errstate(divide="ignore", invalid="ignore"):
            relative = np.where(scale > 0.0, np.abs(stored - supplied) / scale, 0.0)

        fig = self.Figure(figsize=(11.0, 7.5))
        top, bottom = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": [2.2, 1.0]})
        top.stackplot(t, *terms, labels=["kinetic", "strain (linear elements)",
                                         "damping (dissipated)", "links (work on links)"], alpha=0.8)
        top.plot(t, supplied, "k--", lw=1.2, label="initial + input")
        top.set_ylabel(f"energy [{self.units['energy']}]")
        top.set_title("Energy components (stacked) against the energy supplied", fontsize="medium")
        top.legend(loc="best", fontsize="small")
        top.grid(alpha=0.3)
        bottom.semilogy(t, np.where(relative > 0.0, relative, np.nan), lw=0.8, color="C3", label="balance error")
        bottom.axhline(0.01, color="0.4", ls="--", lw=1.0, label="warning level (1 %)")
        final = number(energy, "balance_error")
        worst = number(energy, "worst_balance_error")
        title = "Balance error |stored + dissipated - supplied| / largest term"
        if worst is not None or final is not None:
            title += f" (summary: final {fmt(final)}, worst {fmt(worst)})"
        bottom.set_title(title, fontsize="medium")
        bottom.set_xlabel(self.time_label)
        bottom.set_ylabel("balance error [-]")
        bottom.legend(loc="best", fontsize="small")
        bottom.grid(alpha=0.3, which="both")
        self.save(fig, "energy.png", "Energy balance")

    # -- ensemble -------------------------------------------------------------------------------

    def plot_ensemble(self, ensemble):
        limit = ensemble["robust_spread"]
        present = [q for q in ensemble["quantities"]
                   if max(abs(q["min"]), abs(q["max"]), abs(q["unperturbed"])) > 0.0]
        # The least robust first, then, for contrast, robust peak drifts, ductilities and forces.
        loose = sorted((q for q in present if not q["robust"]), key=lambda q: -q["spread"])
        loose = loose[:ENSEMBLE_SHOWN * 2 // 3]
        contrast = ("peak_drift", "ductility", "peak_force")
        robust = sorted((q for q in present if q["robust"]
                         and q["path"].rsplit("/", 1)[-1] in contrast),
                        key=lambda q: contrast.index(q["path"].rsplit("/", 1)[-1]))
        quantities = loose + robust[:ENSEMBLE_SHOWN - len(loose)]
        if not quantities:
            return
        fig = self.Figure(figsize=(11.0, 1.9 + 0.32 * len(quantities)))
        ax = fig.subplots(1, 1)
        for row, q in enumerate(quantities):
            size = max(abs(q["min"]), abs(q["max"]), abs(q["unperturbed"]))
            y = len(quantities) - 1 - row
            ax.plot([q["min"] / size, q["max"] / size], [y, y], color="0.6", lw=1.0)
            ax.plot([q["p16"] / size, q["p84"] / size], [y, y], lw=6.0, solid_capstyle="butt",
                    color="C0" if q["robust"] else "C3", alpha=0.8)
            ax.plot(q["median"] / size, y, "|", color="k", ms=12, mew=2.0)
            ax.plot(q["unperturbed"] / size, y, "o", color="k", mfc="white", ms=5)
        ax.set_yticks(range(len(quantities)))
        ax.set_yticklabels([f"{q['path'].lstrip('/')} ({100 * q['spread']:.0f} %)"
                            for q in reversed(quantities)], fontsize="small")
        for label, q in zip(ax.get_yticklabels(), reversed(quantities)):
            label.set_color("k" if q["robust"] else "C3")
        ax.axvline(0.0, color="0.6", lw=0.5)
        ax.set_xlabel("value / its largest |value| over the runs [-]")
        ax.set_title(f"{ensemble_words(ensemble)}\n"
                     "range (grey), 16–84 % (bar), median (|), unperturbed run (o)\n"
                     f"red: not robust (16–84 % spread above {100 * limit:g} %, or the unperturbed "
                     f"run over {50 * limit:g} % from the median)", fontsize="medium")
        ax.grid(alpha=0.3, axis="x")
        fig.subplots_adjust(left=0.42, right=0.98)
        self.save(fig, "ensemble.png", "Spread of the peaks over the ensemble")

    # -- nodes ----------------------------------------------------------------------------------

    def plot_displacements(self, histories):
        self.plot_node_histories(histories, "u_x", "displacement u_x", "displacements.png",
                                 "Node displacement histories", self.units["length"])

    def plot_accelerations(self, histories):
        self.plot_node_histories(histories, "a_abs_x", "absolute acceleration\na_abs_x",
                                 "accelerations.png",
                                 "Absolute node accelerations (what floor contents feel)",
                                 self.units["acceleration"])

    def plan_nodes(self, histories):
        """[(node, history, {"u_x", "u_y", "u_rz": values})] of every node a history has all
        three of, in file and column order; a node in two files is drawn from the first."""
        nodes = {}
        for history in histories:
            columns = {}
            for name in history.columns[1:]:
                owner, quantity = split_column(name)
                if owner is not None and quantity in ("u_x", "u_y", "u_rz"):
                    columns.setdefault(owner, {})[quantity] = history.values[name]
            for owner, values in columns.items():
                if len(values) == 3 and owner not in nodes:
                    nodes[owner] = (owner, history, values)
        return list(nodes.values())

    def plot_plan_motion(self, histories, in_space):
        """3-D runs: per node a row, its path in plan and its rotation about z."""
        if not in_space:
            return
        for page, items in enumerate(self.pages(self.plan_nodes(histories))):
            fig = self.Figure(figsize=(11.0, 1.2 + 3.6 * len(items)))
            axes = fig.subplots(len(items), 2, squeeze=False,
                                gridspec_kw={"width_ratios": [1.0, 2.1]})
            for (path_ax, turn_ax), (node, history, values) in zip(axes, items):
                self.plan_path(path_ax, node, history.time(), values["u_x"], values["u_y"])
                self.plan_rotation(turn_ax, node, history, values["u_rz"])
            self.save(fig, self.page_name("plan_motion", page),
                      "Plan motion of the recorded nodes (3-D): path in plan and rotation about z")

    def plan_path(self, ax, node, t, ux, uy):
        np = self.np
        length, time = self.units["length"], self.units["time"]
        ax.plot(ux, uy, lw=0.7, color="C0")
        ax.axhline(0.0, color="0.6", lw=0.5)
        ax.axvline(0.0, color="0.6", lw=0.5)
        finite = np.flatnonzero(np.isfinite(ux) & np.isfinite(uy))
        title = f"{node}: path in plan"
        if len(finite):
            first, last = finite[0], finite[-1]
            # a ring round the start, a smaller square at the end: both seen where they meet
            ax.plot(ux[first], uy[first], "o", color="C2", mfc="none", mew=1.8, ms=10, zorder=3,
                    label=f"start (t = {fmt(t[first])} {time})")
            ax.plot(ux[last], uy[last], "s", color="C3", ms=5, zorder=4,
                    label=f"end (t = {fmt(t[last])} {time})")
            peak = float(np.max(np.hypot(ux[finite], uy[finite])))
            title += f"\npeak distance from the origin {fmt(peak)} {length}"
            ax.legend(loc="best", fontsize="x-small", framealpha=0.8)
        ax.set_aspect("equal", adjustable="datalim")
        ax.xaxis.set_major_locator(self.MaxNLocator(4, steps=[1, 2, 5, 10]))
        ax.yaxis.set_major_locator(self.MaxNLocator(5, steps=[1, 2, 5, 10]))
        ax.set_title(title, fontsize="medium")
        ax.set_xlabel(f"u_x [{length}]")
        ax.set_ylabel(f"u_y [{length}]")
        ax.grid(alpha=0.3)

    def plan_rotation(self, ax, node, history, rz):
        np = self.np
        t = history.time()
        ax.plot(t, rz, lw=0.8, color="C1")
        ax.axhline(0.0, color="0.6", lw=0.5)
        finite = np.flatnonzero(np.isfinite(rz))
        if len(finite) and not np.any(rz[finite]):  # a node held in torsion, say
            ax.text(0.5, 0.56, "u_rz = 0 throughout", transform=ax.transAxes, ha="center",
                    va="bottom", fontsize="small", color="0.3")
        elif len(finite):
            at = finite[np.argmax(np.abs(rz[finite]))]
            peak, when = float(rz[at]), float(t[at])
            low, high = float(np.min(rz[finite])), float(np.max(rz[finite]))
            span = max(high - low, abs(peak), 1e-300)
            up = peak >= 0.0
            # room for the label beyond the peak, where no other part of the curve is
            ax.set_ylim(low - (0.08 if up else 0.5) * span, high + (0.5 if up else 0.08) * span)
            ax.plot(when, peak, "o", color="C3", ms=5, zorder=3)
            left = when <= 0.5 * (float(t[0]) + float(t[-1]))
            ax.annotate(f"peak {fmt(peak)} rad at t = {fmt(when)} {self.units['time']}",
                        (when, peak), xytext=(-6 if left else 6, 8 if up else -8),
                        textcoords="offset points", ha="left" if left else "right",
                        va="bottom" if up else "top", fontsize="small", color="C3")
        ax.set_title(f"{node}: rotation about z ({os.path.basename(history.path)})",
                     fontsize="medium")
        ax.set_xlabel(self.time_label)
        ax.set_ylabel("rotation u_rz [rad]")
        ax.grid(alpha=0.3)

    def plot_floor_spectra(self, spectra):
        """One panel per damping ratio: Sa against period of every node and direction."""
        panels = {}
        for path, periods, columns in spectra:
            for name, sa in columns.items():
                parsed = spectrum_column(name)
                if parsed is not None:
                    node, direction, damping = parsed
                    panels.setdefault(damping, []).append((f"{node} {direction}", periods, sa))
        if not panels:
            return
        dampings = sorted(panels, key=lambda d: float(d.rstrip("%")))[:PER_PAGE]
        fig, axes = self.figure(len(dampings), 1, 3.2)
        for ax, damping in zip(axes, dampings):
            curves = panels[damping][:NODES_PER_AXES]
            for label, periods, sa in curves:
                positive = periods > 0.0
                ax.plot(periods[positive], sa[positive], lw=1.2, label=label)
            ax.set_xscale("log")
            ax.set_title(f"{damping} damping", fontsize="medium")
            ax.set_xlabel(f"period T [{self.units['time']}]")
            ax.set_ylabel(f"pseudo-spectral acceleration\nSa [{self.units['acceleration']}]")
            ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize="small")
            ax.grid(alpha=0.3, which="both")
        self.save(fig, "floor_spectra.png",
                  "Floor response spectra of the recorded nodes' absolute accelerations")

    def plot_node_histories(self, histories, quantity, label, file_name, title_text, unit):
        panels = []
        for history in histories:
            nodes = [(split_column(name)[0], name) for name in history.columns[1:]
                     if split_column(name)[1] == quantity and split_column(name)[0] is not None]
            if nodes:
                panels.append((history, nodes))
        if not panels:
            return
        panels = panels[:PER_PAGE]
        fig, axes = self.figure(len(panels), 1, 2.8)
        for ax, (history, nodes) in zip(axes, panels):
            shown = nodes
            if len(nodes) > NODES_PER_AXES:  # evenly spaced, first and last included
                picks = sorted({round(i * (len(nodes) - 1) / (NODES_PER_AXES - 1))
                                for i in range(NODES_PER_AXES)})
                shown = [nodes[i] for i in picks]
            for node, name in shown:
                ax.plot(history.time(), history.values[name], lw=0.9, label=node)
            ax.axhline(0.0, color="0.6", lw=0.5)
            title = os.path.basename(history.path)
            if len(shown) < len(nodes):
                title += f" ({len(shown)} of {len(nodes)} nodes shown)"
            ax.set_title(title, fontsize="medium")
            ax.set_xlabel(self.time_label)
            ax.set_ylabel(f"{label}\n[{unit}]")
            ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize="small")
            ax.grid(alpha=0.3)
        self.save(fig, file_name, title_text)


# ----------------------------------------------------------------------------------------------

def main(argv):
    parser = folder_parser(PROG, __doc__, "the --out folder of `pound run`",
                           epilog="Axes name the units of summary.json, else 'model units'.")
    args = parser.parse_checked(argv)
    figure_class = import_matplotlib(PROG, REEXEC_MARK, __file__)
    import numpy

    def draw():
        summary = load_summary(args.folder)
        histories = read_histories(args.folder, numpy)
        spectra = read_spectra(args.folder, numpy)
        ensemble = load_ensemble(args.folder)  # read (and checked) before any figure is written
        plotter = Plotter(args.folder, summary, args.dpi, figure_class, numpy)
        links = plotter.link_series(histories)
        if links:
            plotter.plot_link_forces(links)
            plotter.plot_force_penetration(links)
        plotter.plot_joint_openings(histories)
        plotter.plot_drift_envelopes()
        plotter.plot_energy(histories)
        plotter.plot_displacements(histories)
        plotter.plot_accelerations(histories)
        plotter.plot_plan_motion(histories, scene_in_space(summary, histories, args.folder))
        plotter.plot_floor_spectra(spectra)
        if ensemble is not None:
            plotter.plot_ensemble(ensemble)
        report = write_report(args.folder, summary, list(plotter.written), ensemble)
        print(report)
        return plotter.written + [report]

    return run_plots(PROG, draw, args.folder, "no time histories to plot")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
