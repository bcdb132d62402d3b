#!/usr/bin/python3
"""Runs the "Sample run" line of every example in scripts/examples/ (MFEM's habit: examples carry their own
sample run and the suite runs it, so they never rot), in its small version (the values on the header's "Test
run" line replace the sample run's: a shorter MPM run, fewer particles, a coarser mesh through the script's
arguments), each into a scratch folder, and checks what the driver (scripts/hybrid_run.py) promises: exit 0;
series.csv, summary.md and the five figures written; the series starting at the transfer time and ending at
transfer + duration.

Physics checks, from the examples' headers (each example is built to fail):
- the slope moves: the largest horizontal travel since the transfer is above 0.3 m and more than 2 % of the
  mass is moving (measured, small versions: slope_on_foundation 1.4 m and 28 %, embankment_two_layers 1.07 m
  and 13 %; each ~25 s of wall time on the loaded 2-core machine, ~3 s of CPU);
- no particle crosses a roller wall given in the sample run (--left-wall/--right-wall roller at the
  --extent's xmin/xmax), within half a cell;
- the script's own factor of safety (`-fos yes`, strength reduction from the gravity state, with the test
  run's script arguments) is below 1 (slope_on_foundation, embankment_two_layers, clay_slope: 0.86, 0.77,
  0.64 on the test run's coarse cells; 0.68, 0.59, 0.57 on the default ones).
An example whose header says "Factor of safety: none" (the u-p tailings dam: PM4Sand has no strength to reduce)
skips that check, one that says "Runout: not asserted" the runout ones; a u-p example (its FEM writes pp.out)
must hand liquefied particles (r_u > 0.7 in /pore_pressure) to MPM.
slope_on_foundation runs twice: as written and with `-mesh tri` (every SSPquad as two tri31 triangles; the
same checks).
"""
import argparse
import csv
import json
import glob
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist  # noqa: E402


def header_command(path, title):
    """The words on the line after '# <title>' in the example's header (None if there is none)."""
    lines = open(path).read().splitlines()
    for k, line in enumerate(lines):
        if line.lstrip("# ").lower().startswith(title) and k + 1 < len(lines):
            return shlex.split(lines[k + 1].lstrip("#").strip())
    return None


def small_version(words, overrides):
    """The sample run with the values of the header's 'Test run' options put in (the words after its `--`
    become the script's arguments): a smaller, faster run of the same command."""
    words = list(words)
    if "--" in overrides:
        k = overrides.index("--")
        overrides, script_args = overrides[:k], overrides[k + 1:]
    else:
        script_args = []
    for i in range(0, len(overrides), 2):
        k = words.index(overrides[i])   # a ValueError here: the test-run line names an option the sample run lacks
        words[k + 1] = overrides[i + 1]
    return words + (["--"] + script_args if script_args else [])


