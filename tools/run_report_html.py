"""report.html of a `pound run` folder: one self-contained page (figures inlined as PNG data, no
external file, script or font) with the run's facts, its warnings, the excitations the model file
names, the tables of links, joints, piers and storeys, the energy balance, the ensemble's spread
when there is one, and every figure plot_run.py drew. Attach it to a design note as it is.

Used by plot_run.py, which writes it after the figures."""

import base64
import html
import json
import os

from plot_common import MODEL_UNITS, units_of, write_atomically

STYLE = """
body { font-family: sans-serif; margin: 2em auto; max-width: 70em; color: #222; }
h1 { font-size: 1.4em; } h2 { font-size: 1.15em; margin-top: 1.6em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; font-size: 0.85em; margin: 0.5em 0; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: right; }
th:first-child, td:first-child { text-align: left; }
th { background: #f0f0f0; }
.failed { color: #b00; font-weight: bold; } .warning { color: #a50; }
.note { color: #666; font-size: 0.85em; }
figure { margin: 1em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
"""

# (key in summary, column heading, dimension or None), per table; a column is shown when any row
# has it. A heading names its unit; a hinge's row (summary "rotational") gives its moments and
# rotations with their units in the cells of the force and length columns.
LINK_COLUMNS = [("role", "role", None), ("impacts", "impacts", None),
                ("peak_force", "peak force", "force"),
                ("peak_penetration", "peak penetration", "length"),
                ("peak_tension", "peak tension", "force"),
                ("peak_opening", "peak opening", "length"),
                ("peak_deformation", "peak deformation", "length"),
                ("residual_deformation", "residual deformation", "length"),
                ("impulse", "impulse", "impulse"), ("work", "work", "energy"),
                ("ductility", "ductility", None),
                ("hysteretic_energy", "hysteretic energy", "energy"),
                ("first_contact", "first contact", "time"),
                ("last_contact", "last contact", "time")]
JOINT_COLUMNS = [("peak_opening", "peak opening", "length"),
                 ("peak_closing", "peak closing", "length"),
                 ("peak_seat_movement", "seat movement", "length"),
                 ("seat_width", "seat width", "length"), ("unseating_margin", "margin", "length"),
                 ("residual_opening", "residual opening", "length"),
                 ("peak_girder_acceleration", "girder end acceleration (absolute)",
                  "acceleration")]
DRIFT_COLUMNS = [("height", "height", "length"), ("peak_drift", "peak drift", "length"),
                 ("drift_ratio", "drift ratio", None),
                 ("residual_drift", "residual drift", "length"),
                 ("ductility", "ductility", None),
                 ("elastic_demand_ratio", "elastic demand ratio", None),
                 ("curvature_ductility", "curvature ductility", None),
                 ("peak_absolute_acceleration", "peak acceleration (absolute)", "acceleration"),
                 ("peak_shear", "peak shear", "force"),
                 ("peak_base_moment", "peak base moment", "moment")]
ENSEMBLE_COLUMNS = [("unperturbed", "unperturbed", None), ("median", "median", None),
                    ("p16", "16 %", None), ("p84", "84 %", None), ("min", "min", None),
                    ("max", "max", None), ("spread", "spread", None),
                    ("deviation", "unperturbed from median", None)]
# A hinge's force and deformation are a moment and a rotation.
ROTATIONAL = {"force": "moment", "length": "angle"}


def escape(value):
    return html.escape(str(value), quote=True)


def cell(value):
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return f"{value:.4g}"
    return escape(value)


def heading(title, dimension, units):
    unit = units.get(dimension) if dimension else None
    return f"{title} [{unit}]" if unit and unit != MODEL_UNITS else title


