#!/usr/bin/env python3
"""Plots the results of `pound batch` (IDA curves and fragility) as PNG figures next to them.

usage: python3 tools/plot_batch.py DIR [--dpi 120] [--quantity NAME ...]

DIR is the --out folder of `pound batch` (batch_summary.csv and batch_stats.json). Written into
DIR, each when its data is there (one line printed per file):
  ida_<quantity>.png  incremental dynamic analysis curves: one line per model and record through
                      its scales, the response on the horizontal axis and the intensity measure
                      [g] on the vertical one, with the median and 84th percentile of every scale
                      whose cases share one intensity (batch_stats.json) and the set's limit on
                      that quantity, dashed
  fragility.png       the cases pound's fit took, each at its intensity (1: exceeded, 0: not;
                      failed cases that had passed the limit count as exceeding, as in the fit),
                      the fraction exceeding at every scale whose cases share one intensity, and
                      the fitted lognormal fragility curve; the fits pound could not make are
                      listed with their reason
Quantities are the ones batch_stats.json lists under "quantities", with their axis labels
(pound's own table: impacts, peak forces, joint openings, drifts, ...): by default every response
among them that a completed case reports, leaving out checks of the analysis such as
energy_balance_error; --quantity names the ones to draw. One panel per model. Failed cases (but
in the fragility as above) and input errors are left out and counted on the figures. Units are
the model's own (named where every model gives them alike), intensities in g.

Needs matplotlib (Debian: python3-matplotlib, installed by tools/install_dependencies.sh).
Run it with the interpreter that has it; if `python3` is another one (pyenv, a venv) without
matplotlib, the script starts itself again with /usr/bin/python3 when that one exists.

Exit codes: 0 ok, 1 usage error or matplotlib missing, 2 bad input (no batch_summary.csv, a
malformed CSV or batch_stats.json; message names the file), 4 a figure could not be written.
"""

import difflib
import json
import math
import os
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_common import (InputError, check_folder, check_width, csv_reader,  # noqa: E402
                         folder_parser, import_matplotlib, not_a_number, read_header, read_json,
                         run_plots, save_png)

PROG = "plot_batch.py"
REEXEC_MARK = "POUND_PLOT_BATCH_REEXEC"

SUMMARY_FILE = "batch_summary.csv"
STATS_FILE = "batch_stats.json"
# Intensities of one scale's cases within this fraction of each other make a stripe (a level of
# multiple-stripe analysis); past it (records scaled to one PGA, measured by Sa) they do not.
STRIPE_SPREAD = 0.05
STATUSES = ("completed", "failed", "input_error")
REQUIRED_COLUMNS = ("name", "model", "record", "scale", "status", "intensity")

MARKERS = "osD^vP"   # observed fractions, one per model
PER_PAGE = 8        # fragility panels per page
MODELS_PER_ROW = 3  # IDA panels side by side
LEGEND_RECORDS = 12  # more records than this: one legend entry for all of them


# ----------------------------------------------------------------------------------------------
# Input

def parse_number(text):
    """A CSV cell as a float; None when empty; ValueError when not a number."""
    text = text.strip()
    if not text:
        return None
    value = float(text)
    return value if math.isfinite(value) else None


class Case:
    """One row of batch_summary.csv: the fields the figures use."""

    def __init__(self, model, record, scale, status, intensity, values, name=""):
        self.name = name  # its folder under the batch's output
        self.model = model
        self.record = record
        self.scale = scale
        self.status = status
        self.intensity = intensity
        self.values = values  # {quantity: float or None}


