#!/usr/bin/python3
"""The tailings dam through the chain (scripts/examples/tailings_dam.tcl): the trends the chain's authors report
(Sordo, Rathje & Kumar, arXiv 2412.08040 and Soil Dyn. Earthq. Eng. 2025, 109371) and the MPM grid's effect.

    /usr/bin/python3 scripts/tailings_dam/study.py [--out results/tailings_dam_study] [--fem DIR] [--jobs 2]
                                                   [--quick] [--duration 10]

One FEM run (or --fem DIR: an earlier run's fem/ folder with the hybrid_run contract's files), then fem2mpm and
mpm (10 s of runout, or --duration S, 1 m cells, 8 x 8 particles per 4 m element: 2 x 2 per cell, Sr = 0.06 sigma'v0,
--effective-friction, the elastic foundation left out with the MPM base at its top: --exclude-material 1 --base-y 8)
for:
  1. the transfer window, T = 4, 6, 8, 10, 12 s: the runout against the depth liquefaction has reached at T
     (the authors: runout measurable once liquefaction reaches ~10 m and growing with its depth);
  2. softening, at T = 12 s: Sr constant at 0.12 sigma'v0 against 0.12 softening to 0.06 sigma'v0 between
     plastic deviatoric strains 0 and 0.5 (the authors: runout substantially larger when the strength softens);
  3. the MPM cell, at T = 12 s: 2 m cells with 2 x 2 particles per cell and with the 1 m runs' particles (4 x 4),
     1 m (2 x 2), 0.5 m with the 1 m runs' particles (1 per cell) and with 2 x 2 per cell (4 times the particles),
     and with --finest 0.25 m with 2 x 2 per cell (16 times the particles, 308,224: the longest run by far): the
     issue asks halving the cell to change the runout by less than 5 %.
Writes study.csv (one row per run), study.png and study.md into --out. Runout: the largest horizontal travel of
a particle in the --duration after T (scripts/hybrid_run.py's definition); liquefied depth: the deepest particle with
r_u >= 0.7 below the ground surface at T. --quick: T = 4 and 12 only (liquefied to ~16 m and ~22 m)
and no other cells; `--quick --duration 40` (four 40 s runs, ~6 min on 2 cores) shows the authors' trends
near rest, which 10 s of early flow hides (README, "A tailings dam through the chain").
--cells-at T: only the MPM cell's effect, at the transfer time T: 2, 1 and 0.5 m cells with 2 x 2 particles per
cell (cells.csv, cells.md); `--cells-at 4 --duration 40` compares runouts at rest (T = 4 s: the flow stops
within 40 s), where a runout at a fixed time while the front still moves carries the front's speed.
"""
import argparse
import csv
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
from geoflow import pipeline, plots  # noqa: E402
import hybrid_run  # noqa: E402

PROG = "tailings_dam/study.py"
MODEL = os.path.join(REPO, "scripts", "examples", "tailings_dam.tcl")
# The foundation (FEM material 1, elastic, 8 m) stays out of MPM, the base at its top (bridge/README.md, "Layers
# and materials": its particles would cost every step and its P-wave speed would halve the time step).
COMMON = ["--units", "kN", "--cfl", "0.4", "--base-friction", "0.6", "--effective-friction",
          "--exclude-material", "1", "--base-y", "8"]


def run_case(bins, fem_dir, out, name, t, options, duration=10.0):
    """fem2mpm at t with COMMON + options into OUT/name, mpm for `duration` s, and the case's row."""
    work = os.path.join(out, name)
    pipeline.remove_outputs(out, (name,))
    wall = pipeline.run_fem2mpm(bins, fem_dir, work, t, COMMON + ["--duration", "%g" % duration] + options)
    wall += pipeline.run_mpm(bins, work, 1)
    rows, _, _ = hybrid_run.runout_series(pipeline.results_dir(work), t, 0.1)
    deck = pipeline.edit_deck(os.path.join(work, "mpm.json"), lambda d: None)
    depth = hybrid_run.liquefied_depth(pipeline.resume_file(os.path.join(work, "mpm.json"), deck), 0.7)
    print("%s: %s: runout %.3g m, liquefied depth %.3g m (%.0f s)" % (PROG, name, rows[-1]["runout"], depth, wall), flush=True)
    return {"case": name, "transfer": t, "runout": rows[-1]["runout"], "moved_mass_fraction": rows[-1]["moved_mass_fraction"],
            "liquefied_depth": depth, "max_speed": rows[-1]["max_speed"], "wall_s": wall}


