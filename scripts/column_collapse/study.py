#!/usr/bin/python3
"""The hybrid FEM-MPM granular column collapse study (Sordo, Rathje & Kumar), end to end.

    scripts/column_collapse/study.py [--full] [--out DIR] [--jobs N] [--sweep]

Runs every configuration of the paper's column (50 m x 40 m, a = 0.8; E = 172 MPa, nu = 0.23,
rho = 1925 kg/m3; Mohr-Coulomb phi = 22.2 deg, psi = 0, c = 0.1 kPa):
  fem        FEM only (fem_tcl column_collapse.tcl), elastic gravity stage, stage switch, transient to 5 s
  mpm        MPM only, from the elastic (K0) geostatic state on the MPM grid
  hyb_<t>    FEM to t = 0, 0.5, 1, 2, 3 s, fem2mpm, then MPM to 20 s TOTAL time (20 - t of MPM time)
and writes the metrics (DESIGN.md "Metrics"), the figures (PNG) and a Markdown summary table to --out.
--sweep adds (or, with --sweep-only, runs only) MPM-only columns of aspect ratio a = 0.5 ... 4 against the
2D runout laws of Lube et al. (2005) and Lajeunesse et al. (2005).

Quick default: 2 m FEM elements and MPM cells, 2 x 2 particles per cell. --full: the paper's resolution,
1 m elements and cells, 4 x 4 particles per cell. Only /usr/bin/python3 with numpy, matplotlib, h5py.
"""
import argparse
import concurrent.futures
import json
import math
import os
import shutil
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
from geoflow import metrics, pipeline, plots  # noqa: E402  (scripts/geoflow: shared with scripts/hybrid_run.py)
from geoflow.metrics import read_series, read_particles, particle_steps, particle_profile  # noqa: E402

# The reference scene (DESIGN.md), SI units for MPM; the FEM script works in kN, m, s, kPa, Mg/m3.
G = 9.81
RHO = 1925.0            # kg/m3
E_MOD = 172.0e6         # Pa
NU = 0.23
PHI = 22.2              # deg
PSI = 0.0               # deg
COHESION = 100.0        # Pa (0.1 kPa: "minimal cohesion"; keeps the apex of the yield surface finite)
BASE_MU = round(math.tan(math.radians(PHI)), 3)   # 0.408: base as rough as the soil (see README)
TRANSFERS = (0.0, 0.5, 1.0, 2.0, 3.0)
T_TOTAL = 20.0          # s, every MPM run ends at this TOTAL time (FEM time + MPM time)
FEM_TEND = 5.0
CFL = 0.5
SCHEME = "musl"
PIC_BLEND = 0.0         # FLIP only
TRANSFER = "apic"       # velocity transfer of every MPM run ("flip", "pic", "apic"): docs/study/transfer_comparison.md


class Scene:
    """One column geometry and resolution."""

    def __init__(self, width, height, cell, ppd, fem_dt=1e-3, record=0.05, out_every=0.1, t_total=T_TOTAL):
        self.width, self.height, self.cell, self.ppd = width, height, cell, ppd
        self.fem_dt, self.record, self.out_every, self.t_total = fem_dt, record, out_every, t_total

    @property
    def aspect(self):
        return self.height / self.width

    @property
    def tau_c(self):
        return math.sqrt(self.height / G)

    def grid_extent(self):
        """x from the left wall to beyond the expected runout (Lube's law + margin), one cell row below the base."""
        a = self.aspect
        x_max = self.width * (3.0 + 2.5 * max(a, a ** (2.0 / 3.0)))
        x_max = math.ceil(x_max / self.cell) * self.cell
        y_top = math.ceil((self.height + 2 * self.cell) / self.cell) * self.cell
        return 0.0, x_max, -self.cell, y_top


def log(msg):
    print(msg, flush=True)


# ----------------------------------------------------------------------------------------------
# Runs
# ----------------------------------------------------------------------------------------------

def run_fem(bins, fem_script, scene, out, tend):
    """The FEM-only run to tend; past an inverted element it goes on (`-on-inversion continue`, as the paper's
    FEM run went on to 5 s); the figures draw it dashed from the first inversion on."""
    d = os.path.join(out, "fem")
    args = ["-width", str(scene.width), "-height", str(scene.height), "-cell", str(scene.cell), "-tend", str(tend),
            "-dt", str(scene.fem_dt), "-record", str(scene.record), "-phi", str(PHI), "-cohesion", str(COHESION / 1000.0),
            "-on-inversion", "continue"]
    wall = pipeline.run_fem_script(bins, fem_script, d, args)
    return {"name": "fem", "kind": "fem", "dir": d, "wall": {"fem": wall}}


def tune_deck(deck_path, smoothing="none", particle_steps=None):
    """Study settings the bridge has no option for: automatic dt (CFL), FLIP/PIC blend, stress smoothing,
    and the steps with particle files (None: every output step)."""
    def edit(deck):
        if particle_steps is not None:
            deck["post_processing"]["particle_output_steps"] = particle_steps
        a = deck["analysis"]
        a["cfl"] = CFL
        a.pop("velocity_update", None)
        a.pop("pic_blend", None)
        a.update(transfer_keys(TRANSFER, PIC_BLEND))
        a["stress_smoothing"] = smoothing
    pipeline.edit_deck(deck_path, edit)


