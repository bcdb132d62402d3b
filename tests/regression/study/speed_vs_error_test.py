#!/usr/bin/python3
"""scripts/column_collapse/speed_vs_error.py on a reduced sweep (4 m and 2 m cells, 1 x 1 particles, FLIP and
APIC, 0.3 s of the column: a few seconds): one row per run in speed_vs_error.csv, the finest APIC run the
reference with error 0, the others' errors |R - R_ref| / |R_ref| recomputed from their runouts, positive
costs, the table and the PNG written; --report rewrites them from the
runs alone; bad arguments are one line naming the option, exit 2, nothing run."""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--repo", required=True)
    a = ap.parse_args()
    script = os.path.join(a.repo, "scripts", "column_collapse", "speed_vs_error.py")
    c = Checklist()
    tmp = tempfile.mkdtemp(prefix="geoflow_speed_vs_error_")
    try:
        out = os.path.join(tmp, "out")
        args = [sys.executable, script, "--out", out, "--bin", a.bin, "--cells", "4,2", "--ppd", "1",
                "--transfers", "flip,apic", "--t-total", "0.3"]
        r = subprocess.run(args, capture_output=True, text=True)
        c.expect("runs exit 0", r.returncode == 0, r.stderr[-400:])
        rows = list(csv.DictReader(open(os.path.join(out, "speed_vs_error.csv")))) if r.returncode == 0 else []
        c.expect("one row per run", len(rows) == 4, "%d rows" % len(rows))
        ref = [x for x in rows if x["reference"] == "True"]
        c.expect("the reference is the finest APIC run", len(ref) == 1 and float(ref[0]["cell"]) == 2.0
                 and ref[0]["transfer"] == "apic" and float(ref[0]["error_percent"]) == 0.0, str(ref))
        if ref:
            r_ref = float(ref[0]["runout"])
            errs = [abs(100.0 * abs(float(x["runout"]) - r_ref) / abs(r_ref) - float(x["error_percent"])) for x in rows]
            c.expect("errors are the runout differences", max(errs) < 1e-9, str(errs))
        costs = {(float(x["cell"]), x["transfer"]): float(x["wall_per_simulated_s"]) for x in rows}
        c.expect("costs positive", all(v > 0 for v in costs.values()), str(costs))
        c.expect("table and figure written", all(os.path.getsize(os.path.join(out, f)) > 0
                                                 for f in ("speed_vs_error.md", "speed_vs_error.png")))
        os.remove(os.path.join(out, "speed_vs_error.csv"))
        r = subprocess.run(args + ["--report"], capture_output=True, text=True)
        c.expect("--report rewrites the table from the runs", r.returncode == 0
                 and os.path.exists(os.path.join(out, "speed_vs_error.csv")), r.stderr[-300:])
        for bad, what in ((["--cells", "0"], "--cells"), (["--ppd", "two"], "--ppd"), (["--transfers", "mls"], "--transfers")):
            bad_out = os.path.join(tmp, "bad")
            r = subprocess.run([sys.executable, script, "--out", bad_out, "--bin", a.bin] + bad, capture_output=True, text=True)
            lines = r.stderr.strip().splitlines()
            c.expect("bad %s: one line, exit 2, nothing run" % what, r.returncode == 2 and len(lines) == 1 and what in lines[0]
                     and not os.path.exists(bad_out), r.stderr.strip())
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return c.exit_status()


if __name__ == "__main__":
    sys.exit(main())
