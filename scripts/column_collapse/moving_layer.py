#!/usr/bin/python3
"""What is still moving in an MPM run near its end: per particle file, the particles faster than --speed,
their depth below the local free surface, the share at the tension-cutoff apex of the Mohr-Coulomb surface
(sxx = syy = the cutoff), their volume over the initial one (V0 = mass / density), their share of the
kinetic energy, and the slope of the free surface under them. With --bands, per time also the vertical
stress of every particle by depth band: its mean against the weight of the soil above (rho g depth), its
10th / 90th percentiles and the share at the apex (the spread is the checkerboard).

    scripts/column_collapse/moving_layer.py RUN_DIR [--tau-c S] [--at 6,6.5,7] [--speed 0.05] [--cutoff PA] [--bands]

RUN_DIR is an mpm working folder (mpm.json and results/<uuid>/particles*.h5), e.g. one of
transfer_study.py's runs. --at lists times in units of tau_c (default: every file); the free surface is the
highest particle in each 1 m column of x. Used for docs/study/transfer_comparison.md ("Why it misses the
issue's t/tau_c = 7").
"""
import argparse
import glob
import json
import math
import os
import re
import sys

import h5py
import numpy as np


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run_dir")
    ap.add_argument("--tau-c", type=float, default=math.sqrt(40.0 / 9.81), help="s (default: the paper's column)")
    ap.add_argument("--at", default="", help="times in units of tau_c, comma separated (default: every file)")
    ap.add_argument("--speed", type=float, default=0.05, help="m/s: faster particles count as moving")
    ap.add_argument("--cutoff", type=float, default=None, help="Pa: the tension cutoff (default: from mpm.json)")
    ap.add_argument("--bands", action="store_true", help="also the vertical stress by depth band")
    args = ap.parse_args(argv)
    with open(os.path.join(args.run_dir, "mpm.json")) as f:
        deck = json.load(f)
    dt = deck["analysis"]["dt"]
    cutoff = args.cutoff if args.cutoff is not None else deck["materials"][0].get("tension_cutoff", 0.0)
    uuid = deck["analysis"].get("uuid", "")
    files = glob.glob(os.path.join(args.run_dir, deck["post_processing"].get("path", "results/"), uuid, "particles*.h5"))
    if not files:
        sys.exit("moving_layer.py: error: no particle files under %s" % args.run_dir)
    step = lambda f: int(re.findall(r"(\d+)\.h5$", f)[0])  # noqa: E731
    wanted = [float(x) for x in args.at.split(",") if x]
    density = deck["materials"][0]["density"]
    bands = []
    print("| t/tau_c | moving | depth below the surface, median / largest (m) | at the apex | volume / V0, median / p90 | "
          "share of KE | largest speed (m/s) | surface slope under them (deg) |")
    print("|---|---|---|---|---|---|---|---|")
    for f in sorted(files, key=step):
        t_star = (step(f) + 1) * dt / args.tau_c
        if wanted and not any(abs(t_star - w) < 0.5 * dt * deck["post_processing"]["output_steps"] / args.tau_c + 1e-9
                              for w in wanted):
            continue
        t = h5py.File(f, "r")["table"][()]
        x, y = t["coord_x"], t["coord_y"]
        speed = np.hypot(t["velocity_x"], t["velocity_y"])
        moving = speed > args.speed
        column = np.floor(x).astype(int)
        top = {}
        for c, yy in zip(column, y):
            top[c] = max(top.get(c, -np.inf), yy)
        depth = np.array([top[c] - yy for c, yy in zip(column, y)])
        apex = (np.abs(t["stress_xx"] - cutoff) < 1.0) & (np.abs(t["stress_yy"] - cutoff) < 1.0)
        ke = 0.5 * t["mass"] * speed ** 2
        if args.bands:
            bands.append((t_star, depth, -t["stress_yy"], apex))
        if not moving.any():
            print("| %.2f | 0 | | | | | %.3g | |" % (t_star, speed.max()))
            continue
        ratio = t["volume"][moving] * density / t["mass"][moving]
        cols = np.array(sorted(c for c in top if x[moving].min() <= c <= x[moving].max()))
        slope = math.degrees(math.atan(-np.polyfit(cols, [top[c] for c in cols], 1)[0])) if len(cols) > 1 else float("nan")
        print("| %.2f | %d (%.1f %%) | %.2f / %.2f | %.0f %% | %.3f / %.3f | %.1f %% | %.3g | %.1f |" % (
            t_star, moving.sum(), 100 * moving.mean(), np.median(depth[moving]), depth[moving].max(),
            100 * apex[moving].mean(), np.median(ratio), np.percentile(ratio, 90), 100 * ke[moving].sum() / ke.sum(),
            speed.max(), slope))
    if bands:
        print()
        print("| t/tau_c | depth (m) | particles | mean -syy / (rho g depth) | -syy p10 / p90 (kPa) | at the apex |")
        print("|---|---|---|---|---|---|")
        g = math.sqrt(sum(v * v for v in deck["external_loading_conditions"]["gravity"]))
        for t_star, depth, syy, apex in bands:
            for lo, hi in [(0, 1), (1, 2), (2, 4), (4, 8), (8, 16), (16, 1e9)]:
                m = (depth >= lo) & (depth < hi)
                if not m.any():
                    continue
                print("| %.2f | %g-%s | %d | %.2f | %.1f / %.1f | %.0f %% |" % (
                    t_star, lo, "" if hi > 1e8 else "%g" % hi, m.sum(), syy[m].mean() / (density * g * depth[m].mean()),
                    np.percentile(syy[m], 10) / 1e3, np.percentile(syy[m], 90) / 1e3, 100 * apex[m].mean()))


if __name__ == "__main__":
    main()
