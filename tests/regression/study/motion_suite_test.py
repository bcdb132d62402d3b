#!/usr/bin/python3
"""scripts/motion_suite.py through the whole chain on a tiny suite: the dry shaken embankment
(scripts/shaken_slope/shaken_slope.tcl at its smallest: 2 m cells, dt 0.01 s, 4 s of shaking, 0.3 s of MPM,
one particle per cell direction) under 3 records -- the seeded synthetic record at PGA 0.2 g and 0.4 g
(--pga) and a PEER-format .AT2 file written here (another seed, 0.3 g, sampled at 0.005 s, so that the model
gets -motion-dt 0.005) -- with --jobs 2, into a scratch folder. Checks:

- exit 0; summary.csv has the 3 records, done, with the synthetic PGAs exact, PGV and Arias intensity scaling
  as PGA and PGA^2 between the two synthetic records, the .AT2 record's PGA 0.3 g, a finite runout >= 0, a
  moved mass fraction in [0, 1], and liquefied depth "n/a" (the embankment is dry: no /pore_pressure);
- the model got the record's files: -motion .../vel.txt -motion-dt 0.005 for the .AT2 record;
- the three figures (runout, liquefied depth, moved mass against the intensity measures) are PNGs;
- resumability: a second invocation runs no chain (every done.json and chain/series.csv untouched, "0 to run");
  with one done.json removed (a run interrupted before its end), a third invocation runs that record only;
- the window: one record with --transfer 3,4 (hybrid_run.py's transfer window, REC/chain/T3 and T4): both times
  in transfers.csv, the later one chosen (a dry model: the mesh rule only, det J ratio > 0.5 at both).
Measured: 60-75 s wall on the loaded 2-core machine (about 10 s of each record's chain is hybrid_run.py's
figures and particle-file reading, the rest fem_tcl, fem2mpm and mpm).
"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist  # noqa: E402

CHAIN = ["--transfer", "4", "--duration", "0.3", "--output-every", "0.1", "--ppd", "1", "--units", "kN",
         "--left-wall", "roller", "--right-wall", "roller", "--base", "friction", "--base-friction", "0.58",
         "--base-y", "0", "--cell-size", "2", "--extent", "0", "72", "-2", "22", "--", "-cell", "2", "-dt", "0.01",
         "-tend", "4"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--repo", required=True)
    a = ap.parse_args()
    sys.path.insert(0, os.path.join(a.repo, "scripts"))
    sys.path.insert(0, os.path.join(a.repo, "scripts", "shaken_slope"))
    from geoflow import records
    import ground_motion
    c = Checklist()
    tmp = tempfile.mkdtemp(prefix="geoflow_motion_suite_")
    try:
        rec_dir = os.path.join(tmp, "records")
        os.makedirs(rec_dir)
        p = dict(ground_motion.DEFAULTS, seed=7, pga=0.3, dt=0.005, duration=8.0)
        _, acc = ground_motion.generate(p)
        records.write_at2(os.path.join(rec_dir, "RSN9999_TEST.AT2"), acc / records.G, p["dt"], "test record, seed 7")
        out = os.path.join(tmp, "suite")
        cmd = [sys.executable, os.path.join(a.repo, "scripts", "motion_suite.py"),
               os.path.join(a.repo, "scripts", "shaken_slope", "shaken_slope.tcl"), "--records", rec_dir, "--pga", "0.2,0.4",
               "--out", out, "--jobs", "2", "--bin", a.bin] + CHAIN

        def run(what):
            t0 = time.perf_counter()
            r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            print("--- %s (%.1f s) ---\n%s" % (what, time.perf_counter() - t0, r.stdout[-3000:]), flush=True)
            return r

        r = run("first invocation")
        c.expect("first invocation: exit 0", r.returncode == 0, "exit %d" % r.returncode)
        path = os.path.join(out, "summary.csv")
        rows = {row["record"]: row for row in csv.DictReader(open(path))} if os.path.exists(path) else {}
        names = ["RSN9999_TEST", "synthetic_pga0.2_seed20261201", "synthetic_pga0.4_seed20261201"]
        c.expect("summary.csv: the 3 records, done", sorted(rows) == names and all(rows[n]["status"] == "done" for n in names),
                 str({n: rows[n]["status"] + " " + rows[n]["note"] for n in rows}))
        if sorted(rows) == names:
            s2, s4, at2 = (rows[n] for n in (names[1], names[2], names[0]))
            f = lambda row, k: float(row[k])  # noqa: E731
            c.expect("synthetic PGAs 0.2 and 0.4 g; PGV x 2 and Arias x 4 between them",
                     abs(f(s2, "pga_g") - 0.2) < 1e-9 and abs(f(s4, "pga_g") - 0.4) < 1e-9
                     and abs(f(s4, "pgv_m_s") / f(s2, "pgv_m_s") - 2) < 1e-4
                     and abs(f(s4, "arias_m_s") / f(s2, "arias_m_s") - 4) < 1e-4,
                     "PGV %s %s, Ia %s %s" % (s2["pgv_m_s"], s4["pgv_m_s"], s2["arias_m_s"], s4["arias_m_s"]))
            c.expect("the .AT2 record: PGA 0.3 g, dt 0.005 s", abs(f(at2, "pga_g") - 0.3) < 1e-6 and f(at2, "dt_s") == 0.005,
                     "PGA %s dt %s" % (at2["pga_g"], at2["dt_s"]))
            for n, row in rows.items():
                if row["status"] != "done":
                    continue
                c.expect("%s: transfer 4 s, runout finite >= 0, moved mass in [0, 1], liquefied depth n/a (dry)" % n,
                         f(row, "transfer_s") == 4.0 and math.isfinite(f(row, "runout_m")) and f(row, "runout_m") >= 0
                         and 0 <= f(row, "moved_mass_fraction") <= 1 and row["liquefied_depth_m"] == "n/a",
                         "runout %s m, moved %s, depth %s" % (row["runout_m"], row["moved_mass_fraction"],
                                                               row["liquefied_depth_m"]))
        log = os.path.join(out, "records", "RSN9999_TEST", "chain.log")
        head = open(log).readline() if os.path.exists(log) else ""
        c.expect("the model got -motion vel.txt -motion-dt 0.005",
                 "-motion %s -motion-dt 0.005" % os.path.join(out, "records", "RSN9999_TEST", "vel.txt") in head, head[-200:])
        for fig in ("runout_vs_im.png", "liquefied_depth_vs_im.png", "moved_mass_vs_im.png"):
            fp = os.path.join(out, fig)
            ok = os.path.exists(fp) and open(fp, "rb").read(8) == b"\x89PNG\r\n\x1a\n" and os.path.getsize(fp) > 5000
            c.expect("figure %s" % fig, ok)

        def stamps():
            st = {}
            for n in names:
                for k in ("done.json", os.path.join("chain", "series.csv")):
                    q = os.path.join(out, "records", n, k)
                    st[(n, k)] = os.stat(q).st_mtime_ns if os.path.exists(q) else None
            return st
        before = stamps()
        r = run("second invocation (nothing to run)")
        c.expect("second invocation: exit 0, '0 to run', no file of a done record touched",
                 r.returncode == 0 and "0 to run" in r.stdout and stamps() == before and None not in before.values())
        os.remove(os.path.join(out, "records", names[1], "done.json"))
        r = run("third invocation (one done.json removed)")
        after = stamps()
        c.expect("third invocation: exit 0, only %s rerun" % names[1],
                 r.returncode == 0 and "1 to run" in r.stdout
                 and all(after[k] == before[k] for k in before if k[0] != names[1])
                 and after[(names[1], "done.json")] is not None)
        # the window: two transfer times through hybrid_run.py's --transfer T1,T2 (one FEM run, REC/chain/T<t>/)
        win = os.path.join(tmp, "window")
        wcmd = [w if w != "4" or k != cmd.index("--transfer") + 1 else "3,4" for k, w in enumerate(cmd)]
        wcmd[wcmd.index("--out") + 1] = win
        del wcmd[wcmd.index("--records"):wcmd.index("--records") + 2]
        wcmd[wcmd.index("--pga") + 1] = "0.4"
        t0 = time.perf_counter()
        r = subprocess.run(wcmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        print("--- window --transfer 3,4 (%.1f s) ---\n%s" % (time.perf_counter() - t0, r.stdout[-2000:]), flush=True)
        tr = os.path.join(win, "records", names[2], "transfers.csv")
        trows = list(csv.DictReader(open(tr))) if os.path.exists(tr) else []
        c.expect("window: transfers.csv has T = 3 and 4 s, the dry rule picks 4 s (the latest, mesh undistorted)",
                 r.returncode == 0 and [float(x["transfer_s"]) for x in trows] == [3.0, 4.0]
                 and [x["chosen"] for x in trows] == ["0", "1"] and all(float(x["fem_min_jacobian_ratio"]) > 0.5 for x in trows),
                 str(trows))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return c.exit_status()


if __name__ == "__main__":
    sys.exit(main())
