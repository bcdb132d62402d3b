"""Pseudo-static limit-equilibrium slope stability with a horizontal seismic coefficient k, and the yield
coefficient k_y (the k at which the factor of safety is 1), for Newmark's sliding-block analysis.

Pseudo-static method (Terzaghi 1950; Kramer 1996, "Geotechnical Earthquake Engineering", section 10.6.1): the
earthquake is a horizontal body force k W on the sliding mass, pointing downslope.

* Infinite slope (dry, slip plane at depth z parallel to a face of inclination beta), per unit plan length:
      FS(k) = [c + gamma z (cos^2 b - k sin b cos b) tan phi] / [gamma z (sin b cos b + k cos^2 b)]
  and FS = 1 gives  k_y = [c / (gamma z) + cos^2 b tan phi - sin b cos b] / [cos^2 b + sin b cos b tan phi],
  for c = 0:  k_y = (tan phi cos b - sin b) / (cos b + tan phi sin b) = tan(phi - b).
* Circular slips, Bishop's simplified method of slices with the seismic force k W at each slice's centroid
  (Bishop 1955; its pseudo-static form, e.g. Kramer 1996 10.6.1, Duncan & Wright 2005 "Soil Strength and
  Slope Stability" ch. 6): for a slope that fails towards +x, about the circle's centre (xc, yc), radius R,
  slice base angle alpha with sin alpha = (xc - x) / R,
      FS = sum[(c b + W tan phi) / m_alpha] / sum[W sin alpha + k W (yc - y_g) / R],
      m_alpha = cos alpha + sin alpha tan phi / FS.
  At FS = 1, m_alpha no longer depends on FS and the equation is linear in k, so each circle's yield
  coefficient is explicit: k_c = (sum[(c b + W tan phi) / (cos a + sin a tan phi)] - sum W sin a) /
  sum[W (yc - y_g) / R]; the slope's k_y is the least k_c over the circles searched (a grid of centres and
  radii, refined around the best one). Strength by layer at each slice base (the ground is one unit weight).
"""
import math

import numpy as np


def infinite_slope_factor_of_safety(beta_deg, phi_deg, c, gamma, z, k=0.0):
    """FS of a dry infinite slope (slip at depth z, kPa and kN/m3 or any consistent units) under k."""
    b, tp = math.radians(beta_deg), math.tan(math.radians(phi_deg))
    s, co = math.sin(b), math.cos(b)
    return (c + gamma * z * (co * co - k * s * co) * tp) / (gamma * z * (s * co + k * co * co))


def infinite_slope_yield_coefficient(beta_deg, phi_deg, c=0.0, gamma=1.0, z=1.0):
    """Closed-form k_y of the dry infinite slope (FS(k_y) = 1)."""
    b, tp = math.radians(beta_deg), math.tan(math.radians(phi_deg))
    s, co = math.sin(b), math.cos(b)
    return (c / (gamma * z) + co * co * tp - s * co) / (co * co + s * co * tp)


def yield_coefficient_by_bisection(fs_of_k, lo=0.0, hi=2.0, tol=1e-10):
    """The k in [lo, hi] with fs_of_k(k) = 1 for a decreasing fs_of_k (bisection)."""
    if fs_of_k(lo) < 1.0:
        return lo
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if fs_of_k(mid) > 1.0 else (lo, mid)
        if hi - lo < tol:
            break
    return 0.5 * (lo + hi)


