#!/usr/bin/python3
"""FLIP, PIC, a 2 % PIC blend and APIC side by side on MPM-only column collapses (issue 10 item 3).

    scripts/column_collapse/transfer_study.py [--out DIR] [--jobs N] [--aspect 3,0.8] [--transfers flip,pic,blend,apic]
                                              [--halved apic] [--doubled ''] [--tau 7] [--smoothing none]
                                              [--base friction] [--normal-lag L,V*]

Each run: the paper's soil (study.py), GIMP cells of 1 m (0.5 m for --halved, 2 m for --doubled transfers), 4 x 4 particles
per cell, MUSL, CFL 0.5, base friction tan(phi), analysis.stress_smoothing --smoothing, the base --base
(friction: y-velocity 0 and Coulomb friction, CB-Geo's; contact: one-sided frictional contact), to t = --tau * tau_c (tau_c = sqrt(H0 / g)). Columns:
a = 3 is 10 m x 30 m, a = 0.8 the paper's 50 m x 40 m. Per run: runout (L - L0)/L0 and PE/PE0 at the end, the
largest particle speed and KE/PE0 at the end, the time (t/tau_c) after which the run stays at rest
(max speed < 0.05 m/s and KE/PE0 < 1e-5), and the wall time per step (on whatever machine ran it). Writes
summary.md (a Markdown table), summary.json and rest.png (each run's largest speed and KE/PE0 against t/tau_c) to
--out.
"""
import argparse
import concurrent.futures
import json
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import study  # noqa: E402

TRANSFERS = {"flip": ("flip", 0.0), "pic": ("pic", 0.0), "blend": ("flip", 0.02), "apic": ("apic", 0.0)}
LABELS = {"flip": "FLIP", "pic": "PIC", "blend": "FLIP + 2 % PIC", "apic": "APIC"}
COLUMNS = {3.0: (10.0, 30.0), 0.8: (50.0, 40.0)}
REST_SPEED, REST_KE = 0.05, 1e-5


def run_one(bins, out, a, key, cell, tau, smoothing, base, normal_lag=None):
    width, height = COLUMNS[a]
    scene = study.Scene(width, height, cell, 4, out_every=0.1)
    transfer, blend = TRANSFERS[key]
    name = "a%g_%s_h%g" % (a, key, cell) + ("" if smoothing == "none" else "_" + smoothing) + \
        ("" if base == "friction" else "_" + base) + ("" if normal_lag is None else "_lag%g" % normal_lag[0])
    t0 = time.time()
    try:
        run = study.run_mpm_only(bins, scene, out, 1, name, duration=tau * scene.tau_c, pic_blend=blend,
                                 transfer=transfer, smoothing=smoothing, base=base,
                                 normal_lag=normal_lag)
    except RuntimeError as e:
        return {"name": name, "a": a, "key": key, "cell": cell, "failed": str(e).splitlines()[-1][:200]}
    r = summarize(run["dir"], a, key, cell)
    r.update({"ms_per_step": 1e3 * run["wall"]["mpm"] / r["nsteps"], "wall": run["wall"]["mpm"],
              "elapsed": time.time() - t0})
    return r


def summarize(run_dir, a, key, cell):
    """The measures of one finished run in `run_dir` (its mpm.json and results/column/series.csv), and its
    largest particle speed and KE/PE0 against t/tau_c (for rest.png)."""
    width, height = COLUMNS[a]
    scene = study.Scene(width, height, cell, 4, out_every=0.1)
    s = study.read_series(os.path.join(run_dir, "results", "column"))
    with open(os.path.join(run_dir, "mpm.json")) as f:
        nsteps = json.load(f)["analysis"]["nsteps"]
    pe0 = s["potential_energy"][0]
    ke = (s["kinetic_energy_x"] + s["kinetic_energy_y"]) / pe0
    t_star = s["time"] / scene.tau_c
    at_rest = (s["max_speed"] < REST_SPEED) & (ke < REST_KE)
    rest = None
    if at_rest[-1]:
        moving = np.nonzero(~at_rest)[0]
        rest = float(t_star[moving[-1] + 1]) if len(moving) else float(t_star[0])
    return {"name": os.path.basename(run_dir), "a": a, "key": key, "cell": cell, "t_end": float(t_star[-1]),
            "runout": float((s["runout_x_p98"][-1] - width) / width), "pe": float(s["potential_energy"][-1] / pe0),
            "max_speed": float(s["max_speed"][-1]), "ke": float(ke[-1]), "rest": rest, "nsteps": nsteps,
            "particles": int(s["n_particles"][-1]),
            "history": {"t_star": t_star.tolist(), "max_speed": s["max_speed"].tolist(), "ke": ke.tolist()}}


