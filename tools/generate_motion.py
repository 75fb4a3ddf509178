#!/usr/bin/env python3
"""Generate a synthetic (not recorded) ground-acceleration record as a PEER-style .AT2 file.

Python 3 standard library only. The record is a stationary band-limited random process times a
time envelope, baseline-corrected and scaled to a peak ground acceleration:

1. Stationary process by the spectral representation method (Shinozuka & Deodatis 1991):
   a sum of cosines with random phases whose amplitudes follow the Kanai-Tajimi spectrum with
   the Clough-Penzien high-pass filter (which removes the unbounded low-frequency content
   Kanai-Tajimi has for displacement),
       S(w) = S0 (wg^4 + 4 zg^2 wg^2 w^2) / ((wg^2 - w^2)^2 + 4 zg^2 wg^2 w^2)
                 * w^4 / ((wf^2 - w^2)^2 + 4 zf^2 wf^2 w^2),
   with the firm- and soft-soil parameters of Der Kiureghian & Neuenhofer (1992), EESD 21,
   band-limited to 0.2-25 Hz (below 0.2 Hz the ground displacement would drift by metres).
   Frequencies are jittered within their bins so the sum does not repeat within the record.
2. Envelope of Jennings, Housner & Tsai (1968): (t/t1)^2 rise to t1 = 0.1 D, a strong phase to
   t2 = 0.45 D, then exp(-c (t - t2)) decaying to 2 % at the end.
3. Baseline correction: a correction shaped like the envelope, e(t) (alpha + beta t), is
   removed with alpha and beta chosen so that the final ground velocity and displacement are
   zero (integrated exactly for the piecewise-linear acceleration).
4. Scaled so that max |a| is the target PGA.

The file has 4 header lines (which say it is synthetic and give the parameters), then
"NPTS=  N, DT=   .0100 SEC", then the values in g, 5 per line in E format.

Example:
    python3 tools/generate_motion.py --seed 1 --duration 25 --dt 0.01 --pga 0.4 \\
        --ground firm --out ground_motions/synthetic_firm_01.AT2
"""

import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_common import OutputError, Parser, report  # noqa: E402

PROG = "generate_motion.py"

# Kanai-Tajimi (wg [rad/s], zg) and Clough-Penzien (wf [rad/s], zf) parameters,
# Der Kiureghian & Neuenhofer (1992).
GROUND = {
    "firm": {"wg": 15.0, "zg": 0.6, "wf": 1.5, "zf": 0.6},
    "soft": {"wg": 5.0, "zg": 0.2, "wf": 0.5, "zf": 0.6},
}
LOWEST_FREQUENCY_HZ = 0.2
HIGHEST_FREQUENCY_HZ = 25.0  # (below Nyquist for dt <= 0.02 s)
VALUES_PER_LINE = 5


def spectral_density(w, p):
    """One-sided Kanai-Tajimi x Clough-Penzien spectrum shape at circular frequency w (S0 = 1)."""
    wg2, wf2 = p["wg"] ** 2, p["wf"] ** 2
    kt = (wg2 * wg2 + 4 * p["zg"] ** 2 * wg2 * w * w) / (
        (wg2 - w * w) ** 2 + 4 * p["zg"] ** 2 * wg2 * w * w)
    cp = w ** 4 / ((wf2 - w * w) ** 2 + 4 * p["zf"] ** 2 * wf2 * w * w)
    return kt * cp


def stationary_process(rng, times, p, duration, dt):
    """Sum of cosines with random phases and the spectrum's amplitudes."""
    w_min = 2 * math.pi * LOWEST_FREQUENCY_HZ
    w_max = 2 * math.pi * min(HIGHEST_FREQUENCY_HZ, 0.5 / dt)
    dw = math.pi / duration  # bins half the fundamental: the sum does not repeat within D
    a = [0.0] * len(times)
    for k in range(int(math.ceil(w_min / dw)), int(w_max / dw)):
        w = (k + rng.random()) * dw
        amplitude = math.sqrt(2 * spectral_density(w, p) * dw)
        phase = 2 * math.pi * rng.random()
        for i, t in enumerate(times):
            a[i] += amplitude * math.cos(w * t + phase)
    return a


