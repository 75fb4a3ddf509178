#!/usr/bin/env python3
"""Writes an OpenSees Tcl script of a pound model, to time the two programs side by side.

    pound expand MODEL.json --out EXPANDED.json
    tools/opensees_timing/to_tcl.py EXPANDED.json OUT.tcl [--record-nodes A,B] [--steps N]

The script builds the same structure (nodes, lumped masses, fixities, elastic beams or springs,
one zeroLength element per link with the matching OpenSees material, Rayleigh damping of the
linear elements at the model's two modes, the record as a UniformExcitation), runs Newmark's
average acceleration over the model's steps (--algorithm, --system and --test choose OpenSees'
iteration; the defaults are the fastest found that converge to the same answers), and prints
`steps N ok 0 solve_ms T`: the time of `analyze` alone, as pound_bench times the solve alone.
With --record-nodes it also writes those nodes' x displacements every step (OUT.tcl's name with
.disp.out), to check the two programs agree until the first impact (compare.py).

Covered, because the bundled three-span bridge and the two SDOF girders need them: plane beams
(elasticBeamColumn) and 1-D bars (a spring E A / L), links along x or y with the laws
bilinear_spring (Steel01), elastic_spring (Elastic), hertz_damp (Hertzdamp), restrainer
(ElasticPPGap with damage: its slack grows by the plastic elongation), backfill
(HyperbolicGapMaterial with R_f = 1 - F_ult / (K delta_ult), unloading with K) and kelvin_voigt
(ViscoelasticGap); records in PEER .AT2 form in units of g, scaled by a factor or to a PGA.
Anything else stops with a message naming it. Known differences, which move results only after
the first impact: OpenSees' Hertzdamp takes the impact velocity from the strain rate at the end
of the first step in contact (pound interpolates the instant of first contact), its tangent has
no damping term, and ViscoelasticGap does not clip tension (pound's kelvin_voigt does, by
default) and has no damping term in its tangent either.
"""
import argparse
import json
import math
import os
import sys

G = 9.80665
source = "the model"  # the file read, named in every message


def fail(message):
    """Input this script does not cover or cannot read: exit 2 with the file named."""
    print(f"to_tcl.py: {source}: {message}", file=sys.stderr)
    sys.exit(2)


def hertz_damp_restitution(damping_ratio, step=1e-3):
    """Restitution of F = delta^1.5 (1 + xi delta_dot / v0) on a unit mass from v0 = 1 (the
    law's e does not depend on k_h, the mass or v0), by RK4 to the separation."""
    def force(x, v):
        return -max(x, 0.0) ** 1.5 * (1 + damping_ratio * v)

    x, v = 0.0, 1.0
    while True:
        k1x, k1v = v, force(x, v)
        k2x, k2v = v + step / 2 * k1v, force(x + step / 2 * k1x, v + step / 2 * k1v)
        k3x, k3v = v + step / 2 * k2v, force(x + step / 2 * k2x, v + step / 2 * k2v)
        k4x, k4v = v + step * k3v, force(x + step * k3x, v + step * k3v)
        x_next = x + step / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
        v_next = v + step / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
        if x > 0 and x_next < 0:
            share = x / (x - x_next)
            return -(v + share * (v_next - v))
        x, v = x_next, v_next


def hertz_damp_ratio(law):
    """xi_bar as pound takes it: given, the published 8 (1 - e) / (5 e), or (the default) the
    exact value that makes the impact reach e, found by bisection."""
    if "damping_ratio" in law:
        return law["damping_ratio"]
    e = law["restitution"]
    if law.get("calibration") == "published":
        return 8 * (1 - e) / (5 * e)
    low, high = 0.0, 20.0
    for _ in range(50):
        middle = 0.5 * (low + high)
        if hertz_damp_restitution(middle) > e:
            low = middle
        else:
            high = middle
    return 0.5 * (low + high)


def read_at2(path):
    try:
        lines = open(path).read().splitlines()
    except OSError as error:
        fail(f"its record cannot be read ({error})")
    if len(lines) < 5 or "NPTS" not in lines[3].upper():
        fail(f"{path}: only PEER .AT2 records are covered (line 4 with NPTS and DT)")
    words = lines[3].replace(",", " ").replace("=", " ").upper().split()
    dt = float(words[words.index("DT") + 1])
    values = [float(v) for line in lines[4:] for v in line.split()]
    return dt, values