def plot_rest(results, path):
    """rest.png: each run's largest particle speed and KE/PE0 against t/tau_c, with the resting thresholds."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    runs = sorted((r for r in results if "history" in r), key=lambda r: (-r["a"], r["key"], -r["cell"]))
    if not runs:
        return
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.5, 7), sharex=True)
    for r in runs:
        h = r["history"]
        rest = "at rest from %.2f" % r["rest"] if r["rest"] is not None else "not at rest"
        label = "a = %g, %s, %g m cells: runout %.3f, %s" % (r["a"], LABELS[r["key"]], r["cell"], r["runout"], rest)
        line, = top.semilogy(h["t_star"], np.maximum(h["max_speed"], 1e-6), lw=1.2, label=label)
        bottom.semilogy(h["t_star"], np.maximum(h["ke"], 1e-14), lw=1.2, color=line.get_color())
    top.axhline(REST_SPEED, color="k", ls="--", lw=0.8)
    bottom.axhline(REST_KE, color="k", ls="--", lw=0.8)
    top.set_ylabel("largest particle speed (m/s)")
    bottom.set_ylabel("KE / PE0")
    bottom.set_xlabel("t / tau_c")
    top.legend(fontsize=7, loc="lower left")
    top.set_title("When the column comes to rest (dashed: the resting thresholds)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def table(results):
    lines = ["| a | transfer | cell | runout (L-L0)/L0 | PE/PE0 | max speed (m/s) | KE/PE0 | at rest from t/tau_c | "
             "ms per step (particles) |", "|---|---|---|---|---|---|---|---|---|"]
    for r in sorted(results, key=lambda r: (-r["a"], list(TRANSFERS).index(r["key"]), -r["cell"])):
        if "failed" in r:
            lines.append("| %g | %s | %g m | failed: %s | | | | | |" % (r["a"], LABELS[r["key"]], r["cell"], r["failed"]))
            continue
        rest = "%.2f" % r["rest"] if r["rest"] is not None else "not at t/tau_c = %.1f" % r["t_end"]
        lines.append("| %g | %s | %g m | %.3f | %.3f | %.3g | %.2g | %s | %.2f (%d) |" % (
            r["a"], LABELS[r["key"]], r["cell"], r["runout"], r["pe"], r["max_speed"], r["ke"], rest, r["ms_per_step"],
            r["particles"]))
    return "\n".join(lines) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(study.REPO, "results", "transfer_study"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--aspect", default="3,0.8")
    ap.add_argument("--transfers", default="flip,pic,blend,apic")
    ap.add_argument("--halved", default="apic", help="transfers also run with 0.5 m cells ('' for none)")
    ap.add_argument("--doubled", default="", help="transfers also run with 2 m cells ('' for none)")
    ap.add_argument("--tau", type=float, default=7.0, help="end time in units of tau_c")
    ap.add_argument("--smoothing", default="none", help="analysis.stress_smoothing of every run (e.g. cell_strain)")
    ap.add_argument("--normal-lag", default="", help="L,V*: the base friction's normal_lag (slip distance m, "
                    "reference speed m/s; mpm/core/lagged_friction.hpp); '' for none")
    ap.add_argument("--base", default="friction", choices=("friction", "contact"),
                    help="friction: y-velocity 0 + Coulomb (CB-Geo); contact: one-sided frictional contact")
    ap.add_argument("--bin", default=os.path.join(study.REPO, "build", "bin"))
    args = ap.parse_args(argv)
    bins = {"mpm": os.path.join(args.bin, "mpm")}
    if not os.access(bins["mpm"], os.X_OK):
        sys.exit("transfer_study.py: error: %s not found (build the mpm target first, or --bin DIR)" % bins["mpm"])
    os.makedirs(args.out, exist_ok=True)
    jobs = []
    for a in [float(x) for x in args.aspect.split(",")]:
        for key in [k for k in args.transfers.split(",") if k]:
            jobs.append((a, key, 1.0))
        for key in [k for k in args.halved.split(",") if k]:
            jobs.append((a, key, 0.5))
        for key in [k for k in args.doubled.split(",") if k]:
            jobs.append((a, key, 2.0))
    results = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        lag = None if not args.normal_lag else tuple(float(v) for v in args.normal_lag.split(","))
        futures = [pool.submit(run_one, bins, args.out, a, key, cell, args.tau, args.smoothing, args.base, lag)
                   for a, key, cell in jobs]
        for f in concurrent.futures.as_completed(futures):
            r = f.result()
            results.append(r)
            study.log("done %s: %s" % (r["name"], json.dumps(r)))
            with open(os.path.join(args.out, "summary.json"), "w") as g:
                json.dump(results, g, indent=1)
            with open(os.path.join(args.out, "summary.md"), "w") as g:
                g.write(table(results))
    plot_rest(results, os.path.join(args.out, "rest.png"))
    print(table(results))


if __name__ == "__main__":
    main()
