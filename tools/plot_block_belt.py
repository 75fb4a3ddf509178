#!/usr/bin/env python3
"""Plots the block-on-belt study of `pound verify block-belt` like Suzuki & Toi (1987), Figs. 13-16.

usage: python3 tools/plot_block_belt.py DIR [--out OUTDIR] [--speeds a,b,c] [--dpi 120]

DIR is the --out folder of `pound verify block-belt` (block_belt_sweep.csv and
block_belt_histories.csv). Written into OUTDIR (default DIR, created when missing), one line
printed per file:
  fig13_spring_elongation.png  spring elongation over the static elongation mu P / k_s (the
                               spring force over mu P) against time in spring periods, one
                               panel per chosen speed Pi, with the static friction level 1 dotted
  fig14_centroid_x.png         the block centroid's displacement along the belt, the same way
  fig15_centroid_y.png         the centroid's displacement normal to the belt, with its value at
                               t = 0 (the static equilibrium) dotted
  fig16_friction_ratio.png     mu_dynamic / mu_static (mean spring force over mu P in the steady
                               part) against Pi = V0 sqrt(m k_s) / (mu P) on a log axis; the
                               stick-slip points filled squares, the tumbling ones hollow (the
                               ratio means little when the block leaves the belt)
Speeds of Figs. 13-15: --speeds picks values of Pi present in the histories (1e5 matches 100000);
by default all of them when there are five or fewer, otherwise the one nearest (on a log scale)
to each decade, thinned evenly to five keeping the lowest and the highest.

Needs matplotlib (Debian: python3-matplotlib, installed by tools/install_dependencies.sh).
Run it with the interpreter that has it; if `python3` is another one (pyenv, a venv) without
matplotlib, the script starts itself again with /usr/bin/python3 when that one exists.

Exit codes: 0 ok, 1 usage error or matplotlib missing, 2 bad input (a missing folder or file, a
missing column, a value that is not a number, an empty table, a --speeds value with no history;
the message names the file), 4 a figure could not be written. Nothing is written unless every
figure is.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_common import (InputError, OutputError, Parser, check_folder, check_width,  # noqa: E402
                         csv_reader, import_matplotlib, not_a_number, read_header, run_plots,
                         tight_layout)

REEXEC_MARK = "POUND_PLOT_BLOCK_BELT_REEXEC"
PROG = "plot_block_belt.py"

SWEEP_FILE = "block_belt_sweep.csv"
HISTORIES_FILE = "block_belt_histories.csv"
SWEEP_COLUMNS = ("dimensionless_speed", "belt_speed", "friction_ratio", "stick_fraction",
                 "stick_slip_cycles", "stick_slip", "lift_fraction", "tumbling", "peak_lift",
                 "steps", "time_step", "run_time_s")
FLAG_COLUMNS = ("stick_slip", "tumbling")
HISTORY_COLUMNS = ("dimensionless_speed", "time_over_period", "elongation", "centroid_x",
                   "centroid_y")
MAX_DEFAULT_SPEEDS = 5

PI_LABEL = r"$\Pi = V_0\sqrt{m\,k_s}\,/\,(\mu P)$"
STATIC = r"$\mu P / k_s$"
# (file, history column, y label, figure title, where the dotted reference line goes)
HISTORY_FIGURES = (
    ("fig13_spring_elongation.png", "elongation",
     f"spring elongation / ({STATIC})", "Spring elongation (Suzuki & Toi 1987, Fig. 13)", "one"),
    ("fig14_centroid_x.png", "centroid_x",
     f"centroid displacement x / ({STATIC})", "Centroid displacement along the belt (Fig. 14)",
     None),
    ("fig15_centroid_y.png", "centroid_y",
     f"centroid displacement y / ({STATIC})", "Centroid displacement normal to the belt (Fig. 15)",
     "first"),
)
FRICTION_FIGURE = "fig16_friction_ratio.png"


# ----------------------------------------------------------------------------------------------
# Input

def read_table(path, required):
    """The required columns of a numeric CSV file: {column: [float]}, every cell checked."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: {'not a file' if os.path.exists(path) else 'no such file'} "
                         "(is the folder the --out of `pound verify block-belt`?)")
    columns = {name: [] for name in required}
    with csv_reader(path) as reader:
        header = read_header(path, reader, required,
                             "(is it written by `pound verify block-belt`?)")
        index = {name: header.index(name) for name in required}
        width = len(header)
        for row in reader:
            if not row or (len(row) == 1 and not row[0].strip()):
                continue
            line = reader.line_num
            check_width(path, line, row, width)
            for name, i in index.items():
                text = row[i].strip()
                try:
                    value = float(text)
                except ValueError:
                    raise not_a_number(path, line, name, row[i]) from None
                if not math.isfinite(value):
                    raise InputError(f"{path}: line {line}, column '{name}': not a finite "
                                     f"number: {row[i]!r}")
                columns[name].append(value)
    if not columns[required[0]]:
        raise InputError(f"{path}: no data rows (only a header)")
    return columns


