#!/usr/bin/env python3
"""How far OpenSees' displacements are from pound's, up to the first impact and after.

    compare.py POUND_NODES.csv POUND_LINKS.csv OPENSEES_DISP.out

POUND_NODES.csv: a pound node history of the nodes to_tcl.py --record-nodes named, in that order;
POUND_LINKS.csv: a pound link history of the contacts (the first nonzero force is the first
impact); OPENSEES_DISP.out: what the script's recorder wrote (time, then x of each node).
Prints the largest difference before the first impact's step, to 4 s, 8 s and the end, and each
node's peak |u_x| in both over the same windows.
"""
import csv
import sys


def main():
    nodes_csv, links_csv, opensees_out = sys.argv[1:4]
    rows = list(csv.reader(open(nodes_csv)))
    columns = [k for k, name in enumerate(rows[0]) if name.endswith(".u_x [m]")]
    names = [rows[0][k].split(".u_x")[0] for k in columns]
    pound = {round(float(r[0]), 9): [float(r[k]) for k in columns] for r in rows[1:]}
    links = list(csv.reader(open(links_csv)))
    forces = [k for k, name in enumerate(links[0]) if ".force" in name]
    first_impact = next((float(r[0]) for r in links[1:] if any(float(r[k]) for k in forces)), None)
    opensees = []
    for line in open(opensees_out):
        values = [float(v) for v in line.split()]
        opensees.append((round(values[0], 9), values[1:]))
    end = opensees[-1][0]
    print(f"first impact in pound at {first_impact} s; {len(opensees)} OpenSees steps to {end} s")
    # the first window ends before the step of the first impact, the others with their last step
    windows = [(first_impact, "before the first impact")] if first_impact else []
    windows += [(t + 1e-9, f"to {t:g} s") for t in sorted({4.0, 8.0, end})]
    for limit, label in windows:
        worst, peak_pound, peak_opensees = 0.0, [0.0] * len(names), [0.0] * len(names)
        for time, values in opensees:
            if time >= limit or time not in pound:
                continue
            for k, (ours, theirs) in enumerate(zip(pound[time], values)):
                worst = max(worst, abs(ours - theirs))
                peak_pound[k] = max(peak_pound[k], abs(ours))
                peak_opensees[k] = max(peak_opensees[k], abs(theirs))
        peaks = "; ".join(f"{n} {p:.5f} / {o:.5f} m"
                          for n, p, o in zip(names, peak_pound, peak_opensees))
        print(f"{label}: largest |u_OpenSees - u_pound| {worst:.2e} m; "
              f"peak |u_x| pound / OpenSees: {peaks}")


if __name__ == "__main__":
    main()
