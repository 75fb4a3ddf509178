#!/usr/bin/env python3
"""Mutation test of pound's input contract (issue 14: every input ends in a clear answer).

Takes every example model (models/*.json) and batch set (sets/*.json), makes mutated variants of
it (numeric extremes, deleted keys and list elements, changed types, duplicated list elements),
runs the pound binary on each (run, check, modes, expand for a model; batch for a set) and
classifies the outcome against the contract:

  exit 2  refused: "error: FILE: /json/path: ..." (or "FILE: line N: ...") and nothing written
  exit 3  failed loudly: a message saying when and why
  exit 0  completed: every number of every output finite (no NaN/Infinity, no null where the
          unmutated input gives a number, no nan/inf in a CSV)
  never a signal, never a hang (timeout), never more memory than the limit, exit 4 only for an
  unwritable output (the outputs here are always writable), the input file never written over.

Mutants are written into a temporary tree that mirrors the repository (models/, sets/, a link
to ground_motions/ and to ../shared beside it), so relative record paths still resolve. The
mutants are deterministic from --seed; the inputs share the time (--budget-seconds) evenly.
--keep DIR saves each mutant that breaks the contract, with a .txt saying the mutation, the
command to replay it (from DIR/root) and the outcome.

With --options it sweeps the command line instead of the files: every option that takes a value
of every command (read from `pound COMMAND --help`, so a new option is swept without a change
here) is given each of the values mutation gives numbers (0, -1, +-1e308, NaN, +-inf, 1e-320,
text, empty, 2^31, hex, a list, ...) beside a valid invocation, in a fresh folder. The contract:
exit 0 with every number finite (stdout and every file written), exit 1 a usage error naming the
option, exit 2 or 3 an "error:" line; on exit 1 or 2 nothing written; never a signal or a hang.

Exit status: 0 no contract break, 1 some contract break (0 with --report-only), 2 usage error.
Python 3 standard library only.
"""

import argparse
import copy
import hashlib
import json
import math
import os
import random
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor

MODEL_COMMANDS = ("run", "check", "modes", "expand")
SET_COMMANDS = ("batch",)

BREAK_CLASSES = (
    "crash",  # killed by a signal
    "hang",  # over the timeout
    "silent_nonfinite",  # exit 0 with a non-finite number (or no/unreadable output)
    "refusal_without_path",  # exit 2 without "error: FILE: /path:" or "FILE: line N:"
    "failure_without_message",  # exit 3 without an "error:" message
    "unexpected_failure",  # exit 3 from an error no check caught ("an unexpected failure")
    "other_exit",  # an exit code other than 0, 2, 3
    "written_on_refusal",  # exit 2 with something in the output folder or file
    "input_overwritten",  # the input file changed during the run
    "usage_without_option",  # --options: exit 1 without the option's name in the message
)

# What main_entry.cpp says of an exception that escaped every check (a gap in them).
UNEXPECTED = "(an unexpected failure: please report it with the input)"
NONFINITE_CSV = re.compile(r"^[+-]?(nan|inf|infinity)(\(.*\))?$", re.IGNORECASE)
REFUSAL = re.compile(r"^error: (?P<file>.+?): (?P<where>/[^:]*|line \d+)(:|$)")


# ----------------------------------------------------------------------------------- mutations


def json_path(path):
    return "/" + "/".join(str(p) for p in path) if path else "/"