def read_summary(folder, known_quantities):
    """The cases of DIR/batch_summary.csv and those of the known quantities its header has."""
    path = os.path.join(folder, SUMMARY_FILE)
    if not os.path.isfile(path):
        raise InputError(f"{folder}: no {SUMMARY_FILE} here (is it the --out folder of `pound batch`?)")
    cases = []
    with csv_reader(path) as reader:
        header = read_header(path, reader, REQUIRED_COLUMNS, "(is it a `pound batch` summary?)")
        index = {name: i for i, name in enumerate(header)}
        quantities = [q for q in known_quantities if q in index]
        width = len(header)
        for row in reader:
            if not row:
                continue
            line = reader.line_num
            check_width(path, line, row, width)
            status = row[index["status"]].strip()
            if status not in STATUSES:
                raise InputError(f"{path}: line {line}, column 'status': {status!r} is not one "
                                 f"of {', '.join(STATUSES)}")

            def cell(column):
                try:
                    return parse_number(row[index[column]])
                except ValueError:
                    raise not_a_number(path, line, column, row[index[column]]) from None

            scale = cell("scale")
            if scale is None:
                raise InputError(f"{path}: line {line}, column 'scale': empty")
            cases.append(Case(row[index["model"]].strip(), row[index["record"]].strip(), scale,
                              status, cell("intensity"), {q: cell(q) for q in quantities},
                              row[index["name"]].strip()))
    return path, cases, quantities


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


class Stats:
    """batch_stats.json, checked: the parts the figures use."""

    def __init__(self, path=None):
        self.path = path
        self.set_name = ""
        self.im_type = "pga"
        self.period = None
        self.damping = None
        self.groups = []      # [{"model", "scale", "responses": {q: {"median", "p84"}}, "limits"}]
        self.fragility = []   # [{"model", "quantity", "limit", "fitted", "median", "dispersion", "reason"}]
        self.counts = {}      # cases, completed, failed, input_errors (when given)
        self.quantities = {}  # {name: {"axis_label", "response"}}, in pound's order

    def label(self, quantity):
        """The axis label of a quantity ("name [?]" for one pound did not describe)."""
        return self.quantities.get(quantity, {}).get("axis_label", f"{quantity} [?]")


def read_stats(folder):
    """DIR/batch_stats.json (a Stats without groups when the file is absent)."""
    path = os.path.join(folder, STATS_FILE)
    if not os.path.isfile(path):
        sys.stderr.write(f"note: {folder}: no {STATS_FILE}, which lists the quantities: no "
                         "figures (`pound batch SET --out DIR --resume` writes it again)\n")
        return Stats()
    try:
        document = read_json(path)
    except RecursionError:
        raise InputError(f"{path}: not valid JSON: nested too deeply") from None

    def bad(where, what):
        return InputError(f"{path}: {where} {what}")

    def obj(value, where):
        if not isinstance(value, dict):
            raise bad(where, "must be an object")
        return value

    def items(parent, key, where):
        value = parent.get(key)
        if value is None:
            return []
        if not isinstance(value, list) or not all(isinstance(item, dict) for item in value):
            raise bad(where, "must be a list of objects")
        return value

    def num(parent, key, where, required=True):
        value = parent.get(key)
        if value is None and not required:
            return None
        if not is_number(value):
            raise bad(f"{where}.{key}", "must be a number")
        return float(value)

    def text(parent, key, where, required=True):
        value = parent.get(key)
        if value is None and not required:
            return ""
        if not isinstance(value, str):
            raise bad(f"{where}.{key}", "must be a string")
        return value

    def flag(parent, key, where):
        value = parent.get(key)
        if not isinstance(value, bool):
            raise bad(f"{where}.{key}", "must be true or false")
        return value

    stats = Stats(path)
    top = obj(document, "the top level")
    stats.set_name = text(top, "set", '"set"', required=False)
    for key in ("cases", "completed", "failed", "input_errors"):
        value = num(top, key, "", required=False)
        if value is not None:
            stats.counts[key] = int(value)
    measure = top.get("intensity_measure")
    if measure is not None:
        measure = obj(measure, '"intensity_measure"')
        stats.im_type = text(measure, "type", "intensity_measure", required=False) or "pga"
        stats.period = num(measure, "period", "intensity_measure", required=False)
        stats.damping = num(measure, "damping", "intensity_measure", required=False)
    quantities = top.get("quantities")
    if quantities is None:
        sys.stderr.write(f"note: {path}: no \"quantities\" (written by an older pound?): no IDA "
                         "figures (`pound batch SET --out DIR --resume` writes it again)\n")
    for quantity, entry in obj({} if quantities is None else quantities, '"quantities"').items():
        at = f"quantities.{quantity}"
        entry = obj(entry, at)
        stats.quantities[quantity] = {"axis_label": text(entry, "axis_label", at),
                                      "response": flag(entry, "response", at),
                                      # older files: every limited quantity was a running peak but
                                      # the residual drift
                                      "running_peak": entry.get("running_peak") is not False}
    for i, group in enumerate(items(top, "groups", '"groups"')):
        where = f"groups[{i}]"
        entry = {"model": text(group, "model", where), "scale": num(group, "scale", where),
                 "responses": {}, "limits": {}}
        responses = group.get("responses")
        for quantity, response in obj({} if responses is None else responses, f"{where}.responses").items():
            at = f"{where}.responses.{quantity}"
            response = obj(response, at)
            entry["responses"][quantity] = {"median": num(response, "median", at, required=False),
                                            "p84": num(response, "p84", at, required=False)}
        exceedance = group.get("exceedance")
        for quantity, limit in obj({} if exceedance is None else exceedance, f"{where}.exceedance").items():
            at = f"{where}.exceedance.{quantity}"
            entry["limits"][quantity] = num(obj(limit, at), "limit", at)
        stats.groups.append(entry)
    for i, fit in enumerate(items(top, "fragility", '"fragility"')):
        where = f"fragility[{i}]"
        fitted = fit.get("fitted", False)
        if not isinstance(fitted, bool):
            raise bad(f"{where}.fitted", "must be true or false")
        entry = {"model": text(fit, "model", where), "quantity": text(fit, "quantity", where),
                 "limit": num(fit, "limit", where), "fitted": fitted,
                 "reason": text(fit, "reason", where, required=False)}
        if fitted:
            entry["median"] = num(fit, "median", where)
            entry["dispersion"] = num(fit, "dispersion", where)
            if entry["median"] <= 0.0 or entry["dispersion"] <= 0.0:
                raise bad(where, "fitted with a median or dispersion that is not positive")
        stats.fragility.append(entry)
    return stats


