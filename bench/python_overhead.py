"""What the Python module adds to a run, and threaded runs on the cores.

For each model: the median over rounds of pound.run's wall time, of the time the C++ run took
inside it (reading, building, solving, summarising: what `pound run` spends too) and of the solve
alone (summary.json's run_time_s); the overhead is the difference of the first two, as a share of
the solve. Then the same runs one after another and on `--threads` threads.

    PYTHONPATH=build/python python3 bench/python_overhead.py
"""

import argparse
import concurrent.futures
import pathlib
import statistics
import time

import pound

REPOSITORY = pathlib.Path(__file__).resolve().parents[1]


def timed_run(model):
    start = time.perf_counter()
    result = pound.run(model)
    wall = time.perf_counter() - start
    return wall, result._core.core_s, result.summary["run_time_s"]


def overhead(name, rounds):
    model = pound.Model.from_file(REPOSITORY / "models" / f"{name}.json")
    timed_run(model)  # warm up
    walls, cores, solves = zip(*(timed_run(model) for _ in range(rounds)))
    wall, core, solve = (statistics.median(v) for v in (walls, cores, solves))
    print(f"{name:<20} pound.run {wall * 1e3:8.2f} ms, C++ inside {core * 1e3:8.2f} ms, "
          f"solve {solve * 1e3:8.2f} ms: Python adds {(wall - core) * 1e3:6.3f} ms = "
          f"{100 * (wall - core) / solve:5.2f} % of the solve")


def scaling(name, runs, threads):
    model = pound.Model.from_file(REPOSITORY / "models" / f"{name}.json")
    start = time.perf_counter()
    for _ in range(runs):
        pound.run(model)
    serial = time.perf_counter() - start
    start = time.perf_counter()
    with concurrent.futures.ThreadPoolExecutor(threads) as pool:
        list(pool.map(lambda _: pound.run(model), range(runs)))
    threaded = time.perf_counter() - start
    print(f"{name:<20} {runs} runs: {serial:.3f} s one after another, {threaded:.3f} s on "
          f"{threads} threads: {serial / threaded:.2f}x")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=20)
    parser.add_argument("--threads", type=int, default=2)
    arguments = parser.parse_args()
    for name in ("two_sdof_girders", "three_span_bridge"):
        overhead(name, arguments.rounds)
    for name in ("two_sdof_girders", "three_span_bridge"):
        scaling(name, 4 * arguments.threads, arguments.threads)


if __name__ == "__main__":
    main()
