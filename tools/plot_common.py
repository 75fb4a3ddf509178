"""Helpers shared by the Python tools (plot_run.py, plot_batch.py, plot_block_belt.py,
plot_pareto.py, adaptive_saving.py, generate_motion.py): the command line, errors and their exit
codes, CSV and JSON input, matplotlib and PNG output. Standard library only until a script asks
for matplotlib.

Not a script of its own. Every message is prefixed by the calling script's name (its `prog`), so
it reads as that script's. The scripts import this module from their own folder:
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
"""

import argparse
import contextlib
import csv
import importlib
import json
import os
import re
import sys
import warnings

EXIT_USAGE = 1
EXIT_INPUT = 2
EXIT_OUTPUT = 4

SYSTEM_PYTHON = "/usr/bin/python3"

DPI_DEFAULT = 120
DPI_RANGE = (20, 1200)


class PlotError(Exception):
    """An error reported as one line, `prog: message`, and its class's exit code."""


class InputError(PlotError):
    """Bad input: the message names the file and what is wrong."""

    exit_code = EXIT_INPUT


class OutputError(PlotError):
    """A figure could not be written."""

    exit_code = EXIT_OUTPUT


MODEL_UNITS = "model units"


def units_of(summary):
    """The units summary.json names (its "units"), typeset; "model units" where it names none
    (forces, moments and energies of a model without a mass unit)."""
    given = summary.get("units") if isinstance(summary.get("units"), dict) else {}

    def named(key):
        value = given.get(key)
        if not isinstance(value, str) or not value or "own" in value:
            return MODEL_UNITS
        return value.replace("^2", "²").replace("*", "·")  # pound's ASCII, typeset

    units = {key: named(key) for key in ("length", "time", "force", "acceleration", "moment")}
    force, length, time = units["force"], units["length"], units["time"]
    units["energy"] = (f"{force}·{length}" if MODEL_UNITS not in (force, length) else MODEL_UNITS)
    units["impulse"] = (f"{force}·{time}" if MODEL_UNITS not in (force, time) else MODEL_UNITS)
    units["angle"] = "rad"
    return units


def report(prog, error):
    """Writes a PlotError as `prog: message` to stderr and returns its exit code."""
    sys.stderr.write(f"{prog}: {error}\n")
    return error.exit_code


