#!/usr/bin/python3
"""Speed against error for the paper's column (issue 37): what each MPM setting costs and how far its runout is
from the finest run, so that a user can pick the cheapest setting that meets an accuracy.

    scripts/column_collapse/speed_vs_error.py [--out results/speed_vs_error] [--cells 2,1,0.5] [--ppd 2,4]
                                              [--transfers flip,apic] [--t-total 20] [--jobs 1] [--report]

Runs the MPM-only column of study.py (50 m x 40 m, a = 0.8, Mohr-Coulomb phi 22.2 deg, K0 geostatic start,
MUSL, CFL 0.5, CB-Geo's frictional base) for every cell size x particles per cell and direction x velocity
transfer, one thread each, to --t-total s (20 s: at rest), and writes into --out:
  speed_vs_error.csv   one row per run: cell, ppd, transfer, particles, final runout (L - L0)/L0 and H/H0, the
                       runout's error relative to the reference run, wall seconds per simulated second, and
                       the work itself, particle-steps per simulated second (exact: particles x steps, which a
                       shared machine's timings are not) with the throughput it ran at;
  speed_vs_error.md    the same as a table;
  speed_vs_error.png   the work per simulated second against the runout error (log-log), with the wall time
                       per simulated second it takes at the runs' median throughput on the right.
The reference is the finest run: the smallest cell with the most particles, APIC (the project's default
transfer; docs/study/transfer_comparison.md found its 0.5 m -> 0.25 m runout change 0.1 %); its own error is 0
and it is drawn at the left edge. Runout: the 98th percentile of the particles' x (study.py's metric).
Timings are single runs of one thread each: with --jobs 2 two runs share the machine's cores (and its memory
bandwidth), so keep --jobs 1 for timings you compare. --report rewrites the table and figure from the runs
already in --out.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
import study  # noqa: E402
from geoflow import pipeline, plots  # noqa: E402

PROG = "column_collapse/speed_vs_error.py"


def run_name(cell, ppd, transfer):
    return "h%g_ppd%d_%s" % (cell, ppd, transfer)


def run_one(bins, out, cell, ppd, transfer, t_total):
    scene = study.Scene(50.0, 40.0, cell, ppd, out_every=1.0, t_total=t_total)
    run = study.run_mpm_only(bins, scene, out, 1, run_name(cell, ppd, transfer), transfer=transfer, keep_times=())
    study.log("%s: %.1f s" % (run_name(cell, ppd, transfer), run["wall"]["mpm"]))


def collect(out, cells, ppds, transfers, t_total):
    rows = []
    for cell in cells:
        for ppd in ppds:
            for transfer in transfers:
                d = os.path.join(out, run_name(cell, ppd, transfer))
                res = os.path.join(d, "results", "column")
                if not os.path.exists(os.path.join(res, "series.csv")) or not os.path.exists(os.path.join(d, "wall.txt")):
                    continue
                s = study.read_series(res)
                if s["time"][-1] < t_total - 0.01:
                    study.log("%s: incomplete (ends at %.2f s), left out" % (os.path.basename(d), s["time"][-1]))
                    continue
                wall = float(open(os.path.join(d, "wall.txt")).read())
                with open(os.path.join(d, "mpm.json")) as f:
                    nsteps = json.load(f)["analysis"]["nsteps"]
                with open(os.path.join(d, "particles.txt")) as f:  # the deck's particle file: its count first
                    particles = int(f.readline())
                rows.append({"cell": cell, "ppd": ppd, "transfer": transfer, "particles": particles,
                             "particle_steps_per_simulated_s": particles * nsteps / t_total,
                             "throughput_m_per_s": particles * nsteps / max(wall, 1e-3) / 1e6,
                             "runout": (s["runout_x_p98"][-1] - 50.0) / 50.0, "height_ratio": s["height_y_p995"][-1] / 40.0,
                             "wall_s": wall, "wall_per_simulated_s": wall / t_total})
    return rows


def reference_of(rows):
    """The finest run: smallest cell, then most particles per cell, APIC before the others."""
    return min(rows, key=lambda r: (r["cell"], -r["ppd"], r["transfer"] != "apic"))


def report(out, rows):
    ref = reference_of(rows)
    for r in rows:
        r["error_percent"] = 100.0 * abs(r["runout"] - ref["runout"]) / abs(ref["runout"])
        r["reference"] = r is ref
    columns = ("cell", "ppd", "transfer", "particles", "runout", "height_ratio", "error_percent", "wall_s",
               "wall_per_simulated_s", "particle_steps_per_simulated_s", "throughput_m_per_s", "reference")
    with open(os.path.join(out, "speed_vs_error.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    lines = ["Reference: %g m cells, %d x %d particles per cell, %s (runout %.4f)." % (
        ref["cell"], ref["ppd"], ref["ppd"], ref["transfer"].upper(), ref["runout"]), "",
             "| cell (m) | particles per cell | transfer | particles | runout (L-L0)/L0 | error | H/H0 | wall s per simulated s "
             "| particle-steps per simulated s | M particle-steps/s |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in sorted(rows, key=lambda r: r["particle_steps_per_simulated_s"]):
        lines.append("| %g | %d x %d | %s | %d | %.4f | %s | %.3f | %.2f | %.3g | %.2f |" % (
            r["cell"], r["ppd"], r["ppd"], r["transfer"].upper(), r["particles"], r["runout"],
            "reference" if r["reference"] else "%.2f %%" % r["error_percent"], r["height_ratio"], r["wall_per_simulated_s"],
            r["particle_steps_per_simulated_s"], r["throughput_m_per_s"]))
    with open(os.path.join(out, "speed_vs_error.md"), "w") as f:
        f.write("\n".join(lines) + "\n")

    plt = plots.pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    floor = 0.5 * min([r["error_percent"] for r in rows if not r["reference"]] or [0.1])
    colors = {c: plt.cm.viridis(i / max(1, len(set(r["cell"] for r in rows)) - 1))
              for i, c in enumerate(sorted(set(r["cell"] for r in rows), reverse=True))}
    for r in rows:
        x = floor if r["reference"] else r["error_percent"]
        y = r["particle_steps_per_simulated_s"]
        ax.plot([x], [y], "o" if r["transfer"] == "apic" else "s", color=colors[r["cell"]],
                markerfacecolor=colors[r["cell"]] if r["ppd"] >= 4 else "white", markersize=7)
        ax.annotate("%g m, %dx%d, %s%s" % (r["cell"], r["ppd"], r["ppd"], r["transfer"].upper(),
                                           " (reference, drawn at the left edge)" if r["reference"] else ""),
                    (x, y), fontsize=6, xytext=(4, 2) if r["transfer"] == "apic" else (4, -8), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("runout error relative to the reference run (%)")
    ax.set_ylabel("work: particle-steps per simulated second")
    # The work is exact; the time it takes is the work over the engine's throughput, which a shared machine's
    # single runs measure only roughly: the right axis converts at the runs' median throughput.
    rate = float(np.median([r["throughput_m_per_s"] for r in rows])) * 1e6
    right = ax.secondary_yaxis("right", functions=(lambda w: w / rate, lambda t: t * rate))
    right.set_ylabel("wall s per simulated s at %.1f M particle-steps/s" % (rate / 1e6))
    ax.set_title("The paper's column (2D, MUSL, CFL 0.5): cost against runout error\n"
                 "circles APIC, squares FLIP; filled 4 x 4 particles per cell, open 2 x 2; colour: cell size", fontsize=8)
    ax.grid(alpha=0.3, which="both")
    fig.savefig(os.path.join(out, "speed_vs_error.png"), bbox_inches="tight", dpi=120)
    plt.close(fig)
    study.log("wrote %s (reference %s)" % (os.path.join(out, "speed_vs_error.png"), run_name(ref["cell"], ref["ppd"], ref["transfer"])))


def fail(message):
    """One line on stderr, exit 2 (nothing run, nothing written)."""
    print("%s: error: %s" % (PROG, message), file=sys.stderr)
    sys.exit(2)


def numbers(text, kind, what):
    try:
        values = [kind(v) for v in text.split(",") if v.strip()]
    except ValueError:
        fail("%s: expected a comma-separated list, got %r" % (what, text))
    if not values or any(not v > 0 for v in values):
        fail("%s: expected positive values, got %r" % (what, text))
    return values


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(REPO, "results", "speed_vs_error"))
    ap.add_argument("--cells", default="2,1,0.5", help="cell sizes, m")
    ap.add_argument("--ppd", default="2,4", help="particles per cell and direction")
    ap.add_argument("--transfers", default="flip,apic", help="velocity transfers (flip, pic, apic)")
    ap.add_argument("--t-total", type=float, default=study.T_TOTAL, help="simulated time of every run, s")
    ap.add_argument("--jobs", type=int, default=1, help="runs at a time (1 for comparable timings)")
    ap.add_argument("--bin", default=None, help="folder with mpm (default build/bin)")
    ap.add_argument("--report", action="store_true", help="only rewrite the table and figure from the runs in --out")
    a = ap.parse_args(argv)
    cells = numbers(a.cells, float, "--cells")
    ppds = numbers(a.ppd, int, "--ppd")
    transfers = [t.strip() for t in a.transfers.split(",") if t.strip()]
    bad = [t for t in transfers if t not in ("flip", "pic", "apic")]
    if bad or not transfers:
        fail("--transfers: expected flip, pic or apic, got %r" % a.transfers)
    if not a.t_total > 0:
        fail("--t-total: expected seconds > 0, got %g" % a.t_total)
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    if not a.report:
        try:
            bins = pipeline.find_bins(a.bin, REPO)
            # The longest runs first, so that a pool of jobs ends together.
            todo = sorted(((c, p, t) for c in cells for p in ppds for t in transfers), key=lambda k: k[0] / k[1])
            with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
                for f in [ex.submit(run_one, bins, out, c, p, t, a.t_total) for c, p, t in todo]:
                    f.result()
        except pipeline.PipelineError as e:
            print("%s: error: %s" % (PROG, e), file=sys.stderr)
            return e.exit_code()
    rows = collect(out, cells, ppds, transfers, a.t_total)
    if not rows:
        fail("no finished run in %s" % out)
    report(out, rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
