#!/usr/bin/python3
"""One model under many ground motions: the chain (fem_tcl -> fem2mpm -> mpm, scripts/hybrid_run.py) per record,
the records' intensity measures, and what each record did: liquefied depth, runout, moved mass.

    scripts/motion_suite.py MODEL.tcl [--records DIR] [--pga LIST] --out DIR --transfer T|T1,T2,.. [--duration D]
                            [--jobs N] [--scale S | --scale-to-pga G] [--seed N[,N...]] [--input velocity|acceleration]
                            [--window-depth 10] [--window-min-ratio 0.5] [--bin DIR] [--ims-only]
                            [hybrid_run / fem2mpm options...] [-- script arguments...]

Records: every PEER NGA `.AT2` file in --records DIR (acceleration in g, as downloaded from the PEER ground
motion database; times --scale, or each scaled to the PGA --scale-to-pga in g), and the project's seeded
synthetic record (scripts/shaken_slope/ground_motion.py: Kanai-Tajimi / Clough-Penzien filtered noise in a
Saragoni-Hart envelope, dt 0.01 s, 12 s) for each seed of --seed and each PGA of --pga (g, comma-separated:
5 PGAs and 6 seeds make a suite of 30 independent records). Each record is
baseline-corrected (geoflow/records.py: a + c0 + c1 t so that it ends at rest with zero displacement, the
correction of ground_motion.py) and integrated (trapezoidal) to the velocity. A malformed .AT2 file (a bad
header, NPTS that disagrees with the data, a token that is not a number) stops everything before any run:
one line `motion_suite.py: error: FILE:LINE: what`, exit 2.

The contract with MODEL.tcl (besides hybrid_run.py's: its output folder first, the recorders): the suite
appends to the script arguments (after `--`, which it passes to the script)
    -motion VEL_FILE -motion-dt DT   (--input velocity, the default) the outcrop velocity, m/s, one value a
                                     line, sample k at t = k DT, starting and ending at rest: for a compliant
                                     base, the Joyner & Chen (1975) force F = rho_r Vs_r A v(t) on a
                                     Lysmer-Kuhlemeyer dashpot (timeSeries Path -dt DT -filePath VEL_FILE), as
                                     scripts/shaken_slope/shaken_slope.tcl does;
    -accel ACC_FILE -motion-dt DT    (--input acceleration) the acceleration, m/s^2, for a rigid base
                                     (timeSeries Path -dt DT -filePath ACC_FILE; pattern UniformExcitation
                                     tag 1 -accel ts); the suite also gives fem2mpm --ground-motion ACC_FILE
                                     --ground-motion-dt DT (unless given), so that an MPM run that starts
                                     before the record ends goes on being shaken.
The files hold the scaled motion (the script applies no factor of its own). The script must run long
enough for the transfer time (its end-time argument after `--`, e.g. -- -tend 12).

The chain: scripts/hybrid_run.py MODEL --transfer T --duration D --out REC/chain [options] -- [script
arguments] -motion ..., run as a subprocess. With one transfer time the record's result is that run's. With
several (T1,T2,..: hybrid_run.py's transfer window, one FEM run and a transfer per time, REC/chain/T<t>/),
the suite picks one by the window rule of Sordo, Rathje & Kumar (issue 36): the window opens at the first
time the liquefied depth reaches --window-depth (m, default 10: runout becomes measurable once liquefaction
reaches ~10 m) and closes at the first time the FEM mesh's smallest corner det J / det J0 falls below
--window-min-ratio (default 0.5, fem_tcl's own mesh-quality warning threshold); the record's result is
the LATEST transfer time inside the window (the deepest liquefaction carried over on an undistorted mesh).
Without an open window (never that deep, or a dry model with no pore pressure): the latest time before the
mesh distorts, flagged in `window`; every time's numbers are in REC/transfers.csv.

Per record (under --out, records/<name>/): accel.txt, vel.txt (the files given to the script), record.json
(source, scaling, baseline correction, intensity measures), spectrum.csv (PSA, 5 %), chain/ (hybrid_run.py's
folder), chain.log, transfers.csv, and done.json -- the results, written last and atomically: a record with a
done.json whose fingerprint (the motion, the model script's text, the chain options) matches is not rerun.
Results: the liquefied depth at the transfer (the largest depth below the ground surface of a particle with
r_u >= fem2mpm's --liquefied threshold, default 0.7, read from the /pore_pressure dataset of the transfer file;
"n/a" for a dry model, which has none), the runout (the largest horizontal travel since the transfer at the
end of the MPM run), the front, the moved mass (travel > hybrid_run.py's --moved, 0.1 m) as a fraction and in
t/m, and whether the mass still moves at the end.

Suite outputs (in --out): summary.csv (one row per record), summary.md, runout_vs_im.png,
liquefied_depth_vs_im.png, moved_mass_vs_im.png (each against PGA, PGV, Arias intensity, CAV and MASI, with
Spearman's rank correlation). Intensity measures (geoflow/records.py has the definitions and references):
PGA (g), PGV (m/s, of the integrated velocity), Arias intensity (m/s), CAV (m/s), D5-95 (s), ASI and MASI
(g s: the 5 %-damped PSA integrated over 0.1-0.5 s and 0.1-2.5 s).

--jobs N (default: every core) records at once, each with max(1, N / running) mpm threads (or hybrid_run.py's
--threads when given). --ims-only: the records and their intensity measures only (no chain). Options that
are not the suite's go to hybrid_run.py unchanged (its --threads, --moved, --output-every and fem2mpm's
options). Exit status: 0 every record done; 2 bad input (nothing run); 1 when a record's chain failed (the
others are done and in the summary; a rerun retries the failed ones only).

Example (the dry shaken embankment, two synthetic PGAs and a folder of PEER records):
    scripts/motion_suite.py scripts/shaken_slope/shaken_slope.tcl --records records/ --pga 0.2,0.4 \\
        --out results/suite --transfer 12 --duration 3 --jobs 2 --ppd 2 --units kN --left-wall roller \\
        --right-wall roller --base friction --base-friction 0.58 --base-y 0 --cell-size 1 --extent 0 72 -1 18 \\
        -- -cell 1 -dt 0.005 -tend 12
"""
import argparse
import csv
import hashlib
import itertools
import json
import math
import os
import re
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "shaken_slope"))
from geoflow import metrics, pipeline, plots, records  # noqa: E402

