"""Newmark (1965) rigid sliding-block displacement, one-directional (downslope only).

A rigid block on a plane of yield acceleration a_y = k_y g (the horizontal acceleration at which the
pseudo-static factor of safety is 1, pseudo_static.py) slides relative to its base while the driving
acceleration a(t) (the base acceleration in the downslope direction's opposite, i.e. the inertial push
downslope) exceeds a_y, and keeps sliding until the relative velocity returns to zero:

    d(v_rel)/dt = a(t) - a_y   while sliding (v_rel > 0, or a(t) > a_y),  v_rel >= 0
    d(d_rel)/dt = v_rel

(Newmark 1965, "Effects of earthquakes on dams and embankments", Geotechnique 15(2), 139-160; Kramer 1996,
"Geotechnical Earthquake Engineering", Prentice Hall, section 10.6.2, the sliding-block analysis.) The record
is taken as piecewise linear between its samples and every step is integrated exactly (v_rel is quadratic
and d_rel cubic in a step; the instants where sliding starts and stops are found inside the step), so the
only error is the sampling of the record itself. A record may repeat a time to hold a jump (a rectangular
pulse).
"""
import math

import numpy as np

G = 9.81


def rectangular_pulse_displacement(amplitude, duration, a_yield):
    """Closed form for a rectangular pulse a(t) = A on 0 < t < T, a_y < A (Newmark 1965, eq. for the
    rectangular pulse: u = V^2 / (2 g N) (1 - N / A) with V = A g T, N and A in g; Kramer 1996 10.6.2):
    d = A (A - a_y) T^2 / (2 a_y) in the units of amplitude * time^2."""
    if amplitude <= a_yield:
        return 0.0
    return amplitude * (amplitude - a_yield) * duration ** 2 / (2.0 * a_yield)


def _first_stop(c2, c1, c0, span):
    """Smallest u in (0, span] where c2 u^2 + c1 u + c0 (the relative velocity, c0 >= 0) returns to zero
    while decreasing, or None."""
    if c2 == 0.0:
        roots = [-c0 / c1] if c1 < 0.0 else []
    else:
        disc = c1 * c1 - 4.0 * c2 * c0
        if disc < 0.0:
            return None
        q = -0.5 * (c1 + math.copysign(math.sqrt(disc), c1))
        roots = [q / c2] + ([c0 / q] if q != 0.0 else [])
    roots = sorted(u for u in roots if 0.0 < u <= span and 2.0 * c2 * u + c1 <= 0.0)
    return roots[0] if roots else None


def newmark_sliding(t, a, a_yield):
    """Relative velocity and displacement (arrays like t) of the sliding block under the driving
    acceleration a (same units as a_yield, e.g. m/s^2), one-directional. t must not decrease."""
    t = np.asarray(t, dtype=float)
    a = np.asarray(a, dtype=float)
    if t.shape != a.shape or t.ndim != 1:
        raise ValueError("t and a must be 1D arrays of the same length")
    if np.any(np.diff(t) < 0.0):
        raise ValueError("times must not decrease")
    if not a_yield > 0.0:
        raise ValueError("the yield acceleration must be > 0, got %r" % a_yield)
    v = np.zeros_like(t)
    d = np.zeros_like(t)
    vk, dk = 0.0, 0.0
    for k in range(len(t) - 1):
        h = t[k + 1] - t[k]
        r0 = a[k] - a_yield               # relative acceleration r(s) = r0 + m s on the step, 0 <= s <= h
        m = (a[k + 1] - a[k]) / h if h > 0.0 else 0.0
        s = 0.0
        while h > 0.0 and s < h:
            if vk == 0.0:                 # at rest: sliding starts where r turns positive
                if r0 + m * s <= 0.0:
                    if m > 0.0 and r0 + m * h > 0.0:
                        s = -r0 / m
                    else:
                        break
            rs = r0 + m * s
            span = h - s
            u = _first_stop(0.5 * m, rs, vk, span)
            step = span if u is None else u
            dk += vk * step + rs * step ** 2 / 2.0 + m * step ** 3 / 6.0
            vk = 0.0 if u is not None else max(vk + rs * step + 0.5 * m * step ** 2, 0.0)
            s += step
        v[k + 1] = vk
        d[k + 1] = dk
    return v, d


def newmark_displacement(t, a, a_yield):
    """Permanent (final) sliding displacement of newmark_sliding."""
    return float(newmark_sliding(t, a, a_yield)[1][-1])
