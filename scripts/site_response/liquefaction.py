#!/usr/bin/python3
"""The excess pore-pressure ratio of a liquefiable_column.tcl run, and the simplified procedure beside it.

Usage: /usr/bin/python3 scripts/site_response/liquefaction.py OUTDIR [--magnitude 7.5] [--ru 0.98]

Reads OUTDIR/column.txt, pp.out and stress.out (their first row is the consolidated state at t = 0) and writes
OUTDIR/ru.png and OUTDIR/liquefaction.md:
  - r_u(z, t) = (p - p0) / sigma'v0 per element (p the mean of its nodes' pore pressures, p0 the hydrostatic
    pressure of the consolidated state, sigma'v0 = -syy of the consolidated state), its map against depth and
    time, time histories, and the depth where r_u first reaches --ru;
  - the simplified procedure (Idriss & Boulanger 2008, "Soil Liquefaction During Earthquakes", EERI MNO-12)
    as a plausibility check, stated as such: CSR = 0.65 tau_max / sigma'v0 from the computed peak shear
    stress of each element, and CRR(M, sigma'v) for (N1)60cs = 46 Dr^2 (their eq. for Dr from (N1)60):
      CRR_M7.5,1atm = exp(N/14.1 + (N/126)^2 - (N/23.6)^3 + (N/25.4)^4 - 2.8)      (eq. 70)
      MSF = min(1.8, 6.9 exp(-M/4) - 0.058)                                       (eq. 47)
      K_sigma = min(1.1, 1 - C_sigma ln(sigma'v0 / Pa)), C_sigma = min(0.3, 1 / (18.9 - 2.55 sqrt(N)))  (eqs. 54-55)
      FS_liq = CRR_M7.5,1atm MSF K_sigma / CSR.
    The computed tau_max is the whole record's, so where the soil liquefied it is the stress the softening
    skeleton could still carry, not the demand on a stiff one: the check is qualitative.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from geoflow import plots  # noqa: E402

PA = 101.3  # kPa


def fail(message):
    print("liquefaction.py: " + message, file=sys.stderr)
    sys.exit(2)


def read_column(path):
    try:
        with open(path) as f:
            lines = [ln.split() for ln in f if ln.strip() and not ln.startswith("#")]
        words = lines[0]
        info = {words[i]: words[i + 1] for i in range(0, len(words) - 1, 2)}
        return {k: (v if k == "base" else float(v)) for k, v in info.items()}
    except (OSError, IndexError, ValueError) as e:
        fail("%s: not a liquefiable_column.tcl column.txt (%s)" % (path, e))


def read_table(path, columns):
    try:
        t = np.loadtxt(path, ndmin=2)
    except (OSError, ValueError) as e:
        fail("%s: %s" % (path, e))
    if t.shape[1] != columns or t.shape[0] < 2:
        fail("%s: expected at least 2 rows of %d columns, got %s" % (path, columns, t.shape))
    return t


def crr_m75(n160cs):
    n = n160cs
    return math.exp(n / 14.1 + (n / 126.0) ** 2 - (n / 23.6) ** 3 + (n / 25.4) ** 4 - 2.8)


def factor_of_safety(dr, sigma_v0, tau_max, magnitude):
    n = 46.0 * dr * dr
    msf = min(1.8, 6.9 * math.exp(-magnitude / 4.0) - 0.058)
    c_sigma = min(0.3, 1.0 / (18.9 - 2.55 * math.sqrt(n)))
    k_sigma = min(1.1, 1.0 - c_sigma * math.log(sigma_v0 / PA))
    csr = 0.65 * tau_max / sigma_v0
    crr = crr_m75(n) * msf * k_sigma
    return crr / csr, csr, crr


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--magnitude", type=float, default=7.5, help="earthquake magnitude for the MSF (default 7.5)")
    ap.add_argument("--ru", type=float, default=0.98, help="the r_u that marks liquefaction (default 0.98)")
    a = ap.parse_args()
    if not (0.0 < a.ru <= 1.0) or not (4.0 <= a.magnitude <= 9.5):
        fail("expected 0 < --ru <= 1 and 4 <= --magnitude <= 9.5")
    col = read_column(os.path.join(a.outdir, "column.txt"))
    ne, h = int(col["elements"]), col["h"]
    loose_from = int(col["loose_from"])
    pp = read_table(os.path.join(a.outdir, "pp.out"), ne + 2)
    st = read_table(os.path.join(a.outdir, "stress.out"), 1 + 3 * ne)
    rows = min(len(pp), len(st))
    t = pp[:rows, 0]
    p = pp[:rows, 1:]                                   # nodes base to top
    excess = p - p[0]
    e_excess = 0.5 * (excess[:, :-1] + excess[:, 1:])  # per element
    sxy = st[:rows, 3::3]
    sv0 = -st[0, 2::3]                                  # consolidated sigma'v0 per element
    if np.any(sv0 <= 0.0):
        fail("stress.out: the consolidated vertical effective stress is not compressive everywhere")
    ru = e_excess / sv0
    H = ne * h
    depth = H - (np.arange(ne) + 0.5) * h               # element centres
    # the first time each element reaches r_u >= --ru
    reached = ru >= a.ru
    t_first = np.where(reached.any(axis=0), t[np.argmax(reached, axis=0)], np.nan)
    liquefied = np.isfinite(t_first)
    tau_max = np.abs(sxy).max(axis=0)
    dr = np.where(np.arange(ne) + 1 >= loose_from, col["Drl"], col["Drd"])
    fs = np.array([factor_of_safety(dr[j], sv0[j], tau_max[j], a.magnitude)[0] for j in range(ne)])

    plt = plots.pyplot()
    fig, ax = plt.subplots(1, 3, figsize=(13, 4.6), gridspec_kw={"width_ratios": [1.6, 1.3, 1]})
    im = ax[0].pcolormesh(t, depth, ru.T, shading="nearest", cmap="magma_r", vmin=0.0, vmax=1.0)
    ax[0].contour(t, depth, ru.T, levels=[a.ru], colors="c", linewidths=1.0)
    ax[0].axhline(H - (loose_from - 1) * h, color="w", ls="--", lw=0.8)
    ax[0].invert_yaxis()
    ax[0].set_xlabel("t (s)")
    ax[0].set_ylabel("depth (m)")
    ax[0].set_title("r_u = excess p / sigma'v0 (cyan: r_u = %.2f)" % a.ru)
    fig.colorbar(im, ax=ax[0], label="r_u")
    for j in np.linspace(0, ne - 1, 5).astype(int)[::-1]:
        ax[1].plot(t, ru[:, j], lw=1.0, label="%.2f m" % depth[j])
    ax[1].axhline(a.ru, color="k", ls=":", lw=0.8)
    ax[1].set_xlabel("t (s)")
    ax[1].set_ylabel("r_u")
    ax[1].set_ylim(-0.2, 1.1)
    ax[1].legend(title="depth", fontsize=7)
    ax[2].plot(ru.max(axis=0), depth, "k-", label="max r_u (FEM)")
    ax[2].plot(np.minimum(fs, 3.0), depth, "b--", label="FS_liq (simplified, capped at 3)")
    ax[2].axvline(1.0, color="gray", lw=0.6)
    ax[2].invert_yaxis()
    ax[2].set_xlim(0.0, 3.0)
    ax[2].set_xlabel("max r_u   /   FS_liq")
    ax[2].set_ylabel("depth (m)")
    ax[2].legend(fontsize=7, loc="lower right")
    ax[2].set_title("plausibility check")
    plots.save(fig, os.path.join(a.outdir, "ru.png"))

    lines = ["# Liquefaction of %s" % os.path.abspath(a.outdir), "",
             "%d elements of %.2f m (%.1f m), loose (Dr %.2f) from element %d up, dense (Dr %.2f) below; base %s, "
             "motion x %.2f; M = %.1f for the MSF." % (ne, h, H, col["Drl"], loose_from, col["Drd"], col["base"],
                                                       col["scale"], a.magnitude), ""]
    if liquefied.any():
        first = int(np.nanargmin(t_first))
        lines.append("r_u first reaches %.2f at depth %.2f m, t = %.2f s; %d of %d elements reach it, between "
                     "%.2f and %.2f m." % (a.ru, depth[first], t_first[first], int(liquefied.sum()), ne,
                                           depth[liquefied].min(), depth[liquefied].max()))
    else:
        lines.append("r_u reaches %.2f nowhere (largest %.3f at %.2f m)." % (a.ru, ru.max(), depth[ru.max(axis=0).argmax()]))
    predicted = fs < 1.0
    lines.append("The simplified procedure (a plausibility check, not a verification) predicts FS_liq < 1 in %d "
                 "elements%s." % (int(predicted.sum()), (", between %.2f and %.2f m" % (depth[predicted].min(), depth[predicted].max()))
                                  if predicted.any() else ""))
    lines += ["", "| depth (m) | Dr | sigma'v0 (kPa) | tau_max (kPa) | max r_u | t(r_u >= %.2f) (s) | CSR | CRR | FS_liq |" % a.ru,
              "|---|---|---|---|---|---|---|---|---|"]
    for j in range(ne - 1, -1, -1):
        f, csr, crr = factor_of_safety(dr[j], sv0[j], tau_max[j], a.magnitude)
        lines.append("| %.2f | %.2f | %.1f | %.2f | %.3f | %s | %.3f | %.3f | %.2f |" % (
            depth[j], dr[j], sv0[j], tau_max[j], ru[:, j].max(), "-" if not liquefied[j] else "%.2f" % t_first[j],
            csr, crr, f))
    with open(os.path.join(a.outdir, "liquefaction.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines[:5]))


if __name__ == "__main__":
    main()