PROG = "motion_suite.py"
REPO = os.path.dirname(HERE)
HYBRID_RUN = os.path.join(HERE, "hybrid_run.py")
# bump when what a done.json means changes (a new result, a new definition): every record is then rerun
CONTRACT_VERSION = "motion_suite 1"
OWN_OPTIONS = {"--records": True, "--pga": True, "--out": True, "--jobs": True, "--transfer": True, "--duration": True,
               "--scale": True, "--scale-to-pga": True, "--seed": True, "--input": True, "--window-depth": True,
               "--window-min-ratio": True, "--bin": True, "--ims-only": False, "--help": False, "-h": False}
# hybrid_run.py options the suite sets per record
SET_BY_SUITE = ("--out", "--transfer", "--duration", "--bin", "--jobs")
SCRIPT_SET_BY_SUITE = ("-motion", "-motion-dt", "-accel")
LIQUEFIED_DEFAULT = 0.7     # fem2mpm's --liquefied default (r_u)
STILL_MOVING = 0.05         # m/s: hybrid_run.py's summary says "still moving" above this largest speed
IMS = (("pga_g", "PGA (g)"), ("pgv_m_s", "PGV (m/s)"), ("arias_m_s", "Arias intensity (m/s)"), ("cav_m_s", "CAV (m/s)"),
       ("masi_g_s", "MASI, 0.1-2.5 s (g s)"))
FIGURES = {"runout_vs_im.png": ("runout_m", "runout (m)", "no record done"),
           "liquefied_depth_vs_im.png": ("liquefied_depth_m", "liquefied depth at T (m)",
                                         "n/a: no pore pressure in the transfers\n(a dry model)"),
           "moved_mass_vs_im.png": ("moved_mass_fraction", "moved mass fraction", "no record done")}
SUMMARY_COLUMNS = ("record", "source", "scale", "dt_s", "npts", "duration_s", "pga_g", "pgv_m_s", "arias_m_s", "cav_m_s",
                   "d5_95_s", "asi_g_s", "masi_g_s", "transfer_s", "window", "liquefied_depth_m",
                   "liquefied_mass_fraction", "runout_m", "front_x_m", "moved_mass_fraction", "moved_mass_t_per_m",
                   "max_speed_end_m_s", "still_moving", "status", "note")


class OneLineParser(argparse.ArgumentParser):
    def error(self, message):
        pipeline.die(PROG, message)


