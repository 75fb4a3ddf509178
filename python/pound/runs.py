"""pound.run and pound.batch."""

import os

from pound import _core
from pound._documents import (INT_MAX, LONG_MAX, flag, integer, path_argument, real, seconds,
                              to_json)
from pound.errors import AnalysisError, InputError
from pound.model import Model
from pound.record import Record
from pound.result import Result


def _model(model):
    if isinstance(model, Model):
        return model
    if isinstance(model, dict):
        return Model.from_dict(model)
    if isinstance(model, (str, os.PathLike)):
        return Model.from_file(model)
    raise InputError("", "model", f"expected a pound.Model, a dict or a path, got "
                                  f"{type(model).__name__}")


def run(model, record=None, out=None, *, max_steps=None, time_limit=0.0, histories=True,
        check=True, progress=None, ensemble=None, perturbation=None, robust_spread=None, jobs=None):
    """Runs the time-history analysis of ``model`` (a :class:`pound.Model`, a dict or a path),
    as ``pound run`` does, and returns a :class:`pound.Result`.

    ``record``: a :class:`pound.Record` replacing the model's first excitation's record.
    ``out``: a folder to write the files ``pound run --out`` writes (summary.json, the recorders'
    CSVs); none is written when None. ``max_steps``, ``time_limit`` [s of solving]: stop with
    an AnalysisError past them (0: no limit; ``max_steps=None``: the model's "max_steps").
    ``histories=False`` skips the recorders.

    The GIL is released while it solves: runs on several threads go in parallel. Ctrl-C stops
    the run (KeyboardInterrupt). A failed analysis raises :class:`pound.AnalysisError` with the
    result up to the failure as ``error.result`` (and, with ``out``, its files written), unless
    ``check=False``, which returns that result instead.

    ``progress``: a callable ``progress(time, end)`` [the model's time unit], called as the
    solve starts, then at most every 0.2 s of solving, and once more as the run ends: with
    ``time == end`` when it completed, at the failure's time when it failed. For a progress bar;
    what it raises stops the run and is raised here.

    ``ensemble=N``: as ``pound run --ensemble N``, also runs N copies with every record scaled
    by 1 + eps, 1 - eps, 1 + 2 eps, ... (eps = ``perturbation``) on ``jobs`` threads (0: every
    core), and gives ``result.ensemble`` (ensemble.json: for every number of the summary the
    unperturbed value, the median, 16 and 84 % and range of the copies, and whether its 16-84 %
    spread is within ``robust_spread`` of its size; defaults 1e-4 and 0.05, as the program's).
    The result is the unperturbed run's; with ``out`` ensemble.json is written too.
    ``progress`` then counts runs: ``progress(done, runs)`` with ``runs = N + 1``.
    """
    model = _model(model)
    if record is not None and not isinstance(record, Record):
        raise InputError("", "record", f"expected a pound.Record, got {type(record).__name__}")
    if progress is not None and not callable(progress):
        raise InputError("", "progress",
                         f"expected a callable progress(time, end), got {type(progress).__name__}")
    copies_only = {"perturbation": perturbation, "robust_spread": robust_spread, "jobs": jobs}
    for name, value in copies_only.items():
        if ensemble is None and value is not None:
            raise InputError("", name, "applies to the copies of an ensemble only: add ensemble=N")
    text, path = model._arguments()
    core = _core.run(text, path, None if record is None else record._motion(),
                     None if out is None else path_argument(out, "out", "a folder"),
                     None if max_steps is None
                     else integer(max_steps, "max_steps", 0, LONG_MAX),
                     seconds(time_limit, "time_limit"), flag(histories, "histories"), progress,
                     None if ensemble is None else integer(ensemble, "ensemble", 1, INT_MAX),
                     1e-4 if perturbation is None else real(perturbation, "perturbation"),
                     0.05 if robust_spread is None else real(robust_spread, "robust_spread"),
                     0 if jobs is None else integer(jobs, "jobs", 0, INT_MAX))
    result = Result(core)
    if flag(check, "check") and not result.completed:
        raise AnalysisError(result.failure_time, result.failure, result)
    return result


def batch(set, out, *, jobs=0, resume=False, progress=None):
    """Runs a batch set (docs/batch_format.md; a path or a dict, whose relative paths start from
    the working directory) as ``pound batch`` does, writing every case's folder, batch_summary.csv
    and batch_stats.json into ``out``. ``jobs``: worker threads (0: every core). ``resume``:
    keep the complete cases of an earlier run of the same set in ``out``. Returns the report
    (cases, resumed, ran, completed, failed, wall_s, ...) with "summary" and "statistics", the
    paths of batch_summary.csv and batch_stats.json.

    The GIL is released while the cases run. Ctrl-C stops the batch (KeyboardInterrupt); the
    cases that ended are kept, and ``resume=True`` runs the rest.

    ``progress``: a callable ``progress(done, total)``, ``total`` the cases this call runs (a
    resumed batch's complete cases not counted) and ``done`` those ended plus the share solved
    of those running; called from the batch's threads, one call at a time, at most every 0.2 s,
    and once more with ``done == total`` when the batch has ended. For a progress bar; what it
    raises stops the batch (the cases running are not kept) and is raised here.
    """
    out = path_argument(out, "out", "a folder")
    if progress is not None and not callable(progress):
        raise InputError("", "progress", "expected a callable progress(done, total), got "
                                         f"{type(progress).__name__}")
    if isinstance(set, dict):
        text, path = to_json(set, "<dict>"), "<dict>"
    else:
        text, path = None, path_argument(set, "set", "a set file's path or a dict")
    report = _core.batch(text, path, out, integer(jobs, "jobs", 0, INT_MAX), flag(resume, "resume"),
                         progress)
    report["summary"] = os.path.join(out, "batch_summary.csv")
    report["statistics"] = os.path.join(out, "batch_stats.json")
    return report