def particle_output_steps(nsteps, dt, every, t0, keep_times):
    """The output steps whose particle files the figures read: the first, the last, and the two around
    each of keep_times (TOTAL time; the state after loop step s is at t0 + (s + 1) dt). mpm writes only
    those (post_processing.particle_output_steps) instead of a ~30 MB file per output step that
    prune_particle_files would delete; series.csv keeps its row at every output step."""
    steps = list(range(0, nsteps, every))
    keep = {steps[0], steps[-1]}
    for t in keep_times:
        x = ((t - t0) / dt - 1.0) / every
        for k in (math.floor(x), math.ceil(x)):
            if 0 <= k < len(steps):
                keep.add(steps[k])
    return sorted(keep)


def mpm_nsteps(scene, duration):
    dt = CFL * scene.cell / p_wave_speed()
    return int(math.ceil(duration / dt - 1e-9)) + 1, dt


def p_wave_speed():
    return math.sqrt(E_MOD * (1 - NU) / ((1 + NU) * (1 - 2 * NU) * RHO))


def run_hybrid(bins, scene, out, fem_dir, t_transfer, threads, keep_times=None):
    name = "hyb_%g" % t_transfer
    d = os.path.join(out, name)
    if os.path.isdir(d):
        shutil.rmtree(d)
    x0, x1, y0, y1 = scene.grid_extent()
    duration = scene.t_total - t_transfer
    nsteps, dt = mpm_nsteps(scene, duration)
    out_steps = max(1, int(round(scene.out_every / dt)))
    options = ["--units", "kN", "--ppd", str(scene.ppd),
               "--cell-size", str(scene.cell), "--extent", str(x0), str(x1), str(y0), str(y1), "--base-y", "0",
               "--right-wall", "none", "--base", "friction", "--base-friction", str(BASE_MU),
               "--scheme", SCHEME, "--dt", repr(dt), "--nsteps", str(nsteps), "--output-steps", str(out_steps),
               "--material-type", "mohr-coulomb", "--phi", str(PHI), "--psi", str(PSI), "--cohesion", str(COHESION / 1000.0)]
    w_bridge = pipeline.run_fem2mpm(bins, fem_dir, d, t_transfer, options)
    tune_deck(os.path.join(d, "mpm.json"),
              particle_steps=None if keep_times is None else
              particle_output_steps(nsteps, dt, out_steps, t_transfer, keep_times))
    w_mpm = pipeline.run_mpm(bins, d, threads)
    return {"name": name, "kind": "hybrid", "dir": d, "t0": t_transfer, "wall": {"fem2mpm": w_bridge, "mpm": w_mpm},
            "results": os.path.join(d, "results", "column")}


def transfer_keys(transfer, pic_blend):
    """analysis keys of a velocity transfer: "flip" (with pic_blend), "pic" or "apic" (mpm/README.md)."""
    return {"transfer": transfer, "pic_blend": pic_blend} if transfer == "flip" else {"transfer": transfer}


