#!/usr/bin/python3
"""scripts/hybrid_run.py on bad input: one line on stderr naming what was expected, exit 2, and no summary
written. Cases: a missing model; an option without its value; an option the driver sets itself; a script
that does not write the contracted files (model.json, disp.out, vel.out, stress.out) in its output folder;
a transfer time after the last recorded row; a bad fem2mpm option (found before the FEM run). Each case is a few fem_tcl commands (well under a second). Then one
run that works, with a warning to repeat and a resume file to rename (below)."""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist  # noqa: E402

NO_RECORDERS = """model basic -ndm 2 -ndf 2
node 1 0 0
node 2 1 0
node 3 1 1
node 4 0 1
nDMaterial ElasticIsotropic 1 1000.0 0.25 2.0
element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0
print -JSON -file [file join [lindex $argv 0] model.json]
"""
RECORDS_TO_ZERO = NO_RECORDERS + """fix 1 1 1
fix 2 1 1
set out [lindex $argv 0]
recorder Node -file [file join $out disp.out] -time -nodeRange 1 4 -dof 1 2 disp
recorder Node -file [file join $out vel.out] -time -nodeRange 1 4 -dof 1 2 vel
recorder Element -file [file join $out stress.out] -time -eleRange 1 1 stress3D
record
"""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--repo", required=True)
    args = ap.parse_args()
    driver = os.path.join(args.repo, "scripts", "hybrid_run.py")
    tmp = tempfile.mkdtemp(prefix="hybrid_run_errors_")
    checks = Checklist()

    def case(what, argv, expect):
        out = os.path.join(tmp, "out_" + what.replace(" ", "_"))
        r = subprocess.run([sys.executable, driver] + argv + ["--bin", args.bin, "--out", out], stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True)
        err = [ln for ln in r.stderr.splitlines() if ln.strip()]
        ok = r.returncode == 2 and len(err) == 1 and expect in err[0] and not os.path.exists(os.path.join(out, "summary.md"))
        checks.expect(what, ok, ": exit %d, stderr %r" % (r.returncode, r.stderr.strip()))

    bad = os.path.join(tmp, "no_recorders.tcl")
    with open(bad, "w") as f:
        f.write(NO_RECORDERS)
    good = os.path.join(tmp, "records_to_zero.tcl")
    with open(good, "w") as f:
        f.write(RECORDS_TO_ZERO)
    case("missing model", [os.path.join(tmp, "nothing.tcl"), "--transfer", "0"], "no such FEM script")
    case("option without value", [good, "--transfer"], "--transfer needs a value")
    case("option set by the driver", [good, "--transfer", "0", "--time", "1"], "--time is set by the driver")
    case("contract not met", [bad, "--transfer", "0"], "did not write disp.out")
    case("transfer after the last row", [good, "--transfer", "1.5"], "recorded only to t = 0 s")
    # A bad fem2mpm option fails before the FEM run, which would take minutes on a real model: the FEM
    # folder stays without recorder files.
    case("bad fem2mpm option", [good, "--transfer", "0", "--cfl", "2"], "--cfl: expected a Courant number in (0, 1], got 2")
    fem_dir = os.path.join(tmp, "out_bad_fem2mpm_option", "fem")
    checks.expect("checked before the FEM run", not os.path.exists(os.path.join(fem_dir, "disp.out")), ": %s" % fem_dir)

    # A run that works: fem2mpm's warning (the density 2 looks like Mg/m3) repeated on stderr and in
    # summary.md; and with --dt 5 fem2mpm's deck has 1 step, the driver's 41 (40 outputs), so the name of
    # the resume file gains a digit (particles0.h5 -> particles00.h5): renamed with the edit (it was not
    # found before 2026-12-03, exit 2).
    out = os.path.join(tmp, "out_runs")
    r = subprocess.run([sys.executable, driver, good, "--transfer", "0", "--duration", "1", "--dt", "5", "--bin", args.bin,
                        "--out", out], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    checks.expect("a run whose resume file name gains a digit", r.returncode == 0, ": exit %d, %s" % (r.returncode, r.stderr))
    checks.expect("fem2mpm's warning repeated on stderr", "fem2mpm: warning: material '1': density 2 kg/m3" in r.stderr,
                  ": %r" % r.stderr)
    summary = open(os.path.join(out, "summary.md")).read() if os.path.exists(os.path.join(out, "summary.md")) else ""
    checks.expect("and listed in summary.md", "## Warnings" in summary and "looks like Mg/m3" in summary, ": %r" % summary)
    shutil.rmtree(tmp, ignore_errors=True)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