class SweepPoint:
    def __init__(self, speed, ratio, stick_slip, tumbling):
        self.speed = speed
        self.ratio = ratio
        self.stick_slip = stick_slip
        self.tumbling = tumbling


def read_sweep(folder):
    path = os.path.join(folder, SWEEP_FILE)
    table = read_table(path, SWEEP_COLUMNS)
    for name in FLAG_COLUMNS:
        for row, value in enumerate(table[name]):
            if value not in (0.0, 1.0):
                raise InputError(f"{path}: data row {row + 1}, column '{name}': {value:g} is "
                                 "neither 0 nor 1")
    points = []
    for row, speed in enumerate(table["dimensionless_speed"]):
        if speed <= 0.0:
            raise InputError(f"{path}: data row {row + 1}, column 'dimensionless_speed': "
                             f"{speed:g} is not positive (Pi is plotted on a log axis)")
        points.append(SweepPoint(speed, table["friction_ratio"][row],
                                 table["stick_slip"][row] == 1.0, table["tumbling"][row] == 1.0))
    points.sort(key=lambda p: p.speed)
    return path, points


def same_speed(a, b):
    return abs(a - b) <= 1e-9 * max(abs(a), abs(b))


def read_histories(folder):
    """The histories file and {speed: {column: [float]}}, speeds in the file's order."""
    path = os.path.join(folder, HISTORIES_FILE)
    table = read_table(path, HISTORY_COLUMNS)
    histories = {}
    for row, speed in enumerate(table["dimensionless_speed"]):
        if speed <= 0.0:
            raise InputError(f"{path}: data row {row + 1}, column 'dimensionless_speed': "
                             f"{speed:g} is not positive")
        key = next((s for s in histories if same_speed(s, speed)), speed)
        history = histories.setdefault(key, {name: [] for name in HISTORY_COLUMNS[1:]})
        for name in HISTORY_COLUMNS[1:]:
            history[name].append(table[name][row])
    return path, histories


def parse_speeds(text):
    """--speeds a,b,c as floats (argparse type: ValueError text becomes the usage message)."""
    values = []
    for item in text.split(","):
        item = item.strip()
        if not item:
            raise argparse.ArgumentTypeError(f"empty value in {text!r}")
        try:
            value = float(item)
        except ValueError:
            raise argparse.ArgumentTypeError(f"not a number: {item!r}") from None
        if not math.isfinite(value) or value <= 0.0:
            raise argparse.ArgumentTypeError(f"not a positive number: {item!r}")
        values.append(value)
    return values


def choose_speeds(present, wanted, path):
    """The speeds to plot: the wanted ones (each must be present) or the default choice."""
    if wanted:
        chosen = []
        for value in wanted:
            match = next((s for s in present if same_speed(s, value)), None)
            if match is None:
                raise InputError(f"{path}: no history for Pi = {value:g} (--speeds); present: "
                                 + ", ".join(f"{s:g}" for s in sorted(present)))
            if match not in chosen:
                chosen.append(match)
        return chosen
    speeds = sorted(present)
    if len(speeds) <= MAX_DEFAULT_SPEEDS:
        return speeds
    logs = [math.log10(s) for s in speeds]
    nearest = []
    for decade in range(math.floor(min(logs)), math.ceil(max(logs)) + 1):
        best = min(range(len(speeds)), key=lambda i: (abs(logs[i] - decade), speeds[i]))
        if best not in nearest:
            nearest.append(best)
    nearest.sort()
    if len(nearest) > MAX_DEFAULT_SPEEDS:
        last = len(nearest) - 1
        picks = sorted({round(k * last / (MAX_DEFAULT_SPEEDS - 1))
                        for k in range(MAX_DEFAULT_SPEEDS)})
        nearest = [nearest[k] for k in picks]
    return [speeds[i] for i in nearest]


# ----------------------------------------------------------------------------------------------
# Figures

