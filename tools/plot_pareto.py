#!/usr/bin/env python3
"""Plot `pound study rod-impact --out DIR`: force error against run time on log axes, one series
per integrator and contact law, one panel per benchmark case, the Pareto front drawn through.

usage: python3 tools/plot_pareto.py DIR   (writes DIR/error_vs_run_time.png)
"""
import csv
import os
import sys


def main():
    if len(sys.argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 1
    folder = sys.argv[1]
    path = os.path.join(folder, "error_study.csv")
    try:
        import matplotlib
    except ImportError:
        # The pyenv python3 of some machines cannot see Debian's python3-matplotlib.
        if os.path.exists("/usr/bin/python3") and sys.executable != "/usr/bin/python3" and not os.environ.get("POUND_PLOT_REEXEC"):
            os.environ["POUND_PLOT_REEXEC"] = "1"
            os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
        print("error: matplotlib is not available (run tools/install_dependencies.sh)", file=sys.stderr)
        return 1
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    try:
        with open(path, newline="") as handle:
            rows = [row for row in csv.DictReader(handle) if row["refused"] == "0"]
    except (OSError, KeyError, csv.Error) as error:
        print(f"error: {path}: {error}", file=sys.stderr)
        return 2
    cases = sorted({row["case"] for row in rows})
    figure, axes = plt.subplots(1, len(cases), figsize=(6 * len(cases), 5), squeeze=False)
    for axis, case in zip(axes[0], cases):
        runs = [row for row in rows if row["case"] == case]
        for method in sorted({(row["integrator"], row["law"]) for row in runs}):
            points = sorted((float(r["run_time_s"]), float(r["force_l2_error"])) for r in runs
                            if (r["integrator"], r["law"]) == method)
            axis.loglog([p[0] for p in points], [p[1] for p in points], "o-", ms=4, lw=0.8,
                        label=f"{method[0]}, {method[1]}")
        front = sorted((float(r["run_time_s"]), float(r["force_l2_error"])) for r in runs if r["pareto"] == "1")
        axis.loglog([p[0] for p in front], [p[1] for p in front], "k--", lw=1.5, label="Pareto front")
        axis.set_xlabel("run time of the solve [s]")
        axis.set_ylabel("force_l2_error [-]")
        axis.set_title(f"rod impact, {case}")
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=7)
    figure.tight_layout()
    output = os.path.join(folder, "error_vs_run_time.png")
    figure.savefig(output, dpi=120)
    print(output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