def envelope(t, duration):
    """Jennings, Housner & Tsai (1968) envelope, 1 during the strong phase."""
    t1, t2 = 0.1 * duration, 0.45 * duration
    decay = math.log(1 / 0.02) / (duration - t2)
    if t < t1:
        return (t / t1) ** 2
    if t <= t2:
        return 1.0
    return math.exp(-decay * (t - t2))


def final_velocity_and_displacement(a, dt):
    """Exact integration of the piecewise-linear acceleration from rest."""
    v = d = 0.0
    for k in range(len(a) - 1):
        d += dt * v + dt * dt / 6 * (2 * a[k] + a[k + 1])
        v += dt / 2 * (a[k] + a[k + 1])
    return v, d


def baseline_correct(a, times, shape, dt):
    """Removes shape(t) (alpha + beta t) so that the final velocity and displacement are zero."""
    v0, d0 = final_velocity_and_displacement(a, dt)
    v1, d1 = final_velocity_and_displacement(shape, dt)
    shaped_t = [s * t for s, t in zip(shape, times)]
    v2, d2 = final_velocity_and_displacement(shaped_t, dt)
    det = v1 * d2 - v2 * d1
    alpha = (v0 * d2 - v2 * d0) / det
    beta = (v1 * d0 - v0 * d1) / det
    return [x - s * (alpha + beta * t) for x, s, t in zip(a, shape, times)]


def generate(seed, duration, dt, pga, ground):
    rng = random.Random(seed)
    n = int(round(duration / dt)) + 1
    times = [k * dt for k in range(n)]
    process = stationary_process(rng, times, GROUND[ground], duration, dt)
    shape = [envelope(t, duration) for t in times]
    a = baseline_correct([x * s for x, s in zip(process, shape)], times, shape, dt)
    peak = max(abs(x) for x in a)
    return [x * pga / peak for x in a]


def at2_text(values, args):
    p = GROUND[args.ground]
    lines = [
        "SYNTHETIC GROUND MOTION (NOT A RECORDED EARTHQUAKE), pound tools/generate_motion.py",
        "seed %d, %s ground (Kanai-Tajimi wg=%g rad/s zg=%g, Clough-Penzien wf=%g rad/s zf=%g), "
        "duration %g s, PGA %g g" % (args.seed, args.ground, p["wg"], p["zg"], p["wf"], p["zf"],
                                     args.duration, args.pga),
        "ACCELERATION TIME SERIES IN UNITS OF G",
        # PEER writes DT without its leading zero: "NPTS=   5372, DT=   .0100 SEC".
        "NPTS=%7d, DT=%8s SEC" % (len(values), ("%.4f" % args.dt).lstrip("0")),
    ]
    for start in range(0, len(values), VALUES_PER_LINE):
        # + 0.0 turns -0.0 into 0.0
        lines.append("".join("%15.7E" % (x + 0.0) for x in values[start:start + VALUES_PER_LINE]))
    return "\n".join(lines) + "\n"


def main(argv):
    parser = Parser(prog=PROG, description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, required=True, help="random seed")
    parser.add_argument("--duration", type=float, default=25.0, help="record length [s]")
    parser.add_argument("--dt", type=float, default=0.01, help="time step [s]")
    parser.add_argument("--pga", type=float, default=0.4, help="peak ground acceleration [g]")
    parser.add_argument("--ground", choices=sorted(GROUND), default="firm",
                        help="Kanai-Tajimi / Clough-Penzien soil parameters")
    parser.add_argument("--out", required=True, help="output .AT2 file")
    args = parser.parse_args(argv)
    if not (args.duration > 0 and args.dt > 0 and args.pga > 0 and args.duration > 10 * args.dt):
        parser.error("--duration, --dt and --pga must be positive, and the record >= 10 steps")
    values = generate(args.seed, args.duration, args.dt, args.pga, args.ground)
    try:
        with open(args.out, "w", newline="\n") as out:
            out.write(at2_text(values, args))
    except OSError as error:
        return report(PROG, OutputError(f"{args.out}: cannot write: {error}"))
    written = [float(x) * 9.80665 for line in at2_text(values, args).splitlines()[4:]
               for x in line.split()]  # the values as rounded in the file, in m/s^2
    v, d = final_velocity_and_displacement(written, args.dt)
    print("%s: %d points, PGA %.4f g, final velocity %.2e m/s, displacement %.2e m"
          % (args.out, len(written), max(abs(x) for x in written) / 9.80665, v, d))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