class Ground:
    """The ground surface y = surface(x) (a polyline, x increasing) over layers: layers is a list of
    (y_bottom, c, phi_deg), a slice base at height y takes the layer with the largest y_bottom <= y."""

    def __init__(self, profile, layers, gamma, y_floor=0.0):
        p = np.asarray(profile, dtype=float)
        self.xs, self.ys = p[:, 0], p[:, 1]
        self.layers = sorted(layers)
        self.gamma = gamma
        self.y_floor = y_floor

    def surface(self, x):
        return np.interp(x, self.xs, self.ys)

    def strength(self, y):
        c = np.full(np.shape(y), self.layers[0][1], dtype=float)
        phi = np.full(np.shape(y), self.layers[0][2], dtype=float)
        for yb, cl, pl in self.layers[1:]:
            c = np.where(y >= yb, cl, c)
            phi = np.where(y >= yb, pl, phi)
        return c, np.radians(phi)

    def mirrored(self):
        """The same ground seen from the other side (x -> -x), so that a slope failing towards -x is
        analysed as one failing towards +x."""
        g = Ground(np.stack([-self.xs[::-1], self.ys[::-1]], axis=1), self.layers, self.gamma, self.y_floor)
        return g


def _depth(ground, xc, yc, R, x):
    """Ground surface minus the lower arc at x (negative outside the circle)."""
    dx = x - xc
    inside = np.abs(dx) < R
    arc = yc - np.sqrt(np.where(inside, R * R - dx * dx, 0.0))
    return np.where(inside, ground.surface(x) - arc, -1.0)


def _slip_ends(ground, xc, yc, R, samples=400):
    """Where each lower arc enters and leaves the ground (first and last crossing, by sampling and
    bisection); (nan, nan) for a circle that does not cut the ground, and for one that is still under the
    ground at an end of the profile (cut off by the model: no slip surface)."""
    x0 = np.maximum(xc - R, ground.xs[0])
    x1 = np.minimum(xc + R, ground.xs[-1])
    u = np.linspace(0.0, 1.0, samples + 1)
    x = x0[:, None] + (x1 - x0)[:, None] * u[None, :]
    h = _depth(ground, xc[:, None], yc[:, None], R[:, None], x)
    under = h > 0.0
    any_under = under.any(axis=1)
    first = np.argmax(under, axis=1)
    last = samples - np.argmax(under[:, ::-1], axis=1)
    cut = any_under & ((first == 0) | (last == samples))
    rows = np.arange(len(xc))

    def bisect(lo, hi, rising):
        for _ in range(40):
            mid = 0.5 * (lo + hi)
            pos = _depth(ground, xc, yc, R, mid) > 0.0
            if rising:
                lo, hi = np.where(pos, lo, mid), np.where(pos, mid, hi)
            else:
                lo, hi = np.where(pos, mid, lo), np.where(pos, hi, mid)
        return 0.5 * (lo + hi)

    xa = bisect(x[rows, np.maximum(first - 1, 0)], x[rows, first], True)
    xb = bisect(x[rows, last], x[rows, np.minimum(last + 1, samples)], False)
    bad = ~any_under | cut
    return np.where(bad, np.nan, xa), np.where(bad, np.nan, xb)


def _slices(ground, xc, yc, R, n):
    """Slices of the sliding masses of the circles (arrays of centres xc, yc, radii R, shape (m,)), n
    between the arc's entry and exit: widths b, weights W, base angles (sin, cos), centroid heights, base
    strengths, base heights; W = 0 for a circle that is no slip surface (_slip_ends)."""
    xa, xb = _slip_ends(ground, xc, yc, R)
    ok = np.isfinite(xa)
    xa, xb = np.where(ok, xa, xc), np.where(ok, xb, xc)
    u = (np.arange(n) + 0.5) / n
    x = xa[:, None] + (xb - xa)[:, None] * u[None, :]
    b = ((xb - xa) / n)[:, None] * np.ones_like(u)[None, :]
    dx = x - xc[:, None]
    yb = yc[:, None] - np.sqrt(np.maximum(R[:, None] ** 2 - dx ** 2, 0.0))
    ys = ground.surface(x)
    h = np.where(ok[:, None], np.maximum(ys - yb, 0.0), 0.0)
    W = ground.gamma * h * b
    sin_a = -dx / R[:, None]
    cos_a = np.sqrt(np.maximum(1.0 - sin_a ** 2, 0.0))
    yg = 0.5 * (ys + yb)
    c, phi = ground.strength(yb)
    return b, W, sin_a, cos_a, yg, c, np.tan(phi), yb