def short(value, limit=40):
    text = json.dumps(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def number_variants(x):
    """The numeric extremes and relative changes tried in place of the number x."""
    out = [0, -1, 1e-300, 5e-324, 1e300, 1e308, -1e308, 2**64]
    for factor in (1e-12, 1e12, -1.0):
        y = x * factor
        if isinstance(y, float) and not math.isfinite(y):
            continue
        out.append(y)
    if isinstance(x, int) and not isinstance(x, bool):
        out += [x + 1, x - 1, 0.5, 2**31, 2**63 - 1]
    seen = []
    for v in out:
        if v == x and type(v) is type(x):
            continue
        if any(v == s and type(v) is type(s) for s in seen):
            continue
        seen.append(v)
    return seen


def enumerate_mutations(doc):
    """Every mutation of doc as (path, kind, argument, description), in a fixed order."""
    muts = []

    def walk(node, path):
        where = json_path(path)
        if isinstance(node, bool):
            muts.append((path, "set", not node, "%s: bool %s -> %s" % (where, short(node), short(not node))))
            muts.append((path, "set", None, "%s: bool -> null" % where))
            muts.append((path, "set", str(node).lower(), "%s: bool -> string" % where))
            muts.append((path, "set", 1, "%s: bool -> number 1" % where))
        elif isinstance(node, (int, float)):
            for v in number_variants(node):
                muts.append((path, "set", v, "%s: number %s -> %s" % (where, short(node), short(v))))
            muts.append((path, "set", str(node), "%s: number -> string %s" % (where, short(str(node)))))
            muts.append((path, "set", None, "%s: number -> null" % where))
            muts.append((path, "set", [node], "%s: number -> list [%s]" % (where, short(node))))
            muts.append((path, "set", {"value": node}, "%s: number -> object" % where))
        elif isinstance(node, str):
            muts.append((path, "set", 1, "%s: string %s -> number 1" % (where, short(node))))
            muts.append((path, "set", None, "%s: string -> null" % where))
            muts.append((path, "set", "", "%s: string %s -> empty string" % (where, short(node))))
            muts.append((path, "set", "zzz", "%s: string %s -> \"zzz\"" % (where, short(node))))
            muts.append((path, "set", [node], "%s: string -> list" % where))
            muts.append((path, "set", True, "%s: string -> true" % where))
        elif node is None:
            muts.append((path, "set", 0, "%s: null -> 0" % where))
        elif isinstance(node, list):
            if path:
                muts.append((path, "set", [], "%s: list -> empty list" % where))
                muts.append((path, "set", None, "%s: list -> null" % where))
                muts.append((path, "set", {}, "%s: list -> object" % where))
                muts.append((path, "set", 1, "%s: list -> number 1" % where))
            for i, item in enumerate(node):
                muts.append((path + [i], "delete", None, "%s/%d: element deleted" % (where.rstrip("/"), i)))
                muts.append((path + [i], "duplicate", None, "%s/%d: element duplicated" % (where.rstrip("/"), i)))
            for i, item in enumerate(node):
                walk(item, path + [i])
        elif isinstance(node, dict):
            if path:
                muts.append((path, "set", {}, "%s: object -> empty object" % where))
                muts.append((path, "set", None, "%s: object -> null" % where))
                muts.append((path, "set", [], "%s: object -> list" % where))
                muts.append((path, "set", "zzz", "%s: object -> string" % where))
            for key in node:
                muts.append((path + [key], "delete", None, "%s: key deleted" % json_path(path + [key])))
            for key, item in node.items():
                walk(item, path + [key])

    walk(doc, [])
    return muts


def apply_mutation(doc, mutation):
    path, kind, arg, _ = mutation
    doc = copy.deepcopy(doc)
    if not path:
        return arg if kind == "set" else doc
    parent = doc
    for p in path[:-1]:
        parent = parent[p]
    last = path[-1]
    if kind == "set":
        parent[last] = copy.deepcopy(arg)
    elif kind == "delete":
        del parent[last]
    elif kind == "duplicate":
        parent.insert(last + 1, copy.deepcopy(parent[last]))
    return doc


# ----------------------------------------------------------------------------------- outputs


class NonFinite(Exception):
    pass


def load_json_strict(text):
    """json.loads that raises NonFinite on NaN/Infinity and on numbers that overflow a double."""

    def constant(name):
        raise NonFinite(name)

    def parse_float(s):
        v = float(s)
        if not math.isfinite(v):
            raise NonFinite(s)
        return v

    return json.loads(text, parse_constant=constant, parse_float=parse_float)


def leaves(node, path=()):
    """(generalised path, value) for every leaf: list indexes become '*'."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from leaves(v, path + (k,))
    elif isinstance(node, list):
        for v in node:
            yield from leaves(v, path + ("*",))
    else:
        yield path, node


# Keys whose null is documented as a meaning, not an overflow: `check --json` writes an unbounded
# explicit stable step (nothing in the scene vibrates) as null, "no limit", and what does not
# apply to a link as null (a Hertz law's stiffness at first touch, bare masses' adjacent
# stiffness, a contact duration not claimed against comparably stiff neighbours, the extended
# penalty's numbers of any other law): a mutant may turn them so without overflowing.
DOCUMENTED_NULLS = {"explicit_stable_step_open", "explicit_stable_step_contact"}
DOCUMENTED_LINK_NULLS = {"stiffness", "adjacent_stiffness", "contact_duration",
                         "approach_velocity", "automatic_alpha0", "automatic_alpha1",
                         "automatic_alpha2"}


def documented_null(kind, path):
    if path[-1] in DOCUMENTED_NULLS:
        return True
    return kind.startswith("check") and path[0] == "links" and path[-1] in DOCUMENTED_LINK_NULLS


class Shapes:
    """Which generalised paths of each output hold numbers in the unmutated runs, and which may
    be null there: a null where an unmutated run has a number is a non-finite number."""

    def __init__(self):
        self.numeric = {}
        self.nullable = {}
        self.lock = threading.Lock()

    def learn(self, kind, doc):
        with self.lock:
            num = self.numeric.setdefault(kind, set())
            nul = self.nullable.setdefault(kind, set())
            for p, v in leaves(doc):
                if v is None:
                    nul.add(p)
                elif isinstance(v, (int, float)) and not isinstance(v, bool):
                    num.add(p)

    def null_numbers(self, kind, doc):
        num = self.numeric.get(kind, set())
        nul = self.nullable.get(kind, set())
        return ["/".join(p) for p, v in leaves(doc)
                if v is None and p in num and p not in nul and not documented_null(kind, p)]


def check_json_text(text, kind, shapes, learn):
    """None if text is a JSON document with finite numbers only, else what is wrong."""
    try:
        doc = load_json_strict(text)
    except NonFinite as e:
        return "non-finite %s in %s" % (e, kind)
    except ValueError as e:
        return "%s is not JSON: %s" % (kind, str(e).splitlines()[0])
    if learn:
        shapes.learn(kind, doc)
        return None
    nulls = shapes.null_numbers(kind, doc)
    if nulls:
        return "null where a number belongs in %s: %s" % (kind, nulls[0])
    return None


def check_csv(path):
    with open(path, "r", errors="replace") as f:
        for n, line in enumerate(f, 1):
            for field in line.rstrip("\r\n").split(","):
                if NONFINITE_CSV.match(field.strip().strip('"')):
                    return "%s line %d: %s" % (os.path.basename(path), n, field.strip())
    return None


def check_folder(folder, shapes, learn, need_summary):
    if not os.path.isdir(folder):
        return "no output folder"
    seen_summary = False
    for dirpath, _, files in os.walk(folder):
        for name in sorted(files):
            p = os.path.join(dirpath, name)
            if name.endswith(".csv"):
                bad = check_csv(p)
            elif name.endswith(".json"):
                if name == "summary.json":
                    seen_summary = True
                with open(p, "r", errors="replace") as f:
                    bad = check_json_text(f.read(), "file " + name, shapes, learn)
            else:
                continue
            if bad:
                return bad
    if need_summary and not seen_summary:
        return "no summary.json"
    return None


def folder_empty(path):
    if not os.path.exists(path):
        return True
    if os.path.isdir(path):
        return not any(os.scandir(path))
    return False


# ----------------------------------------------------------------------------------- running


def limit_memory(limit_bytes):
    def preexec():
        resource.setrlimit(resource.RLIMIT_AS, (limit_bytes, limit_bytes))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))

    return preexec


def sha(path):
    try:
        with open(path, "rb") as f:
            return hashlib.sha256(f.read()).hexdigest()
    except OSError:
        return None


def run_bounded(argv, cwd, timeout, memory_gb):
    """(exit status or None on a timeout, stdout, stderr) of argv under the timeout and memory cap."""
    try:
        proc = subprocess.run(argv, cwd=cwd, capture_output=True, timeout=timeout,
                              preexec_fn=limit_memory(int(memory_gb * 2**30)))
    except subprocess.TimeoutExpired as e:
        return None, "", (e.stderr or b"").decode("utf-8", "replace")
    return proc.returncode, proc.stdout.decode("utf-8", "replace"), proc.stderr.decode("utf-8", "replace")


def classify_abnormal(status, lines):
    """(outcome, [break classes], detail) of a hang, a crash or an exit 3; None for the others."""
    if status is None:
        return "hang", ["hang"], "no answer in the timeout"
    if status < 0 or status >= 128:
        sig = -status if status < 0 else status - 128
        return "crash", ["crash"], "signal %d" % sig
    if status == 3:
        if not any(line.startswith("error:") for line in lines):
            return "failed", ["failure_without_message"], "exit 3 without an error: line"
        if any(UNEXPECTED in line for line in lines):
            return "failed", ["unexpected_failure"], "an error no check caught"
        return "failed", [], None
    return None


def make_tree(dest, repo):
    """dest/root/{models,sets} (copies), dest/root/ground_motions and dest/shared (links), so
    that a mutant in dest/root/models or dest/root/sets finds its records as the original does."""
    root = os.path.join(dest, "root")
    for sub in ("models", "sets"):
        os.makedirs(os.path.join(root, sub), exist_ok=True)
        src = os.path.join(repo, sub)
        for name in os.listdir(src):
            if name.endswith(".json"):
                shutil.copyfile(os.path.join(src, name), os.path.join(root, sub, name))
    for link, target in ((os.path.join(root, "ground_motions"), os.path.join(repo, "ground_motions")),
                         (os.path.join(dest, "shared"), os.path.join(os.path.dirname(repo), "shared"))):
        if os.path.exists(target) and not os.path.lexists(link):
            os.symlink(target, link)
    return root


class Harness:
    def __init__(self, args, repo):
        self.args = args
        self.repo = repo
        self.work = tempfile.mkdtemp(prefix="pound_mutate_")
        self.root = make_tree(self.work, repo)
        self.outs = os.path.join(self.work, "out")
        os.makedirs(self.outs)
        self.shapes = Shapes()
        self.lock = threading.Lock()
        self.counter = 0
        self.results = []
        self.baseline_time = {}
        self.start = time.monotonic()
        self.keep_root = None
        if args.keep:
            self.keep_root = make_tree(os.path.abspath(args.keep), repo)
        self.originals = {}
        for sub in ("models", "sets"):
            d = os.path.join(self.root, sub)
            for name in os.listdir(d):
                self.originals[os.path.join(sub, name)] = sha(os.path.join(d, name))

    def close(self):
        shutil.rmtree(self.work, ignore_errors=True)

    def next_id(self):
        with self.lock:
            self.counter += 1
            return self.counter

    def command_line(self, command, rel_input, out):
        b = self.args.binary
        if command == "run":
            return [b, "run", rel_input, "--out", out, "--quiet", "--time-limit", str(self.args.run_time_limit)]
        if command == "check":
            return [b, "check", rel_input, "--json"]
        if command == "modes":
            return [b, "modes", rel_input, "--json"]
        if command == "expand":
            return [b, "expand", rel_input, "--out", out]
        if command == "batch":
            return [b, "batch", rel_input, "--out", out, "--jobs", "1", "--quiet"]
        raise ValueError(command)

    def execute(self, input_name, command, text, description, baseline=False):
        """Writes text as a mutant of input_name, runs command on it and classifies the outcome."""
        n = self.next_id()
        sub = os.path.dirname(input_name)
        stem = os.path.splitext(os.path.basename(input_name))[0]
        rel = os.path.join(sub, "%s.s%d.m%d.json" % (stem, self.args.seed, n)) if not baseline else input_name
        path = os.path.join(self.root, rel)
        if not baseline:
            with open(path, "w") as f:
                f.write(text)
        before = sha(path)
        scratch = os.path.join(self.outs, str(n))
        os.makedirs(scratch)
        out = os.path.join(scratch, "expanded.json" if command == "expand" else "out")
        argv = self.command_line(command, rel, out)
        if baseline:
            timeout = max(self.args.timeout, 180)
        else:
            timeout = max(self.args.timeout, 3 * self.baseline_time.get((input_name, command), 0) + 5)
        t0 = time.monotonic()
        status, stdout, stderr = run_bounded(argv, self.root, timeout, self.args.memory_gb)
        elapsed = time.monotonic() - t0
        outcome, breaks, detail = self.classify(command, status, stdout, stderr, out, scratch, baseline)
        if sha(path) != before:
            breaks.append("input_overwritten")
            detail = detail or "the input file changed"
        lines = [x for x in stderr.strip().splitlines() if x.strip()]
        result = {
            "input": input_name, "command": command, "mutation": description,
            "outcome": outcome, "breaks": breaks, "exit": status, "seconds": round(elapsed, 3),
            "stderr_last": lines[-1] if lines else "", "detail": detail,
            "replay": " ".join(argv[0:2] + [rel] + argv[3:]),
        }
        if breaks and self.keep_root and not baseline:
            kept = os.path.join(self.keep_root, rel)
            with open(kept, "w") as f:
                f.write(text)
            with open(kept[:-5] + ".txt", "w") as f:
                f.write("%s | mutation %s | cd %s && %s | %s exit %s: %s%s\n" % (
                    input_name, description, self.keep_root, result["replay"].replace(out, "/tmp/mutant_out"),
                    ",".join(breaks), status, result["stderr_last"], " (" + detail + ")" if detail else ""))
            result["kept"] = kept
        if not baseline:
            os.remove(path)
        shutil.rmtree(scratch, ignore_errors=True)
        return result, elapsed

    def classify(self, command, status, stdout, stderr, out, scratch, baseline):
        """(outcome, [break classes], detail)."""
        lines = [x for x in stderr.splitlines() if x.strip()]
        abnormal = classify_abnormal(status, lines)
        if abnormal:
            return abnormal
        if status == 2:
            breaks, detail = [], None
            named = False
            for line in lines:
                m = REFUSAL.match(line.strip())
                if m:
                    named = True
                    break
            if not named:
                breaks.append("refusal_without_path")
                detail = "no 'error: FILE: /path:' line"
            if not folder_empty(out) or any(e.name != os.path.basename(out) for e in os.scandir(scratch)):
                breaks.append("written_on_refusal")
                detail = detail or "output written"
            return "refused", breaks, detail
        if status == 0:
            learn = baseline
            if command in ("run", "batch"):
                bad = check_folder(out, self.shapes, learn, command == "run")
            elif command == "expand":
                if not os.path.isfile(out):
                    bad = "no expanded file"
                else:
                    with open(out, "r", errors="replace") as f:
                        bad = check_json_text(f.read(), "expanded model", self.shapes, False)
            else:
                bad = check_json_text(stdout, command + " --json", self.shapes, learn)
            if bad:
                return "completed", ["silent_nonfinite"], bad
            return "completed", [], None
        return "other", ["other_exit"], "exit %d" % status

    def check_originals(self):
        changed = []
        for rel, digest in self.originals.items():
            if sha(os.path.join(self.root, rel)) != digest:
                changed.append(rel)
        return changed


def plan(harness, inputs, seed):
    """Per input, its (command, mutation) pairs in a seeded order."""
    queues = {}
    for name in inputs:
        with open(os.path.join(harness.root, name)) as f:
            doc = json.load(f)
        commands = SET_COMMANDS if name.startswith("sets") else MODEL_COMMANDS
        muts = enumerate_mutations(doc)
        pairs = [(c, m) for m in muts for c in commands]
        random.Random("%s:%s" % (seed, name)).shuffle(pairs)
        queues[name] = {"doc": doc, "pairs": pairs, "next": 0, "spent": 0.0}
    return queues


# ----------------------------------------------------------------------------------- options

OPTION_VALUES = ("0", "-1", "1e308", "-1e308", "nan", "inf", "-inf", "1e-320", "abc", "", "1e",
                 "5e9", "2147483648", "-0", "0x10", "1,2", "3.5", "0.5", "y")
RECORD = "ground_motions/synthetic_firm_01.AT2"
# A valid invocation of each command (paths in the mirror tree), to which one option is added.
OPTION_BASES = {
    "run": ["run", "models/two_sdof_girders.json", "--quiet", "--time-limit", "10"],
    "verify rod-impact": ["verify", "rod-impact"],
    "verify two-element": ["verify", "two-element"],
    "modes": ["modes", "models/two_sdof_girders.json"],
    "pushover": ["pushover", "models/three_span_bridge.json", "--node", "bridge.g1.n2", "--to", "0.1"],
    # A 1-D model: --direction y read past its DOF map (the value "y" above).
    "pushover 1-D": ["pushover", "models/two_sdof_girders.json", "--node", "ground_2", "--to",
                     "0.05"],
    "spectrum": ["spectrum", RECORD],
    "batch": ["batch", "sets/adjacent_buildings_pounding.json", "--quiet", "--out", "batch_out"],
    "study rod-impact": ["study", "rod-impact", "--quick", "--repeats", "1"],
    "study stability": ["study", "stability", "--quick"],
    # Options whose help starts "rod-impact-2d:" or "block-belt:" are swept on that benchmark only.
    "verify rod-impact-2d": ["verify", "rod-impact-2d"],
    "verify block-belt": ["verify", "block-belt", "--model", "models/block_on_belt.json",
                          "--speeds", "1", "--periods", "0.5"],
}
BENCHMARK_PREFIX = re.compile(r"^(rod-impact-2d|block-belt):")
# What an option needs beside it to be read at all (help texts that start "--motion:" need
# --motion, which is found from the text).
OPTION_NEEDS = {
    ("run", "--perturbation"): ["--ensemble", "3"],
    ("run", "--robust-spread"): ["--ensemble", "3"],
    ("run", "--jobs"): ["--ensemble", "3"],
    ("spectrum", "--rotation"): ["--pair", RECORD],
    ("verify rod-impact", "--alpha"): ["--integrator", "hht"],
    ("verify rod-impact", "--rho-inf"): ["--integrator", "generalized_alpha"],
    ("verify rod-impact", "--eta"): ["--law", "extended_penalty"],
}
HELP_OPTION = re.compile(r"^  (?:-\w \[ )?(--[a-z][a-z0-9-]*)(?: \])? arg\b")
# A value printed as one: a word of its own (a legend's "(NaN/Inf or ...)" is not).
NONFINITE_TEXT = re.compile(r"(?:^|(?<=[\s=,:]))[-+]?(nan|inf|infinity)(?=[\s,]|$)",
                            re.IGNORECASE | re.MULTILINE)


def value_options(binary, base):
    """(option, needs, names_output) of every option of base's command that takes a value, from
    its --help."""
    command = base[:2] if base[0] in ("verify", "study") else base[:1]
    text = subprocess.run([binary] + command + ["--help"], capture_output=True, text=True).stdout
    # The benchmark whose own options this base sweeps (None: rod-impact's and the shared ones).
    own = base[1] if base[0] == "verify" and BENCHMARK_PREFIX.match(base[1] + ":") else None
    lines = text.splitlines()
    found = []
    for k, line in enumerate(lines):
        m = HELP_OPTION.match(line)
        if not m or m.group(1) == "--help":
            continue
        described = re.sub(r"^\s*\(=[^)]*\)", "", line[m.end():]).strip()
        if not described and k + 1 < len(lines):  # a long default pushes it to the next line
            described = lines[k + 1].strip()
        needs = ["--motion", RECORD] if described.startswith("--motion:") else []
        # An output's name is printed back ("-> inf/"): stdout is no evidence there.
        names_output = re.search(r"\b(folder|write)", described) is not None
        benchmark = BENCHMARK_PREFIX.match(described)
        if base[0] == "verify" and (benchmark.group(1) if benchmark else None) != own:
            continue  # another benchmark's option (verify refuses it: its base sweeps that)
        found.append((m.group(1), needs, names_output))
    return found


def option_argv(binary, key, base, option, needs, value):
    """base with option set to value (replacing base's own value of it) and what it needs."""
    argv = list(base)
    if option in argv:
        at = argv.index(option)
        del argv[at:at + 2]
    argv += OPTION_NEEDS.get((key, option), needs)
    return [binary] + argv + [option + "=" + value]


def nonfinite_in_outputs(folder, stdout, names_output):
    """What is not finite in stdout (unless it prints an output's name) or in the files written
    into folder, or None."""
    # No unmutated run to learn the outputs' shapes from: finite numbers only (learn=True checks
    # that alone).
    shapes = Shapes()
    stripped = stdout.strip()
    if not names_output:
        if stripped.startswith("{"):
            bad = check_json_text(stripped, "stdout", shapes, True)
            if bad:
                return bad
        elif NONFINITE_TEXT.search(stdout):
            return "stdout: " + NONFINITE_TEXT.search(stdout).group(0)
    return check_folder(folder, shapes, True, False)


def classify_option_run(option, names_output, status, stdout, stderr, folder):
    """(outcome, [break classes], detail) of one option's run in its own folder."""
    lines = [x for x in stderr.splitlines() if x.strip()]
    abnormal = classify_abnormal(status, lines)
    if abnormal:
        return abnormal
    written = any(os.scandir(folder))
    if status in (1, 2):
        breaks = []
        if status == 1 and option.lstrip("-") not in stderr:
            breaks.append("usage_without_option")
        if status == 2 and not any(line.startswith("error:") for line in lines):
            breaks.append("refusal_without_path")
        if written:
            breaks.append("written_on_refusal")
        return "refused", breaks, "output written" if written else None
    if status == 0:
        bad = nonfinite_in_outputs(folder, stdout, names_output)
        return "completed", ["silent_nonfinite"] if bad else [], bad
    return "other", ["other_exit"], "exit %d" % status


def sweep_options(args, repo):
    """--options: every value option of every command, each value of OPTION_VALUES."""
    work = tempfile.mkdtemp(prefix="pound_options_")
    root = make_tree(work, repo)
    def in_tree(words):  # paths of the repository as the mirror tree's
        return [os.path.join(root, w) if os.path.exists(os.path.join(root, w)) else w for w in words]

    cases = []
    for key, base in OPTION_BASES.items():
        base = in_tree(base)
        for option, needs, names_output in value_options(args.binary, base):
            needs = in_tree(needs)
            for value in OPTION_VALUES:
                cases.append((key, option, names_output, value,
                              option_argv(args.binary, key, base, option, needs, value)))
    random.Random("options:%s" % args.seed).shuffle(cases)
    start = time.monotonic()
    lock = threading.Lock()
    pending = list(reversed(cases))

    def worker():
        out = []
        while True:
            with lock:
                if not pending or time.monotonic() - start >= args.budget_seconds or (
                        args.limit and len(cases) - len(pending) >= args.limit):
                    return out
                key, option, names_output, value, argv = pending.pop()
            folder = tempfile.mkdtemp(dir=work, prefix="run_")
            status, stdout, stderr = run_bounded(argv, folder, args.timeout, args.memory_gb)
            outcome, breaks, detail = classify_option_run(option, names_output, status, stdout,
                                                          stderr, folder)
            lines = [x for x in stderr.strip().splitlines() if x.strip()]
            result = {"command": key, "option": option, "value": value, "outcome": outcome,
                      "breaks": breaks, "exit": status, "detail": detail,
                      "stderr_last": lines[-1] if lines else "",
                      "replay": " ".join(repr(a) if a == "" or " " in a else a for a in argv)}
            if args.verbose and breaks:
                print("BREAK %s %s %s=%r: exit %s: %s" % (",".join(breaks), key, option, value, status,
                                                          result["stderr_last"] or detail), flush=True)
            shutil.rmtree(folder, ignore_errors=True)
            out.append(result)

    try:
        with ThreadPoolExecutor(max_workers=args.jobs) as pool:
            parts = [pool.submit(worker) for _ in range(args.jobs)]
            results = [r for p in parts for r in p.result()]
    finally:
        shutil.rmtree(work, ignore_errors=True)
    counts = {"runs": len(results), "of": len(cases)}
    for outcome in ("refused", "failed", "completed"):
        counts[outcome] = sum(1 for r in results if r["outcome"] == outcome and not r["breaks"])
    for c in BREAK_CLASSES:
        counts[c] = sum(1 for r in results if c in r["breaks"])
    options = sorted({(r["command"], r["option"]) for r in results})
    print("pound option sweep: seed %d, %.0f s, %d of %d runs (%d options of %d commands), binary %s" % (
        args.seed, time.monotonic() - start, len(results), len(cases), len(options),
        len({c for c, _ in options}), args.binary))
    print("  refused (exit 1, 2)   %6d" % counts["refused"])
    print("  failed loudly (3)     %6d" % counts["failed"])
    print("  completed finite (0)  %6d" % counts["completed"])
    print("contract breaks:")
    for c in BREAK_CLASSES:
        if counts[c] or c in ("crash", "hang", "silent_nonfinite", "usage_without_option"):
            print("  %-24s%6d" % (c, counts[c]))
    broken = [r for r in results if r["breaks"]]
    for r in broken[:40]:
        print("  %s: %s (%s)\n      %s" % (",".join(r["breaks"]), r["stderr_last"] or "(no stderr)",
                                          r["detail"] or "exit %s" % r["exit"], r["replay"]))
    if args.report:
        with open(args.report, "w") as f:
            json.dump({"seed": args.seed, "binary": args.binary, "counts": counts,
                       "results": results}, f, indent=1)
    return 1 if broken and not args.report_only else 0


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    repo = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--binary", default=os.path.join(repo, "build", "src", "pound"))
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--budget-seconds", type=float, default=240.0,
                    help="start no run after this many seconds (default 240)")
    ap.add_argument("--limit", type=int, default=0, help="at most this many mutant runs (0: no limit)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=20.0,
                    help="seconds per run before it counts as a hang (at least 3x the unmutated run + 5)")
    ap.add_argument("--run-time-limit", type=float, default=10.0, help="pound run --time-limit")
    ap.add_argument("--memory-gb", type=float, default=4.0, help="address-space limit per run")
    ap.add_argument("--inputs", nargs="*", help="only these inputs (e.g. models/rod_impact.json)")
    ap.add_argument("--exclude", nargs="*", default=[], help="leave out these inputs (e.g. slow ones)")
    ap.add_argument("--report", help="write every result and the counts to this JSON file")
    ap.add_argument("--keep", help="save each mutant that breaks the contract into this folder")
    ap.add_argument("--report-only", action="store_true", help="exit 0 even when the contract breaks")
    ap.add_argument("--verbose", action="store_true", help="print every contract break as found")
    ap.add_argument("--options", action="store_true",
                    help="sweep every command's options with extreme values instead of the files")
    args = ap.parse_args()
    args.binary = os.path.abspath(args.binary)
    if not os.access(args.binary, os.X_OK):
        print("mutate.py: %s is not an executable (--binary)" % args.binary, file=sys.stderr)
        return 2
    if args.options:
        return sweep_options(args, repo)

    harness = Harness(args, repo)
    try:
        return drive(harness, args)
    finally:
        harness.close()


def drive(harness, args):
    inputs = sorted(os.path.join("models", n) for n in os.listdir(os.path.join(harness.root, "models")))
    inputs += sorted(os.path.join("sets", n) for n in os.listdir(os.path.join(harness.root, "sets")))
    if args.inputs:
        wanted = {os.path.normpath(i) for i in args.inputs}
        inputs = [i for i in inputs if i in wanted]
    if args.exclude:
        unwanted = {os.path.normpath(i) for i in args.exclude}
        inputs = [i for i in inputs if i not in unwanted]
    queues = plan(harness, inputs, args.seed)
    budget_end = harness.start + args.budget_seconds

    # Unmutated runs first: their timing sets the timeout, their outputs the numeric shapes.
    baselines = []
    jobs = []
    for name in inputs:
        for command in SET_COMMANDS if name.startswith("sets") else MODEL_COMMANDS:
            jobs.append((name, command))
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [(name, command, pool.submit(harness.execute, name, command, None, "unmutated", True))
                   for name, command in jobs]
        for name, command, fut in futures:
            result, elapsed = fut.result()
            harness.baseline_time[(name, command)] = elapsed
            baselines.append(result)

    lock = threading.Lock()
    started = [0]

    def take():
        with lock:
            if time.monotonic() >= budget_end or (args.limit and started[0] >= args.limit):
                return None
            live = [q for q in queues.items() if q[1]["next"] < len(q[1]["pairs"])]
            if not live:
                return None
            name, q = min(live, key=lambda item: (item[1]["spent"], item[0]))
            command, mutation = q["pairs"][q["next"]]
            q["next"] += 1
            q["spent"] += harness.baseline_time.get((name, command), 0.1)  # charged now, corrected later
            started[0] += 1
            return name, command, mutation

    def worker():
        out = []
        while True:
            item = take()
            if item is None:
                return out
            name, command, mutation = item
            q = queues[name]
            text = json.dumps(apply_mutation(q["doc"], mutation), indent=1)
            result, elapsed = harness.execute(name, command, text, mutation[3])
            with lock:
                q["spent"] += elapsed - harness.baseline_time.get((name, command), 0.1)
            if args.verbose and result["breaks"]:
                print("BREAK %s %s %s: %s exit %s: %s" % (",".join(result["breaks"]), name, command,
                                                          mutation[3], result["exit"], result["stderr_last"]),
                      flush=True)
            out.append(result)

    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        parts = [pool.submit(worker) for _ in range(args.jobs)]
        results = [r for p in parts for r in p.result()]

    changed = harness.check_originals()
    counts = {"inputs_tried": len(results), "refused": 0, "failed_loudly": 0, "completed_finite": 0}
    for c in BREAK_CLASSES:
        counts[c] = 0
    for r in results:
        for b in r["breaks"]:
            counts[b] += 1
        if not r["breaks"]:
            key = {"refused": "refused", "failed": "failed_loudly", "completed": "completed_finite"}[r["outcome"]]
            counts[key] += 1
    baseline_breaks = [r for r in baselines if r["breaks"]]
    if changed:
        counts["input_overwritten"] += len(changed)

    # Distinct breaks: class, command and the last stderr line with its numbers and names masked.
    groups = {}
    for r in results + baseline_breaks:
        for b in r["breaks"]:
            msg = re.sub(r"\S+\.s\d+\.m\d+\.json", "FILE", r["stderr_last"])
            msg = re.sub(r"[-+]?\d[\d.e+-]*", "N", msg)
            key = (b, r["command"], msg[:160])
            groups.setdefault(key, []).append(r)

    elapsed = time.monotonic() - harness.start
    per_input = {}
    for r in results:
        per_input[r["input"]] = per_input.get(r["input"], 0) + 1
    print("pound mutation test: seed %d, %.0f s, %d runs of %d inputs (%s), binary %s" % (
        args.seed, elapsed, len(results), len(inputs), ", ".join(
            "%s %d" % (os.path.basename(k), v) for k, v in sorted(per_input.items())), args.binary))
    print("  inputs tried          %6d" % counts["inputs_tried"])
    print("  refused (exit 2)      %6d" % counts["refused"])
    print("  failed loudly (3)     %6d" % counts["failed_loudly"])
    print("  completed finite (0)  %6d" % counts["completed_finite"])
    print("contract breaks:")
    for c in BREAK_CLASSES:
        print("  %-24s%6d" % (c, counts[c]))
    for r in baseline_breaks:
        print("  unmutated %s %s: %s exit %s: %s" % (r["input"], r["command"], ",".join(r["breaks"]),
                                                     r["exit"], r["stderr_last"] or r["detail"]))
    for rel in changed:
        print("  the copy of %s changed during the runs" % rel)
    if groups:
        print("distinct breaks (class, command, last stderr line; count; one example):")
        for (b, command, msg), rs in sorted(groups.items(), key=lambda kv: (-len(kv[1]), kv[0])):
            ex = rs[0]
            print("  %s %s: %s  [%d]\n      e.g. %s: %s%s" % (
                b, command, msg or "(no stderr)", len(rs), ex["input"], ex["mutation"],
                " (" + ex["detail"] + ")" if ex["detail"] else ""))
    if args.report:
        with open(args.report, "w") as f:
            json.dump({"seed": args.seed, "seconds": round(elapsed, 1), "binary": args.binary,
                       "counts": counts, "baselines": baselines, "results": results}, f, indent=1)
    broken = sum(counts[c] for c in BREAK_CLASSES) + len(baseline_breaks)
    return 1 if broken and not args.report_only else 0


if __name__ == "__main__":
    sys.exit(main())