def write_mpm_only_deck(scene, d, smoothing="none", duration=None, out_every=None, pic_blend=PIC_BLEND,
                        transfer=TRANSFER, base="friction", keep_times=None, normal_lag=None):
    """MPM only: particles on the MPM grid (ppd x ppd per cell, at the centres of equal sub-cells), K0
    elastic geostatic stresses sigma_v = -rho g (H - y), sigma_h = sigma_z = nu / (1 - nu) sigma_v.
    base "friction": CB-Geo's base (y-velocity 0 and Coulomb friction); "contact": the friction constraint
    alone, which mpm takes as a one-sided frictional contact (fem2mpm --base contact). normal_lag: None, or
    (slip distance m, reference speed m/s) of the base friction's lagged strength (mpm/core/lagged_friction.hpp)."""
    os.makedirs(d, exist_ok=True)
    h, n = scene.cell, scene.ppd
    nx, ny = int(round(scene.width / h)), int(round(scene.height / h))
    sub = (np.arange(n) + 0.5) / n * h
    xs, ys = [], []
    for j in range(ny):
        for i in range(nx):
            for b in range(n):
                for a in range(n):
                    xs.append(i * h + sub[a])
                    ys.append(j * h + sub[b])
    xs, ys = np.array(xs), np.array(ys)
    sv = -RHO * G * (scene.height - ys)
    sh = NU / (1 - NU) * sv
    with open(os.path.join(d, "particles.txt"), "w") as f:
        f.write("%d\n" % len(xs))
        for x, y in zip(xs, ys):
            f.write("%.10g\t%.10g\n" % (x, y))
    with open(os.path.join(d, "particles_stresses.txt"), "w") as f:
        f.write("%d\n" % len(xs))
        for a, b in zip(sh, sv):
            f.write("%.10g\t%.10g\t%.10g\t0\t0\t0\n" % (a, b, a))
    vol = h * h / (n * n)
    with open(os.path.join(d, "particles_volumes.txt"), "w") as f:
        for k in range(len(xs)):
            f.write("%d\t%.10g\n" % (k, vol))
    x0, x1, y0, y1 = scene.grid_extent()
    cx, cy = int(round((x1 - x0) / h)), int(round((y1 - y0) / h))
    # mesh.generator lattice: node id = i + j * nodes_x from the lower-left HALO node (GIMP ring).
    nodes_x, nodes_y = cx + 3, cy + 3
    base_nodes = [i + j * nodes_x for j in range(nodes_y) for i in range(nodes_x) if y0 + (j - 1) * h <= 1e-9 * h]
    with open(os.path.join(d, "entity_sets.json"), "w") as f:
        json.dump({"node_sets": [{"id": 1, "set": base_nodes}]}, f)
    duration = scene.t_total if duration is None else duration
    nsteps, dt = mpm_nsteps(scene, duration)
    out_every = scene.out_every if out_every is None else out_every
    deck = {
        "title": "MPM-only column collapse from the K0 geostatic state (study.py)",
        "mesh": {"generator": {"origin": [x0, y0], "cell_size": [h, h], "cells": [cx, cy]},
                 "cell_type": "ED2Q16G", "entity_sets": "entity_sets.json",
                 "particles_stresses": "particles_stresses.txt", "particles_volumes": "particles_volumes.txt",
                 "boundary_conditions": {
                     "velocity_constraints": [{"nset_id": "left", "dir": 0, "velocity": 0.0}] +
                                             ([{"nset_id": 1, "dir": 1, "velocity": 0.0}] if base == "friction" else []),
                     "friction_constraints": [dict({"nset_id": 1, "dir": 1, "sign_n": -1, "friction": BASE_MU},
                                                   **({} if normal_lag is None else {"normal_lag": {
                                                       "slip_distance": normal_lag[0],
                                                       "reference_velocity": normal_lag[1]}}))]}},
        "particles": [{"generator": {"type": "file", "location": "particles.txt", "io_type": "Ascii2D",
                                     "check_duplicates": False, "particle_type": "P2D", "material_id": 0,
                                     "pset_id": 0}}],
        "materials": [{"id": 0, "type": "MohrCoulomb2D", "density": RHO, "youngs_modulus": E_MOD,
                       "poisson_ratio": NU, "friction": PHI, "dilation": PSI, "cohesion": COHESION,
                       "residual_friction": PHI, "residual_dilation": PSI, "residual_cohesion": COHESION,
                       "peak_pdstrain": 0.0, "residual_pdstrain": 0.0,
                       "tension_cutoff": COHESION / math.tan(math.radians(PHI)), "softening": False}],
        "external_loading_conditions": {"gravity": [0.0, -G]},
        "analysis": dict({"type": "MPMExplicit2D", "mpm_scheme": SCHEME, "locate_particles": True,
                          "dt": dt, "cfl": CFL, "stress_smoothing": smoothing,
                          "nsteps": nsteps, "uuid": "column",
                          "damping": {"type": "Cundall", "damping_factor": 0.0}}, **transfer_keys(transfer, pic_blend)),
        "post_processing": {"path": "results/", "output_steps": max(1, int(round(out_every / dt)))},
    }
    if keep_times is not None:
        every = deck["post_processing"]["output_steps"]
        deck["post_processing"]["particle_output_steps"] = particle_output_steps(nsteps, dt, every, 0.0, keep_times)
    with open(os.path.join(d, "mpm.json"), "w") as f:
        json.dump(deck, f, indent=2)


def run_mpm_only(bins, scene, out, threads, name="mpm", smoothing="none", duration=None, out_every=None,
                 pic_blend=PIC_BLEND, transfer=TRANSFER, base="friction", keep_times=None, normal_lag=None):
    """keep_times: the TOTAL times whose particle files are written (particle_output_steps); None: all."""
    d = os.path.join(out, name)
    if os.path.isdir(d):
        shutil.rmtree(d)
    write_mpm_only_deck(scene, d, smoothing, duration, out_every, pic_blend, transfer, base, keep_times, normal_lag)
    w = pipeline.run_mpm(bins, d, threads)
    with open(os.path.join(d, "wall.txt"), "w") as f:
        f.write("%.3f\n" % w)
    return {"name": name, "kind": "mpm", "dir": d, "t0": 0.0, "wall": {"mpm": w},
            "results": os.path.join(d, "results", "column"), "aspect": scene.aspect,
            "width": scene.width, "height": scene.height}


# ----------------------------------------------------------------------------------------------
# Metrics
# ----------------------------------------------------------------------------------------------

def mpm_run_series(run, fem=None):
    """Time series of a MPM run on TOTAL time: the transfer (or initial) state, then series.csv."""
    return metrics.mpm_run_series(run["results"], run["t0"], run["kind"] == "hybrid")


def fem_series(fem_dir, cell):
    out, xy, disp = metrics.fem_series(fem_dir, RHO)
    t_q, det_j, ratio = metrics.fem_mesh_quality(fem_dir)
    out["minJ_t"] = t_q
    out["minJ"] = ratio if ratio is not None else det_j
    out["minJ0"] = 1.0 if ratio is not None else cell * cell / 4.0   # corner det J of an undistorted square element
    out["t_inverted"] = metrics.fem_first_inversion(fem_dir)
    return out, xy, disp


def fem_outline(xy, u, width, height, cell):
    """Top surface then right face of the deformed FEM mesh (x, y arrays)."""
    nx, ny = int(round(width / cell)), int(round(height / cell))
    cur = xy + u
    top = [ny * (nx + 1) + i for i in range(nx + 1)]
    right = [j * (nx + 1) + nx for j in range(ny, -1, -1)]
    idx = top + right[1:]
    return cur[idx, 0], cur[idx, 1]


