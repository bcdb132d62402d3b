#!/usr/bin/python3
"""Generates the synthetic "recorded-style" outcrop acceleration of the shaken-slope example and stores it
with its provenance (scripts/shaken_slope/motion/). Deterministic: the same seed gives the same files.

    /usr/bin/python3 scripts/shaken_slope/ground_motion.py [--seed 20261201] [--pga 0.40] [--out DIR]

How (a standard stochastic ground-motion recipe; every step is plain numpy):
1. Gaussian white noise, n = duration / dt samples, numpy.random.default_rng(seed).
2. Filtered in the frequency domain by the Kanai-Tajimi filter (Kanai 1957; Tajimi 1960), ground
   frequency f_g = 2.0 Hz, damping zeta_g = 0.6, times the Clough-Penzien high-pass filter (Clough & Penzien
   1975) f_f = 0.25 Hz, zeta_f = 0.6 (removes the long-period drift of the KT spectrum), and a cosine taper
   from 12 to 15 Hz (the FEM mesh carries 1 m elements: Vs / (8 h) ~ 12 Hz).
3. Multiplied by the Saragoni & Hart (1974) envelope in Boore's (2003) parametrization,
   w(t) = a (t / t_eta)^b exp(-c t / t_eta), b = -eps ln(eta) / (1 + eps (ln eps - 1)), c = b / eps,
   a = (e / eps)^b, with eps = 0.2, eta = 0.05, t_eta = 10 s: peak at eps t_eta = 2 s, 5 % at 10 s.
4. Baseline correction: a + c0 + c1 t with c0, c1 such that the velocity and the displacement at the end are
   zero (trapezoidal integration, exact for the piecewise-linear record), then a 1 s cosine taper at the
   end (the correction repeated after it, so both still end at zero).
5. Scaled to the peak ground acceleration --pga (in g) (the scaling keeps the end velocity zero).

Files (plain numbers, one a line, sample k at t = k dt, so `timeSeries Path -dt 0.01 -filePath f` reads
them): accel.txt (m/s^2), vel.txt (m/s, the trapezoidal integral of accel.txt, used for the Joyner-Chen
force F = rho_r Vs_r A v_outcrop), and motion.json (the parameters above, seed, dt, PGA, PGV, Arias
intensity, significant duration D5-95, end velocity and displacement, numpy version).
"""
import argparse
import json
import math
import os
import sys

import numpy as np

G = 9.81
DEFAULTS = dict(seed=20261201, dt=0.01, duration=12.0, pga=0.40, fg=2.0, zeta_g=0.6, ff=0.25, zeta_f=0.6,
                f_taper=(12.0, 15.0), eps=0.2, eta=0.05, t_eta=10.0, end_taper=1.0)


def saragoni_hart(t, eps, eta, t_eta):
    """Saragoni & Hart (1974) envelope in Boore's (2003) parametrization, peak 1 at t = eps t_eta."""
    b = -eps * math.log(eta) / (1.0 + eps * (math.log(eps) - 1.0))
    c = b / eps
    a = (math.e / eps) ** b
    x = t / t_eta
    return a * x ** b * np.exp(-c * x)


def integrate(a, dt):
    """Trapezoidal cumulative integral starting at 0."""
    return np.concatenate([[0.0], np.cumsum(0.5 * (a[1:] + a[:-1]) * dt)])


def baseline_correct(a, dt):
    """a + c0 + c1 t with the end velocity and end displacement (trapezoidal) zero."""
    t = np.arange(len(a)) * dt
    basis = [np.ones_like(t), t]
    m = np.array([[integrate(f, dt)[-1] for f in basis], [integrate(integrate(f, dt), dt)[-1] for f in basis]])
    rhs = -np.array([integrate(a, dt)[-1], integrate(integrate(a, dt), dt)[-1]])
    c = np.linalg.solve(m, rhs)
    return a + c[0] * basis[0] + c[1] * basis[1]


