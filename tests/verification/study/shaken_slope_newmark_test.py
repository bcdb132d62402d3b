#!/usr/bin/python3
"""Verification of the shaken-slope study's two analytical tools (scripts/shaken_slope/):

1. sliding_block.newmark_sliding (Newmark 1965 rigid sliding block, one-directional) against closed forms:
   - a rectangular pulse A on 0 < t < T, yield a_y < A: d = A (A - a_y) T^2 / (2 a_y) (Newmark 1965, the
     rectangular-pulse result u = V^2 / (2 g N) (1 - N / A), V = A g T; Kramer 1996 section 10.6.2);
     the record holds the jumps (repeated times), so the integrator must be exact to round-off;
   - a pulse with A <= a_y: no sliding;
   - a half-sine pulse A sin(pi t / T) (piecewise linear on a fine sampling): the closed form of the same
     equations integrated by hand (sliding from t1 = T asin(a_y / A) / pi, relative acceleration
     A sin(pi t / T) - a_y until the velocity returns to zero), within 1e-5;
   - two pulses: the block stops between them and the displacements add.
2. pseudo_static (Kramer 1996 section 10.6.1, the infinite slope; Bishop's simplified method):
   - the closed-form k_y of a dry infinite slope, k_y = (tan phi cos b - sin b) / (cos b + tan phi sin b)
     (c = 0), equals tan(phi - b) and the root of its FS(k) = 1 (bisection), also with c > 0;
   - the circle search on a long planar slope of c = 0 sand finds the shallow slip whose k_y is the infinite
     slope's (within 0.5 %: the critical "circle" flattens onto the face), and the static FS tan phi / tan b.
"""
import math
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "scripts", "shaken_slope"))
import pseudo_static  # noqa: E402
import sliding_block  # noqa: E402


def half_sine_displacement(A, T, ay):
    """Closed form of the one-directional block under A sin(pi t / T) on (0, T), then 0 (by hand from
    dv/dt = A sin(w t) - a_y, w = pi / T): slides from t1 (A sin(w t1) = a_y) until v = 0."""
    w = math.pi / T
    t1 = math.asin(ay / A) / w

    def v(t):   # relative velocity while sliding, t1 <= t
        if t <= T:
            return A / w * (math.cos(w * t1) - math.cos(w * t)) - ay * (t - t1)
        return v(T) - ay * (t - T)

    def d(t):
        if t <= T:
            return A / w * (math.cos(w * t1) * (t - t1) - (math.sin(w * t) - math.sin(w * t1)) / w) - ay * (t - t1) ** 2 / 2
        return d(T) + v(T) * (t - T) - ay * (t - T) ** 2 / 2

    if v(T) > 0:
        ts = T + v(T) / ay
    else:   # stops inside the pulse: bisection on v between the peak and T
        lo, hi = T / 2, T
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if v(mid) > 0 else (lo, mid)
        ts = lo
    return d(ts)


