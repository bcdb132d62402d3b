#!/usr/bin/python3
"""Checkerboard remedies on the study's MPM-only column (issue 10 item 4; docs/study/README.md "Checkerboard").

    scripts/column_collapse/checkerboard.py [--cells 2,1,0.5] [--remedies none,cell_volumetric,...]
                                            [--runout-cells 1] [--jobs 2] [--out DIR]

For every cell size and remedy (analysis.stress_smoothing) it runs the study's MPM-only column (50 m x 40 m,
GIMP, MUSL, FLIP, CFL 0.5, 4 x 4 particles per cell; study.py write_mpm_only_deck) to t = --snap + --tail and
reads mpm's checkerboard index at t = --snap (the study's shear snapshot time, 1 s); for the cells in
--runout-cells it also runs to 20 s and reads the normalized runout (L - L0) / L0 (L = 98th percentile of x).
Writes checkerboard.md / checkerboard.json to --out (default results/checkerboard) and, with --figure, the
shear-stress snapshot of every remedy on one cell size (the paper's Figure 9). Each run is single-threaded.
"""
import argparse
import concurrent.futures
import json
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import study  # noqa: E402


def run_one(mpm, out, cell, ppd, remedy, duration, out_every, t_total):
    scene = study.Scene(50.0, 40.0, cell, ppd, t_total=t_total)
    name = "h%g_%s_%gs" % (cell, remedy, duration)
    run = study.run_mpm_only({"mpm": mpm}, scene, out, 1, name, remedy, duration, out_every)
    ser = study.read_series(run["results"])
    return run, ser