def generate(p):
    n = int(round(p["duration"] / p["dt"])) + 1
    t = np.arange(n) * p["dt"]
    rng = np.random.default_rng(p["seed"])
    noise = rng.standard_normal(n)
    f = np.fft.rfftfreq(n, p["dt"])
    w = 2.0 * math.pi * f
    wg, wf = 2.0 * math.pi * p["fg"], 2.0 * math.pi * p["ff"]
    kanai_tajimi = (wg ** 2 + 2j * p["zeta_g"] * wg * w) / (wg ** 2 - w ** 2 + 2j * p["zeta_g"] * wg * w)
    clough_penzien = w ** 2 / (wf ** 2 - w ** 2 + 2j * p["zeta_f"] * wf * w)
    f0, f1 = p["f_taper"]
    taper = np.where(f <= f0, 1.0, np.where(f >= f1, 0.0, 0.5 * (1.0 + np.cos(math.pi * (f - f0) / (f1 - f0)))))
    a = np.fft.irfft(np.fft.rfft(noise) * kanai_tajimi * clough_penzien * taper, n)
    a *= saragoni_hart(t, p["eps"], p["eta"], p["t_eta"])
    a = baseline_correct(a, p["dt"])
    tail = t > t[-1] - p["end_taper"]
    a[tail] *= 0.5 * (1.0 + np.cos(math.pi * (t[tail] - (t[-1] - p["end_taper"])) / p["end_taper"]))
    a = baseline_correct(a, p["dt"])
    a *= p["pga"] * G / np.max(np.abs(a))
    return t, a


def describe(t, a, p):
    dt = p["dt"]
    v = integrate(a, dt)
    d = integrate(v, dt)
    arias = math.pi / (2.0 * G) * integrate(a * a, dt)
    d5, d95 = np.interp([0.05 * arias[-1], 0.95 * arias[-1]], arias, t)
    return {"pga_g": float(np.max(np.abs(a)) / G), "pga_time_s": float(t[np.argmax(np.abs(a))]),
            "pgv_m_s": float(np.max(np.abs(v))), "pgd_m": float(np.max(np.abs(d))),
            "arias_intensity_m_s": float(arias[-1]), "significant_duration_D5_95_s": float(d95 - d5),
            "end_velocity_m_s": float(v[-1]), "end_displacement_m": float(d[-1])}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seed", type=int, default=DEFAULTS["seed"])
    ap.add_argument("--pga", type=float, default=DEFAULTS["pga"], help="peak ground acceleration, g")
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "motion"))
    args = ap.parse_args(argv)
    if not args.pga > 0.0:
        ap.error("--pga: expected a value > 0, got %g" % args.pga)
    p = dict(DEFAULTS, seed=args.seed, pga=args.pga)
    t, a = generate(p)
    v = integrate(a, p["dt"])
    os.makedirs(args.out, exist_ok=True)
    for name, values in (("accel.txt", a), ("vel.txt", v)):
        tmp = os.path.join(args.out, name + ".tmp")
        np.savetxt(tmp, values, fmt="%.9e")
        os.replace(tmp, os.path.join(args.out, name))
    info = {"what": "synthetic outcrop acceleration for scripts/shaken_slope (not a real record)",
            "generator": "scripts/shaken_slope/ground_motion.py", "command": " ".join(["ground_motion.py"] + list(argv or sys.argv[1:])),
            "numpy": np.__version__, "samples": len(a), "dt_s": p["dt"], "units": {"accel.txt": "m/s^2", "vel.txt": "m/s"},
            "parameters": {k: p[k] for k in DEFAULTS}, "measures": describe(t, a, p)}
    tmp = os.path.join(args.out, "motion.json.tmp")
    with open(tmp, "w") as f:
        json.dump(info, f, indent=1)
        f.write("\n")
    os.replace(tmp, os.path.join(args.out, "motion.json"))
    print("ground_motion.py: %d samples, PGA %.3f g at %.2f s, PGV %.3f m/s, D5-95 %.1f s, end v %.1e m/s -> %s"
          % (len(a), info["measures"]["pga_g"], info["measures"]["pga_time_s"], info["measures"]["pgv_m_s"],
             info["measures"]["significant_duration_D5_95_s"], info["measures"]["end_velocity_m_s"], args.out))


if __name__ == "__main__":
    main()
