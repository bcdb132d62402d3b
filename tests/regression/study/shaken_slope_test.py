#!/usr/bin/python3
"""The shaken-slope chain in its small version (scripts/shaken_slope/study.py --quick: 2 m cells, 4 s of the
record at dt 0.01 s, 0.3 s of MPM), shaken and unshaken, into a scratch folder; checks what the study
claims, each an assertion that fails when the chain breaks:

- the shaking leaves a permanent downslope displacement of both shoulders (FEM, relative to the base),
  larger than 2 cm and more than 10 times the unshaken run's (measured: left 0.102 m, right 0.077 m;
  unshaken below 1e-4 m), and a settlement of the crest;
- the pseudo-static analysis of the same slope: static FS above 1 and k_y between 0.1 and 0.2 (measured
  1.318, 0.154), the record's PGA (0.40 g) above k_y, and Newmark's displacement with the outcrop record
  within an order of magnitude (factor 10) of the FEM's on the face it drives (measured 0.050 m vs 0.102 m);
- fem2mpm carried the model over: the dashpot skipped with its warning, roller walls at x = 0 and 72 and a
  frictional base at y = 0 in report.json, and no particle beyond the walls at the end of the MPM run
  (half a cell); the shaken deposit's runout is at least the unshaken one's.
Measured: 16-22 s wall on the loaded 2-core machine.
"""
import argparse
import json
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
    args = ap.parse_args()
    scratch = tempfile.mkdtemp(prefix="shaken_slope_")
    checks = Checklist()

    def check(ok, what):
        checks.expect(what, ok)

    try:
        r = subprocess.run([sys.executable, os.path.join(args.repo, "scripts", "shaken_slope", "study.py"), "--quick", "--no-figure",
                            "--out", scratch, "--bin", args.bin], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        print(r.stdout[-3000:])
        if r.returncode != 0:
            print("FAILED: study.py --quick exited %d" % r.returncode)
            return 1
        s = json.load(open(os.path.join(scratch, "summary.json")))
        nm, ps, mpm = s["newmark"], s["pseudo_static"], s["mpm"]
        for face, sign in (("left", -1.0), ("right", 1.0)):
            shaken = sign * nm[face]["fem_shoulder_ux_shaken_m"]
            unshaken = abs(nm[face]["fem_shoulder_ux_unshaken_m"])
            check(shaken > 0.02 and shaken > 10 * unshaken,
                  "%s shoulder: downslope %.4f m shaken > 0.02 m and > 10 x unshaken %.2e m" % (face, shaken, unshaken))
            check(nm[face]["fem_shoulder_uy_shaken_m"] < -0.01 and nm[face]["fem_shoulder_uy_shaken_m"] < nm[face]["fem_shoulder_uy_unshaken_m"],
                  "%s shoulder settles: uy %.4f m (unshaken %.2e m)" % (face, nm[face]["fem_shoulder_uy_shaken_m"],
                                                                        nm[face]["fem_shoulder_uy_unshaken_m"]))
        check(ps["static_fs"] > 1.0 and 0.1 < ps["k_y"] < 0.2, "static FS %.3f > 1, 0.1 < k_y %.4f < 0.2" % (ps["static_fs"], ps["k_y"]))
        check(s["motion"]["pga_g"] > ps["k_y"], "PGA %.2f g above k_y" % s["motion"]["pga_g"])
        fem_left, nmk = -nm["left"]["fem_shoulder_ux_shaken_m"], nm["left"]["outcrop_record_m"]
        check(0.1 < nmk / fem_left < 10.0, "Newmark (outcrop) %.4f m within a factor 10 of the FEM's %.4f m" % (nmk, fem_left))
        log = open(os.path.join(scratch, "shaken", "mpm", "fem2mpm.log")).read()
        check("zeroLength elements" in log and "not transferred" in log, "fem2mpm skipped the dashpot with a warning")
        for case in ("shaken", "unshaken"):
            b = {e["edge"]: e for e in mpm[case]["boundaries"]}
            check(abs(b["left wall"]["x"]) < 1e-9 and abs(b["right wall"]["x"] - 72.0) < 1e-9 and "roller" in b["left wall"]["condition"]
                  and "roller" in b["right wall"]["condition"], "%s: roller walls at x = 0 and 72" % case)
            check(abs(b["base"]["y"]) < 1e-9 and "friction" in b["base"]["condition"] and b["base"]["fem_line"]["kind"] == "roller",
                  "%s: frictional base at y = 0 on the FEM's roller base line" % case)
            half = 0.5 * s["settings"]["cell"]
            check(mpm[case]["x_min_end"] > -half and mpm[case]["x_max_end"] < 72.0 + half,
                  "%s: particles within the walls at the end (x %.3f .. %.3f)" % (case, mpm[case]["x_min_end"], mpm[case]["x_max_end"]))
        check(mpm["shaken"]["runout_m"] >= mpm["unshaken"]["runout_m"],
              "MPM runout shaken %.4f m >= unshaken %.4f m" % (mpm["shaken"]["runout_m"], mpm["unshaken"]["runout_m"]))
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
