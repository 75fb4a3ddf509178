#!/usr/bin/env python3
"""Run time and accuracy of adaptive against fixed time steps on a model with records.

usage: python3 tools/adaptive_saving.py POUND_BINARY MODEL.json REFERENCE_DT

Runs the model at a fixed reference step REFERENCE_DT, at 0.5, 1, 2, 4 times its own step and
adaptively (tolerances 1e-3, 1e-4, 1e-5), each three times (best CPU time of the process), and
prints a Markdown table: steps, CPU seconds, the worst relative error of the peak drifts, joint
openings and seat movements against the reference, and the error of the peak contact force.

Exit codes: 0 ok, 1 usage error, 2 bad input (the model cannot be read or has no record; the
message names the file), 3 a run of pound failed (its message is shown).
"""

import copy
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_common import InputError, Parser, PlotError, read_json, report  # noqa: E402

PROG = "adaptive_saving.py"
EXIT_RUN_FAILED = 3
REPEATS = 3
# (tag, the model's own step times this factor, adaptive tolerance or None)
RUNS = [("fixed_x0.5", 0.5, None), ("fixed", 1.0, None), ("fixed_x2", 2.0, None),
        ("fixed_x4", 4.0, None), ("adaptive_1e-3", 1.0, 1e-3), ("adaptive_1e-4", 1.0, 1e-4),
        ("adaptive_1e-5", 1.0, 1e-5)]


class RunError(PlotError):
    """A run of pound failed."""

    exit_code = EXIT_RUN_FAILED


def read_model(path):
    """The model with its first record's path made absolute (the runs are written elsewhere)."""
    model = read_json(path)
    try:
        excitation = model["excitations"][0]
        record = excitation["record"]
        model["analysis"]["time_step"] = float(model["analysis"]["time_step"])
    except (KeyError, IndexError, TypeError, ValueError):
        raise InputError(f"{path}: needs excitations[0].record and analysis.time_step") from None
    excitation["record"] = os.path.normpath(
        os.path.join(os.path.dirname(os.path.abspath(path)), record))
    return model


class Study:
    def __init__(self, pound, model, name, work):
        self.pound = pound
        self.model = model
        self.name = name
        self.work = work

    def run(self, tag, dt, tolerance):
        """Steps, best CPU time, peak responses and peak contact force of one setting."""
        model = copy.deepcopy(self.model)
        model["analysis"]["time_step"] = dt
        if tolerance:
            model["analysis"]["adaptive"] = {"tolerance": tolerance}
        path = os.path.join(self.work, f"{self.name}_{tag}.json")
        with open(path, "w", encoding="utf-8") as file:
            json.dump(model, file)
        out = os.path.join(self.work, f"o_{self.name}_{tag}")
        best = min(self.cpu_time([self.pound, "run", path, "--out", out, "-q"])
                   for _ in range(REPEATS))
        summary = read_json(os.path.join(out, "summary.json"))
        responses = {}
        for monitor in summary.get("piers", []) + summary.get("storeys", []):
            responses["drift " + monitor["id"]] = monitor["peak_drift"]
        for joint in summary.get("joints", []):
            responses["open " + joint["id"]] = joint["peak_opening"]
            responses["seat " + joint["id"]] = joint["peak_seat_movement"]
        force = max((link["peak_force"] for link in summary["links"]), default=0.0)
        return {"steps": summary["steps"], "cpu": best, "responses": responses, "force": force}

    @staticmethod
    def cpu_time(command):
        """CPU seconds of the child process running command."""
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                              text=True)
        if done.returncode != 0:
            raise RunError(f"{' '.join(command)} exited {done.returncode}: {done.stderr.strip()}")
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def relative_error(value, reference):
    return abs(value / reference - 1) if reference else float("nan")


def table(study, reference_dt):
    """The Markdown table, line by line."""
    reference = study.run("ref", reference_dt, None)
    own_dt = study.model["analysis"]["time_step"]
    lines = [f"{study.name}: reference dt {reference_dt}: {reference['steps']} steps, "
             f"{reference['cpu']:.2f} s CPU",
             "| run | first dt [s] | steps | CPU [s] | worst peak drift/opening/seat error "
             "| peak contact force error |",
             "|---|---|---|---|---|---|"]
    for tag, factor, tolerance in RUNS:
        dt = own_dt * factor
        run = study.run(tag, dt, tolerance)
        worst = max((relative_error(run["responses"][key], value)
                     for key, value in reference["responses"].items() if value > 0),
                    default=float("nan"))
        force_error = relative_error(run["force"], reference["force"])
        lines.append(f"| {tag} | {dt:g} | {run['steps']} | {run['cpu']:.3f} | {worst:.2e} "
                     f"| {force_error:.2e} |")
    return lines


def main(argv):
    parser = Parser(prog=PROG, description=__doc__.split("\n\n")[0])
    parser.add_argument("pound", metavar="POUND_BINARY")
    parser.add_argument("model", metavar="MODEL.json")
    parser.add_argument("reference_dt", metavar="REFERENCE_DT", type=float)
    args = parser.parse_args(argv)
    if not args.reference_dt > 0.0:
        parser.error(f"REFERENCE_DT must be positive, got {args.reference_dt}")
    work = tempfile.mkdtemp(prefix="pound_adaptive_")
    try:
        name = os.path.basename(args.model).replace(".json", "")
        study = Study(args.pound, read_model(args.model), name, work)
        for line in table(study, args.reference_dt):
            print(line, flush=True)
    except PlotError as error:
        return report(PROG, error)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