def option(words, name, count=1):
    k = words.index(name)
    return words[k + 1:k + 1 + count]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--repo", required=True)
    args = ap.parse_args()
    examples = sorted(glob.glob(os.path.join(args.repo, "scripts", "examples", "*.tcl")))
    checks = Checklist()
    check = checks.expect

    runs = 0
    cases = []
    for ex in examples:
        words = header_command(ex, "sample run")
        if words is None:
            continue   # a sourced helper (no sample run)
        words = small_version(words, header_command(ex, "test run") or [])
        cases.append((ex, os.path.basename(ex), words))
        if os.path.basename(ex) == "slope_on_foundation.tcl":
            # The same slope meshed with tri31 triangles (-mesh tri), through fem2mpm's triangle split.
            cases.append((ex, "slope_on_foundation.tcl -mesh tri", words + ([] if "--" in words else ["--"]) + ["-mesh", "tri"]))
    for ex, name, words in cases:
        runs += 1
        words = list(words)
        out = tempfile.mkdtemp(prefix="example_%s_" % os.path.splitext(name)[0])
        try:
            check("%s: the sample run calls scripts/hybrid_run.py" % name, words[0] == "scripts/hybrid_run.py", words[0])
            k = words.index("--out")
            words[k + 1] = out
            k = words.index("--") if "--" in words else len(words)
            cmd = [sys.executable, os.path.join(args.repo, words[0])] + words[1:k] + ["--bin", args.bin] + words[k:]
            r = subprocess.run(cmd, cwd=args.repo, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            print(r.stdout[-3000:])
            check("%s: exit 0" % name, r.returncode == 0, "(%d)" % r.returncode)
            if r.returncode != 0:
                continue
            for f in ("series.csv", "summary.md", "fem_mesh_T.png", "particles_T.png", "particles_end.png",
                      "runout.png", "energy.png"):
                check("%s: %s written" % (name, f), os.path.getsize(os.path.join(out, f)) > 0)
            with open(os.path.join(out, "series.csv")) as f:
                rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
            t_transfer = float(option(words, "--transfer")[0])
            duration = float(option(words, "--duration")[0])
            check("%s: series starts at the transfer" % name, abs(rows[0]["time"] - t_transfer) < 1e-9, str(rows[0]["time"]))
            check("%s: series ends at transfer + duration" % name, abs(rows[-1]["time"] - t_transfer - duration) < 0.01,
                  str(rows[-1]["time"]))
            header = open(ex).read()
            if "# Runout: not asserted" not in header:
                check("%s: runout > 0.3 m" % name, rows[-1]["runout"] > 0.3, "%.3g m" % rows[-1]["runout"])
                check("%s: some mass moving" % name, rows[-1]["moved_mass_fraction"] > 0.02,
                      "%.3g" % rows[-1]["moved_mass_fraction"])
            # A u-p example (pp.out recorded): the transfer carries the pore pressures and liquefied particles.
            if os.path.exists(os.path.join(out, "fem", "pp.out")):
                first = sorted(glob.glob(os.path.join(out, "mpm", "results", "*", "particles*.h5")))[0]
                with h5py.File(first, "r") as h:
                    ru = np.asarray(h["pore_pressure"])[:, 2] if "pore_pressure" in h else np.zeros(0)
                check("%s: the transfer has liquefied particles (r_u > 0.7)" % name, ru.size > 0 and ru.max() > 0.7,
                      "max r_u %.3g" % (ru.max() if ru.size else float("nan")))
            # The walls fem2mpm made (from the FEM supports or the options): no particle crosses one.
            with open(os.path.join(out, "mpm", "report.json")) as f:
                walls = [b for b in json.load(f)["boundaries"]
                         if b["edge"] in ("left wall", "right wall") and not b["condition"].startswith("none")]
            with open(os.path.join(out, "mpm", "mesh.txt")) as f:
                f.readline()
                cell = abs(float(f.readline().split()[0]) - float(f.readline().split()[0]))
            last = sorted(glob.glob(os.path.join(out, "mpm", "results", "*", "particles*.h5")))[-1]
            with h5py.File(last, "r") as h:
                x = np.asarray(h["table"]["coord_x"], dtype=float)
            check("%s: at least one wall" % name, len(walls) > 0, str(len(walls)))
            for w in walls:
                if w["edge"] == "left wall":
                    check("%s: no particle left of the left wall" % name, x.min() >= w["x"] - 0.5 * cell, "min x %.4g" % x.min())
                else:
                    check("%s: no particle right of the right wall" % name, x.max() <= w["x"] + 0.5 * cell, "max x %.4g" % x.max())
            # Built to fail: the script's own factor of safety (-fos yes, hybrid_stages.tcl fos_stage) is below 1
            # (an example whose header says "Factor of safety: none", the liquefying tailings dam, has none).
            if "# Factor of safety: none" in header:
                continue
            script_args = words[words.index("--") + 1:] if "--" in words else []
            fos_dir = os.path.join(out, "fos")
            r = subprocess.run([os.path.join(args.bin, "fem_tcl"), ex, fos_dir] + script_args + ["-fos", "yes"],
                               cwd=out, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            fos = [float(line.split()[1]) for line in r.stdout.splitlines() if line.startswith("FoS ")]
            check("%s: -fos yes prints a factor of safety" % name, r.returncode == 0 and len(fos) == 1, r.stdout[-500:])
            if fos:
                check("%s: factor of safety below 1" % name, 0.2 < fos[0] < 1.0, "%.4g" % fos[0])
        finally:
            shutil.rmtree(out, ignore_errors=True)
    check("at least two examples with a sample run", runs >= 2, str(runs))
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