class Script:
    def __init__(self, model, model_dir):
        self.model = model
        self.model_dir = model_dir
        self.dimension = model["dimension"]
        if self.dimension not in (1, 2):
            fail("only plane (2) and line (1) models are covered")
        self.tag_of = {node["id"]: k + 1 for k, node in enumerate(model["nodes"])}
        self.coordinates = {n["id"]: (n["x"], n.get("y", 0.0)) for n in model["nodes"]}
        self.lines = []
        self.record_values = []
        self.mass = {node: 0.0 for node in self.tag_of}
        self.beam_nodes = set()
        self.linear_elements = []

    def put(self, text):
        self.lines.append(text)

    def structure(self):
        dofs = 3 if self.dimension == 2 else 1
        self.put(f"wipe\nmodel BasicBuilder -ndm {self.dimension} -ndf {dofs}")
        for node, tag in self.tag_of.items():
            x, y = self.coordinates[node]
            self.put(f"node {tag} {x!r}" + (f" {y!r}" if self.dimension == 2 else ""))
        materials = {m["id"]: m for m in self.model.get("materials", [])}
        if self.dimension == 2:
            self.put("geomTransf Linear 1")
        for tag, element in enumerate(self.model.get("elements", []), start=1):
            self.element(tag, element, materials[element["material"]])
        for mass in self.model.get("masses", []):
            self.mass[mass["node"]] += mass["mass"]
        self.supports()
        for node, mass in self.mass.items():
            if mass > 0:
                extra = f" {mass!r} 0.0" if self.dimension == 2 else ""
                self.put(f"mass {self.tag_of[node]} {mass!r}{extra}")

    def element(self, tag, element, material):
        first, second = element["nodes"]
        (xa, ya), (xb, yb) = self.coordinates[first], self.coordinates[second]
        length = math.hypot(xb - xa, yb - ya)
        if element.get("mass", "lumped") != "lumped":
            fail(f"element {element['id']}: only lumped mass is covered")
        per_length = material["density"] * element["area"] + element.get("extra_mass", 0.0)
        self.mass[first] += per_length * length / 2  # half of it at each end, no rotary inertia
        self.mass[second] += per_length * length / 2
        modulus = material["youngs_modulus"]
        a, b = self.tag_of[first], self.tag_of[second]
        if element["type"] == "beam" and self.dimension == 2:
            self.put(f"element elasticBeamColumn {tag} {a} {b} {element['area']!r} {modulus!r} "
                     f"{element['inertia']!r} 1")
            self.beam_nodes.update([first, second])
        elif element["type"] == "truss" and self.dimension == 1:
            self.put(f"uniaxialMaterial Elastic {tag} {modulus * element['area'] / length!r}")
            self.put(f"element zeroLength {tag} {a} {b} -mat {tag} -dir 1")
        else:
            fail(f"element {element['id']}: type {element['type']} is not covered")
        self.linear_elements.append(tag)

    def supports(self):
        fixed = {node: set() for node in self.tag_of}
        for support in self.model.get("supports", []):
            fixed[support["node"]].update(support["fix"])
        for node, directions in fixed.items():
            if self.dimension == 2:
                # a node no beam joins has no rotation in pound: fixed here
                rotation = "rz" in directions or node not in self.beam_nodes
                flags = ["x" in directions, "y" in directions, rotation]
            else:
                flags = ["x" in directions]
            if any(flags):
                self.put(f"fix {self.tag_of[node]} " + " ".join(str(int(f)) for f in flags))

    def links(self):
        tag = 10000
        for link in self.model.get("links", []):
            tag += 1
            self.put(self.material(tag, link))
            first, second = link["nodes"]
            axis = link["axis"]
            along = [k for k, a in enumerate(axis) if a != 0.0]
            if len(along) != 1 or abs(axis[along[0]]) != 1.0:
                fail(f"link {link['id']}: only links along x or y are covered")
            # pound's delta is compression positive along the axis from the first node; a
            # zeroLength element's strain is the second node's displacement less the first's
            a, b = (first, second) if axis[along[0]] > 0 else (second, first)
            self.put(f"element zeroLength {tag} {self.tag_of[a]} {self.tag_of[b]} -mat {tag} "
                     f"-dir {along[0] + 1}")

    def material(self, tag, link):
        law, gap = link["law"], link["gap"]
        kind = law["type"]
        if kind == "bilinear_spring":
            return (f"uniaxialMaterial Steel01 {tag} {law['yield_force']!r} {law['stiffness']!r} "
                    f"{law.get('hardening_ratio', 0.0)!r}")
        if kind == "elastic_spring":
            return f"uniaxialMaterial Elastic {tag} {law['stiffness']!r}"
        if kind == "hertz_damp":
            return (f"uniaxialMaterial Hertzdamp {tag} {law['stiffness']!r} "
                    f"{hertz_damp_ratio(law)!r} {-gap!r}")
        if kind == "restrainer":
            return (f"uniaxialMaterial ElasticPPGap {tag} {law['stiffness']!r} "
                    f"{law['yield_force']!r} {law['slack']!r} {law.get('hardening_ratio', 0.0)!r} "
                    "damage")
        if kind == "backfill":
            stiffness, ultimate = law["initial_stiffness"], law["ultimate_force"]
            failure_ratio = 1 - ultimate / (stiffness * law["ultimate_deformation"])
            return (f"uniaxialMaterial HyperbolicGapMaterial {tag} {stiffness!r} {stiffness!r} "
                    f"{failure_ratio!r} {-ultimate!r} {-gap!r}")
        if kind == "kelvin_voigt" and "restitution" in law:
            first, second = link["nodes"]
            m1, m2 = self.mass[first], self.mass[second]
            effective = m1 * m2 / (m1 + m2)
            log_e = math.log(law["restitution"])
            ratio = -log_e / math.sqrt(math.pi ** 2 + log_e ** 2)
            damping = 2 * ratio * math.sqrt(law["stiffness"] * effective)
            return (f"uniaxialMaterial ViscoelasticGap {tag} {law['stiffness']!r} {damping!r} "
                    f"{-gap!r}")
        fail(f"link {link['id']}: law {kind} is not covered")

    def damping(self):
        for mass in self.model.get("masses", []):
            if "mass_damping" in mass:
                tag = self.tag_of[mass["node"]]
                self.put(f"region {100 + tag} -nodeOnly {tag} "
                         f"-rayleigh {mass['mass_damping']!r} 0 0 0")
        damping = self.model.get("damping")
        if not damping:
            return
        if damping.get("type", "rayleigh") != "rayleigh":
            fail("damping: only Rayleigh damping is covered")
        if "modes" in damping:
            first, second = damping["modes"]
            ratio = damping["ratio"]
            self.put(f"set eigenvalues [eigen -fullGenLapack {second}]")
            self.put(f"set w1 [expr sqrt([lindex $eigenvalues {first - 1}])]")
            self.put(f"set w2 [expr sqrt([lindex $eigenvalues {second - 1}])]")
            self.put(f"set a0 [expr 2.0*{ratio!r}*$w1*$w2/($w1+$w2)]")
            self.put(f"set a1 [expr 2.0*{ratio!r}/($w1+$w2)]")
            self.put('puts "periods [expr 2*acos(-1)/$w1] [expr 2*acos(-1)/$w2] a0 $a0 a1 $a1"')
        elif "periods" not in damping:
            self.put(f"set a0 {damping.get('mass_coefficient', 0.0)!r}")
            self.put(f"set a1 {damping.get('stiffness_coefficient', 0.0)!r}")
        else:
            fail("damping: Rayleigh at two modes or by its coefficients is covered, not periods")
        # C = a0 M + a1 K of the linear elements (pound's Rayleigh matrix leaves links out)
        elements = " ".join(map(str, self.linear_elements))
        self.put(f"region 1 -eleOnly {elements} -rayleigh 0 0 $a1 0")
        masses = " ".join(str(self.tag_of[n]) for n, m in self.mass.items() if m > 0)
        self.put(f"region 2 -nodeOnly {masses} -rayleigh $a0 0 0 0")

    def excitation(self, out_prefix):
        excitations = self.model.get("excitations", [])
        if len(excitations) != 1 or excitations[0].get("units", "g") != "g":
            fail("only one excitation, a record in units of g, is covered")
        excitation = excitations[0]
        dt, values = read_at2(os.path.join(self.model_dir, excitation["record"]))
        scale = excitation.get("scale", {})
        factor = scale.get("factor", 1.0)
        if "pga" in scale:
            factor = scale["pga"] / max(abs(v) for v in values)
        elif set(scale) - {"factor"}:
            fail("excitation scale: only a factor or a PGA is covered")
        if excitation.get("direction", [1.0])[0] != 1.0:
            fail("only an excitation along x is covered")
        self.record_values = values  # written beside the script once all of it is made
        self.put(f"timeSeries Path 1 -dt {dt!r} -filePath {out_prefix}.acc -factor {G * factor!r}")
        self.put("pattern UniformExcitation 1 1 -accel 1")
        return (len(values) - 1) * dt

    def analysis(self, duration, steps, record_nodes, solver, out_prefix):
        analysis = self.model["analysis"]
        integrator = analysis["integrator"]
        if (integrator.get("beta"), integrator.get("gamma")) != (0.25, 0.5):
            fail("only Newmark's average acceleration is covered")
        step = analysis["time_step"]
        steps = steps or math.ceil(analysis.get("duration", duration) / step - 1e-9)
        if record_nodes:
            tags = " ".join(str(self.tag_of[n]) for n in record_nodes)
            self.put(f"recorder Node -file {out_prefix}.disp.out -time -precision 16 -node {tags} "
                     "-dof 1 disp")
        self.put(f"constraints Plain\nnumberer RCM\nsystem {solver.system}\ntest {solver.test}")
        self.put(f"algorithm {solver.algorithm}\nintegrator Newmark 0.5 0.25\nanalysis Transient")
        self.put("set t0 [clock microseconds]")
        self.put(f"set ok [analyze {steps} {step!r}]")
        self.put("set t1 [clock microseconds]")
        self.put(f'puts "steps {steps} ok $ok solve_ms [expr ($t1-$t0)/1000.0]"\nwipe')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("expanded", help="the model as `pound expand` writes it")
    parser.add_argument("tcl", help="the OpenSees script to write")
    parser.add_argument("--record-nodes", default="", help="node ids, comma separated")
    parser.add_argument("--steps", type=int, default=0, help="steps (default: the model's)")
    # The defaults are the fastest of the settings tried on the bundled bridge that give pound's
    # displacements to 1.5e-14 m before the first impact (docs/performance.md)
    parser.add_argument("--test", default="NormUnbalance 1e-2 25",
                        help="OpenSees convergence test (default: %(default)s)")
    parser.add_argument("--system", default="ProfileSPD",
                        help="OpenSees system of equations (default: %(default)s)")
    parser.add_argument("--algorithm", default="ModifiedNewton",
                        help="OpenSees solution algorithm (default: %(default)s)")
    args = parser.parse_args()
    global source
    source = args.expanded
    try:
        model = json.load(open(args.expanded))
    except (OSError, ValueError) as error:
        fail(f"cannot be read as JSON ({error})")
    if not isinstance(model, dict) or "nodes" not in model or "analysis" not in model:
        fail("expected a model as `pound expand` writes it (nodes, analysis)")
    record_nodes = [n for n in args.record_nodes.split(",") if n]
    prefix = os.path.splitext(os.path.abspath(args.tcl))[0]
    try:
        script = Script(model, os.path.dirname(os.path.abspath(args.expanded)))
        for node in record_nodes:
            if node not in script.tag_of:
                fail(f"--record-nodes: no node {node}")
        script.structure()
        script.links()
        script.damping()
        duration = script.excitation(prefix)
        script.analysis(duration, args.steps, record_nodes, args, prefix)
    except (KeyError, TypeError, ValueError, ArithmeticError) as error:
        # wrong types, a missing field, zero masses at a Kelvin-Voigt link, ...
        fail(f"not a model as `pound expand` writes it ({type(error).__name__}: {error})")
    with open(prefix + ".acc", "w") as out:
        out.write("\n".join(repr(v) for v in script.record_values) + "\n")
    with open(args.tcl, "w") as out:
        out.write("\n".join(script.lines) + "\n")


if __name__ == "__main__":
    main()
