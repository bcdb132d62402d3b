#!/usr/bin/python3
"""scripts/geoflow/records.py and scripts/motion_suite.py without the chain (a few seconds, no binaries run):

- the PEER .AT2 reader: a written record read back (both header forms, NGA-West2 `NPTS= n, DT= dt SEC` and
  NGA-West1 `n dt NPTS, DT`);
- the intensity measures against closed forms: a sine a = A sin(w t) over 20 whole cycles: PGA = A, Arias
  intensity pi A^2 T_d / (4 g), CAV 2 A T_d / pi; PGV = A / w for the record that starts at rest with zero
  mean velocity, a = A cos(w t) (v = A/w sin(w t); the sine from rest has v = A/w (1 - cos w t), PGV 2 A/w,
  and a drifting displacement, which the baseline correction then changes), which the baseline correction
  leaves as it is; the correction of a drifting record ends at rest (v = d = 0);
- the response spectrum against the step response of a damped oscillator: a = A constant from t = 0 gives
  max |u| = A / w^2 (1 + exp(-pi zeta / sqrt(1 - zeta^2))) at every period, so PSA = 1.8544 A (zeta 5 %),
  ASI = 0.4 s x that, MASI = 2.4 s x that;
- malformed .AT2 files through motion_suite.py: one line on stderr naming the file and the line, exit 2,
  nothing written: a velocity file (line 3), a bad NPTS line (line 4), fewer values than NPTS (the last data
  line), more values (the line of the first extra), a non-number and a 'nan' (their lines);
- the liquefied depth of a transfer file with a /pore_pressure dataset (a block of particles, the lower left
  quarter liquefied: depth from the ground surface to the deepest liquefied particle) and of a dry one (n/a);
  the window rule on made-up transfer rows;
- motion_suite.py --ims-only: summary.csv with the records' intensity measures (a synthetic PGA exactly); with
  several seeds one record per seed and PGA (--seed 5,5 is one line, exit 2).
"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default=None)
    ap.add_argument("--repo", required=True)
    a = ap.parse_args()
    sys.path.insert(0, os.path.join(a.repo, "scripts"))
    from geoflow import records as R
    import motion_suite as MS
    c = Checklist()
    tmp = tempfile.mkdtemp(prefix="geoflow_motion_records_")
    g = R.G
    try:
        # ---- the reader
        A, f, n, dt = 0.4 * g, 2.0, 20, 0.005
        w = 2 * math.pi * f
        Td = n / f
        t = np.arange(int(round(Td / dt)) + 1) * dt
        sine = A * np.sin(w * t)
        p = os.path.join(tmp, "sine.AT2")
        R.write_at2(p, sine / g, dt)
        r = R.read_at2(p)
        c.expect("AT2 round trip: NPTS, DT, values", r["npts"] == len(t) and r["dt"] == dt
                 and np.max(np.abs(r["accel_g"] - sine / g)) < 1e-7, "npts %d dt %g" % (r["npts"], r["dt"]))
        old = os.path.join(tmp, "old.AT2")
        with open(old, "w") as fh:
            fh.write("PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.\nIMPERIAL VALLEY 5/19/40, "
                     "EL CENTRO ARRAY #9, 180\nACCELERATION TIME HISTORY IN UNITS OF G\n  7   0.0200   NPTS, DT\n"
                     "  .1E-02  -.2E-02  .3E-02\n -.4E-02  .5E-02\n  -.6E-02  .7E-02\n")
        r = R.read_at2(old)
        c.expect("AT2, the NGA-West1 header 'n dt NPTS, DT'", r["npts"] == 7 and r["dt"] == 0.02
                 and np.allclose(r["accel_g"], [1e-3, -2e-3, 3e-3, -4e-3, 5e-3, -6e-3, 7e-3]))
        # ---- intensity measures, closed forms
        ims = R.intensity_measures(sine, dt, spectrum=False)
        c.within("sine: PGA / A", ims["pga_g"] * g / A, 1 - 1e-12, 1 + 1e-12)
        c.within("sine: Arias / (pi A^2 Td / 4g)", ims["arias_m_s"] / (math.pi * A * A * Td / (4 * g)), 0.999, 1.001)
        c.within("sine: CAV / (2 A Td / pi)", ims["cav_m_s"] / (2 * A * Td / math.pi), 0.999, 1.001)
        cosine = A * np.cos(w * t)
        corrected, (c0, c1) = R.baseline_correct(cosine, dt)
        c.expect("cosine: the baseline correction leaves it as it is", abs(c0) < 1e-9 * A and abs(c1) < 1e-9 * A,
                 "c0 %.3g c1 %.3g" % (c0, c1))
        ims = R.intensity_measures(corrected, dt, spectrum=False)
        c.within("cosine: PGV / (A / w)", ims["pgv_m_s"] / (A / w), 0.999, 1.001)
        drift = cosine + 0.01 * g + 0.002 * g * t
        fixed, _ = R.baseline_correct(drift, dt)
        v = R.integrate(fixed, dt)
        c.expect("a drifting record corrected: ends at rest, zero displacement",
                 abs(v[-1]) < 1e-9 and abs(R.integrate(v, dt)[-1]) < 1e-9, "v_end %.2e d_end %.2e" % (v[-1], R.integrate(v, dt)[-1]))
        # ---- response spectrum: the step
        step = np.full(int(round(4.0 / 0.002)) + 1, 0.3 * g)
        z = R.DAMPING
        peak = 0.3 * (1 + math.exp(-math.pi * z / math.sqrt(1 - z * z)))
        ims = R.intensity_measures(step, 0.002)
        c.within("step: PSA / A (1 + exp(-pi z / sqrt(1 - z^2))), worst period", float(np.max(np.abs(ims["_psa_g"] / peak - 1))),
                 0.0, 0.005)
        c.within("step: MASI / (2.4 s x PSA)", ims["masi_g_s"] / (2.4 * peak), 0.995, 1.005)
        c.within("step: ASI / (0.4 s x PSA)", ims["asi_g_s"] / (0.4 * peak), 0.995, 1.005)
        # ---- malformed files through the CLI
        good = open(p).read().splitlines()
        cases = {
            "velocity_file": (good[:2] + ["VELOCITY TIME SERIES IN UNITS OF CM/S"] + good[3:], 3, "bad header"),
            "bad_npts_line": (good[:3] + ["NPTS=  abc, DT= .0050 SEC"] + good[4:], 4, "bad header"),
            "too_few": (good[:-1], len(good) - 1, "NPTS"),
            "too_many": (good + ["  1.0E-03"], len(good) + 1, "more values than NPTS"),
            "not_a_number": (good[:6] + [good[6].replace("E", "Q", 1)] + good[7:], 7, "not a number"),
            "nan": (good[:8] + ["  nan"] + good[8:], 9, "not a finite number"),
        }
        model = os.path.join(a.repo, "scripts", "shaken_slope", "shaken_slope.tcl")
        for name, (lines, line, what) in cases.items():
            d = os.path.join(tmp, "bad_" + name)
            os.makedirs(d)
            path = os.path.join(d, name + ".AT2")
            with open(path, "w") as fh:
                fh.write("\n".join(lines) + "\n")
            out = os.path.join(tmp, "out_" + name)
            r = subprocess.run([sys.executable, os.path.join(a.repo, "scripts", "motion_suite.py"), model, "--records", d,
                                "--out", out, "--transfer", "1"], capture_output=True, text=True)
            err = [ln for ln in r.stderr.splitlines() if ln.strip()]
            c.expect("malformed AT2 (%s): exit 2, one line naming %s:%d" % (name, os.path.basename(path), line),
                     r.returncode == 2 and len(err) == 1 and ("%s:%d:" % (path, line)) in err[0] and what in err[0]
                     and not os.path.exists(out), "exit %d: %r" % (r.returncode, r.stderr.strip()))
        # ---- liquefied depth from /pore_pressure, and a dry transfer
        import h5py
        xs, ys = np.meshgrid(np.arange(20) + 0.5, np.arange(10) + 0.5)
        x, y = xs.ravel(), ys.ravel()
        ru = np.where((x < 10) & (y < 5), 0.9, 0.2)
        table = np.zeros(len(x), dtype=[("coord_x", "f8"), ("coord_y", "f8"), ("mass", "f8"), ("volume", "f8")])
        table["coord_x"], table["coord_y"], table["mass"], table["volume"] = x, y, 1.9, 1.0
        wet, dry = os.path.join(tmp, "wet.h5"), os.path.join(tmp, "dry.h5")
        with h5py.File(wet, "w") as fh:
            fh["table"] = table
            fh["pore_pressure"] = np.stack([ru * 50e3, np.full(len(x), 50e3), ru], axis=1)
        with h5py.File(dry, "w") as fh:
            fh["table"] = table
        depth, frac = MS.liquefaction_at_transfer(wet, 0.7)
        c.expect("liquefied depth: surface y = 10, deepest liquefied particle at y = 0.5: 9.5 m, a quarter of the mass",
                 abs(depth - 9.5) < 1e-12 and abs(frac - 0.25) < 1e-12, "depth %s, fraction %s" % (depth, frac))
        c.expect("liquefied depth of a dry transfer: n/a", MS.liquefaction_at_transfer(dry, 0.7) == (None, None))
        rows = [{"transfer_s": T, "liquefied_depth_m": dd, "fem_min_jacobian_ratio": jr}
                for T, dd, jr in ((5, 4.0, 0.9), (10, 11.0, 0.8), (15, 16.0, 0.6), (20, 19.0, 0.3), (25, 20.0, 0.7))]
        chosen, why = MS.window_rule(rows, 10.0, 0.5)
        c.expect("window rule: the latest time with depth >= 10 m before the mesh distorts (15 s)", chosen["transfer_s"] == 15,
                 "%s (%s)" % (chosen["transfer_s"], why))
        chosen, why = MS.window_rule([dict(r, liquefied_depth_m=None) for r in rows], 10.0, 0.5)
        c.expect("window rule, dry: the latest undistorted time (15 s)", chosen["transfer_s"] == 15 and "dry" in why, why)
        # ---- --ims-only
        out = os.path.join(tmp, "ims_only")
        r = subprocess.run([sys.executable, os.path.join(a.repo, "scripts", "motion_suite.py"), model, "--records",
                            os.path.dirname(old), "--pga", "0.25", "--out", out, "--ims-only"], capture_output=True, text=True)
        ok = r.returncode == 0
        rows = list(csv.DictReader(open(os.path.join(out, "summary.csv")))) if ok else []
        syn = [row for row in rows if row["record"].startswith("synthetic_pga0.25")]
        c.expect("--ims-only: summary.csv with 3 records, the synthetic one at PGA 0.25 g", ok and len(rows) == 3 and len(syn) == 1
                 and abs(float(syn[0]["pga_g"]) - 0.25) < 1e-9 and float(syn[0]["masi_g_s"]) > 0,
                 "exit %d %s" % (r.returncode, r.stderr.strip()[-300:]))
        # ---- several seeds: one record per seed and PGA, each at its PGA exactly, the seeds' records different
        out = os.path.join(tmp, "seeds")
        r = subprocess.run([sys.executable, os.path.join(a.repo, "scripts", "motion_suite.py"), model, "--pga", "0.2,0.3",
                            "--seed", "5,6", "--out", out, "--ims-only"], capture_output=True, text=True)
        rows = list(csv.DictReader(open(os.path.join(out, "summary.csv")))) if r.returncode == 0 else []
        names = sorted(row["record"] for row in rows)
        c.expect("--seed 5,6 --pga 0.2,0.3: four records, one per seed and PGA",
                 names == ["synthetic_pga0.2_seed5", "synthetic_pga0.2_seed6", "synthetic_pga0.3_seed5", "synthetic_pga0.3_seed6"],
                 "exit %d %s %s" % (r.returncode, names, r.stderr.strip()[-300:]))
        by = {row["record"]: row for row in rows}
        if len(by) == 4:
            c.expect("each at its PGA; two seeds give two records (Arias intensities differ)",
                     all(abs(float(by["synthetic_pga%s_seed%d" % (p, s)]["pga_g"]) - float(p)) < 1e-9
                         for p in ("0.2", "0.3") for s in (5, 6))
                     and float(by["synthetic_pga0.2_seed5"]["arias_m_s"]) != float(by["synthetic_pga0.2_seed6"]["arias_m_s"]),
                     str([(k, v["pga_g"], v["arias_m_s"]) for k, v in sorted(by.items())]))
        r = subprocess.run([sys.executable, os.path.join(a.repo, "scripts", "motion_suite.py"), model, "--pga", "0.2",
                            "--seed", "5,5", "--out", os.path.join(tmp, "bad_seeds"), "--ims-only"], capture_output=True, text=True)
        c.expect("--seed 5,5: one line naming --seed, exit 2", r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1
                 and "--seed" in r.stderr and not os.path.exists(os.path.join(tmp, "bad_seeds")), r.stderr.strip())
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return c.exit_status()


if __name__ == "__main__":
    sys.exit(main())
