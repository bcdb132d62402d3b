#!/usr/bin/python3
"""What is still moving in an MPM run near its end: per particle file, the particles faster than --speed,
their depth below the local free surface, the share at the tension-cutoff apex of the Mohr-Coulomb surface
(sxx = syy = the cutoff), their share of the kinetic energy, and the slope of the free surface under them.

    scripts/column_collapse/moving_layer.py RUN_DIR [--tau-c S] [--at 6,6.5,7] [--speed 0.05] [--cutoff PA]

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
    print("| t/tau_c | moving | depth below the surface, median / largest (m) | at the apex | share of KE | "
          "largest speed (m/s) | surface slope under them (deg) |")
    print("|---|---|---|---|---|---|---|")
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
        if not moving.any():
            print("| %.2f | 0 | | | | %.3g | |" % (t_star, speed.max()))
            continue
        cols = np.array(sorted(c for c in top if x[moving].min() <= c <= x[moving].max()))
        slope = math.degrees(math.atan(-np.polyfit(cols, [top[c] for c in cols], 1)[0])) if len(cols) > 1 else float("nan")
        print("| %.2f | %d (%.1f %%) | %.2f / %.2f | %.0f %% | %.1f %% | %.3g | %.1f |" % (
            t_star, moving.sum(), 100 * moving.mean(), np.median(depth[moving]), depth[moving].max(),
            100 * apex[moving].mean(), 100 * ke[moving].sum() / ke.sum(), speed.max(), slope))


if __name__ == "__main__":
    main()
