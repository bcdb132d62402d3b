"""Reading the chain's files and the metrics of DESIGN.md ("Metrics"): runout, height, potential and kinetic
energies of FEM nodes and MPM particles, FEM mesh quality, surface profiles."""
import csv
import glob
import json
import os

import numpy as np

G = 9.81
PARTICLE_FIELDS = ("id", "coord_x", "coord_y", "displacement_x", "displacement_y", "velocity_x", "velocity_y", "mass",
                   "tau_xy", "material_id", "volume")


def read_series(results_dir):
    """mpm's series.csv as {column: array}."""
    with open(os.path.join(results_dir, "series.csv")) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def read_particles(path):
    """The particle table of a CB-Geo / mpm HDF5 file as {field: float array} (PARTICLE_FIELDS)."""
    import h5py
    with h5py.File(path, "r") as f:
        t = f["table"][...]
    return {k: np.asarray(t[k], dtype=float) for k in PARTICLE_FIELDS if k in t.dtype.names}


def particle_steps(results_dir):
    """{step: path} of the particles<step>.h5 files of a run."""
    files = {}
    for p in glob.glob(os.path.join(results_dir, "particles*.h5")):
        s = os.path.basename(p)[len("particles"):-3]
        if s.isdigit():
            files[int(s)] = p
    return files


def state_metrics(x, y, vx, vy, m, g=G):
    """L = 98th percentile of x, H = 99.5th percentile of y, PE = sum m g y, KEx, KEy (DESIGN.md)."""
    return {"L": np.percentile(x, 98), "H": np.percentile(y, 99.5), "PE": float(np.sum(m * g * y)),
            "KEx": float(np.sum(0.5 * m * vx ** 2)), "KEy": float(np.sum(0.5 * m * vy ** 2))}


def mpm_run_series(results, t0, resumed):
    """Time series of an MPM run on TOTAL time (t0 + MPM time): for a resumed (hybrid) run the transfer state
    (the fem2mpm file, step 0) first, then series.csv. Keys t, L, H, PE, KEx, KEy."""
    steps = particle_steps(results)
    s = read_series(results)
    cols = {"t": s["time"] + t0, "L": s["runout_x_p98"], "H": s["height_y_p995"], "PE": s["potential_energy"],
            "KEx": s["kinetic_energy_x"], "KEy": s["kinetic_energy_y"]}
    if resumed:
        p = read_particles(steps[min(steps)])
        m0 = state_metrics(p["coord_x"], p["coord_y"], p["velocity_x"], p["velocity_y"], p["mass"])
        for k in ("L", "H", "PE", "KEx", "KEy"):
            cols[k] = np.concatenate([[m0[k]], cols[k]])
        cols["t"] = np.concatenate([[t0], cols["t"]])
    return cols


def prune_particle_files(results, t0, keep_times):
    """Deletes the particle files of a run not needed for the figures (the first, the last and the ones
    closest to keep_times, TOTAL time, are kept; a full-resolution output is ~13 MB)."""
    s = read_series(results)
    tt = s["time"] + t0
    keep = {int(s["step"][int(np.argmin(np.abs(tt - t)))]) for t in keep_times if len(tt)}
    steps = particle_steps(results)
    keep.add(min(steps))
    keep.add(max(steps))
    for st, p in steps.items():
        if st not in keep:
            os.remove(p)


# ---- FEM files -------------------------------------------------------------------------------------

def load_fem_model(fem_dir):
    """Nodes (reference x, y in tag order) and the soil elements' connectivity (indices into them) of
    model.json; zeroLength elements (dashpots and springs of the boundary, as fem2mpm) are left out."""
    with open(os.path.join(fem_dir, "model.json")) as f:
        model = json.load(f)
    geo = model["StructuralAnalysisModel"]["geometry"]
    nodes = {n["name"]: n["crd"] for n in geo["nodes"]}
    tags = sorted(nodes)
    xy = np.array([nodes[t][:2] for t in tags], dtype=float)
    index = {t: k for k, t in enumerate(tags)}
    elems = np.array([[index[n] for n in e["nodes"]] for e in geo["elements"] if e.get("type") != "ZeroLength"],
                     dtype=int)
    return xy, elems


