#!/usr/bin/python3
"""One command for your own model: FEM (fem_tcl) to the transfer time, fem2mpm, MPM (mpm) for the runout.

    scripts/hybrid_run.py MODEL.tcl --transfer T [--duration D] [--out DIR] [driver options]
                          [fem2mpm options...] [-- script arguments...]

MODEL.tcl is run as `fem_tcl MODEL.tcl DIR/fem [script arguments...]`. The contract: the script takes its
output folder as its FIRST argument and writes there
    model.json   print -JSON -file [file join $out model.json]        (after the model is built)
    disp.out     recorder Node -file [file join $out disp.out] -time -nodeRange 1 $nNodes -dof 1 2 disp
    vel.out      recorder Node -file [file join $out vel.out]  -time -nodeRange 1 $nNodes -dof 1 2 vel
    stress.out   recorder Element -file [file join $out stress.out] -time -eleRange 1 $nEle stress3D
and, for a model with applied nodal loads (a surcharge, a footing) that the MPM run must keep carrying,
    loads.out    recorder Node -file [file join $out loads.out] -time -nodeRange 1 $nNodes -dof 1 2 unbalance
and, for an effective-stress (u-p) model, the pore pressures of its 3-dof nodes in tag order, given to fem2mpm
as --pore-pressure (r_u, total stresses and the liquefied strength: bridge/README.md),
    pp.out       recorder Node -file [file join $out pp.out] -time -node {*}$upNodes -dof 3 vel
with a row at the transfer time T (e.g. `-dT` a divisor of T, or land a step on T). Then
`fem2mpm ... --time T --duration D` writes the particles and the MPM deck into DIR/mpm, `mpm` runs it,
and DIR receives what an engineer looks at:
    series.csv           per MPM output (and the transfer state first): time (s, total: T + MPM time),
                         runout (m: the largest horizontal travel of a particle since T), front_x (m: x of
                         the moving mass farthest along the direction of travel; moving: travelled more than
                         --moved since T), height (m: 99.5th percentile of particle y), moved_mass_fraction,
                         potential_energy, kinetic_energy, kinetic_energy_x, kinetic_energy_y (J/m), max_speed
    fem_mesh_T.png       the FEM mesh at T, deformed (true scale), coloured by |displacement|
    particles_T.png      the particles at T and
    particles_end.png    at the end, coloured by |displacement| since the start of the FEM run
    runout.png, energy.png   runout and front; potential-energy loss and kinetic energy against time
    ru_T.png             for a u-p model (pp.out): the particles at T coloured by r_u
    summary.md           one page: the run, the transfer, the result, the figures
    fem/, mpm/           the FEM output and the MPM working folder (deck, results/<uuid>/particles*.h5)

Options that are not the driver's own (below) go to fem2mpm unchanged (bridge/README.md: --units kN,
--ppd, --cell-size, --extent, --left-wall, --right-wall, --base, --base-friction, --base-y, --material-type,
--phi, --cohesion, --scheme, --cfl, ...); --model, --disp, --vel, --stress, --loads, --time, --row and --out are
set by the driver. Everything after `--` goes to the script. Errors: one line on stderr; exit 2 for bad
input (a missing model, an option without its value, a script that does not write the contracted files,
a transfer time the FEM did not record), 3 when fem2mpm or mpm stops on a numerical failure (mpm's
runaway or energy-growth checks), 1 when a stage fails otherwise. The warnings of fem2mpm and mpm (units
that look wrong, a time step above the stability limit, particles removed) are repeated on stderr and
listed in summary.md.

The transfer window: `--transfer 5,10,15,20` runs the FEM once and a transfer and MPM run per time (at most
--jobs at once), each into DIR/T<t>/ (its mpm/, series.csv, figures and summary.md), and writes into DIR
    window.csv, window.png   per transfer time: the runout and moving mass at the end, the liquefied depth at
                             the transfer (the deepest particle with r_u >= fem2mpm's --liquefied threshold
                             below the ground surface, from the /pore_pressure dataset; empty for a dry model)
                             and the FEM mesh's smallest corner det J / det J0 at T (near 0: distorting)
    summary.md               the table and the figure

Example (scripts/examples/slope_on_foundation.tcl):
    scripts/hybrid_run.py scripts/examples/slope_on_foundation.tcl --transfer 0.5 --duration 4 \\
        --out results/slope --units kN --extent -2 62 -1 30 --base-y 0 --left-wall roller --right-wall roller
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from geoflow import metrics, pipeline, plots  # noqa: E402

PROG = "hybrid_run.py"
REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# the driver's own options: name -> takes a value
DRIVER_OPTIONS = {"--transfer": True, "--duration": True, "--out": True, "--bin": True, "--threads": True,
                  "--output-every": True, "--moved": True, "--jobs": True, "--help": False, "-h": False}
# what the driver writes into DIR (removed first, so a failed run never leaves an older one behind)
OUTPUTS = ("fem", "mpm", "series.csv", "summary.md", "fem_mesh_T.png", "particles_T.png", "particles_end.png",
           "runout.png", "energy.png", "ru_T.png", "window.csv", "window.png")
# the r_u above which fem2mpm marks a particle liquefied, unless --liquefied says otherwise (its default)
LIQUEFIED_DEFAULT = 0.7
SET_BY_DRIVER = ("--model", "--disp", "--vel", "--stress", "--loads", "--time", "--row", "--out")


class OneLineParser(argparse.ArgumentParser):
    """argparse with one-line errors (exit 2)."""

    def error(self, message):
        pipeline.die(PROG, message)


def driver_parser():
    ap = OneLineParser(prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                                 usage="%(prog)s MODEL.tcl --transfer T [--duration D] [--out DIR] [options] "
                                       "[fem2mpm options] [-- script arguments]")
    ap.add_argument("model", help="the FEM script (takes its output folder as its first argument)")
    ap.add_argument("--transfer", type=transfer_times, required=True,
                    help="transfer time T, s (a time in the FEM recorders), or several, comma-separated (the "
                         "transfer window: one FEM run, a transfer and an MPM run per time, window.csv/png)")
    ap.add_argument("--jobs", type=int, default=1, help="transfers run at once (default 1)")
    ap.add_argument("--duration", type=float, default=5.0, help="MPM time after the transfer, s (default 5)")
    ap.add_argument("--out", default=None, help="output folder (default results/hybrid_<model name>)")
    ap.add_argument("--bin", default=None, help="folder with fem_tcl, fem2mpm, mpm (default build/bin)")
    ap.add_argument("--threads", type=int, default=1, help="mpm threads (default 1)")
    ap.add_argument("--output-every", type=float, default=None,
                    help="MPM particle output interval, s (default duration / 40; fem2mpm's --output-steps wins)")
    ap.add_argument("--moved", type=float, default=0.1,
                    help="travel since T above which a particle counts as moving (front_x, moved_mass_fraction), m")
    return ap


def transfer_times(text):
    """`5` or `5,10,15,20`: sorted, distinct, each >= 0."""
    try:
        times = sorted({float(w) for w in text.split(",") if w.strip()})
    except ValueError:
        raise argparse.ArgumentTypeError("expected a time or comma-separated times in s, got %r" % text)
    if not times or times[0] < 0 or not all(np.isfinite(times)):
        raise argparse.ArgumentTypeError("expected times >= 0 s, got %r" % text)
    return times


def split_arguments(argv):
    """(driver words, fem2mpm words, script words), pipeline.split_words with the driver's options."""
    return pipeline.split_words(PROG, argv, DRIVER_OPTIONS, SET_BY_DRIVER,
                                "the driver (the FEM output of the script, --transfer, --out)")


