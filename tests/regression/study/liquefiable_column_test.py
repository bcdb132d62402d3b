#!/usr/bin/python3
"""scripts/site_response/liquefiable_column.tcl and liquefaction.py, their sample run shortened to 4 s of shaking:

- the consolidated state is hydrostatic: p0 = rho_f g depth at every node (to 1e-4 of the base's), and the
  consolidated sigma'v0 = (rho - rho_f) g depth at the element centres (1 %: the skeleton's weight, buoyant);
- the loose layer (Dr 0.4) builds up more excess pore pressure than the dense one (Dr 0.75): its largest r_u
  is above 0.8 and above the dense layer's largest (measured: 0.98 against 0.69 at 4 s);
- the simplified procedure (Idriss & Boulanger 2008, the plausibility check of liquefaction.py) gives
  FS_liq < 1 in the whole loose layer and > 1 in the whole dense one;
- ru.png and liquefaction.md are written; a bad option is one line on stderr and exit 2 (both programs).
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--repo", required=True)
    a = ap.parse_args()
    c = Checklist()
    script = os.path.join(a.repo, "scripts/site_response/liquefiable_column.tcl")
    post = os.path.join(a.repo, "scripts/site_response/liquefaction.py")
    with tempfile.TemporaryDirectory(prefix="geoflow_liquefiable_") as tmp:
        out = os.path.join(tmp, "run")
        r = subprocess.run([os.path.join(a.bin, "fem_tcl"), script, out, "-tend", "4"], capture_output=True, text=True)
        c.expect("fem_tcl exit 0", r.returncode == 0, r.stderr[-2000:])
        r = subprocess.run(["/usr/bin/python3", post, out], capture_output=True, text=True)
        c.expect("liquefaction.py exit 0", r.returncode == 0, r.stderr[-2000:])
        for f in ("ru.png", "liquefaction.md"):
            c.expect(f + " written", os.path.getsize(os.path.join(out, f)) > 0)
        g, rhof, rho, h = 9.81, 1.0, 1.9, 0.5
        pp = np.loadtxt(os.path.join(out, "pp.out"))
        st = np.loadtxt(os.path.join(out, "stress.out"))
        ne = st.shape[1] // 3
        H = ne * h
        depth_nodes = H - h * np.arange(ne + 1)
        p0 = pp[0, 1:]
        err = np.abs(p0 - rhof * g * depth_nodes).max()
        c.expect("hydrostatic consolidated pressures", err < 1e-4 * p0.max(), "largest difference %.3g kPa" % err)
        depth = H - h * (np.arange(ne) + 0.5)
        sv0 = -st[0, 2::3]
        err = np.abs(sv0 - (rho - rhof) * g * depth).max()
        c.expect("buoyant consolidated sigma'v0", err < 0.01 * sv0.max(), "largest difference %.3g kPa" % err)
        excess = pp[:, 1:] - p0
        ru = 0.5 * (excess[:, :-1] + excess[:, 1:]) / sv0
        loose = depth < 6.0
        ru_loose, ru_dense = ru[:, loose].max(), ru[:, ~loose].max()
        c.expect("the loose layer builds up more excess pressure", ru_loose > 0.8 and ru_loose > ru_dense,
                 "largest r_u loose %.3f, dense %.3f" % (ru_loose, ru_dense))
        rows = [ln.split("|")[1:-1] for ln in open(os.path.join(out, "liquefaction.md")) if ln.startswith("| ") and
                not ln.startswith("| depth")]
        fs = {float(row[0]): float(row[-1]) for row in rows}
        c.expect("FS_liq < 1 in the loose layer, > 1 in the dense one",
                 all(v < 1.0 for d, v in fs.items() if d < 6.0) and all(v > 1.0 for d, v in fs.items() if d > 6.0), str(fs))
        r = subprocess.run([os.path.join(a.bin, "fem_tcl"), script, os.path.join(tmp, "bad"), "-Drl", "abc"],
                           capture_output=True, text=True)
        c.expect("a bad option: one line, exit 2", r.returncode == 2 and "-Drl expects a positive number" in r.stderr
                 and len(r.stderr.splitlines()) == 1, r.stderr)
        r = subprocess.run(["/usr/bin/python3", post, os.path.join(tmp, "missing")], capture_output=True, text=True)
        c.expect("liquefaction.py on a missing run: one line, exit 2", r.returncode == 2 and "column.txt" in r.stderr
                 and len(r.stderr.splitlines()) == 1, r.stderr)
    return c.exit_status()


if __name__ == "__main__":
    sys.exit(main())