class NewmarkSlidingBlock(unittest.TestCase):
    def test_rectangular_pulse_is_exact(self):
        for A, T, ay in ((3.0, 0.5, 1.0), (0.4 * 9.81, 0.2, 0.15 * 9.81), (2.0, 1.0, 1.999)):
            t = np.array([0.0, 0.0, T, T, T + 100.0])
            a = np.array([0.0, A, A, 0.0, 0.0])
            d = sliding_block.newmark_displacement(t, a, ay)
            exact = sliding_block.rectangular_pulse_displacement(A, T, ay)
            self.assertAlmostEqual(exact, A * (A - ay) * T * T / (2 * ay), places=14)
            self.assertLess(abs(d - exact), 1e-12 * exact, (A, T, ay, d, exact))
            v, dd = sliding_block.newmark_sliding(t, a, ay)
            self.assertEqual(v[-1], 0.0)   # at rest at the end, and never sliding back
            self.assertTrue(np.all(np.diff(dd) >= 0.0))

    def test_no_sliding_below_the_yield_acceleration(self):
        t = np.linspace(0.0, 2.0, 201)
        self.assertEqual(sliding_block.newmark_displacement(t, 0.99 * np.sin(3 * t), 1.0), 0.0)

    def test_half_sine_pulse_against_closed_form(self):
        for A, T, ay in ((3.0, 0.5, 1.0), (5.0, 0.3, 4.0)):
            t = np.linspace(0.0, T + 5.0, 200001)
            a = np.where(t < T, A * np.sin(math.pi * t / T), 0.0)
            d = sliding_block.newmark_displacement(t, a, ay)
            exact = half_sine_displacement(A, T, ay)
            self.assertLess(abs(d - exact), 1e-5 * exact, (A, T, ay, d, exact))

    def test_two_pulses_add(self):
        A, T, ay = 3.0, 0.5, 1.0
        t = np.array([0.0, 0.0, T, T, 10.0, 10.0, 10.0 + T, 10.0 + T, 20.0])
        a = np.array([0.0, A, A, 0.0, 0.0, A, A, 0.0, 0.0])
        self.assertAlmostEqual(sliding_block.newmark_displacement(t, a, ay),
                               2 * sliding_block.rectangular_pulse_displacement(A, T, ay), places=12)

    def test_bad_input(self):
        with self.assertRaises(ValueError):
            sliding_block.newmark_sliding([0.0, 1.0], [1.0, 2.0], 0.0)
        with self.assertRaises(ValueError):
            sliding_block.newmark_sliding([1.0, 0.0], [1.0, 2.0], 1.0)


class PseudoStatic(unittest.TestCase):
    def test_infinite_slope_closed_form(self):
        for beta, phi in ((20.0, 30.0), (30.0, 35.0), (33.7, 40.0)):
            b, tp = math.radians(beta), math.tan(math.radians(phi))
            closed = (tp * math.cos(b) - math.sin(b)) / (math.cos(b) + tp * math.sin(b))
            self.assertAlmostEqual(pseudo_static.infinite_slope_yield_coefficient(beta, phi), closed, places=14)
            self.assertAlmostEqual(closed, math.tan(math.radians(phi - beta)), places=14)
            root = pseudo_static.yield_coefficient_by_bisection(
                lambda k: pseudo_static.infinite_slope_factor_of_safety(beta, phi, 0.0, 19.0, 3.0, k))
            self.assertAlmostEqual(root, closed, places=8)
        # with cohesion: the root of FS(k) = 1 against the closed form
        ky = pseudo_static.infinite_slope_yield_coefficient(30.0, 30.0, c=5.0, gamma=19.0, z=2.0)
        root = pseudo_static.yield_coefficient_by_bisection(
            lambda k: pseudo_static.infinite_slope_factor_of_safety(30.0, 30.0, 5.0, 19.0, 2.0, k))
        self.assertAlmostEqual(root, ky, places=8)
        self.assertAlmostEqual(pseudo_static.infinite_slope_factor_of_safety(30.0, 30.0, 5.0, 19.0, 2.0, ky), 1.0, places=12)

    def test_circle_search_on_a_long_cohesionless_slope(self):
        beta, phi, length = 30.0, 35.0, 200.0
        height = length * math.tan(math.radians(beta))
        ground = pseudo_static.Ground([(-50.0, height), (0.0, height), (length, 0.0), (length + 50.0, 0.0)],
                                      [(-1e9, 0.0, phi)], 20.0, y_floor=-1e9)
        window = ((20.0, 180.0), (0.2 * height + 50.0, height + 200.0), (5.0, 400.0))
        ky = pseudo_static.critical_circle(ground, *window, n=20, levels=5)[3]
        closed = pseudo_static.infinite_slope_yield_coefficient(beta, phi)
        self.assertLess(abs(ky - closed), 5e-3 * closed, (ky, closed))
        fs = pseudo_static.critical_circle(ground, *window, n=14, levels=4, k=0.0)[3]
        fs_closed = math.tan(math.radians(phi)) / math.tan(math.radians(beta))
        self.assertLess(abs(fs - fs_closed), 5e-3 * fs_closed, (fs, fs_closed))


if __name__ == "__main__":
    unittest.main()
