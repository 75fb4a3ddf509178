#!/usr/bin/env python3
"""Run time and accuracy of adaptive against fixed time steps on a model with records.

usage: python3 tools/adaptive_saving.py POUND_BINARY MODEL.json REFERENCE_DT

Runs the model at a fixed reference step REFERENCE_DT, at 0.5, 1, 2, 4 times its own step and
adaptively (tolerances 1e-3, 1e-4, 1e-5), each three times (best CPU time of the process), and
prints a Markdown table: steps, CPU seconds, the worst relative error of the peak drifts, joint
openings and seat movements against the reference, and the error of the peak contact force.
"""
import json, os, resource, subprocess, sys, tempfile

if len(sys.argv) != 4:
    sys.exit(__doc__)
pound, model_path, ref_dt_text = sys.argv[1], sys.argv[2], sys.argv[3]
work = tempfile.mkdtemp(prefix='pound_adaptive_')
base = json.load(open(model_path))
rec = base['excitations'][0]['record']
base['excitations'][0]['record'] = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(model_path)), rec))
name = os.path.basename(model_path).replace('.json','')
def run(tag, dt, tol):
    m = json.loads(json.dumps(base))
    m['analysis']['time_step'] = dt
    if tol: m['analysis']['adaptive'] = {"tolerance": tol}
    path = f'{work}/{name}_{tag}.json'
    json.dump(m, open(path, 'w'))
    best = None
    for _ in range(3):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run([pound, 'run', path, '--out', f'{work}/o_{name}_{tag}', '-q'], check=True, stderr=subprocess.DEVNULL)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        best = cpu if best is None else min(best, cpu)
    d = json.load(open(f'{work}/o_{name}_{tag}/summary.json'))
    resp = {}
    for p in d.get('piers', []) + d.get('storeys', []): resp['drift ' + p['id']] = p['peak_drift']
    for j in d.get('joints', []): resp['open ' + j['id']] = j['peak_opening']; resp['seat ' + j['id']] = j['peak_seat_movement']
    force = max(l['peak_force'] for l in d['links'])
    return dict(steps=d['steps'], cpu=best, resp=resp, force=force, solve=d['run_time_s'])
ref_dt = float(ref_dt_text); default_dt = base['analysis']['time_step']
ref = run('ref', ref_dt, None)
rows = []
for tag, dt, tol in [('fixed_x0.5', default_dt/2, None), ('fixed', default_dt, None), ('fixed_x2', default_dt*2, None), ('fixed_x4', default_dt*4, None),
                     ('adaptive_1e-3', default_dt, 1e-3), ('adaptive_1e-4', default_dt, 1e-4), ('adaptive_1e-5', default_dt, 1e-5)]:
    r = run(tag, dt, tol)
    err = max(abs(r['resp'][k]/ref['resp'][k]-1) for k in ref['resp'] if ref['resp'][k] > 0)
    ferr = abs(r['force']/ref['force']-1)
    rows.append((tag, dt, r['steps'], r['cpu'], err, ferr))
print(f"{name}: reference dt {ref_dt}: {ref['steps']} steps, {ref['cpu']:.2f} s CPU")
print("| run | first dt [s] | steps | CPU [s] | worst peak drift/opening/seat error | peak contact force error |")
print("|---|---|---|---|---|---|")
for tag, dt, steps, cpu, err, ferr in rows:
    print(f"| {tag} | {dt:g} | {steps} | {cpu:.3f} | {err:.2e} | {ferr:.2e} |")
import shutil
shutil.rmtree(work, ignore_errors=True)