def option_given(words, name):
    return any(w == name or w.startswith(name + "=") for w in words)


# ---- metrics of the runout ---------------------------------------------------------------------------

def runout_series(results, t_transfer, moved):
    """Per particle file (step 0 = the transfer state): the metrics of series.csv (see the module help),
    and the particles at T and at the end for the figures."""
    steps = metrics.particle_steps(results)
    if not steps:
        raise pipeline.PipelineError("mpm wrote no particle files in %s" % results)
    ser = metrics.read_series(results)
    row_of_step = {int(s): k for k, s in enumerate(ser["step"])}
    first = metrics.read_particles(steps[min(steps)])
    order = np.argsort(first["id"])
    ids0 = first["id"][order]
    x0, y0 = first["coord_x"][order], first["coord_y"][order]
    u0 = np.stack([first["displacement_x"][order], first["displacement_y"][order]], axis=1)
    mass0 = first["mass"][order]
    rows, states = [], {}
    last_step = max(steps)
    for step in sorted(steps):
        p = metrics.read_particles(steps[step])
        o = np.argsort(p["id"])
        if not np.array_equal(p["id"][o], ids0):
            raise pipeline.PipelineError("particle ids of %s differ from the transfer file" % steps[step])
        x, y = p["coord_x"][o], p["coord_y"][o]
        vx, vy = p["velocity_x"][o], p["velocity_y"][o]
        dx, dy = x - x0, y - y0
        travel = np.hypot(dx, dy)
        mov = travel > moved
        e = metrics.state_metrics(x, y, vx, vy, mass0)
        if step == min(steps) or step not in row_of_step:
            t = t_transfer if step == min(steps) else float("nan")
            max_speed = float(np.sqrt(np.max(vx ** 2 + vy ** 2)))
        else:
            k = row_of_step[step]
            t = t_transfer + ser["time"][k]
            max_speed = ser["max_speed"][k]
        rows.append({"time": t, "runout": float(np.max(np.abs(dx))), "dx_sum": float(np.sum(mass0[mov] * dx[mov])),
                     "mov": mov, "x": x, "height": e["H"], "moved_mass_fraction": float(mass0[mov].sum() / mass0.sum()),
                     "potential_energy": e["PE"], "kinetic_energy": e["KEx"] + e["KEy"], "kinetic_energy_x": e["KEx"],
                     "kinetic_energy_y": e["KEy"], "max_speed": max_speed})
        if step in (min(steps), last_step):
            states["T" if step == min(steps) else "end"] = {"x": x, "y": y, "u": u0 + np.stack([dx, dy], axis=1),
                                                            "volume": p["volume"][o]}
    # the direction of travel: that of the moving mass at the end
    direction = 1.0 if rows[-1]["dx_sum"] >= 0.0 else -1.0
    for r in rows:
        r["front_x"] = float(direction * np.max(direction * r["x"][r["mov"]])) if np.any(r["mov"]) else float("nan")
        for k in ("dx_sum", "mov", "x"):
            del r[k]
    # a mass moving the other way too (a dam or ridge failing on both faces): its front and share at the end
    dx_end = states["end"]["x"] - x0
    other = (np.hypot(dx_end, states["end"]["y"] - y0) > moved) & (direction * dx_end < 0.0)
    moving_mass = rows[-1]["moved_mass_fraction"] * mass0.sum()
    rows[-1]["other_side"] = ({"front_x": float(-direction * np.max(-direction * states["end"]["x"][other])),
                               "share": float(mass0[other].sum() / moving_mass)}
                              if np.any(other) and moving_mass > 0 else None)
    return rows, states, direction