def read_recorder(path):
    """A recorder file as a 2D array (rows cut to the shortest, e.g. a truncated last row)."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.strip():
                rows.append(np.array(line.split(), dtype=float))
    n = min(len(r) for r in rows)
    return np.array([r[:n] for r in rows])


def read_time_recorder(path):
    """A `-time` recorder with rows of equal time collapsed to the last one (after `loadConst -time 0` the
    t = 0 row may appear twice)."""
    a = read_recorder(path)
    return a[np.r_[np.diff(a[:, 0]) > 1e-12, True]]


def fem_last_time(fem_dir):
    """Time of the last row of the FEM displacement recorder."""
    last = 0.0
    with open(os.path.join(fem_dir, "disp.out")) as f:
        for line in f:
            if line.strip():
                last = float(line.split(None, 1)[0])
    return last


def fem_displacements_at(fem_dir, t):
    """Nodal displacements (n x 2) of the disp.out row at time t (the last of equal times), or None."""
    disp = read_time_recorder(os.path.join(fem_dir, "disp.out"))
    k = np.where(np.abs(disp[:, 0] - t) <= 1e-6 * max(1.0, abs(t)))[0]
    return disp[k[-1], 1:].reshape(-1, 2) if len(k) else None


def element_areas(xy, elems):
    """Shoelace areas of the quadrilaterals (reference configuration)."""
    p = xy[elems]
    a = 0.0
    for k in range(4):
        q = (k + 1) % 4
        a = a + p[:, k, 0] * p[:, q, 1] - p[:, q, 0] * p[:, k, 1]
    return 0.5 * np.abs(a)


def fem_series(fem_dir, density, g=G):
    """FEM metrics per recorder row (t, L, H, PE, KEx, KEy) with lumped nodal masses: element area x
    density / 4 to each corner (reference configuration). Returns (series, reference xy, displacement rows)."""
    xy, elems = load_fem_model(fem_dir)
    m = np.zeros(len(xy))
    np.add.at(m, elems.ravel(), np.repeat(element_areas(xy, elems) * density / 4.0, 4))
    disp = read_time_recorder(os.path.join(fem_dir, "disp.out"))
    vel = read_time_recorder(os.path.join(fem_dir, "vel.out"))
    n = min(len(disp), len(vel))
    out = {k: [] for k in ("t", "L", "H", "PE", "KEx", "KEy")}
    for r in range(n):
        u = disp[r, 1:].reshape(-1, 2)
        v = vel[r, 1:].reshape(-1, 2)
        s = state_metrics(xy[:, 0] + u[:, 0], xy[:, 1] + u[:, 1], v[:, 0], v[:, 1], m, g)
        out["t"].append(disp[r, 0])
        for k in s:
            out[k].append(s[k])
    return {k: np.array(v) for k, v in out.items()}, xy, disp


def fem_mesh_quality(fem_dir):
    """fem_tcl's `recorder MeshQuality` file (rows `time minDetJ element minRatio element`) in FEM_DIR, found by
    name (*quality*, *jac*, *meshq*): (time, min det J, min ratio or None). Empty arrays when there is none."""
    cands = [p for p in sorted(glob.glob(os.path.join(fem_dir, "*")))
             if any(k in os.path.basename(p).lower() for k in ("jac", "quality", "meshq"))
             and not p.endswith((".log", ".json"))]
    for p in cands:
        try:
            a = read_recorder(p)
        except (ValueError, OSError):
            continue
        if a.ndim == 2 and a.shape[1] >= 4:
            return a[:, 0], a[:, 1], a[:, 3]
        if a.ndim == 2 and a.shape[1] >= 2:
            return a[:, 0], a[:, 1], None
    return np.array([]), np.array([]), None


def fem_first_inversion(fem_dir):
    """Time of the first step with a corner det J <= 0 (the mesh inverted), or None."""
    t, det_j, _ = fem_mesh_quality(fem_dir)
    k = np.where(det_j <= 0.0)[0]
    return float(t[k[0]]) if len(k) else None


def particle_profile(x, y, width):
    """Free-surface profile of a particle cloud: the highest particle per column of the given width."""
    k = np.floor(x / width).astype(int)
    xs, ys = [], []
    for kk in range(k.min(), k.max() + 1):
        sel = k == kk
        if np.any(sel):
            xs.append((kk + 0.5) * width)
            ys.append(y[sel].max())
    return np.array(xs), np.array(ys)
