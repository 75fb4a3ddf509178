#!/usr/bin/env python3
"""Plots `pound study rod-impact --out DIR`: force error against run time on log axes.

usage: python3 tools/plot_pareto.py DIR [--dpi 120]

Reads DIR/error_study.csv and writes DIR/error_vs_run_time.png (its path printed): one series per
integrator and contact law, one panel per benchmark case, the Pareto front drawn through. Runs
the study refused (explicit steps above their stable limit) are left out.

Needs matplotlib (Debian: python3-matplotlib, installed by tools/install_dependencies.sh); if
`python3` is one without it (pyenv, a venv), the script starts itself again with /usr/bin/python3
when that one exists.

Exit codes: 0 ok, 1 usage error or matplotlib missing, 2 bad input (no error_study.csv, a
malformed one, no run to plot; the message names the file), 4 the figure could not be written.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_common import (InputError, check_folder, check_width, csv_reader,  # noqa: E402
                         folder_parser, import_matplotlib, not_a_number, read_header, run_plots,
                         save_png)

PROG = "plot_pareto.py"
REEXEC_MARK = "POUND_PLOT_PARETO_REEXEC"
STUDY_FILE = "error_study.csv"
FIGURE_FILE = "error_vs_run_time.png"
COLUMNS = ("case", "integrator", "law", "refused", "force_l2_error", "run_time_s", "pareto")


class Run:
    """One row of error_study.csv that the study did not refuse."""

    def __init__(self, case, method, run_time, error, pareto):
        self.case = case
        self.method = method  # (integrator, law)
        self.run_time = run_time
        self.error = error
        self.pareto = pareto


def read_runs(folder):
    """The runs of DIR/error_study.csv that were not refused."""
    check_folder(folder)
    path = os.path.join(folder, STUDY_FILE)
    if not os.path.isfile(path):
        raise InputError(f"{folder}: no {STUDY_FILE} here (is it the --out folder of "
                         "`pound study rod-impact`?)")
    runs = []
    with csv_reader(path) as reader:
        header = read_header(path, reader, COLUMNS, "(is it written by `pound study rod-impact`?)")
        index = {name: i for i, name in enumerate(header)}
        for row in reader:
            if not row:
                continue
            check_width(path, reader.line_num, row, len(header))
            if row[index["refused"]].strip() != "0":
                continue

            def number(column):
                text = row[index[column]]
                try:
                    return float(text)
                except ValueError:
                    raise not_a_number(path, reader.line_num, column, text) from None

            runs.append(Run(row[index["case"]], (row[index["integrator"]], row[index["law"]]),
                            number("run_time_s"), number("force_l2_error"),
                            row[index["pareto"]].strip() == "1"))
    if not runs:
        raise InputError(f"{path}: no run to plot (every run was refused, or there are none)")
    return runs


def plot(runs, figure_class, path, dpi):
    cases = sorted({run.case for run in runs})
    figure = figure_class(figsize=(6 * len(cases), 5))
    axes = figure.subplots(1, len(cases), squeeze=False)[0]
    for axis, case in zip(axes, cases):
        in_case = [run for run in runs if run.case == case]
        for method in sorted({run.method for run in in_case}):
            points = sorted((run.run_time, run.error) for run in in_case if run.method == method)
            axis.loglog([p[0] for p in points], [p[1] for p in points], "o-", ms=4, lw=0.8,
                        label=f"{method[0]}, {method[1]}")
        front = sorted((run.run_time, run.error) for run in in_case if run.pareto)
        axis.loglog([p[0] for p in front], [p[1] for p in front], "k--", lw=1.5,
                    label="Pareto front")
        axis.set_xlabel("run time of the solve [s]")
        axis.set_ylabel("force_l2_error [-]")
        axis.set_title(f"rod impact, {case}")
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=7)
    save_png(figure, path, dpi)
    print(path)


def main(argv):
    parser = folder_parser(PROG, __doc__, "the --out folder of `pound study rod-impact`")
    args = parser.parse_checked(argv)
    figure_class = import_matplotlib(PROG, REEXEC_MARK, __file__)
    return run_plots(PROG, lambda: plot(read_runs(args.folder), figure_class,
                                        os.path.join(args.folder, FIGURE_FILE), args.dpi))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