def table(rows, columns, units, first="id"):
    """An HTML table of `rows` (dicts): `first` and each column some row has, headed with its
    unit in `units` (plot_common.units_of)."""
    shown = [column for column in columns if any(column[0] in row for row in rows)]
    if not rows:
        return "<p class=\"note\">none</p>"
    head = "".join(f"<th>{escape(heading(title, dimension, units))}</th>"
                   for _, title, dimension in shown)

    def value(row, key, dimension):
        if key not in row:
            return ""
        if row.get("rotational") and dimension in ROTATIONAL:
            unit = units.get(ROTATIONAL[dimension], MODEL_UNITS)
            return cell(row[key]) + ("" if unit == MODEL_UNITS else " " + escape(unit))
        return cell(row[key])

    body = "".join(
        "<tr><td>" + escape(row.get(first, "")) + "</td>" +
        "".join(f"<td>{value(row, key, dimension)}</td>" for key, _, dimension in shown) +
        "</tr>" for row in rows)
    return f"<table><tr><th>{escape(first)}</th>{head}</tr>{body}</table>"


def facts(summary, units):
    status = summary.get("status", "?")
    lines = [("model", summary.get("model")), ("status", status),
             ("integrator", summary.get("integrator")),
             (heading("time step", "time", units), summary.get("time_step")),
             (heading("duration", "time", units), summary.get("duration")),
             ("DOFs", summary.get("dofs")),
             ("steps", summary.get("steps")), ("Newton iterations", summary.get("newton_iterations")),
             ("solve time [s]", summary.get("run_time_s"))]
    if status == "failed":
        lines.append((heading("failed at", "time", units), summary.get("failure_time")))
        lines.append(("reason", summary.get("failure")))
    rows = "".join(f"<tr><td>{escape(name)}</td><td>{cell(value)}</td></tr>"
                   for name, value in lines if value is not None)
    css = " class=\"failed\"" if status == "failed" else ""
    return f"<table{css}>{rows}</table>"


def excitations(summary, folder):
    """The excitations as the run applied them (summary.json), else as the model file names them."""
    applied = summary.get("excitations")
    if isinstance(applied, list) and applied:
        rows = []
        for e in applied:
            if not isinstance(e, dict):
                continue
            scaling = e.get("scaling") if isinstance(e.get("scaling"), dict) else {}
            rows.append({"record": e.get("record", ""), "sha1": e.get("sha1", ""),
                         "format": e.get("format", ""), "units": e.get("units", ""),
                         "scaling": ", ".join("as recorded" if k == "as_recorded" else
                                              f"{k} {v}" for k, v in scaling.items()),
                         "factor": e.get("factor"), "pga_g": e.get("pga_g"),
                         "replaced_by": e.get("replaced_by", "")})
        return (table(rows, [("sha1", "SHA-1", None), ("format", "format", None),
                             ("units", "units", None), ("scaling", "scaling asked", None),
                             ("factor", "factor applied", None), ("pga_g", "PGA [g]", None),
                             ("replaced_by", "replaced by", None)], {}, first="record") +
                "<p class=\"note\">As the run applied them (summary.json); <code>sha1sum</code> "
                "of a record file gives its SHA-1.</p>")
    model = summary.get("model")
    candidates = [model, os.path.join(folder, model)] if isinstance(model, str) else []
    for path in candidates:
        if path and os.path.isfile(path):
            try:
                with open(path, encoding="utf-8") as f:
                    spec = json.load(f)
            except (OSError, ValueError):
                break
            items = spec.get("excitations") if isinstance(spec, dict) else None
            if not isinstance(items, list) or not items:
                return "<p class=\"note\">The model has no excitations (initial velocities only).</p>"
            rows = [{"record": e.get("record", ""), "units": e.get("units", ""),
                     "scale": json.dumps(e.get("scale")) if "scale" in e else "",
                     "direction": json.dumps(e.get("direction")) if "direction" in e else ""}
                    for e in items if isinstance(e, dict)]
            return (table(rows, [("units", "units", None), ("scale", "scale", None),
                                 ("direction", "direction", None)], {}, first="record") +
                    f"<p class=\"note\">As {escape(path)} names them (a <code>--motion</code> "
                    "given to <code>pound run</code> replaced the first).</p>")
    return "<p class=\"note\">The model file was not found from here: see summary.json.</p>"