def import_matplotlib(prog, reexec_mark, script):
    """Returns matplotlib's Figure class (Agg backend), or exits with a clear message.

    When matplotlib is missing, starts `script` (the calling script's path) again with the system
    python3 once (`reexec_mark`, an environment variable, prevents a loop)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        from matplotlib.figure import Figure
        importlib.import_module("numpy")  # the scripts use it too
        return Figure
    except ImportError as error:
        missing = error
    # A pyenv or venv python3 does not see Debian's python3-matplotlib: use the system one.
    if (not os.environ.get(reexec_mark) and os.access(SYSTEM_PYTHON, os.X_OK)
            and os.path.realpath(sys.executable) != os.path.realpath(SYSTEM_PYTHON)):
        os.environ[reexec_mark] = "1"
        try:
            os.execv(SYSTEM_PYTHON, [SYSTEM_PYTHON, os.path.abspath(script)] + sys.argv[1:])
        except OSError:
            pass
    sys.stderr.write(
        f"{prog}: matplotlib is not available to {sys.executable} ({missing}); install it "
        "with tools/install_dependencies.sh (Debian package python3-matplotlib) or run this "
        f"script with a python3 that has it\n")
    sys.exit(EXIT_USAGE)


# ----------------------------------------------------------------------------------------------
# Command line

class Parser(argparse.ArgumentParser):
    """Usage errors exit EXIT_USAGE (argparse's own code is 2, the scripts' bad-input code)."""

    def error(self, message):
        self.print_usage(sys.stderr)
        sys.stderr.write(f"{self.prog}: {message}\n")
        sys.exit(EXIT_USAGE)

    def add_dpi(self):
        self.add_argument("--dpi", type=int, default=DPI_DEFAULT,
                          help=f"resolution of the PNGs (default {DPI_DEFAULT})")

    def check_dpi(self, args):
        low, high = DPI_RANGE
        if not low <= args.dpi <= high:
            self.error(f"--dpi must be between {low} and {high}, got {args.dpi}")

    def parse_checked(self, argv):
        """The arguments, with --dpi in range."""
        args = self.parse_args(argv)
        self.check_dpi(args)
        return args


def folder_parser(prog, doc, folder_help, epilog=None):
    """The command line every plotting script starts from: the folder DIR it reads and --dpi."""
    parser = Parser(prog=prog, description=doc.split("\n\n")[0], epilog=epilog)
    parser.add_argument("folder", metavar="DIR", help=folder_help)
    parser.add_dpi()
    return parser


def run_plots(prog, draw, folder=None, nothing_drawn=None):
    """Runs draw() and returns the exit code: a PlotError's, else 0. draw returns what it wrote;
    when that is empty, `nothing_drawn` (if given) is noted on stderr."""
    try:
        written = draw()
    except PlotError as error:
        return report(prog, error)
    if nothing_drawn and not written:
        sys.stderr.write(f"{prog}: {folder}: {nothing_drawn}\n")
    return 0


# ----------------------------------------------------------------------------------------------
# Input

def check_folder(folder):
    if not os.path.isdir(folder):
        raise InputError(f"{folder}: {'not a folder' if os.path.exists(folder) else 'no such folder'}")


def read_json(path):
    """The parsed JSON document of a file (a RecursionError of a deeply nested one passes)."""
    try:
        with open(path, encoding="utf-8") as file:
            return json.load(file)
    except (OSError, UnicodeDecodeError) as error:
        raise InputError(f"{path}: cannot read: {error}") from None
    except json.JSONDecodeError as error:
        raise InputError(f"{path}: not valid JSON: {error}") from None


@contextlib.contextmanager
def csv_reader(path):
    """A csv.reader on the file; failing to open, decode or parse it raises InputError."""
    try:
        with open(path, encoding="utf-8", newline="") as file:
            yield csv.reader(file)
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        raise InputError(f"{path}: cannot read: {error}") from None


def strip_header(path, header):
    """A CSV header row (None: the file is empty) with its names stripped, and without the
    " [unit]" pound writes after a name (the units are summary.json's)."""
    if header is None:
        raise InputError(f"{path}: empty file (no header line)")
    return [re.sub(r"\s*\[[^\[\]]*\]$", "", column.strip()) for column in header]


def check_column_names(path, header):
    if any(not column for column in header):
        raise InputError(f"{path}: header has an empty column name")
    duplicates = sorted({column for column in header if header.count(column) > 1})
    if duplicates:
        raise InputError(f"{path}: header repeats column(s) {', '.join(duplicates)}")


def read_header(path, reader, required, hint):
    """The checked header of a CSV file that must have the required columns (hint: what the file
    should be, said when it has not)."""
    header = strip_header(path, next(reader, None))
    check_column_names(path, header)
    missing = [column for column in required if column not in header]
    if missing:
        raise InputError(f"{path}: header has no column(s) {', '.join(missing)} {hint}")
    return header


def check_width(path, line, row, width):
    if len(row) != width:
        raise InputError(f"{path}: line {line}: {len(row)} fields, expected {width} (the header's)")


def not_a_number(path, line, column, text):
    return InputError(f"{path}: line {line}, column '{column}': not a number: {text!r}")


# ----------------------------------------------------------------------------------------------
# Output

def tight_layout(fig):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fig.tight_layout()


def write_atomically(path, write):
    """Calls write(temporary) and renames the temporary file to path: never half a file."""
    temporary = f"{path}.tmp.{os.getpid()}"
    try:
        write(temporary)
        os.replace(temporary, path)
    except (OSError, ValueError) as error:
        try:
            os.remove(temporary)
        except OSError:
            pass
        raise OutputError(f"{path}: cannot write: {error}") from None


def save_png(fig, path, dpi):
    """Lays the figure out and writes it to path through a temporary file (never half a PNG)."""
    tight_layout(fig)
    write_atomically(path, lambda temporary: fig.savefig(temporary, format="png", dpi=dpi))