def circle_yield_coefficients(ground, xc, yc, R, n=60, m_alpha_min=0.2):
    """Each circle's k at FS = 1 (Bishop simplified, pseudo-static; module help); inf where the circle
    does not cut a sliding mass, leaves the model (below y_floor) or has a slice with m_alpha < m_alpha_min
    (the usual numerical guard near a steep exit)."""
    b, W, sa, ca, yg, c, tp, yb = _slices(ground, xc, yc, R, n)
    loaded = W > 0.0
    m_alpha = ca + sa * tp
    resist = np.where(loaded, (c * b + W * tp) / np.where(m_alpha > 1e-9, m_alpha, 1.0), 0.0).sum(axis=1)
    drive = (W * sa).sum(axis=1)
    arm = (W * (yc[:, None] - yg) / R[:, None]).sum(axis=1)
    bad = np.any(loaded & (m_alpha < m_alpha_min), axis=1) | (yc - R < ground.y_floor - 1e-9) | (arm <= 0.0) \
        | (W.sum(axis=1) <= 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        k = (resist - drive) / arm
    return np.where(bad, np.inf, k)


def circle_factor_of_safety(ground, xc, yc, R, k=0.0, n=60, iterations=60):
    """Bishop's simplified FS of each circle under k (fixed-point iteration on m_alpha)."""
    b, W, sa, ca, yg, c, tp, yb = _slices(ground, xc, yc, R, n)
    loaded = W > 0.0
    drive = (W * sa).sum(axis=1) + k * (W * (yc[:, None] - yg) / R[:, None]).sum(axis=1)
    F = np.ones_like(xc)
    for _ in range(iterations):
        m_alpha = np.maximum(ca + sa * tp / F[:, None], 1e-6)
        with np.errstate(divide="ignore", invalid="ignore"):
            F = np.where(loaded, (c * b + W * tp) / m_alpha, 0.0).sum(axis=1) / drive
    return F


def _grid(xlim, ylim, rlim, n):
    xc, yc, R = np.meshgrid(np.linspace(*xlim, n), np.linspace(*ylim, n), np.linspace(*rlim, n), indexing="ij")
    return xc.ravel(), yc.ravel(), R.ravel()


def critical_circle(ground, xlim, ylim, rlim, n=24, levels=4, slices=60, k=None):
    """The critical circle (xc, yc, R, value) from a grid search over centres xlim x ylim and radii rlim,
    refined `levels` times around the best circle (each level a grid a quarter as wide). k None: the least
    yield coefficient k_c (circle_yield_coefficients); k a number: the least factor of safety under k."""
    def score(xc, yc, R):
        if k is None:
            return circle_yield_coefficients(ground, xc, yc, R, slices)
        fs = circle_factor_of_safety(ground, xc, yc, R, k, slices)
        valid = np.isfinite(circle_yield_coefficients(ground, xc, yc, R, slices))
        return np.where(valid & (fs > 0.0), fs, np.inf)

    best = None
    for level in range(levels + 1):
        xc, yc, R = _grid(xlim, ylim, rlim, n)
        value = score(xc, yc, R)
        i = int(np.argmin(value))
        if not np.isfinite(value[i]):
            raise ValueError("no circle of the search cuts a sliding mass")
        if best is None or value[i] < best[3]:
            best = (float(xc[i]), float(yc[i]), float(R[i]), float(value[i]))
        widths = [(lim[1] - lim[0]) / 4.0 for lim in (xlim, ylim, rlim)]
        xlim = (best[0] - widths[0] / 2, best[0] + widths[0] / 2)
        ylim = (best[1] - widths[1] / 2, best[1] + widths[1] / 2)
        rlim = (max(best[2] - widths[2] / 2, 1e-3), best[2] + widths[2] / 2)
    return best


def inside_circle(x, y, circle):
    """Points (x, y) inside the circle (xc, yc, R, ...): the sliding mass when they are in the ground."""
    return np.hypot(np.asarray(x) - circle[0], np.asarray(y) - circle[1]) < circle[2]