# ----------------------------------------------------------------------------------------------
# Figures

def fmt(value):
    return "n/a" if value is None else f"{value:.4g}"


def same_scale(a, b):
    return abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b))


def mean(values):
    return sum(values) / len(values)


def median(values):
    values = sorted(values)
    middle = len(values) // 2
    return values[middle] if len(values) % 2 else 0.5 * (values[middle - 1] + values[middle])


def one_intensity(values):
    """Whether these intensities make one stripe: some, within STRIPE_SPREAD of each other."""
    return bool(values) and max(values) <= (1.0 + STRIPE_SPREAD) * min(values)


def plural(count, word):
    return f"{count} {word}{'' if count == 1 else 's'}"


class Plotter:
    def __init__(self, folder, cases, stats, dpi, figure_class, numpy):
        self.folder = folder
        self.cases = cases
        self.stats = stats
        self.dpi = dpi
        self.Figure = figure_class
        self.np = numpy
        self.completed = [c for c in cases if c.status == "completed"]
        self.models = list(dict.fromkeys(c.model for c in cases))
        records = list(dict.fromkeys(c.record for c in cases))
        self.record_colour = {r: f"C{k % 10}" if len(records) <= 10 else
                              self.colormap(k, len(records)) for k, r in enumerate(records)}
        name = stats.set_name or os.path.basename(os.path.abspath(folder))
        self.set_name = os.path.splitext(os.path.basename(name))[0] if name else "batch"
        self.written = []
        self.units = self.shared_units()

    def shared_units(self):
        """The units every model of the set gives its numbers in (summary.json's "units" of a
        completed case of each), or None where they differ or cannot be read: then the axes say
        "model ... units"."""
        found = {}
        for c in self.completed:
            if c.model in found:
                continue
            try:
                with open(os.path.join(self.folder, c.name, "summary.json"), encoding="utf-8") as f:
                    units = json.load(f).get("units")
            except (OSError, ValueError, AttributeError):
                return None
            if not isinstance(units, dict):
                return None
            found[c.model] = units
        values = list(found.values())
        return values[0] if values and all(v == values[0] for v in values) else None

    def label(self, quantity):
        """The quantity's axis label, its "[model force units]" and the like named where every
        model gives them in the same units."""
        label = self.stats.label(quantity)
        if self.units:
            for dimension in ("force", "length", "acceleration"):
                unit = self.units.get(dimension)
                if isinstance(unit, str) and unit and not unit.startswith("the model"):
                    label = label.replace(f"[model {dimension} units]", f"[{unit}]")
        return label

    @staticmethod
    def colormap(k, count):
        from matplotlib import colormaps
        return colormaps["turbo"](0.05 + 0.9 * k / max(1, count - 1))

    # -- labels ---------------------------------------------------------------------------------

    def im_label(self):
        if self.stats.im_type == "sa":
            details = []
            if self.stats.period is not None:
                details.append(f"T = {self.stats.period:g} s")
            if self.stats.damping is not None:
                details.append(f"{100.0 * self.stats.damping:g} % damping")
            return f"Sa({', '.join(details)}) [g]" if details else "Sa [g]"
        if self.stats.im_type == "pga":
            return "PGA [g]"
        return f"{self.stats.im_type} [g]"

    def left_out_note(self, cases):
        """'16 cases, 14 completed; 1 failed, 1 input error left out' for these cases."""
        failed = sum(c.status == "failed" for c in cases)
        errors = sum(c.status == "input_error" for c in cases)
        note = f"{plural(len(cases), 'case')}"
        if failed or errors:
            parts = ([f"{failed} failed"] if failed else []) + \
                    ([plural(errors, 'input error')] if errors else [])
            note += f", {len(cases) - failed - errors} completed; {' and '.join(parts)} left out"
        else:
            note += ", all completed"
        return note

    def limit(self, model, quantity):
        """The set's limit on a quantity (None: the set has none). Limits are the set's, the same
        for every model: one given for another model is taken when this one has none."""
        found = None
        for entry in self.stats.fragility:
            if entry["quantity"] == quantity and (found is None or entry["model"] == model):
                found = entry["limit"]
        for group in self.stats.groups:
            if quantity in group["limits"] and (found is None or group["model"] == model):
                found = group["limits"][quantity]
        return found

    # -- saving ---------------------------------------------------------------------------------

    def save(self, fig, name):
        path = os.path.join(self.folder, name)
        save_png(fig, path, self.dpi)
        print(path)
        self.written.append(path)

    def panels(self, count, row_height, column_width, max_columns):
        columns = min(count, max_columns)
        rows = math.ceil(count / columns)
        fig = self.Figure(figsize=(max(7.5, column_width * columns), 1.4 + row_height * rows))
        axes = fig.subplots(rows, columns, squeeze=False).ravel()
        for ax in axes[count:]:
            ax.set_visible(False)
        return fig, axes[:count]

    # -- IDA curves -----------------------------------------------------------------------------

    def stripe_intensity(self, model, scale):
        """Median intensity of the completed cases of a model at a scale (None: none known, or
        the cases' intensities differ by more than STRIPE_SPREAD: records scaled to one PGA and
        measured by Sa at a period, whose scale is no intensity level, and whose statistics at
        "the" intensity would mix levels)."""
        values = [c.intensity for c in self.completed
                  if c.model == model and same_scale(c.scale, scale) and c.intensity is not None]
        return median(values) if one_intensity(values) else None

    def plot_ida(self, quantity):
        models = [m for m in self.models if any(c.model == m and c.values.get(quantity) is not None
                                                and c.intensity is not None for c in self.completed)]
        if not models:
            return False
        fig, axes = self.panels(len(models), 5.6, 6.4 if len(models) > 1 else 9.5, MODELS_PER_ROW)
        for ax in axes[1:]:
            ax.sharey(axes[0])
        for ax, model in zip(axes, models):
            self.ida_panel(ax, model, quantity, len(models) > 1)
        fig.suptitle(f"Incremental dynamic analysis, {quantity}: {self.set_name}\n"
                     f"{self.left_out_note(self.cases)}", fontsize="large")
        self.save(fig, f"ida_{quantity}.png")
        return True

    def ida_panel(self, ax, model, quantity, several_models):
        cases = [c for c in self.completed if c.model == model
                 and c.values.get(quantity) is not None and c.intensity is not None]
        records = list(dict.fromkeys(c.record for c in cases))
        label_records = len(records) <= LEGEND_RECORDS
        for k, record in enumerate(records):
            points = sorted(((c.intensity, c.values[quantity]) for c in cases if c.record == record),
                            key=lambda point: point[0])
            ax.plot([x for _, x in points], [y for y, _ in points], "-o", ms=3.5, lw=1.0,
                    alpha=0.85, color=self.record_colour[record],
                    label=record if label_records else (f"{len(records)} records" if k == 0 else None))

        groups = sorted((g for g in self.stats.groups if g["model"] == model), key=lambda g: g["scale"])
        for key, style, label in (("median", "-", "median of each scale"),
                                  ("p84", "--", "84th percentile of each scale")):
            xs, ys = [], []
            for group in groups:
                value = group["responses"].get(quantity, {}).get(key)
                intensity = self.stripe_intensity(model, group["scale"])
                if value is not None and intensity is not None:
                    xs.append(value)
                    ys.append(intensity)
            if xs:
                ax.plot(xs, ys, style, color="k", lw=2.2, marker="s", ms=5, label=label, zorder=5)
        if groups and not any(self.stripe_intensity(model, g["scale"]) for g in groups):
            ax.plot([], [], " ", label="no stripe statistics: the intensities differ within each "
                                       "scale")

        limit = self.limit(model, quantity)
        if limit is not None:
            ax.axvline(limit, color="C3", ls="--", lw=1.4, label=f"limit {limit:.4g}", zorder=4)

        ax.set_xlim(left=0.0)
        ax.set_ylim(bottom=0.0)
        ax.set_xlabel(self.label(quantity))
        ax.set_ylabel(f"intensity: {self.im_label()}")
        model_cases = [c for c in self.cases if c.model == model]
        title = f"{model}: {plural(len(records), 'record')}"
        if several_models:
            title += f"\n{self.left_out_note(model_cases)}"
        ax.set_title(title, fontsize="medium")
        ax.grid(alpha=0.3)
        if several_models:  # panels side by side: the legend inside, where it hides least
            ax.legend(loc="best", fontsize="small", framealpha=0.9)
        else:
            ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small")

    # -- fragility ------------------------------------------------------------------------------

    def observations(self, model, quantity, limit):
        """[(scale, intensity, exceeded)]: the cases pound's fit takes, each at its own intensity.
        The completed cases that report the quantity, and the failed ones whose running peak had
        passed the limit before they stopped (as exceeding; docs/batch_format.md)."""
        running_peak = self.stats.quantities.get(quantity, {}).get("running_peak", True)
        found = []
        for c in self.cases:
            value = c.values.get(quantity)
            if c.model != model or value is None or c.intensity is None or not c.intensity > 0.0:
                continue
            if c.status == "completed":
                found.append((c.scale, c.intensity, value > limit))
            elif c.status == "failed" and running_peak and value > limit:
                found.append((c.scale, c.intensity, True))
        return found

    def observed_fractions(self, model, quantity, limit):
        """[(mean intensity, exceeded, count)] per scale of a model whose cases share one
        intensity (within STRIPE_SPREAD); a scale whose intensities differ has no fraction."""
        stripes = {}
        for scale, intensity, exceeded in self.observations(model, quantity, limit):
            key = next((s for s in stripes if same_scale(s, scale)), scale)
            stripes.setdefault(key, []).append((intensity, exceeded))
        return [(mean([i for i, _ in items]), sum(e for _, e in items), len(items))
                for _, items in sorted(stripes.items()) if one_intensity([i for i, _ in items])]

    def plot_fragility(self):
        entries = self.stats.fragility
        if not entries:
            return
        quantities = list(dict.fromkeys((e["quantity"], e["limit"]) for e in entries))
        pages = [quantities[i:i + PER_PAGE] for i in range(0, len(quantities), PER_PAGE)]
        for page, keys in enumerate(pages):
            self.fragility_page(keys, [e for e in entries if (e["quantity"], e["limit"]) in keys],
                                "fragility.png" if page == 0 else f"fragility_{page + 1}.png")

    def fragility_page(self, keys, entries, name):
        notes = []
        for e in entries:
            note = self.fragility_note(e)
            if note:
                notes += textwrap.wrap(f"{e['model']}, {e['quantity']} > {e['limit']:.4g}: {note}",
                                       125, subsequent_indent="    ")
        columns = min(len(keys), 2)
        rows = math.ceil(len(keys) / columns)
        note_height = 0.2 + 0.16 * len(notes) if notes else 0.0
        fig = self.Figure(figsize=(7.0 * columns if columns > 1 else 9.5,
                                   1.2 + 4.6 * rows + note_height))
        grid = fig.add_gridspec(rows + (1 if notes else 0), columns,
                                height_ratios=[4.6] * rows + ([note_height] if notes else []))
        several_models = len({e["model"] for e in entries}) > 1
        for k, key in enumerate(keys):
            ax = fig.add_subplot(grid[k // columns, k % columns])
            self.fragility_panel(ax, key, [e for e in entries if (e["quantity"], e["limit"]) == key],
                                 several_models)
        if notes:
            note = fig.add_subplot(grid[rows, :])
            note.axis("off")
            note.text(0.0, 1.0, "\n".join(notes), va="top", ha="left", fontsize="small",
                      transform=note.transAxes)
        fig.suptitle(f"Fragility (lognormal, maximum likelihood): {self.set_name}\n"
                     f"{self.left_out_note(self.cases)}", fontsize="large")
        self.save(fig, name)

    def fragility_note(self, entry):
        """Why an entry has no curve, or a warning when its median lies outside the data."""
        if not entry["fitted"]:
            return f"not fitted: {entry['reason'] or 'no reason given'}"
        cases = self.observations(entry["model"], entry["quantity"], entry["limit"])
        if not cases:
            return ""
        low, high = min(x for _, x, _ in cases), max(x for _, x, _ in cases)
        counts = f"{sum(e for _, _, e in cases)} of {len(cases)} cases exceed"
        if entry["median"] < low:
            return (f"fitted median {entry['median']:.3g} g is below the lowest intensity {low:.3g} g "
                    f"({counts}): an extrapolation, poorly constrained by the data")
        if entry["median"] > high:
            return (f"fitted median {entry['median']:.3g} g is above the highest intensity {high:.3g} g "
                    f"({counts}): an extrapolation, poorly constrained by the data")
        return ""

    def fragility_panel(self, ax, key, entries, several_models):
        np = self.np
        quantity, limit = key
        observed = [self.observed_fractions(e["model"], quantity, limit) for e in entries]
        cases = [self.observations(e["model"], quantity, limit) for e in entries]
        highest = max((x for found in cases for _, x, _ in found), default=0.0)
        top = 1.15 * highest if highest > 0.0 else 1.0
        for entry in entries:  # show the fitted median when it is not far beyond the data
            if entry["fitted"] and top < entry["median"] < 5.0 * top:
                top = 1.3 * entry["median"]
        for m, (entry, stripes, found) in enumerate(zip(entries, observed, cases)):
            colour = f"C{m % 10}"
            prefix = f"{entry['model']}: " if several_models else ""
            if found:  # every case the fit takes, at its own intensity: 1 exceeded, 0 not
                offset = 0.012 * (m - 0.5 * (len(entries) - 1))
                ax.plot([x for _, x, _ in found], [(1.0 if e else 0.0) + offset for _, _, e in found],
                        "|", ms=9, mew=1.2, color=colour, alpha=0.6, zorder=4,
                        label=f"{prefix}cases of the fit (1: exceeded, 0: not)")
            if stripes:
                ax.plot([x for x, _, _ in stripes], [e / n for _, e, n in stripes],
                        MARKERS[m % len(MARKERS)], ms=7, color=colour, alpha=0.85, zorder=5,
                        label=f"{prefix}fraction exceeding at a scale")
                for x, exceeded, count in stripes:
                    ax.annotate(f"{exceeded}/{count}", (x, exceeded / count), fontsize="small",
                                xytext=(5, -12 if exceeded > 0.5 * count else 6),
                                textcoords="offset points", color=colour)
            if entry["fitted"]:
                x = np.geomspace(top * 1e-4, top, 400)
                p = normal_cdf(np.log(x / entry["median"]) / entry["dispersion"], np)
                ax.plot(np.concatenate([[0.0], x]), np.concatenate([[0.0], p]), "-", color=colour,
                        lw=1.8, label=f"{prefix}lognormal fit: median {entry['median']:.3g} g, "
                                      f"dispersion {entry['dispersion']:.3g}")
            else:
                ax.plot([], [], " ", label=f"{prefix}no fit (see the note below)")
        ax.set_xlim(0.0, top)
        ax.set_ylim(-0.03, 1.05)
        ax.set_xlabel(f"intensity: {self.im_label()}")
        ax.set_ylabel("probability of exceeding the limit [-]")
        ax.set_title(f"{self.label(quantity).split(' [')[0]} > {limit:.4g}",
                     fontsize="medium")
        ax.grid(alpha=0.3)
        ax.legend(loc="lower right", fontsize="small", framealpha=0.9)


def normal_cdf(z, np):
    """Standard normal CDF of an array (math.erf element by element: no scipy needed)."""
    erf = np.frompyfunc(math.erf, 1, 1)
    return 0.5 * (1.0 + erf(z / math.sqrt(2.0)).astype(float))


# ----------------------------------------------------------------------------------------------

def wanted_quantities(parser, names, stats):
    """The quantities to draw: those named (each one batch_stats.json lists), or its responses."""
    known = stats.quantities
    if not names:
        return [q for q, entry in known.items() if entry["response"]]
    for name in names:
        if known and name not in known:
            close = difflib.get_close_matches(name, known, n=1)
            parser.error(f"--quantity: unknown quantity {name!r}"
                         + (f" (did you mean {close[0]}?)" if close else "")
                         + f"; one of {', '.join(known)}")
    return list(dict.fromkeys(names))


def main(argv):
    parser = folder_parser(PROG, __doc__, "the --out folder of `pound batch`",
                           epilog="Units on the axes are the model's own, intensities in g.")
    parser.add_argument("--quantity", metavar="NAME", nargs="+", action="extend",
                        help="plot the IDA curves of these quantities only (default: every "
                             "response quantity batch_stats.json lists)")
    args = parser.parse_checked(argv)
    figure_class = import_matplotlib(PROG, REEXEC_MARK, __file__)
    import numpy

    def draw():
        check_folder(args.folder)
        stats = read_stats(args.folder)
        path, cases, columns = read_summary(args.folder, stats.quantities)
        wanted = wanted_quantities(parser, args.quantity, stats)
        plotter = Plotter(args.folder, cases, stats, args.dpi, figure_class, numpy)
        for quantity in wanted:
            if quantity not in columns:
                if args.quantity:
                    sys.stderr.write(f"note: {path}: no column {quantity}: ida_{quantity}.png "
                                     "not drawn\n")
            elif not plotter.plot_ida(quantity) and args.quantity:
                sys.stderr.write(f"note: {path}: no completed case reports {quantity}: "
                                 f"ida_{quantity}.png not drawn\n")
        plotter.plot_fragility()
        return plotter.written

    return run_plots(PROG, draw, args.folder, "no completed cases to plot")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
