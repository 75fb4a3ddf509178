"""How wide a gap keeps two adjacent buildings apart? Sweeps the separation of the bundled
building pair (models/adjacent_buildings.json) over the bundled records, runs every case on
threads with pound.run, and plots the peak impact force and the peak storey drift ratio against
the gap.

    PYTHONPATH=build/python python3 examples/python/gap_sweep.py --out out/gap_sweep
"""

import argparse
import concurrent.futures
import json
import os
import pathlib

import numpy as np

import pound

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def buildings_with_gap(gap):
    """The bundled pair with its separation set to `gap` [m]."""
    model = json.loads((REPOSITORY / "models" / "adjacent_buildings.json").read_text())
    model["generators"][0]["separation"] = gap
    return pound.Model.from_dict(model, name=f"buildings {gap * 100:g} cm apart",
                                 folder=REPOSITORY / "models")


def peaks(model, record):
    """The largest impact force over the links and the largest storey drift ratio."""
    summary = pound.run(model, record, histories=False).summary
    force = max((link["peak_force"] for link in summary["links"]), default=0.0)
    drift = max(storey["drift_ratio"] for storey in summary["storeys"])
    return force, drift


def sweep(gaps, records, jobs):
    """peaks[gap][record] over every pair, run `jobs` at a time."""
    models = {gap: buildings_with_gap(gap) for gap in gaps}
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        futures = {(gap, k): pool.submit(peaks, models[gap], record)
                   for gap in gaps for k, record in enumerate(records)}
        return {key: future.result() for key, future in futures.items()}


def plot(gaps, records, results, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, (force_axes, drift_axes) = plt.subplots(1, 2, figsize=(10, 4))
    for k, record in enumerate(records):
        force = [results[gap, k][0] / 1e6 for gap in gaps]
        drift = [results[gap, k][1] * 100 for gap in gaps]
        force_axes.plot(np.array(gaps) * 100, force, "o-", label=record.name)
        drift_axes.plot(np.array(gaps) * 100, drift, "o-", label=record.name)
    force_axes.set(xlabel="gap [cm]", ylabel="peak impact force [MN]",
                   title="pounding force against gap")
    drift_axes.set(xlabel="gap [cm]", ylabel="peak storey drift ratio [%]",
                   title="storey drift against gap")
    force_axes.legend(fontsize=8)
    for axes in (force_axes, drift_axes):
        axes.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(out / "gap_sweep.png", dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="out/gap_sweep", help="folder for gap_sweep.png/.csv")
    parser.add_argument("--gaps", default="0,0.5,1,2,3,5,8,12",
                        help="separations to try [cm], comma-separated")
    parser.add_argument("--jobs", type=int, default=os.cpu_count(), help="threads")
    arguments = parser.parse_args()
    gaps = [float(g) / 100 for g in arguments.gaps.split(",")]
    records = [pound.Record.from_file(path)
               for path in sorted((REPOSITORY / "ground_motions").glob("synthetic_*.AT2"))]
    results = sweep(gaps, records, arguments.jobs)
    out = pathlib.Path(arguments.out)
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "gap_sweep.csv", "w") as table:
        table.write("gap_m,record,peak_impact_force_N,peak_drift_ratio\n")
        for (gap, k), (force, drift) in sorted(results.items()):
            table.write(f"{gap},{records[k].name},{force:.6g},{drift:.6g}\n")
    plot(gaps, records, results, out)
    print(f"{len(results)} runs -> {out}/gap_sweep.png, {out}/gap_sweep.csv")


if __name__ == "__main__":
    main()
