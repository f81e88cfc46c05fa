#!/usr/bin/env python3
"""Look at the issue-16 rebound reference data: Legendre et al. (2006) fit of e/e_dry against St and
rough restitution estimates derived here from the two Gondret et al. (2002) trajectories.

Not a test: the derived estimates are weak (see SOURCE.md). Writes rebound_reference.png next to this file.
Run: /usr/bin/python3 check_rebound_reference.py
"""
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
BETA = 35.0          # Legendre et al. (2006): e/e_dry = exp(-beta / St)
E_DRY = 0.97         # steel on glass, as used by Biegert et al. (2017) Table 1 for these two cases
CM = 0.5             # added-mass coefficient in Legendre's modified Stokes number
# Gondret pairs (Biegert et al. 2017, Table 1): nominal St, impact speed [m/s], rho_p/rho_f
PAIRS = {"st27": (27.0, 0.518, 8.083), "st152": (152.0, 0.585, 8.342)}


def legendre(st):
    return np.exp(-BETA / np.asarray(st))


def load(name):
    return np.loadtxt(HERE / f"gondret2002_trajectory_{name}.csv", delimiter=",", comments="#",
                      skiprows=5, usecols=(0, 1))


def speeds_at(t, h, i, deg, n):
    """Slopes of polynomial fits to the n points before and after sample i (a contact), at t[i]."""
    before = np.polyfit(t[i - n:i], h[i - n:i], deg)
    after = np.polyfit(t[i + 1:i + 1 + n], h[i + 1:i + 1 + n], deg)
    return -np.polyval(np.polyder(before), t[i]), np.polyval(np.polyder(after), t[i])


def derived_points():
    """(St, St*, e/e_dry median, low, high, label) per bounce; spread over fit degree 1-2 and 3-4 points."""
    rows = []
    t, h = load("st152").T
    st0, u0, ratio = PAIRS["st152"]
    contacts = [i for i in range(1, len(h) - 1) if h[i] < h[i - 1] and h[i] <= h[i + 1]][:3]
    for k, i in enumerate(contacts):
        est = np.array([speeds_at(t, h, i, deg, n) for deg in (1, 2) for n in (3, 4)])
        uin = np.median(est[:, 0])
        e = est[:, 1] / est[:, 0]
        st = st0 * uin / u0 if k else st0
        rows.append((st, st * (1 + CM / ratio), np.median(e) / E_DRY, e.min() / E_DRY, e.max() / E_DRY,
                     f"St152 trajectory, bounce {k + 1}"))
    t, h = load("st27").T
    st0, u0, ratio = PAIRS["st27"]
    e = []
    for deg in (1, 2):
        for n in (3, 4, 5):
            p = np.polyfit(t[:n], h[:n], deg)
            e.append(np.polyval(np.polyder(p), 0.0) / u0)
    e = np.array(e)
    rows.append((st0, st0 * (1 + CM / ratio), np.median(e) / E_DRY, e.min() / E_DRY, e.max() / E_DRY,
                 "St27 trajectory, bounce 1"))
    return rows


def main():
    rows = derived_points()
    print("St      St*     e/e_dry (median, range)   Legendre(St)  Legendre(St*)  source")
    for st, sts, med, lo, hi, lab in rows:
        print(f"{st:6.1f}  {sts:6.1f}  {med:.2f} ({lo:.2f}-{hi:.2f})          {legendre(st):.3f}         "
              f"{legendre(sts):.3f}          {lab}")
    st = np.logspace(0, 3, 400)
    print("Legendre fit: e/e_dry = 0.01 at St = %.1f, 0.1 at %.1f, 0.5 at %.1f, 0.9 at %.0f, 0.97 at %.0f"
          % tuple(BETA / -math.log(v) for v in (0.01, 0.1, 0.5, 0.9, 0.97)))

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.5))
    ax.semilogx(st, legendre(st), "k-", label=r"Legendre et al. (2006): $e/e_{dry}=\exp(-35/St)$")
    for k, (s, sts, med, lo, hi, lab) in enumerate(rows):
        ax.errorbar([s], [med], yerr=[[med - lo], [hi - med]], fmt="o", capsize=3,
                    label=f"{lab} (derived here, weak)")
    ax.axvline(10, color="0.6", ls=":", lw=1)
    ax.text(10.5, 0.9, "St = 10", color="0.4")
    ax.set_xlim(1, 1000)
    ax.set_ylim(-0.02, 1.05)
    ax.set_xlabel(r"St = $\rho_p U d / (9 \mu)$")
    ax.set_ylabel(r"$e / e_{dry}$")
    ax.legend(fontsize=7, loc="upper left")
    ax.set_title("No digitised Gondret/Joseph e(St) points were found")
    for name, d in (("st27", 0.006), ("st152", 0.003)):
        t, h = load(name).T
        bx.plot(t / math.sqrt(d / 9.81), h / d, "o-", ms=3, label=f"Gondret et al. (2002), {name}")
    bx.set_xlabel(r"$t / \sqrt{d/g}$")
    bx.set_ylabel("gap / d")
    bx.legend(fontsize=8)
    bx.set_title("Rebound trajectories (PARTIES digitisation)")
    fig.tight_layout()
    out = HERE / "rebound_reference.png"
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
