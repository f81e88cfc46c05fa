#!/usr/bin/env python3
"""Sphere approaching a plane wall / a plane free (shear-free) surface in Stokes flow.

F = kappa * 6 pi mu r U; delta = gap from the sphere surface to the plane; h = r + delta;
alpha = arccosh(h / r). Bispherical-coordinate series of Brenner (1961), Chem. Eng. Sci. 16, 242
(rigid wall: the form checked in ../../../../shared/reference/sphere_wall.md; free surface: see
two_spheres_free_surface.md). The free-surface case equals two equal spheres approaching head-on
with speeds U and -U (the mid-plane is shear-free with zero normal velocity), delta = half the gap.

Run: /usr/bin/python3 free_surface_series.py   (prints the table and the limit checks; exits 1 on failure)

The same two series in double precision, as fddem's comparisons use them, are
python/fddem/sphere_wall.py (brenner_kappa, free_plane_kappa; written with e^{-x} so that no
sinh overflows): the last check holds them to these 40-digit sums.
"""
import os
import sys

from mpmath import acosh, cosh, log, mp, mpf, sinh

mp.dps = 40


def kappa(delta_over_r, plane):
    """Series summed until a term is below 1e-30 of the sum. plane: 'wall' or 'free'."""
    a = acosh(1 + mpf(delta_over_r))
    total, n = mpf(0), 1
    while True:
        k = 2 * n + 1
        if plane == "wall":
            ratio = (2 * sinh(k * a) + k * sinh(2 * a)) / (
                4 * sinh((n + mpf(1) / 2) * a) ** 2 - k**2 * sinh(a) ** 2)
        else:
            ratio = (4 * cosh((n + mpf(1) / 2) * a) ** 2 + k**2 * sinh(a) ** 2) / (
                2 * sinh(k * a) - k * sinh(2 * a))
        term = mpf(n * (n + 1)) / ((2 * n - 1) * (2 * n + 3)) * (ratio - 1)
        total += term
        if n > 5 and abs(term) < mpf(10) ** -30 * abs(total):
            return mpf(4) / 3 * sinh(a) * total, n
        n += 1


def main():
    ok = True
    print("delta/r  kappa_free      kappa_wall      r/(4 delta)   free/(r/4delta)  terms")
    for d in [2, 1, 0.5, 0.2, 0.1, 0.05, 0.02]:
        kf, n = kappa(d, "free")
        kw, _ = kappa(d, "wall")
        print(f"{d:<7g}  {float(kf):<14.6f}  {float(kw):<14.6f}  {0.25 / d:<12.4f}  {float(kf) * 4 * d:<15.4f}  {n}")
    # near field: kappa - r/(4 delta) - (9/20) ln(r/(2 delta)) -> constant
    c = [float(kappa(d, "free")[0] - mpf(1) / (4 * mpf(d)) - mpf(9) / 20 * log(1 / (2 * mpf(d))))
         for d in (1e-3, 1e-4, 1e-5)]
    print("near-field remainder kappa - r/(4d) - (9/20) ln(r/(2d)) at d/r = 1e-3, 1e-4, 1e-5:", c)
    ok &= abs(c[2] - c[1]) < 1e-3 and abs(c[1] - c[0]) < 2e-3
    # far field: reflections give kappa = 1/(1 - (3/4) x) + O(x^3)? check 1 + 3/4 x + 9/16 x^2
    for d in (99.0, 999.0):
        x = 1 / (1 + d)
        kf = float(kappa(d, "free")[0])
        ref = 1 + 0.75 * x + 9 / 16 * x**2
        print(f"far field d/r={d:g}: kappa-1 = {kf - 1:.6e}, (3/4)x + (9/16)x^2 = {ref - 1:.6e}")
        ok &= abs(kf - ref) < 2 * x**3
    # rigid wall against the tabulated values of ../shared/reference/sphere_wall.md
    for d, k in [(0.4, 3.73562), (0.1, 11.4592), (0.01, 101.896)]:
        ok &= abs(float(kappa(d, "wall")[0]) - k) < 6e-5 * k
    # the package's double-precision sums against these
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "python"))
    from fddem.sphere_wall import brenner_kappa, free_plane_kappa

    worst = max(abs(summed(d) / float(kappa(d, plane)[0]) - 1)
                for d in (2, 1, 0.5, 0.2, 0.1, 0.05, 0.02)
                for plane, summed in (("free", free_plane_kappa), ("wall", brenner_kappa)))
    print(f"python/fddem/sphere_wall.py against these sums: largest relative difference "
          f"{worst:.1e}")
    ok &= worst < 1e-12
    print("checks", "passed" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
