"""Ground-motion records for the suites (scripts/motion_suite.py): PEER NGA `.AT2` files, the baseline
correction, and the intensity measures. numpy only.

Reading (`read_at2`): the PEER NGA format, as the NGA-West2 / NGA-Sub / NGA-East flatfile tools write it,

    line 1  PEER NGA STRONG MOTION DATABASE RECORD           (free text)
    line 2  event, date, station, component                  (free text)
    line 3  ACCELERATION TIME SERIES IN UNITS OF G
    line 4  NPTS=  4000, DT=   .0100 SEC                    (NGA-West2 and later)
       or   4000   .0100   NPTS, DT                          (NGA-West1: the two numbers first)
    line 5+ the NPTS accelerations in g, any number a line (usually 5, Fortran E format)

A malformed file (a header that is not this, NPTS that disagrees with the data, a token that is not a finite
number) raises RecordError, whose str() is one line `FILE:LINE: what`.

The baseline correction (`baseline_correct`), applied to every record before anything else: the acceleration
plus c0 + c1 t, with c0 and c1 chosen so that the velocity and the displacement (trapezoidal integrals,
exact for the piecewise-linear record a Path time series reads) are zero at the end: the ground starts and
ends at rest, where it started. It is the correction of scripts/shaken_slope/ground_motion.py (step 4) and
the usual first step of record processing (Boore & Bommer 2005, "Processing of strong-motion accelerograms",
Soil Dyn. Earthq. Eng. 25: a low-order polynomial baseline); for a record that PEER has already filtered
it is a small change (its size is reported: `correction_peak_g`).

Intensity measures (`intensity_measures`), of the corrected acceleration a (m/s^2), g = 9.81 m/s^2; the
integrals over time by the trapezoidal rule on the samples (as ground_motion.py's motion.json and the usual
record-processing tools compute them; the velocity so is exact for the piecewise-linear record the FEM's
Path series reads):
    PGA     max |a|                                                   (g)
    PGV     max |v|, v(t) = int_0^t a dt (trapezoidal, exact)         (m/s)
    Arias   I_a = pi / (2 g) int a^2 dt        (Arias 1970)          (m/s)
    CAV     int |a| dt                         (EPRI 1988, without the 5 gal threshold of CAV_STD) (m/s)
    D5-95   the time between 5 % and 95 % of I_a   (Trifunac & Brady 1975)  (s)
    ASI     int_0.1^0.5 PSA(T, 5 %) dT          (Von Thun et al. 1988)  (g s)
    MASI    int_0.1^2.5 PSA(T, 5 %) dT          (g s) -- the "modified" ASI: ASI's integral over the longer
            period range 0.1-2.5 s of Housner's (1952) spectrum intensity, which reaches the longer periods of
            a soft, liquefying deposit. This is the definition of the open ground-motion IM libraries we
            found; we could not read the one in Sordo, Rathje & Kumar (2025) or Bray & Macedo's papers, so
            the range is an argument (`masi_range`): another definition is one change. ASI (0.1-0.5 s) is
            reported beside it.
PSA(T, zeta) = omega^2 max |u|, u the relative displacement of a linear oscillator of period T and damping
zeta under the record, by the exact solution for piecewise-linear excitation (Nigam & Jennings 1969; Chopra,
Dynamics of Structures, sec. 5.2), the record resampled (linearly: the same excitation) to at least 20
points per period so that the sampled maximum is within 1.3 % of the true one; periods every 0.01 s,
integrated by the trapezoidal rule.
"""
import math
import os
import re

import numpy as np

G = 9.81
SPECTRUM_PERIODS = np.round(np.arange(0.10, 2.5 + 1e-9, 0.01), 10)
ASI_RANGE = (0.1, 0.5)
MASI_RANGE = (0.1, 2.5)
DAMPING = 0.05
POINTS_PER_PERIOD = 20


class RecordError(ValueError):
    """A malformed record file; str() is the one-line `FILE:LINE: what`."""

    def __init__(self, path, line, what):
        super().__init__("%s:%d: %s" % (path, line, what))
        self.path, self.line, self.what = path, line, what


# ---- reading ---------------------------------------------------------------------------------------------

_NUMBER = r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?)"
_NEW_HEADER = re.compile(r"^\s*NPTS\s*=\s*" + _NUMBER + r"\s*,?\s*DT\s*=\s*" + _NUMBER + r"\s*(SEC)?\s*,?\s*$", re.I)
_OLD_HEADER = re.compile(r"^\s*" + _NUMBER + r"\s+" + _NUMBER + r"\s+NPTS\s*,\s*DT\b.*$", re.I)


def _number(token):
    return float(token.replace("D", "E").replace("d", "e"))