def energy(summary, units):
    """The energy terms in the energy's unit; the errors and fractions are ratios."""
    terms = summary.get("energy")
    if not isinstance(terms, dict):
        return "<p class=\"note\">none</p>"
    rows = "".join(
        f"<tr><td>{escape(heading(k, None if 'error' in k or 'fraction' in k else 'energy', units))}"
        f"</td><td>{cell(v)}</td></tr>"
        for k, v in terms.items() if isinstance(v, (int, float)))
    return f"<table>{rows}</table>"


def ensemble_table(ensemble):
    """The headline quantities of plot_run.load_ensemble's result, least robust first."""
    if not ensemble or not ensemble.get("quantities"):
        return ""
    rows = sorted((dict(q) for q in ensemble["quantities"]),
                  key=lambda q: -(q.get("spread") or 0.0))
    for row in rows:
        row["robust"] = bool(row.get("robust"))
    failed = int(ensemble.get("failed") or 0)
    failures = (f" {failed} of the {ensemble.get('copies')} copies failed and are left out: if they "
                "were collapses, the medians are biased low." if failed else "")
    perturbed = escape(ensemble.get("perturbed") or "the records")
    return ("<h2>Robustness over the ensemble</h2><p class=\"note\">Headline numbers over copies "
            f"with {perturbed} perturbed at the level of numerical noise, least robust first: read "
            "the late pounding peaks as distributions." + failures + "</p>" +
            table(rows, ENSEMBLE_COLUMNS + [("robust", "robust", None)], {}, first="path"))


def figures(paths):
    parts = []
    for path in paths:
        with open(path, "rb") as f:
            data = base64.b64encode(f.read()).decode("ascii")
        name = escape(os.path.basename(path))
        parts.append(f"<figure><img alt=\"{name}\" src=\"data:image/png;base64,{data}\">"
                     f"<figcaption class=\"note\">{name}</figcaption></figure>")
    return "".join(parts) or "<p class=\"note\">none</p>"


def units_note(units):
    if MODEL_UNITS in (units["force"], units["length"], units["time"]):
        return ("A heading without a unit is in the model's own units (its forces and energies "
                "have none unless the model names a mass unit).")
    return "Each heading names its unit (the model's)."


def write_report(folder, summary, pngs, ensemble=None):
    """Writes folder/report.html; returns its path."""
    title = summary.get("title") or summary.get("model") or os.path.basename(folder)
    warnings = summary.get("warnings") or []
    warning_items = "".join(
        f"<li class=\"warning\">{escape(w.get('warning', w) if isinstance(w, dict) else w)}</li>"
        for w in warnings)
    units = units_of(summary)
    piers = [dict(p, kind="pier") for p in summary.get("piers") or []]
    storeys = [dict(s, kind="storey") for s in summary.get("storeys") or []]
    page = (
        "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\">"
        f"<title>pound run: {escape(title)}</title><style>{STYLE}</style></head><body>"
        f"<h1>{escape(title)}</h1>{facts(summary, units)}"
        "<h2>Warnings</h2>" + (f"<ul>{warning_items}</ul>" if warnings else "<p>none</p>") +
        "<h2>Excitations</h2>" + excitations(summary, folder) +
        "<h2>Links</h2>" + table(summary.get("links") or [], LINK_COLUMNS, units) +
        "<h2>Joints</h2>" + table(summary.get("joints") or [], JOINT_COLUMNS, units) +
        "<h2>Piers and storeys</h2>" +
        table(piers + storeys, [("kind", "kind", None)] + DRIFT_COLUMNS, units) +
        "<h2>Energy balance</h2>" + energy(summary, units) + ensemble_table(ensemble) +
        "<h2>Figures</h2>" + figures(pngs) +
        f"<p class=\"note\">{escape(units_note(units))} Written by tools/plot_run.py from "
        "summary.json and the histories in this folder.</p></body></html>\n")
    path = os.path.join(folder, "report.html")

    def write(temporary):
        with open(temporary, "w", encoding="utf-8") as f:
            f.write(page)

    write_atomically(path, write)
    return path