class Plotter:
    def __init__(self, out_folder, dpi, figure_class):
        self.out_folder = out_folder
        self.dpi = dpi
        self.Figure = figure_class
        self.figures = []  # (file name, figure), saved together at the end

    def history_figure(self, name, column, ylabel, title, reference, speeds, histories):
        count = len(speeds)
        fig = self.Figure(figsize=(8.5, 1.3 + 1.9 * count))
        axes = fig.subplots(count, 1, sharex=True, squeeze=False)[:, 0]
        for k, (ax, speed) in enumerate(zip(axes, speeds)):
            history = histories[speed]
            ax.plot(history["time_over_period"], history[column], "-", lw=1.1, color=f"C{k % 10}")
            if reference == "one":
                ax.axhline(1.0, color="k", ls=":", lw=1.0)
            elif reference == "first":
                ax.axhline(history[column][0], color="k", ls=":", lw=1.0)
            ax.set_title(f"Pi = {speed:.2e}", fontsize="medium")
            ax.grid(alpha=0.3)
        axes[-1].set_xlabel("time / spring period $2\\pi\\sqrt{m/k_s}$")
        fig.supylabel(ylabel)
        note = {"one": "dotted: 1, the static friction level",
                "first": "dotted: the value at t = 0 (static equilibrium)"}.get(reference)
        fig.suptitle(title + (f"\n{note}" if note else ""), fontsize="large")
        self.figures.append((name, fig))

    def friction_figure(self, points):
        fig = self.Figure(figsize=(8.5, 5.5))
        ax = fig.subplots()
        meaningful = [p for p in points if not p.tumbling]
        if meaningful:
            ax.plot([p.speed for p in meaningful], [p.ratio for p in meaningful], "-", lw=1.0,
                    color="C0", alpha=0.6, zorder=2)

        def draw(selected, marker, colour, hollow, label):
            if not selected:
                return
            ax.plot([p.speed for p in selected], [p.ratio for p in selected], marker, ms=8,
                    color=colour, markerfacecolor="none" if hollow else colour,
                    markeredgewidth=1.6, linestyle="none", label=label, zorder=4)

        draw([p for p in points if not p.stick_slip and not p.tumbling], "o", "C0", False,
             "steady sliding")
        draw([p for p in points if p.stick_slip and not p.tumbling], "s", "C3", False,
             "stick-slip")
        draw([p for p in points if p.tumbling and not p.stick_slip], "o", "C1", True,
             "tumbling (ratio not meaningful)")
        draw([p for p in points if p.tumbling and p.stick_slip], "s", "C1", True,
             "tumbling, stick-slip (ratio not meaningful)")
        ax.axhline(1.0, color="k", ls=":", lw=1.0, label="rigid block (Coulomb): 1")
        # Tumbling ratios can be anything (the spring throws the block): the axis is set by the
        # meaningful points, and tumbling points beyond it are drawn at its top edge.
        top = max([1.2] + [1.1 * p.ratio for p in meaningful])
        bottom = min([0.0] + [1.1 * p.ratio for p in meaningful])
        ax.set_ylim(bottom, top)
        beyond = [p for p in points if p.tumbling and not bottom <= p.ratio <= top]
        if beyond:
            ax.plot([p.speed for p in beyond], [0.98 * top] * len(beyond), "^", ms=8, color="C1",
                    markerfacecolor="none", markeredgewidth=1.6, linestyle="none",
                    label=f"tumbling, ratio beyond {top:.2g} (off the axis)", zorder=5)
        ax.set_xscale("log")
        ax.set_xlabel(PI_LABEL)
        ax.set_ylabel(r"$\mu_{dynamic} / \mu_{static}$ (mean spring force / $\mu P$)")
        ax.set_title("Dynamic over static friction (Suzuki & Toi 1987, Fig. 16)", fontsize="large")
        ax.grid(alpha=0.3, which="both")
        ax.legend(loc="best", fontsize="small", framealpha=0.9)
        self.figures.append((FRICTION_FIGURE, fig))

    def save_all(self):
        """Every figure to a temporary file, then all moved into place: all of them or none."""
        try:
            os.makedirs(self.out_folder, exist_ok=True)
        except OSError as error:
            raise OutputError(f"{self.out_folder}: cannot create the folder: {error}") from None
        if not os.path.isdir(self.out_folder):
            raise OutputError(f"{self.out_folder}: not a folder")
        temporaries = []
        try:
            for name, fig in self.figures:
                tight_layout(fig)
                path = os.path.join(self.out_folder, name)
                temporary = f"{path}.tmp.{os.getpid()}"
                temporaries.append((temporary, path))
                try:
                    fig.savefig(temporary, format="png", dpi=self.dpi)
                except (OSError, ValueError) as error:
                    raise OutputError(f"{path}: cannot write: {error}") from None
            for temporary, path in temporaries:
                try:
                    os.replace(temporary, path)
                except OSError as error:
                    raise OutputError(f"{path}: cannot write: {error}") from None
        finally:
            for temporary, _ in temporaries:
                try:
                    os.remove(temporary)
                except OSError:
                    pass
        for _, path in temporaries:
            print(path)


# ----------------------------------------------------------------------------------------------

def main(argv):
    parser = Parser(prog=PROG, description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", metavar="DIR", help="the --out folder of `pound verify block-belt`")
    parser.add_argument("--out", metavar="OUTDIR", help="folder for the PNGs (default DIR)")
    parser.add_argument("--speeds", metavar="a,b,c", type=parse_speeds,
                        help="values of Pi to plot in Figs. 13-15 (default: up to five, one per "
                             "decade)")
    parser.add_dpi()
    args = parser.parse_checked(argv)
    figure_class = import_matplotlib(PROG, REEXEC_MARK, __file__)

    def draw():
        folder = args.folder
        check_folder(folder)
        _, points = read_sweep(folder)
        histories_path, histories = read_histories(folder)
        speeds = choose_speeds(list(histories), args.speeds, histories_path)
        plotter = Plotter(args.out if args.out is not None else folder, args.dpi, figure_class)
        for name, column, ylabel, title, reference in HISTORY_FIGURES:
            plotter.history_figure(name, column, ylabel, title, reference, speeds, histories)
        plotter.friction_figure(points)
        plotter.save_all()

    return run_plots(PROG, draw)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