def index_at(ser, t):
    k = int(np.argmin(np.abs(ser["time"] - t)))
    return float(ser["checkerboard_index"][k]), float(ser["time"][k])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cells", default="2,1,0.5", help="cell sizes, m (comma list)")
    ap.add_argument("--ppd", type=int, default=4, help="particles per cell and direction")
    ap.add_argument("--remedies", default="none,cell_volumetric,nodal_strain", help="stress_smoothing values")
    ap.add_argument("--snap", type=float, default=1.0, help="time of the index snapshot, s")
    ap.add_argument("--tail", type=float, default=0.5, help="the short runs end at --snap + --tail, s")
    ap.add_argument("--no-short", action="store_true", help="only the runout runs")
    ap.add_argument("--runout-cells", default="1", help="cell sizes that also run to 20 s for the runout ('' none)")
    ap.add_argument("--t-total", type=float, default=20.0, help="end of the runout runs, s")
    ap.add_argument("--cfl", type=float, default=study.CFL, help="analysis.cfl (the study's 0.5)")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time")
    ap.add_argument("--out", default=os.path.join(study.REPO, "results", "checkerboard"))
    ap.add_argument("--bin", default=os.path.join(study.REPO, "build", "bin"))
    ap.add_argument("--figure", default=None, help="write the shear snapshot of every remedy on this cell size")
    args = ap.parse_args(argv)

    study.CFL = args.cfl
    mpm = os.path.join(args.bin, "mpm")
    if not os.access(mpm, os.X_OK):
        sys.exit("checkerboard.py: error: %s not found (build the mpm target first)" % mpm)
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    cells = [float(c) for c in args.cells.split(",") if c.strip()]
    runout_cells = [float(c) for c in args.runout_cells.split(",") if c.strip()]
    remedies = [r for r in args.remedies.split(",") if r.strip()]
    jobs = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        for cell in cells:
            for remedy in remedies:
                if cell in runout_cells:
                    jobs[(cell, remedy, "long")] = ex.submit(run_one, mpm, out, cell, args.ppd, remedy, args.t_total,
                                                             args.snap / 2, args.t_total)
                if not args.no_short:
                    jobs[(cell, remedy, "short")] = ex.submit(run_one, mpm, out, cell, args.ppd, remedy, args.snap + args.tail,
                                                              min(0.1, args.snap / 2), args.t_total)
        rows = []
        for cell in cells:
            for remedy in remedies:
                row = {"cell": cell, "remedy": remedy}
                try:
                    run, ser = jobs[(cell, remedy, "short" if not args.no_short else "long")].result()
                    row["index"], row["t_index"] = index_at(ser, args.snap)
                    row["wall_short"] = run["wall"]["mpm"]
                    row["kex_snap"] = float(ser["kinetic_energy_x"][int(np.argmin(np.abs(ser["time"] - args.snap)))])
                except RuntimeError as e:
                    row["error_short"] = str(e).splitlines()[0]
                if (cell, remedy, "long") in jobs:
                    try:
                        run, ser = jobs[(cell, remedy, "long")].result()
                        row["runout"] = float((ser["runout_x_p98"][-1] - 50.0) / 50.0)
                        row["t_end"] = float(ser["time"][-1])
                        row["index_end"] = float(ser["checkerboard_index"][-1])
                        row["wall_long"] = run["wall"]["mpm"]
                        study.prune_particle_files(run, (args.snap,))
                    except RuntimeError as e:
                        row["error_long"] = str(e).splitlines()[0]
                rows.append(row)
                print(json.dumps(row), flush=True)
    base = {r["cell"]: r for r in rows if r["remedy"] == "none"}
    lines = ["| cell (m) | remedy | checkerboard index at t = %g s | reduction vs none | runout (L-L0)/L0 at %g s | change vs none |"
             % (args.snap, args.t_total), "|---|---|---|---|---|---|"]
    for r in rows:
        b = base.get(r["cell"], {})
        red = "%.1fx" % (b["index"] / r["index"]) if "index" in r and "index" in b and r["index"] > 0 else ""
        ro = "%.3f" % r["runout"] if "runout" in r else r.get("error_long", "")
        dro = "%+.1f %%" % (100 * (r["runout"] / b["runout"] - 1)) if "runout" in r and "runout" in b else ""
        idx = "%.4f" % r["index"] if "index" in r else r.get("error_short", "")
        lines.append("| %g | %s | %s | %s | %s | %s |" % (r["cell"], r["remedy"], idx, red, ro, dro))
    with open(os.path.join(out, "checkerboard.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(out, "checkerboard.json"), "w") as f:
        json.dump(rows, f, indent=1)
    print("\n".join(lines))
    if args.figure:
        figure(out, float(args.figure), args.ppd, remedies, args.snap, args.snap + args.tail)
    return 0


def figure(out, cell, ppd, remedies, snap, duration):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scene = study.Scene(50.0, 40.0, cell, ppd)
    fig, axs = plt.subplots(1, len(remedies), figsize=(3.4 * len(remedies), 3.0), sharey=True)
    for ax, remedy in zip(np.atleast_1d(axs), remedies):
        d = os.path.join(out, "h%g_%s_%gs" % (cell, remedy, duration))
        run = {"results": os.path.join(d, "results", "column"), "kind": "mpm", "t0": 0.0}
        p = study.particles_at(run, snap)
        if p is None:
            continue
        sel = p["coord_x"] < 50.0 * 1.6
        spacing = scene.cell / scene.ppd
        sc = ax.scatter(p["coord_x"][sel], p["coord_y"][sel], c=p["tau_xy"][sel] / 1e3, s=(2.4 * spacing) ** 2,
                        marker="s", cmap="RdBu_r", vmin=-120, vmax=120, linewidths=0)
        ci, _ = index_at(study.read_series(run["results"]), snap)
        ax.set_title("%s, t = %g s\ncheckerboard index %.4f" % (remedy, snap, ci), fontsize=7)
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
    np.atleast_1d(axs)[0].set_ylabel("y (m)")
    fig.colorbar(sc, ax=axs, label="tau_xy (kPa)", shrink=0.8)
    path = os.path.join(out, "shear_stress_h%g.png" % cell)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    print("figure:", path)


if __name__ == "__main__":
    sys.exit(main())