def particles_at(run, t_total):
    """Particle file of a run closest to TOTAL time t (None if the run does not cover t)."""
    res = run["results"]
    s = read_series(res)
    tt = s["time"] + run["t0"]
    if run["kind"] == "hybrid" and abs(t_total - run["t0"]) < 1e-9:
        return read_particles(particle_steps(res)[0])
    if len(tt) == 0 or t_total < run["t0"] or t_total > tt[-1] + 1e-9:
        return None
    k = int(np.argmin(np.abs(tt - t_total)))
    f = particle_steps(res).get(int(s["step"][k]))
    return read_particles(f) if f else None


def prune_particle_files(run, keep_times):
    """Deletes the particle files not needed for the figures (a full run writes ~13 MB per output)."""
    metrics.prune_particle_files(run["results"], run["t0"], keep_times)


# ----------------------------------------------------------------------------------------------
# Figures and table
# ----------------------------------------------------------------------------------------------

def figures(out, scene, series, fem_prof, hybrid_run, snap_runs):
    """The paper's Figure 5 (profiles, runout and height, energies) and the extra figures. The FEM-only curves
    are dashed and labelled past the first inverted element (the run went on with -on-inversion continue);
    dotted lines mark t = 3 and 5 s, where the paper compares the runs."""
    plt = plots.pyplot()
    tau, L0, H0 = scene.tau_c, scene.width, scene.height
    fem_series_ = series.get("fem")
    t_inv = fem_series_.get("t_inverted") if fem_series_ is not None else None
    inv_label = "past its first inverted element (t = %.3g s)" % t_inv if t_inv is not None else ""

    def draw(ax, name, s, x, y):
        """One run's curve; FEM only split at its first inversion."""
        if name == "fem":
            plots.plot_split_at(ax, x, y, None if t_inv is None else t_inv / tau, colors.get(name),
                                labels.get(name, name), inv_label)
        else:
            ax.plot(x, y, color=colors.get(name), label=labels.get(name, name), lw=1.2)

    def mark_compare_times(ax):
        for tc in (3.0, 5.0):
            ax.axvline(tc / tau, ls=":", color="0.6", lw=0.7)
            ax.text(tc / tau, 1.0, " %g s" % tc, transform=ax.get_xaxis_transform(), fontsize=6.5, color="0.4",
                    va="bottom", ha="center")
    colors = {"fem": "k", "mpm": "tab:blue"}
    cyc = ["tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown"]
    for k, t in enumerate(TRANSFERS):
        colors["hyb_%g" % t] = cyc[k % len(cyc)]
    labels = {"fem": "FEM only", "mpm": "MPM only"}
    for t in TRANSFERS:
        labels["hyb_%g" % t] = "hybrid, transfer at %g s" % t
    paths = []

    def save(fig, name):
        paths.append(plots.save(fig, os.path.join(out, name)))

    # 1. surface profiles: FEM and the 1 s hybrid at t = 1, 3, 5 s
    fig, axs = plt.subplots(3, 1, figsize=(7, 6.5), sharex=True)
    for ax, t in zip(axs, (1.0, 3.0, 5.0)):
        ax.plot([0, L0, L0], [H0, H0, 0], ":", color="0.6", lw=1, label="initial column")
        if t in fem_prof and t_inv is not None and t > t_inv:
            ax.plot(*fem_prof[t], "k--", lw=1.5, label="FEM only (deformed mesh outline), %s" % inv_label)
        elif t in fem_prof:
            ax.plot(*fem_prof[t], "k-", lw=1.5, label="FEM only (deformed mesh outline)")
        else:
            ax.text(0.6, 0.8, "FEM did not reach t = %g s" % t, transform=ax.transAxes)
        if hybrid_run is not None:
            p = particles_at(hybrid_run, t)
            if p is not None:
                ax.plot(*particle_profile(p["coord_x"], p["coord_y"], scene.cell), "-", color="tab:green", lw=1.5,
                        label="hybrid (transfer at 1 s), particle surface")
        ax.set_ylabel("y (m)")
        ax.set_title("t = %g s (t/tau_c = %.2f)" % (t, t / tau), fontsize=9)
        ax.set_aspect("equal")
        ax.set_ylim(0, H0 * 1.1)
        ax.set_xlim(0, L0 * 3.2)
    for ax in axs:
        ax.legend(loc="upper right", fontsize=6.5)
    axs[-1].set_xlabel("x (m)")
    save(fig, "profiles.png")

    # 2. runout and height
    fig, axs = plt.subplots(1, 2, figsize=(9, 3.4))
    for name, s in series.items():
        draw(axs[0], name, s, s["t"] / tau, (s["L"] - L0) / L0)
        draw(axs[1], name, s, s["t"] / tau, s["H"] / H0)
    axs[0].axhline(1.53, ls="--", color="0.4", lw=0.8)
    axs[0].text(0.2, 1.56, "empirical 1.53 (a = 0.8)", fontsize=7, color="0.3")
    axs[0].axhline(1.6, ls=":", color="0.4", lw=0.8)
    axs[0].set_ylabel("normalized runout (L - L0)/L0")
    axs[1].set_ylabel("normalized height H/H0")
    for ax in axs:
        ax.set_xlabel("t / tau_c")
        ax.grid(alpha=0.3)
        mark_compare_times(ax)
    axs[0].legend(fontsize=6.5)
    save(fig, "runout_height.png")

    # 3. energies
    for key, title, fname in (("PE", "potential energy PE/PE0", "energy_pe.png"),
                              ("KEx", "horizontal kinetic energy KEx/PE0", "energy_kex.png"),
                              ("KEy", "vertical kinetic energy KEy/PE0", "energy_key.png")):
        fig, ax = plt.subplots(figsize=(5.5, 3.4))
        for name, s in series.items():
            draw(ax, name, s, s["t"] / tau, s[key] / s["PE0"])
        mark_compare_times(ax)
        if key == "PE":
            ax.axhline(0.6, ls="--", color="0.4", lw=0.8)
        ax.set_xlabel("t / tau_c")
        ax.set_ylabel(title)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6.5)
        save(fig, fname)

    # 4. FEM minimum Jacobian
    fem = series.get("fem")
    if fem is not None and len(fem["minJ"]):
        fig, ax = plt.subplots(figsize=(5.5, 3.4))
        ax.plot(fem["minJ_t"] / tau, fem["minJ"] / fem["minJ0"], "k-")
        ax.axhline(0, color="tab:red", lw=0.8)
        ax.axvline(1.75, ls="--", color="0.5", lw=0.8)
        ax.set_xlim(0, max(2.5, fem["minJ_t"][-1] / tau))
        ax.text(1.78, 0.9, "paper: mesh unusable\npast t/tau_c ~ 1.75", fontsize=7)
        ax.set_xlabel("t / tau_c")
        ax.set_ylabel("min det J / det J of the undistorted element")
        ax.set_title("FEM only: mesh quality", fontsize=9)
        ax.grid(alpha=0.3)
        save(fig, "fem_min_jacobian.png")

    # 5. shear-stress snapshot with and without the checkerboard remedy
    if snap_runs:
        fig, axs = plt.subplots(1, len(snap_runs), figsize=(3.4 * len(snap_runs), 3.0), sharey=True)
        for ax, (title, run, t) in zip(np.atleast_1d(axs), snap_runs):
            p = particles_at(run, t)
            if p is None:
                continue
            sel = p["coord_x"] < L0 * 1.6
            spacing = scene.cell / scene.ppd
            sc = ax.scatter(p["coord_x"][sel], p["coord_y"][sel], c=p["tau_xy"][sel] / 1e3, s=(2.4 * spacing) ** 2,
                            marker="s", cmap="RdBu_r", vmin=-120, vmax=120, linewidths=0)
            ser = read_series(run["results"])
            ci = ser["checkerboard_index"][int(np.argmin(np.abs(ser["time"] + run["t0"] - t)))]
            ax.set_title("%s, t = %g s\ncheckerboard index %.3f" % (title, t, ci), fontsize=7)
            ax.set_aspect("equal")
            ax.set_xlabel("x (m)")
        np.atleast_1d(axs)[0].set_ylabel("y (m)")
        fig.colorbar(sc, ax=axs, label="tau_xy (kPa)", shrink=0.8)
        save(fig, "shear_stress_checkerboard.png")
    return paths


