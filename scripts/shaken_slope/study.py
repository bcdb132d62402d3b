#!/usr/bin/python3
"""The shaken-embankment study (docs/study/shaken_slope.md): the embankment of shaken_slope.tcl shaken by
the synthetic record (motion/), and the same model unshaken, each through the whole chain (fem_tcl to the
end of the shaking, fem2mpm, mpm to rest: scripts/hybrid_run.py); then the pseudo-static limit equilibrium
(pseudo_static.py: Bishop circles, k_y) and Newmark's sliding block (sliding_block.py) for the same slope,
with the outcrop record and with the mean acceleration of the sliding mass in the FEM (a third, elastic FEM
run, -plastic 0: the decoupled analysis of Makdisi & Seed 1978; and the plastic run's own).

    /usr/bin/python3 scripts/shaken_slope/study.py [--out results/shaken_slope] [--bin build/bin]
                     [--figure docs/study/shaken_slope.png] [--quick] [--no-figure]

--quick: the small version the regression test runs (2 m cells, dt 0.01 s, 4 s of shaking (the strong
part), 0.3 s of MPM, one particle per direction, a coarser circle search). Writes into --out: shaken/ and
unshaken/ (hybrid_run.py's folders), summary.json (every number of the study), summary.md (the table) and
shaken_slope.png (record, crest displacement histories with the Newmark ones, MPM deposits).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
import pseudo_static  # noqa: E402
import sliding_block  # noqa: E402
from geoflow import metrics, pipeline, plots  # noqa: E402

G = sliding_block.G
# the model of shaken_slope.tcl (its header): foundation 0..72 x 0..6, embankment toes 16 and 56, shoulders
# 28 and 44 at y = 14; rho 1.9 everywhere; embankment c 4 kPa phi 30, foundation c 30 phi 38
D, H, L = 6.0, 8.0, 72.0
PROFILE = [(0.0, D), (16.0, D), (28.0, D + H), (44.0, D + H), (56.0, D), (L, D)]
GAMMA = 1.9 * G
LAYERS = [(-1e9, 30.0, 38.0), (D, 4.0, 30.0)]
MOTION = os.path.join(HERE, "motion")
# the periodic sides have no MPM counterpart (fem2mpm warns): roller walls at the model's sides, the grid
# from x = 0 to 72 (cell = the FEM cell, one row below the base for GIMP), a frictional base mu = tan 30
FEM2MPM = ["--units", "kN", "--left-wall", "roller", "--right-wall", "roller", "--base", "friction",
           "--base-friction", "0.58", "--base-y", "0"]


def fem2mpm_options(cell):
    return FEM2MPM + ["--cell-size", repr(cell), "--extent", "0", repr(L), repr(-cell), repr(D + H + 4 * cell)]


def settings(quick):
    if quick:
        return dict(cell=2.0, dt=0.01, tend=4.0, duration=0.3, ppd=1, search=(12, 2))
    return dict(cell=1.0, dt=0.005, tend=12.0, duration=3.0, ppd=2, search=(20, 4))


def run_case(name, scale, s, out, bins):
    """hybrid_run.py on shaken_slope.tcl with the input scaled by `scale` (0: unshaken)."""
    cmd = [sys.executable, os.path.join(REPO, "scripts", "hybrid_run.py"), os.path.join(HERE, "shaken_slope.tcl"),
           "--transfer", repr(s["tend"]), "--duration", repr(s["duration"]), "--out", os.path.join(out, name),
           "--ppd", str(s["ppd"])] + fem2mpm_options(s["cell"]) + (["--bin", bins] if bins else []) + \
          ["--", "-cell", repr(s["cell"]), "-dt", repr(s["dt"]), "-tend", repr(s["tend"]), "-scale", repr(scale)]
    print("study.py: %s: %s" % (name, " ".join(os.path.relpath(w, REPO) if w.startswith(REPO) else w for w in cmd[1:])),
          flush=True)
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    sys.stdout.write(r.stdout)
    if r.returncode != 0:
        sys.exit("study.py: %s: hybrid_run.py failed (exit %d)" % (name, r.returncode))
    return cmd


def crest_history(fem_dir):
    """t, ux - ux_base and uy of the left shoulder, crest centre and right shoulder (the FEM every step)."""
    c = metrics.read_time_recorder(os.path.join(fem_dir, "crest.out"))
    b = metrics.read_time_recorder(os.path.join(fem_dir, "base.out"))
    n = min(len(c), len(b))
    c, b = c[:n], b[:n]
    return {"t": c[:, 0], "ux": c[:, 1::2] - b[:, 1:2], "uy": c[:, 2::2]}


def sliding_mass_acceleration(fem_dir, circle, face):
    """Mean horizontal (absolute) acceleration of the embankment nodes inside the critical circle of the
    given face (-1: the left face, +1: the right one), weighted by lumped nodal areas: the seismic
    coefficient history of the sliding mass (the decoupled Newmark analysis, Makdisi & Seed 1978)."""
    xy, elems = metrics.load_fem_model(fem_dir)
    with open(os.path.join(fem_dir, "model.json")) as f:
        tags = sorted(n["name"] for n in json.load(f)["StructuralAnalysisModel"]["geometry"]["nodes"])
    area = np.zeros(len(xy))
    np.add.at(area, elems.ravel(), np.repeat(metrics.element_areas(xy, elems) / 4.0, 4))
    acc = metrics.read_time_recorder(os.path.join(fem_dir, "embankment_accel.out"))
    n_emb = acc.shape[1] - 1
    index = {t: k for k, t in enumerate(tags)}
    # the recorder's nodes are the last n_emb soil nodes before the dummy node, in tag order
    soil_tags = tags[:-1]
    emb = soil_tags[-n_emb:]
    k = np.array([index[t] for t in emb])
    x, y = xy[k, 0], xy[k, 1]
    xc = circle[0] if face < 0 else L - circle[0]
    inside = pseudo_static.inside_circle(x, y, (xc, circle[1], circle[2]))
    w = area[k] * inside
    return acc[:, 0], acc[:, 1:] @ w / w.sum(), int(inside.sum())


def final_particles(case_dir):
    results = pipeline.results_dir(os.path.join(case_dir, "mpm"))
    steps = metrics.particle_steps(results)
    p0 = metrics.read_particles(steps[min(steps)])
    p1 = metrics.read_particles(steps[max(steps)])
    o0, o1 = np.argsort(p0["id"]), np.argsort(p1["id"])
    return {"x0": p0["coord_x"][o0], "y0": p0["coord_y"][o0], "x": p1["coord_x"][o1], "y": p1["coord_y"][o1],
            "volume": p1["volume"][o1]}


def read_series_csv(path):
    a = np.genfromtxt(path, delimiter=",", names=True)
    return {k: a[k] for k in a.dtype.names}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(REPO, "results", "shaken_slope"))
    ap.add_argument("--bin", default=None)
    ap.add_argument("--figure", default=None, help="also copy the figure here (e.g. docs/study/shaken_slope.png)")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--no-figure", action="store_true", help="skip shaken_slope.png (the regression test)")
    args = ap.parse_args(argv)
    s = settings(args.quick)
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)

    # --- pseudo-static limit equilibrium (left face, seen mirrored so that it fails towards +x)
    ground = pseudo_static.Ground(PROFILE, LAYERS, GAMMA).mirrored()
    n, levels = s["search"]
    window = ((-60.0, -20.0), (D + H, D + 4 * H), (3.0, 40.0))
    ky_circle = pseudo_static.critical_circle(ground, *window, n=n, levels=levels)
    fs_circle = pseudo_static.critical_circle(ground, *window, n=n, levels=levels, k=0.0)
    ky = ky_circle[3]
    circle = (-ky_circle[0], ky_circle[1], ky_circle[2])  # real coordinates, left face
    print("study.py: pseudo-static: static FS %.3f; k_y = %.4f (circle centre (%.2f, %.2f), R %.2f m)"
          % (fs_circle[3], ky, circle[0], circle[1], circle[2]), flush=True)

    # --- the chain, shaken and unshaken
    commands = {name: run_case(name, scale, s, out, args.bin) for name, scale in (("shaken", 1.0), ("unshaken", 0.0))}

    # --- Newmark: outcrop record, and the FEM's sliding-mass acceleration
    a_rec = np.loadtxt(os.path.join(MOTION, "accel.txt"))
    v_rec = np.loadtxt(os.path.join(MOTION, "vel.txt"))
    t_rec = np.arange(len(a_rec)) * 0.01
    keep = t_rec <= s["tend"] + 1e-9
    t_rec, a_rec, v_rec = t_rec[keep], a_rec[keep], v_rec[keep]
    fem = {c: crest_history(os.path.join(out, c, "fem")) for c in commands}
    elastic_dir = os.path.join(out, "elastic")
    elastic_cmd = [os.path.join(args.bin or os.path.join(REPO, "build", "bin"), "fem_tcl"),
                   os.path.join(HERE, "shaken_slope.tcl"), elastic_dir, "-cell", repr(s["cell"]), "-dt", repr(s["dt"]),
                   "-tend", repr(s["tend"]), "-plastic", "0"]
    print("study.py: elastic (decoupled Newmark): %s" % " ".join(elastic_cmd), flush=True)
    os.makedirs(elastic_dir, exist_ok=True)
    pipeline.run_cmd(elastic_cmd, logfile=os.path.join(elastic_dir, "fem_tcl.log"))
    newmark = {}
    for face, sign, col in (("left", 1.0, 0), ("right", -1.0, 2)):
        _, d_out = sliding_block.newmark_sliding(t_rec, sign * a_rec, ky * G)
        ta, am, n_in = sliding_mass_acceleration(os.path.join(out, "shaken", "fem"), circle, -1 if face == "left" else 1)
        _, d_fem = sliding_block.newmark_sliding(ta, sign * am, ky * G)
        te, ae, _ = sliding_mass_acceleration(elastic_dir, circle, -1 if face == "left" else 1)
        _, d_el = sliding_block.newmark_sliding(te, sign * ae, ky * G)
        perm = [fem[c]["ux"][-1, col] - fem[c]["ux"][0, col] for c in ("shaken", "unshaken")]
        newmark[face] = {"outcrop_record_m": float(d_out[-1]), "fem_sliding_mass_accel_m": float(d_fem[-1]),
                         "sliding_mass_peak_accel_g": float(np.max(np.abs(am)) / G), "sliding_mass_nodes": n_in,
                         "elastic_sliding_mass_accel_m": float(d_el[-1]),
                         "elastic_sliding_mass_peak_accel_g": float(np.max(np.abs(ae)) / G),
                         "fem_shoulder_ux_shaken_m": float(perm[0]), "fem_shoulder_ux_unshaken_m": float(perm[1]),
                         "fem_shoulder_uy_shaken_m": float(fem["shaken"]["uy"][-1, col] - fem["shaken"]["uy"][0, col]),
                         "fem_shoulder_uy_unshaken_m": float(fem["unshaken"]["uy"][-1, col] - fem["unshaken"]["uy"][0, col]),
                         "history": {"t_out": t_rec, "d_out": d_out, "t_fem": ta, "d_fem": d_fem, "t_el": te, "d_el": d_el}}

    # --- MPM: runout and deposits
    mpm = {}
    for c in commands:
        ser = read_series_csv(os.path.join(out, c, "series.csv"))
        with open(os.path.join(out, c, "mpm", "report.json")) as f:
            report = json.load(f)
        p = final_particles(os.path.join(out, c))
        mpm[c] = {"runout_m": float(ser["runout"][-1]), "moved_mass_fraction": float(ser["moved_mass_fraction"][-1]),
                  "max_speed_end_m_s": float(ser["max_speed"][-1]), "height_end_m": float(ser["height"][-1]),
                  "particles": int(len(p["x"])), "x_min_end": float(p["x"].min()), "x_max_end": float(p["x"].max()),
                  "boundaries": report.get("boundaries"), "particles_state": p}

    summary = {"settings": s, "commands": {c: " ".join(commands[c][1:]) for c in commands},
               "motion": json.load(open(os.path.join(MOTION, "motion.json")))["measures"],
               "pseudo_static": {"static_fs": fs_circle[3], "static_circle": fs_circle[:3], "k_y": ky,
                                 "k_y_circle_real_xy_R": circle, "method": "Bishop simplified, pseudo-static"},
               "newmark": {f: {k: v for k, v in d.items() if k != "history"} for f, d in newmark.items()},
               "mpm": {c: {k: v for k, v in d.items() if k != "particles_state"} for c, d in mpm.items()}}
    with open(os.path.join(out, "summary.json.tmp"), "w") as f:
        json.dump(summary, f, indent=1, default=float)
    os.replace(os.path.join(out, "summary.json.tmp"), os.path.join(out, "summary.json"))
    write_table(out, summary)
    if not args.no_figure:
        figure(out, args.figure, s, t_rec, a_rec, v_rec, fem, newmark, mpm, ky)
    print("study.py: done: %s" % os.path.join(out, "summary.md"))
    return 0


def write_table(out, sm):
    nm = sm["newmark"]
    lines = ["# Shaken embankment: summary", "",
             "Static FS %.3f, k_y %.4f (Bishop, pseudo-static); record PGA %.2f g."
             % (sm["pseudo_static"]["static_fs"], sm["pseudo_static"]["k_y"], sm["motion"]["pga_g"]), "",
             "| face | FEM shoulder ux shaken (m) | unshaken (m) | FEM uy shaken (m) | Newmark, outcrop record (m) | "
             "Newmark, elastic FEM sliding-mass accel (m) | its peak (g) | Newmark, plastic FEM sliding-mass accel (m) | its peak (g) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for face in ("left", "right"):
        d = nm[face]
        lines.append("| %s | %.4f | %.4f | %.4f | %.4f | %.4f | %.3f | %.4f | %.3f |" % (
            face, d["fem_shoulder_ux_shaken_m"], d["fem_shoulder_ux_unshaken_m"], d["fem_shoulder_uy_shaken_m"],
            d["outcrop_record_m"], d["elastic_sliding_mass_accel_m"], d["elastic_sliding_mass_peak_accel_g"],
            d["fem_sliding_mass_accel_m"], d["sliding_mass_peak_accel_g"]))
    lines += ["", "| MPM | runout since transfer (m) | moving mass | largest speed at the end (m/s) |", "|---|---|---|---|"]
    for c, d in sm["mpm"].items():
        lines.append("| %s | %.4f | %.1f %% | %.3g |" % (c, d["runout_m"], 100 * d["moved_mass_fraction"],
                                                       d["max_speed_end_m_s"]))
    with open(os.path.join(out, "summary.md.tmp"), "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(os.path.join(out, "summary.md.tmp"), os.path.join(out, "summary.md"))


def figure(out, copy_to, s, t_rec, a_rec, v_rec, fem, newmark, mpm, ky):
    plt = plots.pyplot()
    fig, axs = plt.subplots(3, 1, figsize=(8, 9.5))
    ax = axs[0]
    ax.plot(t_rec, a_rec / G, color="tab:blue", lw=0.7, label="acceleration (g)")
    ax.axhline(ky, color="tab:red", ls="--", lw=0.8, label="k_y = %.3f" % ky)
    ax.axhline(-ky, color="tab:red", ls="--", lw=0.8)
    ax2 = ax.twinx()
    ax2.plot(t_rec, v_rec, color="tab:gray", lw=0.8, label="velocity (m/s)")
    ax2.set_ylabel("velocity (m/s)")
    ax.set_ylabel("acceleration (g)")
    ax.set_title("synthetic outcrop record (motion/, seeded; PGA %.2f g)" % (np.max(np.abs(a_rec)) / G), fontsize=9)
    ax.legend(loc="upper right", fontsize=7)
    ax = axs[1]
    for face, col, colour in (("left", 0, "tab:blue"), ("right", 2, "tab:orange")):
        sign = -1.0 if face == "left" else 1.0   # downslope is -x on the left face
        for c, ls in (("shaken", "-"), ("unshaken", ":")):
            f = fem[c]
            ax.plot(f["t"], sign * (f["ux"][:, col] - f["ux"][0, col]), ls, color=colour, lw=1.0,
                    label="FEM %s shoulder, %s (downslope ux rel. to base)" % (face, c))
        h = newmark[face]["history"]
        ax.plot(h["t_out"], h["d_out"], "--", color=colour, lw=0.9, label="Newmark, outcrop record (%s face)" % face)
        ax.plot(h["t_el"], h["d_el"], "-.", color=colour, lw=0.9, label="Newmark, elastic-FEM sliding-mass accel (%s)" % face)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("downslope displacement (m)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=6, ncol=2)
    ax = axs[2]
    width = s["cell"]
    p = mpm["unshaken"]["particles_state"]
    xs, ys = metrics.particle_profile(p["x0"], p["y0"], width)
    ax.plot(xs, ys, color="0.6", lw=1.0, label="before shaking (unshaken transfer)")
    for c, colour in (("unshaken", "tab:green"), ("shaken", "tab:red")):
        p = mpm[c]["particles_state"]
        xs, ys = metrics.particle_profile(p["x"], p["y"], width)
        ax.plot(xs, ys, color=colour, lw=1.0, label="MPM deposit, %s (runout %.2f m)" % (c, mpm[c]["runout_m"]))
    pu, pk = mpm["unshaken"]["particles_state"], mpm["shaken"]["particles_state"]
    xu, yu = metrics.particle_profile(pu["x"], pu["y"], width)
    xk, yk = metrics.particle_profile(pk["x"], pk["y"], width)
    axd = ax.twinx()
    axd.plot(xk, yk - np.interp(xk, xu, yu), color="k", lw=0.8, ls="--", label="shaken - unshaken")
    axd.set_ylabel("surface difference, shaken - unshaken (m)")
    axd.legend(loc="lower right", fontsize=7)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("surface y (m)")
    ax.set_ylim(D - 1, D + H + 1.5)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("surface at the end of the MPM run (%g s after the shaking)" % s["duration"], fontsize=9)
    fig.tight_layout()
    path = plots.save(fig, os.path.join(out, "shaken_slope.png"))
    if copy_to:
        shutil.copyfile(path, copy_to + ".tmp")
        os.replace(copy_to + ".tmp", copy_to)


if __name__ == "__main__":
    sys.exit(main())