# A failure on both sides: the summary names the second front when that side holds this share of the moving mass.
OTHER_SIDE_SHARE = 0.1

SERIES_COLUMNS = ("time", "runout", "front_x", "height", "moved_mass_fraction", "potential_energy", "kinetic_energy",
                  "kinetic_energy_x", "kinetic_energy_y", "max_speed")


def write_series(path, rows):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(",".join(SERIES_COLUMNS) + "\n")
        for r in rows:
            f.write(",".join("%.9g" % r[c] for c in SERIES_COLUMNS) + "\n")
    os.replace(tmp, path)


# ---- figures and summary -----------------------------------------------------------------------------

def figures(out, fem_dir, t_transfer, rows, states, spacing):
    plt = plots.pyplot()
    paths = {}
    xy, elems = metrics.load_fem_model(fem_dir)
    u = metrics.fem_displacements_at(fem_dir, t_transfer)
    umax_end = max(float(np.linalg.norm(states["end"]["u"], axis=1).max()), 1e-12)
    if u is not None:
        fig, ax = plt.subplots(figsize=(7, 3.6))
        pc = plots.plot_fem_mesh(ax, xy, elems, u)
        fig.colorbar(pc, ax=ax, label="|displacement| (m)", shrink=0.8)
        ax.set_title("FEM at the transfer, t = %g s (deformed, true scale; grey: undeformed)" % t_transfer, fontsize=9)
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        paths["fem"] = plots.save(fig, os.path.join(out, "fem_mesh_T.png"))
    for key, title, name in (("T", "particles at the transfer, t = %g s" % t_transfer, "particles_T.png"),
                             ("end", "particles at the end, t = %g s" % rows[-1]["time"], "particles_end.png")):
        s = states[key]
        fig, ax = plt.subplots(figsize=(7, 3.6))
        sc = plots.plot_particles(ax, s["x"], s["y"], np.linalg.norm(s["u"], axis=1), spacing, 0.0, umax_end)
        fig.colorbar(sc, ax=ax, label="|displacement| since the FEM start (m)", shrink=0.8)
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        paths[key] = plots.save(fig, os.path.join(out, name))
    t = np.array([r["time"] for r in rows])
    fig, axs = plt.subplots(1, 2, figsize=(9, 3.2))
    axs[0].plot(t, [r["runout"] for r in rows], "-", color="tab:blue", label="runout: largest horizontal travel")
    axs[0].set_ylabel("runout since the transfer (m)")
    axs[1].plot(t, [r["front_x"] for r in rows], "-", color="tab:orange", label="front of the moving mass")
    axs[1].set_ylabel("front x (m)")
    for ax in axs:
        ax.set_xlabel("t (s)")
        ax.axvline(t_transfer, ls=":", color="0.5", lw=0.8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    paths["runout"] = plots.save(fig, os.path.join(out, "runout.png"))
    fig, ax = plt.subplots(figsize=(5.5, 3.2))
    pe0 = rows[0]["potential_energy"]
    ax.plot(t, [(pe0 - r["potential_energy"]) / 1e3 for r in rows], "-", color="tab:green", label="potential energy released")
    ax.plot(t, [r["kinetic_energy"] / 1e3 for r in rows], "-", color="tab:red", label="kinetic energy")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("energy (kJ per m of thickness)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    paths["energy"] = plots.save(fig, os.path.join(out, "energy.png"))
    return paths


def repeat_warnings(logfile):
    """A stage's warnings (pipeline.log_warnings), repeated on stderr; returns them."""
    found = pipeline.log_warnings(logfile)
    for w in found:
        print("%s: %s" % (PROG, w), file=sys.stderr, flush=True)
    return found


def write_summary(out, args, t_transfer, command, forward, script_args, walls, rows, direction, report, deck, n_nodes,
                  n_elems, fem_end, paths, warnings):
    end = rows[-1]
    lines = ["# hybrid_run: %s" % os.path.basename(args.model), "",
             "`%s`" % " ".join(command), "",
             "| stage | what | wall (s) |", "|---|---|---|",
             "| FEM | `fem_tcl %s` (%s): %d nodes, %d elements, recorded to t = %g s | %.1f |"
             % (os.path.basename(args.model), " ".join(script_args) or "no script arguments", n_nodes, n_elems, fem_end,
                walls["fem"]),
             "| transfer | `fem2mpm --time %g %s`: %s particles | %.1f |"
             % (t_transfer, " ".join(forward), report.get("particles", "?"), walls["fem2mpm"]),
             "| MPM | %g s (%d steps of %.3g s, %s) | %.1f |"
             % (args.duration, deck["analysis"]["nsteps"], deck["analysis"]["dt"], deck["analysis"]["mpm_scheme"].upper(),
                walls["mpm"]), ""]
    lines += ["## Result at t = %g s" % end["time"], "",
              "| | |", "|---|---|",
              "| runout (largest horizontal travel since the transfer) | %.3g m |" % end["runout"],
              ("| front of the moving mass (travel > %g m), moving %s | x = %.4g m |"
               % (args.moved, "right (+x)" if direction > 0 else "left (-x)", end["front_x"]))
              if np.isfinite(end["front_x"]) else
              "| front of the moving mass | none: no particle travelled more than %g m (--moved) |" % args.moved,
              "| mass moving | %.1f %% |" % (100 * end["moved_mass_fraction"]),
              ("| and moving %s, %.0f %% of the moving mass | front x = %.4g m |"
               % ("left (-x)" if direction > 0 else "right (+x)", 100 * end["other_side"]["share"],
                  end["other_side"]["front_x"]))
              if end.get("other_side") and end["other_side"]["share"] >= OTHER_SIDE_SHARE else None,
              "| height (99.5th percentile of y) at T -> end | %.4g m -> %.4g m |" % (rows[0]["height"], end["height"]),
              "| potential energy released | %.4g kJ/m |" % ((rows[0]["potential_energy"] - end["potential_energy"]) / 1e3),
              "| kinetic energy at T -> end (largest) | %.4g -> %.4g kJ/m (%.4g) |"
              % (rows[0]["kinetic_energy"] / 1e3, end["kinetic_energy"] / 1e3, max(r["kinetic_energy"] for r in rows) / 1e3),
              "| largest speed at the end | %.3g m/s |" % end["max_speed"], ""]
    lines = [ln for ln in lines if ln is not None]
    if warnings:
        lines += ["## Warnings", ""] + ["- `%s`" % w for w in warnings] + [""]
    if end["max_speed"] > 0.05:
        lines += ["The mass is still moving at the end (largest speed %.3g m/s): run longer (--duration) for the "
                  "final runout." % end["max_speed"], ""]
    lines += ["Series: `series.csv`; transfer report: `mpm/report.json`; particles: `mpm/%s`." %
              os.path.relpath(pipeline.results_dir(os.path.join(out, "mpm")), os.path.join(out, "mpm")), ""]
    for key in ("fem", "ru", "T", "end", "runout", "energy"):
        if key in paths:
            lines.append("![%s](%s)" % (key, os.path.basename(paths[key])))
    tmp = os.path.join(out, "summary.md.tmp")
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, os.path.join(out, "summary.md"))


def liquefied_depth(transfer_file, threshold):
    """The largest depth below the ground surface of a particle with r_u >= threshold in the transfer file's
    /pore_pressure dataset (fem2mpm; rows p, sigma'v0, r_u per /table row): the surface is the highest particle
    of each column one particle spacing wide. None for a dry transfer (no dataset); 0 when none liquefied."""
    import h5py
    with h5py.File(transfer_file, "r") as f:
        if "pore_pressure" not in f:
            return None
        ru = np.asarray(f["pore_pressure"])[:, 2]
        table = f["table"]
        x, y, vol = table["coord_x"], table["coord_y"], table["volume"]
    liquefied = ru >= threshold
    if not np.any(liquefied):
        return 0.0
    width = float(np.sqrt(np.median(vol)))
    column = np.floor(x / width).astype(int)
    top = {}
    for c, yy in zip(column, y):
        top[c] = max(top.get(c, -np.inf), yy)
    return float(max(top[c] - yy for c, yy in zip(column[liquefied], y[liquefied])))


def ru_figure(out, transfer_file, t_transfer, spacing):
    """ru_T.png: the particles at the transfer coloured by r_u (the /pore_pressure dataset fem2mpm writes for a
    u-p model); None for a dry transfer."""
    import h5py
    with h5py.File(transfer_file, "r") as f:
        if "pore_pressure" not in f:
            return None
        ru = np.asarray(f["pore_pressure"])[:, 2]
        x, y = np.asarray(f["table"]["coord_x"]), np.asarray(f["table"]["coord_y"])
    plt = plots.pyplot()
    fig, ax = plt.subplots(figsize=(7, 3.6))
    sc = plots.plot_particles(ax, x, y, np.clip(ru, 0.0, 1.0), spacing, 0.0, 1.0, cmap="magma_r")
    fig.colorbar(sc, ax=ax, label="r_u = excess pore pressure / sigma'v0", shrink=0.8)
    ax.set_title("excess pore-pressure ratio at the transfer, t = %g s" % t_transfer, fontsize=9)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    return plots.save(fig, os.path.join(out, "ru_T.png"))


def fem_min_jacobian_ratio(fem_dir, t):
    """The smallest corner det J / det J(reference) of the FEM mesh at time t (from model.json and disp.out):
    1 undeformed, <= 0 inverted. None when disp.out has no row at t."""
    xy, elems = metrics.load_fem_model(fem_dir)
    u = metrics.fem_displacements_at(fem_dir, t)
    if u is None:
        return None
    cur = xy + u
    worst = np.inf
    for e in elems:
        n = len(e)
        for a in range(n):
            b, c = e[(a + 1) % n], e[(a - 1) % n]
            r1, r2 = xy[b] - xy[e[a]], xy[c] - xy[e[a]]
            e1, e2 = cur[b] - cur[e[a]], cur[c] - cur[e[a]]
            ref = r1[0] * r2[1] - r1[1] * r2[0]
            worst = min(worst, (e1[0] * e2[1] - e1[1] * e2[0]) / ref if ref > 0 else -np.inf)
    return float(worst)


def run_transfer(args, bins, fem_dir, out, t_transfer, command, forward, script_args, fem_wall, fem_end):
    """fem2mpm at t_transfer into OUT/mpm, mpm, and OUT's series, figures and summary; returns the end row of the
    series with the transfer's liquefied depth and the FEM mesh quality. Raises pipeline.PipelineError."""
    mpm_dir = os.path.join(out, "mpm")
    walls = {"fem": fem_wall}
    warnings = []
    fem2mpm_options = list(forward) + ["--duration", repr(args.duration)]
    print("%s: transfer at t = %g s: fem2mpm %s" % (PROG, t_transfer, " ".join(forward)), flush=True)
    walls["fem2mpm"] = pipeline.run_fem2mpm(bins, fem_dir, mpm_dir, t_transfer, fem2mpm_options)
    warnings += repeat_warnings(os.path.join(mpm_dir, "fem2mpm.log"))
    if not option_given(forward, "--output-steps"):
        n_out = max(1, int(round(args.duration / (args.output_every or args.duration / 40.0))))

        def set_output(deck):
            # n_out outputs, the last one at exactly T + D: nsteps - 1 a multiple of output_steps, and dt
            # (never larger than fem2mpm's) such that nsteps dt = D (file s holds the state at (s + 1) dt)
            a = deck["analysis"]
            every = int(np.ceil((a["nsteps"] - 1) / n_out))
            a["nsteps"] = every * n_out + 1
            a["dt"] = args.duration / a["nsteps"]
            deck["post_processing"]["output_steps"] = every
        deck = pipeline.edit_deck(os.path.join(mpm_dir, "mpm.json"), set_output)
    else:
        deck = pipeline.edit_deck(os.path.join(mpm_dir, "mpm.json"), lambda d: None)
    print("%s: MPM from t = %g s: %g s, %d steps" % (PROG, t_transfer, args.duration, deck["analysis"]["nsteps"]),
          flush=True)
    try:
        walls["mpm"] = pipeline.run_mpm(bins, mpm_dir, args.threads)
    finally:
        warnings += repeat_warnings(os.path.join(mpm_dir, "mpm.log"))
    results = pipeline.results_dir(mpm_dir)
    rows, states, direction = runout_series(results, t_transfer, args.moved)
    write_series(os.path.join(out, "series.csv"), rows)
    with open(os.path.join(mpm_dir, "report.json")) as f:
        report = json.load(f)
    xy, elems = metrics.load_fem_model(fem_dir)
    report.setdefault("particles", len(states["T"]["x"]))
    spacing = float(np.sqrt(np.median(states["T"]["volume"])))
    paths = figures(out, fem_dir, t_transfer, rows, states, spacing)
    transfer_file = pipeline.resume_file(os.path.join(mpm_dir, "mpm.json"), deck)
    ru_png = ru_figure(out, transfer_file, t_transfer, spacing)
    if ru_png:
        paths["ru"] = ru_png
    write_summary(out, args, t_transfer, command, forward, script_args, walls, rows, direction, report, deck, len(xy),
                  len(elems), fem_end, paths, warnings)
    threshold = LIQUEFIED_DEFAULT
    for k, w in enumerate(forward):
        if w == "--liquefied" and k + 1 < len(forward):
            threshold = float(forward[k + 1])
        elif w.startswith("--liquefied="):
            threshold = float(w.split("=", 1)[1])
    end = dict(rows[-1])
    end["transfer"] = t_transfer
    end["liquefied_depth"] = liquefied_depth(transfer_file, threshold)
    end["fem_min_jacobian_ratio"] = fem_min_jacobian_ratio(fem_dir, t_transfer)
    end["direction"] = direction
    return end


WINDOW_COLUMNS = ("transfer", "runout", "moved_mass_fraction", "liquefied_depth", "fem_min_jacobian_ratio", "front_x",
                  "time", "max_speed")


def write_window(out, ends, args):
    """window.csv (one row per transfer time) and window.png: runout, moved mass and liquefied depth against the
    transfer time, with the FEM's smallest det J ratio at that time (the window: liquefied deep enough, the mesh
    not yet distorted)."""
    tmp = os.path.join(out, "window.csv.tmp")
    with open(tmp, "w") as f:
        f.write(",".join(WINDOW_COLUMNS) + "\n")
        for e in ends:
            f.write(",".join("%.9g" % (e[c] if e[c] is not None else float("nan")) for c in WINDOW_COLUMNS) + "\n")
    os.replace(tmp, os.path.join(out, "window.csv"))
    plt = plots.pyplot()
    t = [e["transfer"] for e in ends]
    fig, axs = plt.subplots(1, 4, figsize=(14, 3.4))
    panels = (("runout", "runout at the end (m)"), ("moved_mass_fraction", "moving mass fraction"),
              ("liquefied_depth", "liquefied depth at T (m)"), ("fem_min_jacobian_ratio", "FEM min det J / det J0 at T"))
    for ax, (key, label) in zip(axs, panels):
        ax.plot(t, [e[key] if e[key] is not None else np.nan for e in ends], "o-")
        ax.set_xlabel("transfer time T (s)")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axs[3].axhline(0.0, color="r", lw=0.8)
    fig.suptitle("the transfer window of %s (MPM %g s after each T)" % (os.path.basename(args.model), args.duration),
                 fontsize=9)
    fig.tight_layout()
    return plots.save(fig, os.path.join(out, "window.png"))


def write_window_summary(out, args, command, ends, png):
    lines = ["# hybrid_run: the transfer window of %s" % os.path.basename(args.model), "", "`%s`" % " ".join(command), "",
             "| T (s) | runout (m) | moving mass | liquefied depth at T (m) | FEM min det J ratio at T | run |",
             "|---|---|---|---|---|---|"]
    for e in ends:
        lines.append("| %g | %.3g | %.1f %% | %s | %s | [T%g/summary.md](T%g/summary.md) |" % (
            e["transfer"], e["runout"], 100 * e["moved_mass_fraction"],
            "-" if e["liquefied_depth"] is None else "%.2f" % e["liquefied_depth"],
            "-" if e["fem_min_jacobian_ratio"] is None else "%.3f" % e["fem_min_jacobian_ratio"], e["transfer"],
            e["transfer"]))
    lines += ["", "Liquefied: r_u >= the fem2mpm threshold (--liquefied, default %g); a det J ratio near 0 means the "
                  "FEM mesh was distorting at T (a later transfer carries a distorted state)." % LIQUEFIED_DEFAULT,
              "", "![window](%s)" % os.path.basename(png)]
    tmp = os.path.join(out, "summary.md.tmp")
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, os.path.join(out, "summary.md"))


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    driver_words, forward, script_args = split_arguments(argv)
    ap = driver_parser()
    args = ap.parse_args(driver_words)
    if not os.path.isfile(args.model):
        pipeline.die(PROG, "%s: no such FEM script" % args.model)
    if not (args.duration > 0):
        pipeline.die(PROG, "--duration: expected a time > 0 s, got %g" % args.duration)
    for name, value in (("--moved", args.moved), ("--output-every", args.output_every), ("--threads", args.threads),
                        ("--jobs", args.jobs)):
        if value is not None and not (value > 0):
            pipeline.die(PROG, "%s: expected a value > 0, got %g" % (name, value))
    if option_given(forward, "--duration") or option_given(forward, "--nsteps"):
        pipeline.die(PROG, "give the MPM time with the driver's --duration")
    name = os.path.splitext(os.path.basename(args.model))[0]
    out = os.path.abspath(args.out or os.path.join(REPO, "results", "hybrid_" + name))
    fem_dir = os.path.join(out, "fem")
    window = len(args.transfer) > 1
    # one transfer: its outputs in OUT; several: each in OUT/T<t>/, the window's in OUT
    transfer_dirs = [os.path.join(out, "T%g" % t) if window else out for t in args.transfer]
    try:
        bins = pipeline.find_bins(args.bin, REPO)
    except pipeline.PipelineError as e:
        pipeline.die(PROG, str(e))
    os.makedirs(out, exist_ok=True)
    pipeline.remove_outputs(out, OUTPUTS + tuple(os.path.basename(d) for d in transfer_dirs if window))
    command = [PROG] + argv
    stage = "fem2mpm options"
    try:
        pipeline.check_fem2mpm_options(bins, fem_dir, os.path.join(transfer_dirs[0], "mpm"), args.transfer[0],
                                       list(forward) + ["--duration", repr(args.duration)])
        stage = "FEM"
        print("%s: FEM: fem_tcl %s %s %s" % (PROG, args.model, fem_dir, " ".join(script_args)), flush=True)
        fem_wall = pipeline.run_fem_script(bins, os.path.abspath(args.model), fem_dir, script_args)
        fem_end = metrics.fem_last_time(fem_dir)
        if args.transfer[-1] > fem_end + 1e-9:
            pipeline.die(PROG, "--transfer %g: the FEM run recorded only to t = %g s (%s; run the script longer, "
                               "e.g. with its end-time argument after --, such as -- -tend %g for the examples)"
                         % (args.transfer[-1], fem_end, os.path.join(fem_dir, "disp.out"), args.transfer[-1]))
        stage = "transfer"
        jobs = [(t, d) for t, d in zip(args.transfer, transfer_dirs)]
        if args.jobs > 1 and window:
            from concurrent.futures import ThreadPoolExecutor  # the work is in fem2mpm and mpm subprocesses
            with ThreadPoolExecutor(max_workers=args.jobs) as pool:
                ends = list(pool.map(lambda j: run_transfer(args, bins, fem_dir, j[1], j[0], command, forward,
                                                            script_args, fem_wall, fem_end), jobs))
        else:
            ends = [run_transfer(args, bins, fem_dir, d, t, command, forward, script_args, fem_wall, fem_end)
                    for t, d in jobs]
        if window:
            stage = "window"
            png = write_window(out, ends, args)
            write_window_summary(out, args, command, ends, png)
    except pipeline.PipelineError as e:
        print("%s: error: %s: %s" % (PROG, stage, e), file=sys.stderr)
        return e.exit_code()
    for e in ends:
        front = ("front x = %.4g m" % e["front_x"]) if np.isfinite(e["front_x"]) else \
            "no moving front (no travel above %g m)" % args.moved
        other = e.get("other_side")
        if other and other["share"] >= OTHER_SIDE_SHARE:
            front += " (and x = %.4g m the other way, %.0f %% of the moving mass)" % (other["front_x"], 100 * other["share"])
        liq = "" if e["liquefied_depth"] is None else "; liquefied to %.2f m at the transfer" % e["liquefied_depth"]
        print("%s: done: T = %g s: runout %.3g m, %s, %.0f %% of the mass moving at t = %g s%s"
              % (PROG, e["transfer"], e["runout"], front, 100 * e["moved_mass_fraction"], e["time"], liq), flush=True)
    print("%s: %s" % (PROG, os.path.join(out, "summary.md")), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