def read_at2(path):
    """A PEER NGA .AT2 file -> {"accel_g": array, "dt": s, "npts": n, "title": line 2, "path": path}.
    Raises RecordError (one line naming the file and the line) for a malformed file."""
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError as e:
        raise RecordError(path, 0, "cannot read: %s" % (e.strerror or e))
    try:
        text = raw.decode("ascii")
    except UnicodeDecodeError as e:
        line = raw[:e.start].count(b"\n") + 1
        raise RecordError(path, line, "a byte that is not ASCII (0x%02x): not a PEER .AT2 text file" % raw[e.start])
    lines = text.splitlines()
    if len(lines) < 4:
        raise RecordError(path, len(lines) + 1 if lines else 1,
                          "bad header: a PEER .AT2 file has 4 header lines (title, event, 'ACCELERATION TIME SERIES "
                          "IN UNITS OF G', 'NPTS= n, DT= dt SEC'), this one has %d lines" % len(lines))
    units = lines[2].upper()
    if "ACCELERATION" not in units:
        kind = "velocity" if "VELOCITY" in units else "displacement" if "DISPLACEMENT" in units else None
        raise RecordError(path, 3, "bad header: expected 'ACCELERATION TIME SERIES IN UNITS OF G', got %r%s"
                          % (lines[2].strip()[:80], " (a %s file: give the .AT2 acceleration file)" % kind if kind else ""))
    if not re.search(r"\bUNITS\s+OF\s+G\b", units) and not re.search(r"\bIN\s+G\b", units):
        raise RecordError(path, 3, "bad header: expected the acceleration in units of g ('... IN UNITS OF G'), got %r"
                          % lines[2].strip()[:80])
    m = _NEW_HEADER.match(lines[3]) or _OLD_HEADER.match(lines[3])
    if not m:
        raise RecordError(path, 4, "bad header: expected 'NPTS= n, DT= dt SEC' (or 'n dt NPTS, DT'), got %r"
                          % lines[3].strip()[:80])
    npts_f, dt = _number(m.group(1)), _number(m.group(2))
    if not (npts_f == int(npts_f) and npts_f >= 2):
        raise RecordError(path, 4, "bad header: NPTS must be an integer >= 2, got %s" % m.group(1))
    if not (math.isfinite(dt) and dt > 0):
        raise RecordError(path, 4, "bad header: DT must be a time > 0 s, got %s" % m.group(2))
    npts = int(npts_f)
    values = []
    last_data_line = 4
    for k, ln in enumerate(lines[4:], start=5):
        for tok in ln.split():
            try:
                v = _number(tok)
            except ValueError:
                raise RecordError(path, k, "not a number: %r" % tok[:40])
            if not math.isfinite(v):
                raise RecordError(path, k, "not a finite number: %r" % tok[:40])
            values.append(v)
            if len(values) > npts:
                raise RecordError(path, k, "more values than NPTS = %d (line 4) declares" % npts)
        if ln.strip():
            last_data_line = k
    if len(values) < npts:
        raise RecordError(path, last_data_line, "the data ends after %d values; NPTS (line 4) declares %d"
                          % (len(values), npts))
    return {"accel_g": np.array(values), "dt": dt, "npts": npts, "title": lines[1].strip(), "path": path}


def write_at2(path, accel_g, dt, title="synthetic record", event="geoflow"):
    """Writes a PEER NGA-West2-style .AT2 file (5 values a line, E format)."""
    a = np.asarray(accel_g, dtype=float)
    with open(path, "w") as f:
        f.write("PEER NGA STRONG MOTION DATABASE RECORD\n%s, %s\nACCELERATION TIME SERIES IN UNITS OF G\n" % (event, title))
        f.write("NPTS=%7d, DT= %10.4f SEC\n" % (len(a), dt))
        for i in range(0, len(a), 5):
            f.write("".join("%15.7E" % v for v in a[i:i + 5]) + "\n")


# ---- processing ------------------------------------------------------------------------------------------

def integrate(a, dt):
    """Trapezoidal cumulative integral from 0 (exact for a piecewise-linear a)."""
    a = np.asarray(a, dtype=float)
    return np.concatenate([[0.0], np.cumsum(0.5 * (a[1:] + a[:-1]) * dt)])


def baseline_correct(a, dt):
    """(a + c0 + c1 t, (c0, c1)): the end velocity and end displacement (trapezoidal) zero."""
    a = np.asarray(a, dtype=float)
    t = np.arange(len(a)) * dt
    basis = (np.ones_like(t), t)
    m = np.array([[integrate(f, dt)[-1] for f in basis], [integrate(integrate(f, dt), dt)[-1] for f in basis]])
    v = integrate(a, dt)
    rhs = -np.array([v[-1], integrate(v, dt)[-1]])
    c = np.linalg.solve(m, rhs)
    return a + c[0] + c[1] * t, (float(c[0]), float(c[1]))


# ---- intensity measures ----------------------------------------------------------------------------------

def arias_history(a, dt, g=G):
    """I_a(t) = pi / (2 g) int_0^t a^2 dt, trapezoidal on the samples (m/s)."""
    a = np.asarray(a, dtype=float)
    return math.pi / (2.0 * g) * integrate(a * a, dt)


def cav(a, dt):
    """int |a| dt, trapezoidal on the samples (m/s)."""
    return float(integrate(np.abs(np.asarray(a, dtype=float)), dt)[-1])