def parser():
    ap = OneLineParser(prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                       usage="%(prog)s MODEL.tcl [--records DIR] [--pga LIST] --out DIR --transfer T [options] "
                             "[hybrid_run options] [-- script arguments]")
    ap.add_argument("model", help="the FEM script (hybrid_run.py's contract, and -motion/-motion-dt or -accel)")
    ap.add_argument("--records", help="a folder of PEER NGA .AT2 files (acceleration in g)")
    ap.add_argument("--pga", type=float_list, default=[], help="synthetic records at these PGAs, g (comma-separated)")
    ap.add_argument("--out", required=True, help="the suite's folder (records/<name>/, summary.csv, figures)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="records at once (default: every core)")
    ap.add_argument("--transfer", default=None, help="transfer time T, s, or T1,T2,... (the window rule)")
    ap.add_argument("--duration", type=float, default=5.0, help="MPM time after the transfer, s (default 5)")
    ap.add_argument("--scale", type=float, default=None, help="factor on the .AT2 records (default 1)")
    ap.add_argument("--scale-to-pga", type=float, default=None, help="scale each .AT2 record to this PGA, g")
    ap.add_argument("--seed", type=int_list, default=None,
                    help="seeds of the synthetic records, comma-separated: one record per seed and PGA (default ground_motion.py's)")
    ap.add_argument("--input", choices=("velocity", "acceleration"), default="velocity",
                    help="what the script gets: -motion VEL -motion-dt DT (default) or -accel ACC -motion-dt DT")
    ap.add_argument("--window-depth", type=float, default=10.0, help="window rule: liquefied depth that opens it, m")
    ap.add_argument("--window-min-ratio", type=float, default=0.5,
                    help="window rule: FEM min corner det J / det J0 below which it is closed")
    ap.add_argument("--bin", default=None, help="folder with fem_tcl, fem2mpm, mpm (default build/bin)")
    ap.add_argument("--ims-only", action="store_true", help="the records and their intensity measures only")
    return ap


def float_list(text):
    try:
        v = [float(w) for w in text.split(",") if w.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError("expected comma-separated numbers, got %r" % text)
    if not v or not all(math.isfinite(x) and x > 0 for x in v):
        raise argparse.ArgumentTypeError("expected values > 0, got %r" % text)
    return v


def int_list(text):
    try:
        v = [int(w) for w in text.split(",") if w.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError("expected comma-separated integers, got %r" % text)
    if not v or len(set(v)) != len(v):
        raise argparse.ArgumentTypeError("expected distinct integers, got %r" % text)
    return v


def split_arguments(argv):
    """(suite words, hybrid_run words, script words), as hybrid_run.py splits its own (pipeline.split_words)."""
    return pipeline.split_words(PROG, argv, OWN_OPTIONS)


def option_value(words, name):
    """The value of `name V` or `name=V` in words (the last one), or None."""
    value = None
    for k, w in enumerate(words):
        if w == name and k + 1 < len(words):
            value = words[k + 1]
        elif w.startswith(name + "="):
            value = w.split("=", 1)[1]
    return value


def safe_name(text):
    return re.sub(r"[^A-Za-z0-9._-]+", "_", text).strip("_") or "record"


def write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


# ---- the records -----------------------------------------------------------------------------------------

def collect_records(args):
    """[{name, source, kind, dt, accel (m/s^2, corrected and scaled), scale, correction}], every .AT2 file read
    first (a malformed one stops the suite: exit 2, one line)."""
    out = []
    if args.records:
        if not os.path.isdir(args.records):
            pipeline.die(PROG, "--records %s: no such folder" % args.records)
        files = sorted(f for f in os.listdir(args.records) if f.lower().endswith(".at2"))
        if not files:
            pipeline.die(PROG, "--records %s: no .AT2 files in it" % args.records)
        for f in files:
            path = os.path.join(args.records, f)
            try:
                r = records.read_at2(path)
            except records.RecordError as e:
                pipeline.die(PROG, str(e))
            a, corr = records.baseline_correct(r["accel_g"] * records.G, r["dt"])
            pga = float(np.max(np.abs(a)))
            if not pga > 0:
                pipeline.die(PROG, "%s:5: the record is zero everywhere" % path)
            scale = args.scale_to_pga * records.G / pga if args.scale_to_pga else (args.scale if args.scale is not None else 1.0)
            out.append({"name": safe_name(os.path.splitext(f)[0]), "source": os.path.abspath(path), "kind": "at2",
                        "title": r["title"], "dt": r["dt"], "accel": a * scale, "scale": scale,
                        "correction": [c * scale for c in corr]})
    if args.pga:
        import ground_motion
        for seed, pga in itertools.product(args.seed or [ground_motion.DEFAULTS["seed"]], args.pga):
            p = dict(ground_motion.DEFAULTS, seed=seed, pga=pga)
            _, a = ground_motion.generate(p)
            a, corr = records.baseline_correct(a, p["dt"])
            out.append({"name": "synthetic_pga%.3g_seed%d" % (pga, seed), "kind": "synthetic",
                        "source": "scripts/shaken_slope/ground_motion.py --seed %d --pga %g" % (seed, pga),
                        "title": "synthetic (Kanai-Tajimi, Saragoni-Hart), seed %d" % seed, "dt": p["dt"], "accel": a,
                        "scale": 1.0, "correction": list(corr)})
    names = [r["name"] for r in out]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        pipeline.die(PROG, "two records share the name %s (file names that differ only in characters other than "
                           "letters, digits, '.', '_', '-')" % dup[0])
    return out


def prepare_record(rec, folder, input_kind):
    """Writes accel.txt, vel.txt, record.json and spectrum.csv into folder; returns the intensity measures."""
    os.makedirs(folder, exist_ok=True)
    a, dt = rec["accel"], rec["dt"]
    v = records.integrate(a, dt)
    ims = records.intensity_measures(a, dt)
    periods, psa = ims.pop("_periods"), ims.pop("_psa_g")
    records.write_column(os.path.join(folder, "accel.txt"), a)
    records.write_column(os.path.join(folder, "vel.txt"), v)
    write_atomic(os.path.join(folder, "spectrum.csv"), "period_s,psa_g\n" + "".join(
        "%.4g,%.6g\n" % (T, s) for T, s in zip(periods, psa)))
    t = np.arange(len(a)) * dt
    info = {"record": rec["name"], "source": rec["source"], "title": rec["title"], "kind": rec["kind"], "dt_s": dt,
            "npts": len(a), "duration_s": float(t[-1]), "scale": rec["scale"],
            "baseline_correction": {"c0_m_s2": rec["correction"][0], "c1_m_s3": rec["correction"][1],
                                    "correction_peak_g": float(np.max(np.abs(rec["correction"][0] + rec["correction"][1] * t))
                                                         / records.G),
                                    "what": "a + c0 + c1 t: end velocity and end displacement zero (geoflow/records.py)"},
            "files": {"accel.txt": "m/s^2", "vel.txt": "m/s (trapezoidal integral of accel.txt)"},
            "given_to_the_script": input_kind, "intensity_measures": ims,
            "end_velocity_m_s": float(v[-1]), "end_displacement_m": float(records.integrate(v, dt)[-1])}
    write_atomic(os.path.join(folder, "record.json"), json.dumps(info, indent=1) + "\n")
    return ims


def refresh_ims(rec, input_kind):
    """The intensity measures of a done record, its record.json and spectrum.csv rewritten only if they changed."""
    path = os.path.join(rec["folder"], "record.json")
    try:
        with open(path) as f:
            old = json.load(f).get("intensity_measures")
    except (OSError, ValueError):
        old = None
    ims = records.intensity_measures(rec["accel"], rec["dt"])
    ims.pop("_periods"), ims.pop("_psa_g")
    if old is not None and set(old) == set(ims) and all(abs(old[k] - ims[k]) <= 1e-9 * max(1.0, abs(ims[k])) for k in ims):
        return old
    return prepare_record(rec, rec["folder"], input_kind)


def fingerprint(rec, model_text, chain_words):
    h = hashlib.sha256()
    h.update(CONTRACT_VERSION.encode())
    h.update(np.ascontiguousarray(rec["accel"], dtype="<f8").tobytes())
    h.update(repr(rec["dt"]).encode())
    h.update(model_text)
    h.update(json.dumps(chain_words).encode())
    return h.hexdigest()


# ---- reading a chain's results ---------------------------------------------------------------------------

def read_csv_rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def pore_pressure_ru(f):
    """r_u per /table row from the /pore_pressure dataset (rows p, sigma'v0, r_u; or named fields), or None."""
    if "pore_pressure" not in f:
        return None
    d = f["pore_pressure"][...]
    if d.dtype.names:
        for key in d.dtype.names:
            if key.lower().replace("_", "") in ("ru", "rU".lower()):
                return np.asarray(d[key], dtype=float)
        raise ValueError("/pore_pressure has no r_u field (fields %s)" % ", ".join(d.dtype.names))
    d = np.asarray(d, dtype=float)
    if d.ndim != 2 or d.shape[1] < 3:
        raise ValueError("/pore_pressure has shape %s, expected rows (p, sigma'v0, r_u)" % (d.shape,))
    return d[:, 2]


def liquefaction_at_transfer(transfer_file, threshold):
    """(largest depth below the ground surface of a particle with r_u >= threshold, liquefied mass fraction) in
    the transfer file; (None, None) for a dry transfer (no /pore_pressure). The ground surface at a particle:
    the top (y + half a spacing) of the highest particle in its vertical strip one particle spacing wide."""
    import h5py
    with h5py.File(transfer_file, "r") as f:
        ru = pore_pressure_ru(f)
        if ru is None:
            return None, None
        t = f["table"][...]
    x, y = np.asarray(t["coord_x"], float), np.asarray(t["coord_y"], float)
    mass, vol = np.asarray(t["mass"], float), np.asarray(t["volume"], float)
    if len(ru) != len(x):
        raise ValueError("/pore_pressure has %d rows, /table %d" % (len(ru), len(x)))
    liq = ru >= threshold
    if not np.any(liq):
        return 0.0, 0.0
    h = float(np.sqrt(np.median(vol)))
    strip = np.floor((x - x.min()) / h).astype(int)
    top = np.full(strip.max() + 1, -np.inf)
    np.maximum.at(top, strip, y + 0.5 * h)
    depth = top[strip[liq]] - y[liq]
    return float(depth.max()), float(mass[liq].sum() / mass.sum())


def mesh_ratio_at(fem_dir, t, window_csv_rows):
    """The FEM mesh's smallest corner det J / det J0 at the transfer time t: hybrid_run.py's window.csv when it
    has the time, else fem_tcl's mesh_quality.out (the row at t); None when neither."""
    for r in window_csv_rows or []:
        if abs(r.get("transfer", float("nan")) - t) < 1e-9 and math.isfinite(r.get("fem_min_jacobian_ratio", float("nan"))):
            return r["fem_min_jacobian_ratio"]
    times, _, ratio = metrics.fem_mesh_quality(fem_dir)
    if ratio is None or not len(times):
        return None
    k = np.searchsorted(times, t + 1e-9) - 1
    return float(ratio[max(k, 0)])


def read_chain(chain, threshold):
    """One row per transfer made in CHAIN (hybrid_run.py's folder: one transfer in CHAIN itself, several in
    CHAIN/T<t>/): transfer time, the end of its MPM run, liquefaction at the transfer, the mesh quality."""
    folders = [chain] if os.path.exists(os.path.join(chain, "series.csv")) else sorted(
        os.path.join(chain, d) for d in os.listdir(chain)
        if re.match(r"^T[0-9.eE+-]+$", d) and os.path.exists(os.path.join(chain, d, "series.csv")))
    if not folders:
        raise pipeline.PipelineError("hybrid_run.py wrote no series.csv in %s" % chain)
    window_rows = read_csv_rows(os.path.join(chain, "window.csv")) if os.path.exists(os.path.join(chain, "window.csv")) else None
    fem_dir = os.path.join(chain, "fem")
    rows = []
    for d in folders:
        ser = read_csv_rows(os.path.join(d, "series.csv"))
        t0, end = ser[0]["time"], ser[-1]
        mpm_dir = os.path.join(d, "mpm")
        with open(os.path.join(mpm_dir, "report.json")) as f:
            report = json.load(f)
        steps = metrics.particle_steps(pipeline.results_dir(mpm_dir))
        depth, liq_mass = liquefaction_at_transfer(steps[min(steps)], threshold)
        total = float(report.get("particle_totals", {}).get("mass", float("nan")))
        rows.append({"transfer_s": t0, "end_s": end["time"], "runout_m": end["runout"], "front_x_m": end["front_x"],
                     "moved_mass_fraction": end["moved_mass_fraction"],
                     "moved_mass_t_per_m": end["moved_mass_fraction"] * total / 1e3, "total_mass_t_per_m": total / 1e3,
                     "max_speed_end_m_s": end["max_speed"], "still_moving": bool(end["max_speed"] > STILL_MOVING),
                     "liquefied_depth_m": depth, "liquefied_mass_fraction": liq_mass,
                     "fem_min_jacobian_ratio": mesh_ratio_at(fem_dir, t0, window_rows),
                     "folder": os.path.relpath(d, os.path.dirname(chain))})
    return sorted(rows, key=lambda r: r["transfer_s"])


def window_rule(rows, depth_open, min_ratio):
    """(the chosen row, what the rule found): the latest transfer time with liquefied depth >= depth_open and the
    mesh ratio >= min_ratio; else the latest one with an undistorted mesh; else the earliest one."""
    if len(rows) == 1:
        return rows[0], "one transfer time"
    ok_mesh = [r for r in rows if r["fem_min_jacobian_ratio"] is None or r["fem_min_jacobian_ratio"] >= min_ratio]
    # the window closes at the first distorted time: later times are out even if a ratio recovers
    first_bad = next((k for k, r in enumerate(rows) if r not in ok_mesh), len(rows))
    undistorted = rows[:first_bad]
    dry = all(r["liquefied_depth_m"] is None for r in rows)
    inside = [r for r in undistorted if r["liquefied_depth_m"] is not None and r["liquefied_depth_m"] >= depth_open]
    if inside:
        return inside[-1], "window %g-%g s" % (inside[0]["transfer_s"], inside[-1]["transfer_s"])
    if undistorted:
        why = "dry model: mesh rule only" if dry else "window not open (liquefied depth < %g m)" % depth_open
        return undistorted[-1], why
    return rows[0], "mesh distorted at every transfer time (det J ratio < %g)" % min_ratio


# ---- one record through the chain ------------------------------------------------------------------------

def run_record(rec, ctx, threads):
    """hybrid_run.py for one record; returns the done.json dict (written last). Raises PipelineError."""
    folder = rec["folder"]
    chain = os.path.join(folder, "chain")
    # a rerun starts clean: an earlier run's transfer folders (other times) must not be read as this one's
    pipeline.remove_outputs(folder, ("chain", "chain.log", "transfers.csv"))
    acc, vel = os.path.join(folder, "accel.txt"), os.path.join(folder, "vel.txt")
    motion = (["-motion", vel] if ctx["input"] == "velocity" else ["-accel", acc]) + ["-motion-dt", repr(rec["dt"])]
    forward = list(ctx["forward"])
    if ctx["input"] == "acceleration" and option_value(forward, "--ground-motion") is None:
        forward += ["--ground-motion", acc, "--ground-motion-dt", repr(rec["dt"])]
    # the cores a record may use: hybrid_run.py's transfers at once for a window (several times), else mpm threads
    inner = []
    several = "," in ctx["transfer"].strip(",")
    if several and threads > 1:
        inner += ["--jobs", str(threads)]
    elif option_value(forward, "--threads") is None:
        inner += ["--threads", str(threads)]
    cmd = [sys.executable, HYBRID_RUN, ctx["model"], "--transfer", ctx["transfer"], "--duration", repr(ctx["duration"]),
           "--out", chain] + (["--bin", ctx["bin"]] if ctx["bin"] else []) + inner + forward + \
          ["--"] + ctx["script"] + motion
    t0 = time.perf_counter()
    with open(os.path.join(folder, "chain.log"), "w") as log:
        log.write("$ %s\n" % " ".join(cmd))
        log.flush()
        r = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT)
    wall = time.perf_counter() - t0
    if r.returncode != 0:
        with open(os.path.join(folder, "chain.log"), errors="replace") as f:
            lines = [ln.strip() for ln in f if ln.strip()]
        err = [ln for ln in lines if "error:" in ln]
        raise pipeline.PipelineError("hybrid_run.py exit %d: %s (log: %s)" % (r.returncode, (err or lines or ["?"])[-1],
                                                                           os.path.join(folder, "chain.log")),
                                     bad_input=r.returncode == 2, numerical=r.returncode == 3)
    rows = read_chain(chain, ctx["threshold"])
    chosen, why = window_rule(rows, ctx["window_depth"], ctx["window_min_ratio"])
    cols = ("transfer_s", "liquefied_depth_m", "liquefied_mass_fraction", "fem_min_jacobian_ratio", "runout_m",
            "front_x_m", "moved_mass_fraction", "moved_mass_t_per_m", "max_speed_end_m_s", "folder")
    write_atomic(os.path.join(folder, "transfers.csv"), ",".join(cols) + ",chosen\n" + "".join(
        ",".join(fmt(r[c]) for c in cols) + ",%d\n" % (r is chosen) for r in rows))
    done = dict(chosen)
    done.update({"record": rec["name"], "fingerprint": rec["fingerprint"], "window": why, "transfers": rows,
                 "wall_s": wall, "liquefied_threshold_ru": ctx["threshold"], "command": cmd[1:]})
    return done


def fmt(v):
    if v is None:
        return "n/a"
    if isinstance(v, bool):
        return "1" if v else "0"
    if isinstance(v, float):
        return "%.6g" % v
    return str(v)


# ---- summary and figures ---------------------------------------------------------------------------------

def summary_rows(recs):
    rows = []
    for rec in recs:
        ims, done = rec["ims"], rec.get("done")
        row = {"record": rec["name"], "kind": rec["kind"], "source": rec["source"], "scale": rec["scale"], "dt_s": rec["dt"],
               "npts": len(rec["accel"]), "duration_s": (len(rec["accel"]) - 1) * rec["dt"]}
        row.update({k: ims[k] for k in ("pga_g", "pgv_m_s", "arias_m_s", "cav_m_s", "d5_95_s", "asi_g_s", "masi_g_s")})
        if done:
            row.update({k: done[k] for k in ("transfer_s", "window", "liquefied_depth_m", "liquefied_mass_fraction",
                                             "runout_m", "front_x_m", "moved_mass_fraction", "moved_mass_t_per_m",
                                             "max_speed_end_m_s", "still_moving")})
            row["status"] = "done"
            row["note"] = ""
        else:
            row["status"] = rec.get("status", "failed")
            row["note"] = rec.get("error", "")
        rows.append(row)
    return rows


def write_summary_csv(path, rows):
    """Writes summary.csv; returns whether its content changed."""
    import io
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(SUMMARY_COLUMNS)
    for r in rows:
        w.writerow([fmt(r[c]) if c in r else "" for c in SUMMARY_COLUMNS])
    text = buf.getvalue()
    try:
        with open(path) as f:
            if f.read() == text:
                return False
    except OSError:
        pass
    write_atomic(path, text)
    return True


def spearman(x, y):
    x, y = np.asarray(x, float), np.asarray(y, float)
    if len(x) < 3 or np.ptp(x) == 0 or np.ptp(y) == 0:
        return None
    rx, ry = np.argsort(np.argsort(x)), np.argsort(np.argsort(y))
    return float(np.corrcoef(rx, ry)[0, 1])


def im_figure(path, rows, key, label, missing_note):
    plt = plots.pyplot()
    fig, axs = plt.subplots(1, len(IMS), figsize=(3.0 * len(IMS), 3.0))
    done = [r for r in rows if r["status"] == "done" and r.get(key) is not None]
    for ax, (im, im_label) in zip(axs, IMS):
        for kind, marker, color in (("synthetic", "s", "tab:orange"), ("at2", "o", "tab:blue")):
            pts = [r for r in done if r["kind"] == kind]
            if pts:
                ax.plot([r[im] for r in pts], [r[key] for r in pts], marker, color=color, ls="none", ms=5,
                        label="synthetic (--pga)" if kind == "synthetic" else "PEER .AT2")
        if len(done) <= 12:
            for r in done:
                ax.annotate(r["record"][:18], (r[im], r[key]), fontsize=5, xytext=(2, 2), textcoords="offset points")
        rho = spearman([r[im] for r in done], [r[key] for r in done])
        ax.set_title("Spearman rank correlation %.2f" % rho if rho is not None else "", fontsize=8)
        ax.set_xlabel(im_label)
        ax.grid(alpha=0.3)
        if not done:
            ax.text(0.5, 0.5, missing_note, transform=ax.transAxes, ha="center", va="center", fontsize=7, wrap=True)
    axs[0].set_ylabel(label)
    if done:
        axs[0].legend(fontsize=6)
    fig.tight_layout()
    return plots.save(fig, path)


def write_summary_md(path, args, rows, figs, walls):
    n_done = sum(r["status"] == "done" for r in rows)
    lines = ["# motion_suite: %s" % os.path.basename(args.model), "",
             "%d records, %d done; transfer %s s, MPM %g s after it. `summary.csv` has every number." %
             (len(rows), n_done, args.transfer, args.duration), "",
             "| record | PGA (g) | PGV (m/s) | Ia (m/s) | CAV (m/s) | MASI (g s) | T (s) | liquefied depth (m) | "
             "runout (m) | moved mass | status |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        d = r["status"] == "done"
        lines.append("| %s | %.3f | %.3f | %.3g | %.3g | %.3g | %s | %s | %s | %s | %s |" % (
            r["record"], r["pga_g"], r["pgv_m_s"], r["arias_m_s"], r["cav_m_s"], r["masi_g_s"],
            fmt(r.get("transfer_s")) if d else "", fmt(r.get("liquefied_depth_m")) if d else "",
            "%.3g" % r["runout_m"] if d else "", "%.1f %%" % (100 * r["moved_mass_fraction"]) if d else "",
            r["status"] + ("" if d else ": " + r["note"][:120])))
    lines += ["", "Intensity measures of the baseline-corrected input motion (geoflow/records.py): PGA; PGV of the "
                  "trapezoidal velocity; Arias intensity pi/(2g) int a^2 dt; CAV int |a| dt; MASI the 5 %-damped "
                  "pseudo-spectral acceleration integrated over 0.1-2.5 s (ASI: 0.1-0.5 s, in summary.csv). "
                  "Liquefied depth: the deepest particle with r_u >= the threshold below the ground surface at the "
                  "transfer (n/a: a dry model).", ""]
    if walls:
        lines += ["Chain wall time this invocation: %d records, %.0f s in all (%.0f s per record on average)."
                  % (len(walls), sum(walls), sum(walls) / len(walls)), ""]
    for f in figs:
        lines.append("![%s](%s)" % (os.path.splitext(os.path.basename(f))[0], os.path.basename(f)))
    write_atomic(path, "\n".join(lines) + "\n")


# ---- main ------------------------------------------------------------------------------------------------

def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    own, forward, script = split_arguments(argv)
    args = parser().parse_args(own)
    if not os.path.isfile(args.model):
        pipeline.die(PROG, "%s: no such FEM script" % args.model)
    if not args.records and not args.pga:
        pipeline.die(PROG, "no records: give --records DIR (PEER .AT2 files) and/or --pga LIST (synthetic records)")
    if args.scale is not None and args.scale_to_pga is not None:
        pipeline.die(PROG, "--scale and --scale-to-pga exclude each other")
    for name, value in (("--jobs", args.jobs), ("--duration", args.duration), ("--scale", args.scale),
                        ("--scale-to-pga", args.scale_to_pga), ("--window-min-ratio", args.window_min_ratio),
                        ("--window-depth", args.window_depth)):
        if value is not None and not (value > 0 and math.isfinite(value)):
            pipeline.die(PROG, "%s: expected a value > 0, got %g" % (name, value))
    if not args.ims_only:
        if args.transfer is None:
            pipeline.die(PROG, "--transfer T (or T1,T2,...) is required (or --ims-only)")
        try:
            times = [float(w) for w in args.transfer.split(",") if w.strip()]
            assert times and all(math.isfinite(t) and t >= 0 for t in times)
        except (ValueError, AssertionError):
            pipeline.die(PROG, "--transfer: expected a time >= 0 s or comma-separated times, got %r" % args.transfer)
    for w in forward:
        if w.split("=", 1)[0] in SET_BY_SUITE:
            pipeline.die(PROG, "option %s is set by the suite per record" % w)
    for w in script:
        if w in SCRIPT_SET_BY_SUITE:
            pipeline.die(PROG, "script argument %s is set by the suite per record (the record's files)" % w)
    threshold_text = option_value(forward, "--liquefied")
    try:
        threshold = float(threshold_text) if threshold_text is not None else LIQUEFIED_DEFAULT
    except ValueError:
        pipeline.die(PROG, "--liquefied: expected a number, got %r" % threshold_text)
    recs = collect_records(args)
    bins = None
    if not args.ims_only:
        try:
            bins = pipeline.find_bins(args.bin, REPO)
        except pipeline.PipelineError as e:
            pipeline.die(PROG, str(e))
    out = os.path.abspath(args.out)
    os.makedirs(os.path.join(out, "records"), exist_ok=True)
    with open(args.model, "rb") as f:
        model_text = f.read()
    chain_words = {"transfer": args.transfer, "duration": args.duration, "input": args.input, "forward": forward,
                   "script": script, "threshold": threshold, "window": [args.window_depth, args.window_min_ratio]}
    pending = []
    for rec in recs:
        rec["folder"] = os.path.join(out, "records", rec["name"])
        rec["fingerprint"] = fingerprint(rec, model_text, chain_words)
        done_path = os.path.join(rec["folder"], "done.json")
        done = None
        if os.path.exists(done_path):
            try:
                with open(done_path) as f:
                    done = json.load(f)
            except (OSError, ValueError):
                done = None
            if done and done.get("fingerprint") != rec["fingerprint"]:
                print("%s: %s: the record or the settings changed since its done.json: rerun" % (PROG, rec["name"]),
                      flush=True)
                os.remove(done_path)
                done = None
        if done:
            # the chain is not rerun; the intensity measures are recomputed (cheap), so that a change of their
            # definitions reaches record.json and the summary
            rec["done"] = done
            rec["ims"] = refresh_ims(rec, args.input)
        else:
            rec["ims"] = prepare_record(rec, rec["folder"], args.input)
            pending.append(rec)
    if args.ims_only:
        for rec in recs:
            rec.setdefault("status", "ims only")
        rows = summary_rows(recs)
        write_summary_csv(os.path.join(out, "summary.csv"), rows)
        print("%s: %d records, intensity measures only: %s" % (PROG, len(recs), os.path.join(out, "summary.csv")))
        return 0
    ctx = {"model": os.path.abspath(args.model), "transfer": args.transfer, "duration": args.duration,
           "bin": os.path.dirname(bins["fem_tcl"]), "forward": forward, "script": script, "input": args.input,
           "threshold": threshold, "window_depth": args.window_depth, "window_min_ratio": args.window_min_ratio}
    jobs = max(1, min(args.jobs, len(pending))) if pending else 1
    threads = max(1, args.jobs // jobs)
    print("%s: %d records, %d done before, %d to run%s" % (PROG, len(recs), len(recs) - len(pending), len(pending),
          " (%d at once, %d mpm thread%s each)" % (jobs, threads, "s" if threads > 1 else "") if pending else ""),
          flush=True)
    walls = []

    def work(rec):
        t0 = time.perf_counter()
        print("%s: %s: running" % (PROG, rec["name"]), flush=True)
        try:
            done = run_record(rec, ctx, threads)
        except Exception as e:  # noqa: BLE001 -- one record's failure (a chain error, an unreadable output) is its own
            if not isinstance(e, (pipeline.PipelineError, OSError)):
                e = RuntimeError("%s: %s" % (type(e).__name__, e))
            rec["status"], rec["error"] = "failed", str(e)
            rec["exit"] = e.exit_code() if isinstance(e, pipeline.PipelineError) else 1
            print("%s: %s: failed: %s" % (PROG, rec["name"], e), flush=True)
            return
        write_atomic(os.path.join(rec["folder"], "done.json"), json.dumps(done, indent=1) + "\n")
        rec["done"], rec["ran"] = done, True
        walls.append(time.perf_counter() - t0)
        print("%s: %s: done in %.1f s: T = %g s (%s), liquefied depth %s, runout %.3g m, moved mass %.1f %%"
              % (PROG, rec["name"], walls[-1], done["transfer_s"], done["window"],
                 "n/a" if done["liquefied_depth_m"] is None else "%.2f m" % done["liquefied_depth_m"],
                 done["runout_m"], 100 * done["moved_mass_fraction"]), flush=True)

    if pending:
        with ThreadPoolExecutor(max_workers=jobs) as pool:
            list(pool.map(work, pending))
    rows = summary_rows(recs)
    changed = write_summary_csv(os.path.join(out, "summary.csv"), rows)
    figs = [os.path.join(out, n) for n in FIGURES]
    if changed or not all(os.path.exists(f) for f in figs + [os.path.join(out, "summary.md")]):
        for f, (key, label, note) in zip(figs, FIGURES.values()):
            im_figure(f, rows, key, label, note)
        write_summary_md(os.path.join(out, "summary.md"), args, rows, figs, walls)
    failed = [r for r in recs if not r.get("done")]
    print("%s: %d of %d records done%s; %s" % (PROG, len(recs) - len(failed), len(recs),
                                             (", failed: " + ", ".join(r["name"] for r in failed)) if failed else "",
                                             os.path.join(out, "summary.csv")), flush=True)
    if failed:
        return 2 if len(failed) == len(recs) and all(r.get("exit") == 2 for r in failed) else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
