"""Incremental dynamic analysis of the bundled three-span bridge with pound.batch, and the
fragility of its joints: the probability that the pounding force exceeds a limit, against the
peak ground acceleration, as a lognormal curve fitted by maximum likelihood (pound's batch
statistics fit it; the points are the fraction of records exceeding at each level).

    PYTHONPATH=build/python python3 examples/python/ida_fragility.py --out out/ida
"""

import argparse
import csv
import json
import math
import os
import pathlib
import shutil

import numpy as np

import pound

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def ida_set(scales, limit):
    """The bridge under the bundled records, each scaled to PGA 0.3 g, then times `scales`."""
    return {
        "title": "three-span bridge IDA, bundled records",
        "models": [str(REPOSITORY / "models" / "three_span_bridge.json")],
        "records": [{"folder": str(REPOSITORY / "ground_motions"), "pattern": "synthetic_*.AT2",
                     "units": "g", "scale": {"pga": 0.3}}],
        "scales": scales,
        "intensity_measure": {"type": "pga"},
        "limits": {"max_pounding_force": limit},
        "histories": False,
    }


def lognormal_cdf(x, median, dispersion):
    return 0.5 * (1 + math.erf(math.log(x / median) / (dispersion * math.sqrt(2))))


def plot(rows, fit, limit, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    levels = sorted({float(r["intensity"]) for r in rows if r["status"] == "completed"})
    exceeded = [np.mean([float(r["max_pounding_force"]) > limit for r in rows
                         if r["status"] == "completed" and float(r["intensity"]) == level])
                for level in levels]
    figure, (ida_axes, fragility_axes) = plt.subplots(1, 2, figsize=(10, 4))
    for record in sorted({r["record"] for r in rows}):
        points = sorted((float(r["intensity"]), float(r["max_pounding_force"]) / 1e6)
                        for r in rows if r["record"] == record and r["status"] == "completed")
        ida_axes.plot([p[1] for p in points], [p[0] for p in points], "o-", label=record)
    ida_axes.axvline(limit / 1e6, color="k", ls="--", lw=1, label="limit")
    ida_axes.set(xlabel="peak pounding force [MN]", ylabel="PGA [g]", title="IDA curves")
    ida_axes.legend(fontsize=8)
    fragility_axes.plot(levels, exceeded, "ko", label="fraction of records exceeding")
    if fit and fit["fitted"]:
        grid = np.linspace(min(levels) / 2, max(levels) * 1.5, 200)
        fragility_axes.plot(grid, [lognormal_cdf(x, fit["median"], fit["dispersion"])
                                   for x in grid],
                            label=f"lognormal: median {fit['median']:.3g} g, "
                                  f"beta {fit['dispersion']:.2f}")
    fragility_axes.set(xlabel="PGA [g]", ylabel="P(force > limit)", ylim=(-0.02, 1.02),
                       title=f"fragility: pounding force > {limit / 1e6:g} MN")
    fragility_axes.legend(fontsize=8)
    for axes in (ida_axes, fragility_axes):
        axes.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(out / "ida_fragility.png", dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="out/ida", help="the batch folder (made anew)")
    parser.add_argument("--scales", default="0.25,0.5,0.75,1,1.5,2,3",
                        help="multiples of PGA 0.3 g, comma-separated")
    parser.add_argument("--limit", type=float, default=5e6, help="pounding force limit [N]")
    parser.add_argument("--jobs", type=int, default=os.cpu_count(), help="threads")
    arguments = parser.parse_args()
    out = pathlib.Path(arguments.out)
    shutil.rmtree(out, ignore_errors=True)
    scales = [float(s) for s in arguments.scales.split(",")]
    report = pound.batch(ida_set(scales, arguments.limit), out, jobs=arguments.jobs)
    with open(report["summary"], newline="") as table:
        rows = list(csv.DictReader(table))
    statistics = json.loads(pathlib.Path(report["statistics"]).read_text())
    fit = next((f for f in statistics["fragility"] if f["quantity"] == "max_pounding_force"),
               None)
    plot(rows, fit, arguments.limit, out)
    print(f"{report['completed']} of {report['cases']} cases completed -> "
          f"{out}/ida_fragility.png; fragility: {fit}")


if __name__ == "__main__":
    main()