def response_spectrum(a, dt, periods=SPECTRUM_PERIODS, zeta=DAMPING, points_per_period=POINTS_PER_PERIOD):
    """Pseudo-spectral acceleration PSA(T) = omega^2 max|u| (units of a) of a linear oscillator under the
    piecewise-linear ground acceleration a: the exact recurrence of Nigam & Jennings (1969), all periods at
    once; the record resampled linearly to dt <= T_min / points_per_period (the same excitation)."""
    a = np.asarray(a, dtype=float)
    periods = np.asarray(periods, dtype=float)
    k = max(1, int(math.ceil(dt * points_per_period / periods.min() - 1e-9)))
    if k > 1:
        t = np.arange(len(a)) * dt
        h = dt / k
        a = np.interp(np.arange((len(a) - 1) * k + 1) * h, t, a)
        dt = h
    w = 2.0 * math.pi / periods
    wd = w * math.sqrt(1.0 - zeta ** 2)
    e = np.exp(-zeta * w * dt)
    s, c = np.sin(wd * dt), np.cos(wd * dt)
    r = zeta / math.sqrt(1.0 - zeta ** 2)
    kk = w ** 2
    A = e * (r * s + c)
    B = e * s / wd
    C = (2 * zeta / (w * dt) + e * (((1 - 2 * zeta ** 2) / (wd * dt) - r) * s - (1 + 2 * zeta / (w * dt)) * c)) / kk
    D = (1 - 2 * zeta / (w * dt) + e * ((2 * zeta ** 2 - 1) / (wd * dt) * s + 2 * zeta / (w * dt) * c)) / kk
    Ap = -e * w / math.sqrt(1.0 - zeta ** 2) * s
    Bp = e * (c - r * s)
    Cp = (-1.0 / dt + e * ((w / math.sqrt(1.0 - zeta ** 2) + r / dt) * s + c / dt)) / kk
    Dp = (1.0 - e * (r * s + c)) / (kk * dt)
    p = -a
    u = np.zeros_like(w)
    v = np.zeros_like(w)
    umax = np.zeros_like(w)
    for i in range(len(p) - 1):
        u, v = A * u + B * v + C * p[i] + D * p[i + 1], Ap * u + Bp * v + Cp * p[i] + Dp * p[i + 1]
        np.maximum(umax, np.abs(u), out=umax)
    return kk * umax


def spectrum_intensity(periods, psa, lo, hi):
    """int_lo^hi PSA dT (trapezoidal on the periods inside [lo, hi], which must span it)."""
    periods, psa = np.asarray(periods), np.asarray(psa)
    if periods.min() > lo + 1e-9 or periods.max() < hi - 1e-9:
        raise ValueError("the periods %.3g-%.3g s do not span %.3g-%.3g s" % (periods.min(), periods.max(), lo, hi))
    inside = (periods >= lo - 1e-9) & (periods <= hi + 1e-9)
    x, y = periods[inside], psa[inside]
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(x)))


def intensity_measures(a, dt, g=G, masi_range=MASI_RANGE, asi_range=ASI_RANGE, spectrum=True):
    """The intensity measures of the module help for an acceleration a in m/s^2 (as given: correct it first).
    Returns a dict (pga_g, pgv_m_s, arias_m_s, cav_m_s, d5_95_s, and with spectrum: asi_g_s, masi_g_s, and
    the spectrum itself under "_periods", "_psa_g")."""
    a = np.asarray(a, dtype=float)
    t = np.arange(len(a)) * dt
    v = integrate(a, dt)
    ia = arias_history(a, dt, g)
    d5, d95 = np.interp([0.05 * ia[-1], 0.95 * ia[-1]], ia, t) if ia[-1] > 0 else (0.0, 0.0)
    out = {"pga_g": float(np.max(np.abs(a)) / g), "pgv_m_s": float(np.max(np.abs(v))), "arias_m_s": float(ia[-1]),
           "cav_m_s": cav(a, dt), "d5_95_s": float(d95 - d5)}
    if spectrum:
        lo = min(masi_range[0], asi_range[0])
        hi = max(masi_range[1], asi_range[1])
        periods = SPECTRUM_PERIODS[(SPECTRUM_PERIODS >= lo - 1e-9) & (SPECTRUM_PERIODS <= hi + 1e-9)]
        if periods.min() > lo + 1e-9 or periods.max() < hi - 1e-9:
            periods = np.round(np.arange(lo, hi + 1e-9, 0.01), 10)
        psa = response_spectrum(a, dt, periods) / g
        out["asi_g_s"] = spectrum_intensity(periods, psa, *asi_range)
        out["masi_g_s"] = spectrum_intensity(periods, psa, *masi_range)
        out["_periods"], out["_psa_g"] = periods, psa
    return out


def write_column(path, values):
    """One value a line (%.9e), write-then-rename: the file a `timeSeries Path -filePath` reads."""
    tmp = path + ".tmp"
    np.savetxt(tmp, np.asarray(values, dtype=float), fmt="%.9e")
    os.replace(tmp, path)