def summary_rows(series, walls, scene):
    tau, L0, H0 = scene.tau_c, scene.width, scene.height
    rows = []
    for name, s in series.items():
        rows.append({"run": name, "t_end": s["t"][-1], "runout": (s["L"][-1] - L0) / L0, "height": s["H"][-1] / H0,
                     "pe": s["PE"][-1] / s["PE0"], "t_kex": s["t"][int(np.argmax(s["KEx"]))] / tau,
                     "t_key": s["t"][int(np.argmax(s["KEy"]))] / tau, "wall": walls.get(name, {}),
                     "t_inverted": s.get("t_inverted")})
    return rows


def summary_markdown(rows, scene, mode, not_possible=None):
    """The summary table; the FEM row gives the time of its first inverted element (its values past that time
    come from an inverted mesh), and the transfers that could not be made are listed with the reason."""
    lines = ["| run | end t (s) | runout (L-L0)/L0 | H/H0 | PE/PE0 | t/tau_c at peak KEx | t/tau_c at peak KEy | wall time (s) |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        w = r["wall"]
        wt = ", ".join("%s %.1f" % (k, v) for k, v in w.items())
        name = r["run"]
        if r.get("t_inverted") is not None:
            name += " (first inverted element at %.3g s)" % r["t_inverted"]
        lines.append("| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %s |" % (name, r["t_end"], r["runout"], r["height"],
                                                                               r["pe"], r["t_kex"], r["t_key"], wt))
    for t, why in sorted((not_possible or {}).items()):
        lines.append("| hyb_%g | not possible: %s | | | | | | |" % (t, why))
    lines.append("| paper (MPM, hybrids) | 20 | ~1.6 (empirical 1.53, Soundararajan 2015) | | ~0.6 | ~1.75 | ~1 | |")
    return "\n".join(lines) + "\n"


# ----------------------------------------------------------------------------------------------
# Aspect-ratio sweep
# ----------------------------------------------------------------------------------------------

SWEEP_A = (0.5, 1.0, 2.0, 3.0, 4.0)


def sweep_scene(a, cell, ppd, area=2000.0):
    w = max(2, round(math.sqrt(area / a) / cell)) * cell
    h = max(2, round(a * w / cell)) * cell
    return Scene(w, h, cell, ppd, out_every=0.25)


# 2D runout laws (L - L0)/L0 = lambda1 a (a < a1), lambda2 a^(2/3) (a > a2), as consolidated by Lagree, Staron &
# Popinet (2011, J. Fluid Mech. 686, eq. 3.1): Lube et al. (2005, sand, rice, sugar) 1.2, 1.9, a1 = 1.8, a2 = 2.8;
# Lajeunesse et al. (2005, glass beads, 2D channel) 1.8, 2.3, a1 = a2 = 3. Their continuum mu(I) simulations give
# about 2.2 a up to a ~ 7.
RUNOUT_LAWS = {"lube": (1.2, 1.9, 1.8, 2.8), "lajeunesse": (1.8, 2.3, 3.0, 3.0)}


def runout_law(name, a):
    l1, l2, a1, a2 = RUNOUT_LAWS[name]
    a = np.asarray(a, dtype=float)
    lin, powr = l1 * a, l2 * a ** (2.0 / 3.0)
    mid = lin + (powr - lin) * np.clip((a - a1) / max(a2 - a1, 1e-9), 0, 1)   # straight blend across the transition
    return np.where(a <= a1, lin, np.where(a >= a2, powr, mid))


def lube(a):
    return runout_law("lube", a)


def lajeunesse(a):
    return runout_law("lajeunesse", a)


def sweep_plot(out, results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    a = np.linspace(0.3, 4.5, 300)
    ax.plot(a, lube(a), "k-", lw=1, label="Lube et al. 2005: 1.2 a (a < 1.8), 1.9 a^(2/3) (a > 2.8)")
    ax.plot(a, lajeunesse(a), "k--", lw=1, label="Lajeunesse et al. 2005: 1.8 a (a < 3), 2.3 a^(2/3)")
    ax.plot(a, 2.2 * a, ":", color="0.5", lw=1, label="continuum mu(I), Lagree et al. 2011: ~2.2 a")
    ax.plot([0.8], [1.53], "s", color="0.4", label="empirical 1.53 at a = 0.8 (Soundararajan 2015)")
    ax.plot([r["aspect"] for r in results], [r["runout"] for r in results], "o", color="tab:blue",
            label="MPM only, Mohr-Coulomb phi 22.2 (this study)")
    ax.set_xlabel("aspect ratio a = H0/L0")
    ax.set_ylabel("final normalized runout (L - L0)/L0")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=6.5)
    p = os.path.join(out, "aspect_sweep.png")
    fig.savefig(p, bbox_inches="tight", dpi=110)
    plt.close(fig)
    return p


SWEEP_RETRY_PIC_BLEND = 0.02


def sweep_one(bins, out, a, cell, ppd):
    """One MPM-only column of aspect ratio a; on a numerical failure (FLIP velocity runaway in the thin fast
    front of a tall column) it is run again with a 2 % PIC blend (mpm's CFL 0.5 stability test)."""
    sc = sweep_scene(a, cell, ppd)
    try:
        return run_mpm_only(bins, sc, os.path.join(out, "sweep"), 1, "a_%g" % a, keep_times=())
    except RuntimeError as e:
        log("sweep a = %g failed (%s); again with a %g PIC blend" % (a, str(e).splitlines()[-1][:160], SWEEP_RETRY_PIC_BLEND))
        return run_mpm_only(bins, sc, os.path.join(out, "sweep"), 1, "a_%g" % a, keep_times=(), pic_blend=SWEEP_RETRY_PIC_BLEND,
                            transfer="flip")


def collect_sweep(out, cell, ppd):
    """Results of the sweep runs present in out/sweep (complete runs only)."""
    results = []
    for a in SWEEP_A:
        sc = sweep_scene(a, cell, ppd)
        d = os.path.join(out, "sweep", "a_%g" % a)
        res = os.path.join(d, "results", "column")
        if not os.path.exists(os.path.join(res, "series.csv")):
            continue
        s = read_series(res)
        if s["time"][-1] < sc.t_total - 0.01:
            log("sweep a = %g: incomplete run (ends at %.2f s), left out" % (a, s["time"][-1]))
            continue
        with open(os.path.join(d, "mpm.json")) as f:
            blend = json.load(f)["analysis"].get("pic_blend", 0.0)
        wall = float(open(os.path.join(d, "wall.txt")).read()) if os.path.exists(os.path.join(d, "wall.txt")) else float("nan")
        results.append({"a_nominal": a, "aspect": sc.aspect, "width": sc.width, "height": sc.height,
                        "runout": (s["runout_x_p98"][-1] - sc.width) / sc.width, "height_ratio": s["height_y_p995"][-1] / sc.height,
                        "t_end": s["time"][-1], "wall": wall, "pic_blend": blend})
    return results


def run_sweep(bins, out, cell, ppd, jobs, only=None):
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as ex:
        futs = {ex.submit(sweep_one, bins, out, a, cell, ppd): a for a in (only or SWEEP_A)}
        for f in concurrent.futures.as_completed(futs):
            try:
                run = f.result()
                prune_particle_files(run, [])
                log("sweep a = %g done: %.1f s" % (futs[f], run["wall"]["mpm"]))
            except RuntimeError as e:
                log("sweep a = %g FAILED: %s" % (futs[f], str(e).splitlines()[-1][:200]))
    results = collect_sweep(out, cell, ppd)
    for r in results:
        log("sweep a = %.2f (%g x %g m): runout %.2f (Lube %.2f, Lajeunesse %.2f)" % (
            r["aspect"], r["width"], r["height"], r["runout"], float(lube(r["aspect"])), float(lajeunesse(r["aspect"]))))
    write_sweep_report(out, results)
    return results


def write_sweep_report(out, results):
    """sweep.json, sweep.md (table against the laws) and aspect_sweep.png."""
    for r in results:
        r["lube"], r["lajeunesse"] = float(lube(r["aspect"])), float(lajeunesse(r["aspect"]))
    with open(os.path.join(out, "sweep.json"), "w") as f:
        json.dump(results, f, indent=1)
    lines = ["| a = H0/L0 | column (m) | MPM runout (L-L0)/L0 | Lube et al. 2005 | Lajeunesse et al. 2005 | H/H0 | PIC blend | wall (s) |",
             "|---|---|---|---|---|---|---|---|"]
    for r in results:
        lines.append("| %.2f | %g x %g | %.2f | %.2f | %.2f | %.2f | %g | %.1f |" % (
            r["aspect"], r["width"], r["height"], r["runout"], r["lube"], r["lajeunesse"], r["height_ratio"],
            r.get("pic_blend", 0.0), r["wall"]))
    with open(os.path.join(out, "sweep.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    sweep_plot(out, results)


# ----------------------------------------------------------------------------------------------
# Driver
# ----------------------------------------------------------------------------------------------

def find_bins(bin_dir):
    try:
        return pipeline.find_bins(bin_dir, REPO)
    except pipeline.PipelineError as e:
        sys.exit("study.py: error: %s" % e)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--full", action="store_true", help="the paper's resolution: 1 m elements and cells, 4 x 4 particles per cell")
    ap.add_argument("--out", default=None, help="output folder (default results/study_quick or results/study_full in the repository)")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time (each MPM run uses one thread)")
    ap.add_argument("--sweep", action="store_true", help="also run the aspect-ratio sweep (MPM only)")
    ap.add_argument("--sweep-only", action="store_true", help="run only the aspect-ratio sweep")
    ap.add_argument("--sweep-report", action="store_true", help="rewrite the sweep table and plot from the runs in --out/sweep")
    ap.add_argument("--sweep-a", default=None, help="with --sweep-only: only these aspect ratios (comma list of %s)"
                    % ",".join("%g" % a for a in SWEEP_A))
    ap.add_argument("--bin", default=None, help="folder with fem_tcl, fem2mpm, mpm (default build/bin)")
    ap.add_argument("--fem-script", default=os.path.join(HERE, "column_collapse.tcl"), help="the FEM collapse script")
    ap.add_argument("--width", type=float, default=50.0, help="column width L0, m")
    ap.add_argument("--height", type=float, default=40.0, help="column height H0, m")
    ap.add_argument("--cell", type=float, default=None, help="FEM element and MPM cell size, m (quick 2, full 1)")
    ap.add_argument("--ppd", type=int, default=None, help="particles per cell and direction (quick 2, full 4)")
    ap.add_argument("--t-total", type=float, default=T_TOTAL, help="end of every MPM run, total time, s")
    ap.add_argument("--fem-tend", type=float, default=FEM_TEND, help="end of the FEM-only run, s")
    ap.add_argument("--fem-dt", type=float, default=1e-3, help="FEM time step, s")
    ap.add_argument("--transfers", default=",".join("%g" % t for t in TRANSFERS), help="transfer times, s (comma list)")
    ap.add_argument("--fem-from", default=None, help="reuse the FEM output in this folder (no FEM run)")
    ap.add_argument("--no-figures", action="store_true", help="metrics and table only")
    ap.add_argument("--no-checkerboard", action="store_true", help="skip the extra run with stress smoothing")
    args = ap.parse_args(argv)

    cell = args.cell or (1.0 if args.full else 2.0)
    ppd = args.ppd or (4 if args.full else 2)
    out = os.path.abspath(args.out or os.path.join(REPO, "results", "study_full" if args.full else "study_quick"))
    os.makedirs(out, exist_ok=True)
    bins = find_bins(args.bin)
    t_start = time.perf_counter()
    mode = "full" if args.full else "quick"

    if args.sweep_report:
        write_sweep_report(out, collect_sweep(out, cell, ppd))
        return 0
    if args.sweep_only:
        only = [float(a) for a in args.sweep_a.split(",")] if args.sweep_a else None
        run_sweep(bins, out, cell, ppd, args.jobs, only)
        log("sweep done in %.1f s" % (time.perf_counter() - t_start))
        return 0

    scene = Scene(args.width, args.height, cell, ppd, fem_dt=args.fem_dt, t_total=args.t_total,
                  out_every=0.2 if args.full else 0.1)
    transfers = [float(t) for t in args.transfers.split(",") if t.strip()]
    fem_tend = max([args.fem_tend] + transfers)
    log("study (%s): column %g x %g m, cell %g m, %d x %d particles per cell, tau_c = %.2f s, base friction %.3f, out %s"
        % (mode, scene.width, scene.height, cell, ppd, ppd, scene.tau_c, BASE_MU, out))
    runs = {}
    snap_t = 1.0
    figure_times = (1.0, 3.0, 5.0, snap_t)  # the particle files the figures read (and prune keeps)
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        if args.fem_from:
            f_fem = concurrent.futures.Future()
            f_fem.set_result({"name": "fem", "kind": "fem", "dir": os.path.abspath(args.fem_from), "wall": {}})
        else:
            f_fem = ex.submit(run_fem, bins, args.fem_script, scene, out, fem_tend)
        f_mpm = ex.submit(run_mpm_only, bins, scene, out, 1, keep_times=figure_times)
        f_smooth = {}
        if not args.no_checkerboard:
            for remedy in ("cell_volumetric", "cell_strain", "nodal_strain"):
                f_smooth[remedy] = ex.submit(run_mpm_only, bins, scene, out, 1, "mpm_" + remedy, remedy, snap_t + 0.5, 0.5)
        runs["fem"] = f_fem.result()
        log("fem done: %.1f s" % runs["fem"]["wall"].get("fem", float("nan")))
        t_fem = metrics.fem_last_time(runs["fem"]["dir"])
        t_inv = metrics.fem_first_inversion(runs["fem"]["dir"])
        not_possible = {}
        for t in transfers:
            if t > t_fem + 1e-9:
                not_possible[t] = "the FEM run ended at t = %g s (not converged)" % t_fem
            elif t_inv is not None and t >= t_inv - 1e-9:
                not_possible[t] = "the FEM mesh has inverted elements (first at t = %g s)" % t_inv
        for t, why in not_possible.items():
            log("hybrid %g s skipped: %s" % (t, why))
        transfers = [t for t in transfers if t not in not_possible]
        f_h = {t: ex.submit(run_hybrid, bins, scene, out, runs["fem"]["dir"], t, 1, figure_times) for t in transfers}
        failed = {}
        try:
            runs["mpm"] = f_mpm.result()
            log("mpm only done: %.1f s" % runs["mpm"]["wall"]["mpm"])
        except RuntimeError as e:
            failed["mpm"] = str(e)
        for t, f in f_h.items():
            try:
                runs["hyb_%g" % t] = f.result()
                log("hybrid %g s done: fem2mpm %.1f s, mpm %.1f s" % (t, runs["hyb_%g" % t]["wall"]["fem2mpm"],
                                                                    runs["hyb_%g" % t]["wall"]["mpm"]))
            except RuntimeError as e:
                failed["hyb_%g" % t] = str(e)
        for name, msg in failed.items():
            log("study.py: %s FAILED (left out of the figures): %s" % (name, msg))
        transfers = [t for t in transfers if "hyb_%g" % t in runs]
        smooth = {k: f.result() for k, f in f_smooth.items()}
    t_runs = time.perf_counter() - t_start

    # metrics
    series = {}
    fem_s, fem_xy, fem_disp = fem_series(runs["fem"]["dir"], cell)
    pe0_fem = fem_s["PE"][0]
    fem_s["PE0"] = pe0_fem
    series["fem"] = fem_s
    if "mpm" in runs:
        s = mpm_run_series(runs["mpm"])
        s["PE0"] = RHO * G * scene.width * scene.height ** 2 / 2.0
        series["mpm"] = s
    for t in transfers:
        s = mpm_run_series(runs["hyb_%g" % t])
        s["PE0"] = pe0_fem
        series["hyb_%g" % t] = s
    # FEM profiles at t = 1, 3, 5 s
    fem_prof = {}
    for t in (1.0, 3.0, 5.0):
        k = np.where(np.abs(fem_disp[:, 0] - t) < 1e-6)[0]
        if len(k):
            fem_prof[t] = fem_outline(fem_xy, fem_disp[k[-1], 1:].reshape(-1, 2), scene.width, scene.height, cell)
    # metrics file (CSV per run)
    for name, s in series.items():
        with open(os.path.join(out, "metrics_%s.csv" % name), "w") as f:
            f.write("t,t_over_tau_c,runout_norm,height_norm,pe_ratio,kex_ratio,key_ratio\n")
            for k in range(len(s["t"])):
                f.write("%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n" % (s["t"][k], s["t"][k] / scene.tau_c,
                        (s["L"][k] - scene.width) / scene.width, s["H"][k] / scene.height, s["PE"][k] / s["PE0"],
                        s["KEx"][k] / s["PE0"], s["KEy"][k] / s["PE0"]))
    walls = {name: r["wall"] for name, r in runs.items()}
    rows = summary_rows(series, walls, scene)
    table = summary_markdown(rows, scene, mode, not_possible)
    snaps = [("MPM only, no smoothing", runs["mpm"], snap_t)] if "mpm" in runs else []
    for remedy, run in smooth.items():
        snaps.append(("MPM only, %s smoothing" % remedy, run, snap_t))
    if not args.no_figures:
        hyb1 = runs.get("hyb_1")
        figures(out, scene, series, fem_prof, hyb1, snaps)
    for name, r in runs.items():
        if "results" in r:
            prune_particle_files(r, figure_times)
    for run in smooth.values():
        prune_particle_files(run, (snap_t,))
    t_all = time.perf_counter() - t_start
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("Study (%s): %g x %g m column, %g m cells, %d x %d particles per cell; runs %.1f s, total %.1f s "
                "wall with %d jobs.\n\n" % (mode, scene.width, scene.height, cell, ppd, ppd, t_runs, t_all, args.jobs))
        f.write(table)
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump({"mode": mode, "cell": cell, "ppd": ppd, "width": scene.width, "height": scene.height,
                   "tau_c": scene.tau_c, "base_friction": BASE_MU, "wall_runs": t_runs, "wall_total": t_all,
                   "jobs": args.jobs, "rows": rows}, f, indent=1, default=float)
    log(table)
    if failed:
        with open(os.path.join(out, "summary.md"), "a") as f:
            for name, msg in failed.items():
                f.write("\n%s FAILED: %s\n" % (name, msg.splitlines()[0]))
    if args.sweep:
        run_sweep(bins, out, cell, ppd, args.jobs)
    log("study done: %.1f s wall (runs %.1f s)" % (time.perf_counter() - t_start, t_runs))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
