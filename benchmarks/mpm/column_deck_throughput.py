#!/usr/bin/python3
"""Whole-process MPM throughput on the paper's column as the study runs it (not a test; prints figures).

    benchmarks/mpm/column_deck_throughput.py [--mpm BIN] [--repeats R] [--threads 1,2] [--schemes usf,usl,musl]
                                             [--transfers flip,apic] [--steps SHORT,LONG]

Writes the CB-Geo deck of the MPM-only column of scripts/column_collapse/study.py (--full resolution:
50 m x 40 m, 1 m uGIMP cells, 4 x 4 particles per cell = 32,000 particles, Mohr-Coulomb, rough base, CFL
0.5) into a scratch folder, and times `mpm` on it for SHORT and LONG steps (output only at the end). The
rate is (LONG - SHORT) particle-steps over the difference of the wall times, so reading the deck and
writing the files cancel out (the issue 13 method: 600 minus 100 steps). Medians over R repeats; the
load average is printed with each figure, since the machine may be shared.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "scripts", "column_collapse"))
sys.path.insert(0, os.path.join(REPO, "scripts"))
import study  # noqa: E402


def run(mpm, d, threads, nsteps):
    path = os.path.join(d, "mpm.json")
    with open(path) as f:
        deck = json.load(f)
    deck["analysis"]["nsteps"] = nsteps
    deck["post_processing"]["output_steps"] = nsteps
    with open(path, "w") as f:
        json.dump(deck, f)
    t0 = time.monotonic()
    subprocess.run([mpm, "-f", d + "/", "-i", "mpm.json", "--threads", str(threads)], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--mpm", default=os.path.join(REPO, "build", "bin", "mpm"))
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--schemes", default="usf,usl,musl")
    ap.add_argument("--transfers", default="flip,apic")
    ap.add_argument("--steps", default="100,600")
    a = ap.parse_args()
    short, long_ = (int(s) for s in a.steps.split(","))
    if not os.path.isfile(a.mpm) or not long_ > short > 0:
        print("column_deck_throughput: error: needs an mpm binary (--mpm) and --steps SHORT,LONG with LONG > SHORT > 0",
              file=sys.stderr)
        return 2
    scene = study.Scene(50.0, 40.0, 1.0, 4)
    with tempfile.TemporaryDirectory(prefix="column_deck_") as tmp:
        for scheme in a.schemes.split(","):
            for transfer in a.transfers.split(","):
                d = os.path.join(tmp, "%s_%s" % (scheme, transfer))
                study.SCHEME = scheme
                study.write_mpm_only_deck(scene, d, duration=1.0, transfer=transfer)
                with open(os.path.join(d, "particles.txt")) as f:
                    particles = int(f.readline())
                for threads in (int(t) for t in a.threads.split(",")):
                    rates = []
                    for _ in range(a.repeats):
                        ws = run(a.mpm, d, threads, short)
                        wl = run(a.mpm, d, threads, long_)
                        rates.append(particles * (long_ - short) / max(wl - ws, 1e-9) / 1e6)
                    print("%-4s %-4s threads %d: %6.2f M particle-steps/s (median of %d, %d minus %d steps of %d "
                          "particles; runs %s); load average %.1f" %
                          (scheme.upper(), transfer.upper(), threads, statistics.median(rates), a.repeats, long_,
                           short, particles, " ".join("%.2f" % r for r in rates), os.getloadavg()[0]), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