def cell_study(bins, fem_dir, out, t, duration, jobs):
    """--cells-at T: the runout on 2, 1 and 0.5 m cells (2 x 2 particles per cell) after a transfer at T, and
    how much each halving changes it; cells.csv and cells.md in out."""
    cells = (("2", "4"), ("1", "8"), ("0.5", "16"))
    cases = [("cells_T%g_%sm" % (t, h), t, ["--ppd", ppd, "--cell-size", h, "--residual-ratio", "0.06"]) for h, ppd in cells]
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        rows = list(pool.map(lambda c: run_case(bins, fem_dir, out, *c, duration=duration), cases[::-1]))[::-1]
    columns = ("case", "transfer", "runout", "moved_mass_fraction", "liquefied_depth", "max_speed", "wall_s")
    with open(os.path.join(out, "cells.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        w.writerows(rows)
    lines = ["# The MPM cell, transfer at %g s, %g s of MPM" % (t, duration), "",
             "| cell (m) | runout (m) | moving mass | largest speed at the end (m/s) | wall (s) |", "|---|---|---|---|---|"]
    lines += ["| %s | %.3g | %.1f %% | %.2f | %.0f |" % (h, r["runout"], 100 * r["moved_mass_fraction"], r["max_speed"], r["wall_s"])
              for (h, _), r in zip(cells, rows)]
    lines.append("")
    for (h, _), coarse, fine in zip(cells, rows, rows[1:]):
        lines.append("- halving the cell from %s m changes the runout by %+.1f %%"
                     % (h, 100 * (fine["runout"] - coarse["runout"]) / coarse["runout"]))
    with open(os.path.join(out, "cells.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(REPO, "results", "tailings_dam_study"))
    ap.add_argument("--fem", default=None, help="an earlier run's fem/ folder (skips the FEM run)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--bin", default=None)
    ap.add_argument("--duration", type=float, default=10.0, help="seconds of MPM after each transfer")
    ap.add_argument("--finest", action="store_true", help="also 0.25 m cells with 2 x 2 particles per cell")
    ap.add_argument("--cells-at", type=float, default=None, metavar="T",
                    help="only the MPM cell cases (2, 1, 0.5 m; 2 x 2 particles per cell) at transfer time T")
    a = ap.parse_args()
    if not a.duration > 0:
        print("%s: error: --duration: expected a number of seconds > 0, got %g" % (PROG, a.duration), file=sys.stderr)
        return 2
    if a.cells_at is not None and not a.cells_at >= 0:
        print("%s: error: --cells-at: expected a transfer time >= 0, got %g" % (PROG, a.cells_at), file=sys.stderr)
        return 2
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    try:
        bins = pipeline.find_bins(a.bin, REPO)
        fem_dir = os.path.abspath(a.fem) if a.fem else os.path.join(out, "fem")
        if not a.fem:
            print("%s: FEM: fem_tcl %s %s" % (PROG, MODEL, fem_dir), flush=True)
            pipeline.run_fem_script(bins, MODEL, fem_dir)
        if a.cells_at is not None:
            return cell_study(bins, fem_dir, out, a.cells_at, a.duration, a.jobs)
        window = (4.0, 12.0) if a.quick else (4.0, 6.0, 8.0, 10.0, 12.0)
        base = ["--ppd", "8", "--cell-size", "1"]
        cases = [("T%g" % t, t, base + ["--residual-ratio", "0.06"]) for t in window]
        cases += [("constant_0.12", 12.0, base + ["--residual-ratio", "0.12"]),
                  ("softening_0.12_to_0.06", 12.0, base + ["--residual-ratio", "0.06", "--liquefied-softening", "2", "0", "0.5"])]
        if not a.quick:
            cases += [(name, 12.0, ["--ppd", ppd, "--cell-size", h, "--residual-ratio", "0.06"])
                      for name, h, ppd in (("cell_2m", "2", "4"), ("cell_2m_ppd8", "2", "8"), ("cell_0.5m", "0.5", "8"),
                                           ("cell_0.5m_ppd16", "0.5", "16"))]
            if a.finest:
                cases.append(("cell_0.25m_ppd32", 12.0, ["--ppd", "32", "--cell-size", "0.25", "--residual-ratio", "0.06"]))
            longest = ("cell_0.25m_ppd32", "cell_0.5m_ppd16")  # first, so that the pool ends together
            cases.sort(key=lambda c: longest.index(c[0]) if c[0] in longest else len(longest))
        with ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
            rows = list(pool.map(lambda c: run_case(bins, fem_dir, out, *c, duration=a.duration), cases))
    except pipeline.PipelineError as e:
        print("%s: error: %s" % (PROG, e), file=sys.stderr)
        return e.exit_code()
    columns = ("case", "transfer", "runout", "moved_mass_fraction", "liquefied_depth", "max_speed", "wall_s")
    with open(os.path.join(out, "study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        w.writerows(rows)
    by = {r["case"]: r for r in rows}
    win = [by["T%g" % t] for t in window]
    plt = plots.pyplot()
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.4))
    ax[0].plot([r["liquefied_depth"] for r in win], [r["runout"] for r in win], "o-")
    for r in win:
        ax[0].annotate("T = %g s" % r["transfer"], (r["liquefied_depth"], r["runout"]), fontsize=7)
    ax[0].set_xlabel("liquefied depth at the transfer (m)")
    ax[0].set_ylabel("runout in %g s of MPM (m)" % a.duration)
    ax[0].grid(alpha=0.3)
    cells = [n for n in ("cell_2m", "cell_2m_ppd8", "cell_0.5m", "cell_0.5m_ppd16", "cell_0.25m_ppd32") if n in by]
    names = ["T12", "constant_0.12", "softening_0.12_to_0.06"] + cells
    labels = {"T12": "Sr 0.06", "constant_0.12": "Sr 0.12", "softening_0.12_to_0.06": "0.12 -> 0.06",
              "cell_2m": "2 m, 2x2", "cell_2m_ppd8": "2 m, 4x4", "cell_0.5m": "0.5 m, 1x1",
              "cell_0.5m_ppd16": "0.5 m, 2x2", "cell_0.25m_ppd32": "0.25 m, 2x2"}
    ax[1].bar(range(len(names)), [by[n]["runout"] for n in names])
    ax[1].set_xticks(range(len(names)))
    ax[1].set_xticklabels([labels[n] for n in names], fontsize=7, rotation=20)
    ax[1].set_ylabel("runout (m), T = 12 s")
    ax[1].grid(alpha=0.3, axis="y")
    plots.save(fig, os.path.join(out, "study.png"))
    lines = ["# The tailings dam through the chain", "", "| case | T (s) | liquefied depth (m) | runout (m) | moving mass | wall (s) |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %g | %.2f | %.3g | %.1f %% | %.0f |" % (r["case"], r["transfer"], r["liquefied_depth"], r["runout"],
                                                              100 * r["moved_mass_fraction"], r["wall_s"]))
    grows = all(b["runout"] >= a_["runout"] for a_, b in zip(win, win[1:]))
    lines += ["", "- runout against the liquefied depth: %s" % ("grows with it" if grows else "does not grow monotonically"),
              "- softening: %.3g m (0.12 -> 0.06) against %.3g m (constant 0.12)" % (by["softening_0.12_to_0.06"]["runout"],
                                                                                  by["constant_0.12"]["runout"])]
    for coarse, fine, what in (("cell_2m", "T12", "2 m -> 1 m, 2 x 2 particles per cell"),
                               ("cell_2m_ppd8", "T12", "2 m -> 1 m, the same particles"),
                               ("T12", "cell_0.5m", "1 m -> 0.5 m, the same particles"),
                               ("T12", "cell_0.5m_ppd16", "1 m -> 0.5 m, 2 x 2 particles per cell"),
                               ("cell_0.5m_ppd16", "cell_0.25m_ppd32", "0.5 m -> 0.25 m, 2 x 2 particles per cell")):
        if coarse in by and fine in by:
            change = (by[fine]["runout"] - by[coarse]["runout"]) / by[coarse]["runout"]
            lines.append("- halving the MPM cell (%s) changes the runout by %+.1f %% (moving mass %.0f %% -> %.0f %%)"
                         % (what, 100 * change, 100 * by[coarse]["moved_mass_fraction"], 100 * by[fine]["moved_mass_fraction"]))
    lines += ["", "![study](study.png)"]
    with open(os.path.join(out, "study.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines[-8:]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
