#!/usr/bin/env python3
"""Plots the capacity curve of `pound pushover`.

usage: python3 tools/plot_pushover.py DIR [--dpi 120]

DIR is the --out folder of `pound pushover` (pushover.csv and pushover.json). Written into DIR,
its name printed:
  pushover.png  base shear against the control node's displacement, the first yield of a link
                marked (a dot with the link's name) and the peak base shear (a cross); a second
                panel with every yielding link's |deformation| against the same displacement,
                each over its largest in the push, so that where each hinge or bearing starts
                to take the deformation reads off the curves

Needs matplotlib (Debian: python3-matplotlib, installed by tools/install_dependencies.sh); if
`python3` has none, the script starts itself again with /usr/bin/python3 when that one exists.

Exit codes: 0 ok, 1 usage error or matplotlib missing, 2 bad input (a missing folder or file, a
missing column, a value that is not a number, an empty curve; the message names the file), 4 the
figure could not be written.
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_common import (InputError, check_folder, check_width, csv_reader,  # noqa: E402
                         folder_parser, import_matplotlib, not_a_number, read_header, read_json,
                         run_plots, save_png)

REEXEC_MARK = "POUND_PLOT_PUSHOVER_REEXEC"
PROG = "plot_pushover.py"
CURVE_FILE = "pushover.csv"
SUMMARY_FILE = "pushover.json"
REQUIRED = ("displacement", "base_shear")
DEFORMATION = ".deformation"


def read_curve(folder):
    """{column: [float]} of pushover.csv, every cell checked, at least one row."""
    path = os.path.join(folder, CURVE_FILE)
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file (is the folder the --out of `pound pushover`?)")
    with csv_reader(path) as reader:
        header = read_header(path, reader, REQUIRED, "(is it the pushover.csv of `pound pushover`?)")
        columns = {name: [] for name in header}
        for line, row in enumerate(reader, start=2):
            check_width(path, line, row, len(header))
            for name, text in zip(header, row):
                try:
                    value = float(text)
                except ValueError:
                    raise not_a_number(path, line, name, text) from None
                if not math.isfinite(value):
                    raise not_a_number(path, line, name, text)
                columns[name].append(value)
    if not columns["displacement"]:
        raise InputError(f"{path}: no points (the push stopped before its first increment?)")
    return columns


def read_summary(folder):
    path = os.path.join(folder, SUMMARY_FILE)
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file (is the folder the --out of `pound pushover`?)")
    summary = read_json(path)
    if not isinstance(summary, dict):
        raise InputError(f"{path}: expected a JSON object")
    return summary


def draw_curve(axes, curve, summary):
    axes.plot(curve["displacement"], curve["base_shear"], color="C0", linewidth=1.5)
    first_yield = summary.get("first_yield")
    if isinstance(first_yield, dict):
        axes.plot([first_yield.get("displacement")], [first_yield.get("base_shear")], "o",
                  color="C3", label=f"first yield: {first_yield.get('link')}")
    if "peak_base_shear" in summary:
        axes.plot([summary.get("peak_displacement")], [summary.get("peak_base_shear")], "x",
                  color="k", markersize=8, label="peak base shear")
    axes.set_xlabel(f"displacement of {summary.get('node', 'the control node')} along "
                    f"{summary.get('direction', 'x')}")
    axes.set_ylabel("base shear")
    axes.set_title("Capacity curve" + ("" if summary.get("status") == "completed"
                                       else " (stopped before the target)"))
    axes.grid(True, alpha=0.3)
    if axes.get_legend_handles_labels()[0]:
        axes.legend(fontsize="small")


def draw_links(axes, curve):
    """Each yielding link's |deformation| over its largest one in the push."""
    links = [name for name in curve if name.endswith(DEFORMATION)]
    for name in links:
        largest = max(abs(value) for value in curve[name])
        if largest > 0:
            axes.plot(curve["displacement"], [abs(v) / largest for v in curve[name]],
                      label=name[:-len(DEFORMATION)], linewidth=1)
    axes.set_xlabel("displacement of the control node")
    axes.set_ylabel("|deformation| / its largest")
    axes.set_title("Yielding links")
    axes.grid(True, alpha=0.3)
    if links:
        axes.legend(fontsize="x-small", ncol=2)


def main(argv):
    parser = folder_parser(PROG, __doc__, "the --out folder of `pound pushover`")
    args = parser.parse_checked(argv)
    figure_class = import_matplotlib(PROG, REEXEC_MARK, __file__)

    def draw():
        check_folder(args.folder)
        curve = read_curve(args.folder)
        summary = read_summary(args.folder)
        fig = figure_class(figsize=(11, 4.5))
        draw_curve(fig.add_subplot(1, 2, 1), curve, summary)
        draw_links(fig.add_subplot(1, 2, 2), curve)
        path = os.path.join(args.folder, "pushover.png")
        save_png(fig, path, args.dpi)
        print(path)
        return [path]

    return run_plots(PROG, draw)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
