#!/usr/bin/python3
"""Effective restitution against the Stokes number: fddem's rebound runs against Legendre et al.

    python3 tools/compare_rebound_stokes.py RUN_DIR [RUN_DIR ...] [-o fig.png]

Each RUN_DIR is a rebound run (cases/validation/gondret_rebound_st152 or _st27, possibly with
fluid.viscosity changed). For each run: the impact speed v_in and the
rebound speed v_out, measured from the trajectory as on Gondret's data (python/fddem/rebound.py:
slopes of fits to 0.02 d ≤ gap ≤ 1 d at the first contact and, for v_out, at the separation,
where the experiments' microsecond contact has t_s = t_c), e_eff = −v_out/v_in, the contact's
own ratio of speeds (touch to separation), and St = ρp v_in d / (9 μ) with the run's ρp, d and
μ. Printed as a table; with -o, e_eff/e_dry against St over the fit of Legendre, Zenit, Daniel &
Guiraud (2006), e/e_dry = exp(−35/St) (cases/validation/rebound_stokes/legendre2006_fit.md), and
Gondret et al.'s (2002) two trajectories measured the same way (St 27 and 152 at their
published impact speeds; the St 27 file starts at the contact, so there v_out over the published
impact speed).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from fddem import rebound  # noqa: E402
from fddem.figures import pyplot  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+", help="rebound run directories")
    parser.add_argument("-o", "--output", help="write the figure (PNG)")
    args = parser.parse_args()
    rows = []
    print(f"{'run':40s} {'St':>7s} {'v_in':>7s} {'v_out':>7s} {'e_eff':>6s} {'e/e_dry':>7s} "
          f"{'exp(-35/St)':>11s} {'contact':>7s}")
    for run in args.runs:
        try:
            r = rebound.restitution(run)
        except (OSError, KeyError, ValueError) as error:
            sys.exit(f"compare_rebound_stokes: {run}: {error}")
        fit = rebound.legendre_fit(r["stokes"])

        def number(x, fmt):
            return "n/a" if x is None else format(x, fmt)

        print(f"{os.path.basename(os.path.normpath(run)):40s} {r['stokes']:7.1f} "
              f"{number(r['v_in'], '7.4f')} {number(r['v_out'], '7.4f')} "
              f"{number(r['e_eff'], '6.3f')} {number(r['ratio'], '7.3f')} {fit:11.3f} "
              f"{number(r['e_contact'], '7.3f')}")
        rows.append(r)
    if not args.output:
        return
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    rebound.plot_restitution(ax, rows, film_run=args.runs[0] if args.runs else None)
    for r, run in zip(rows, args.runs):
        ax.annotate(os.path.basename(os.path.normpath(run)), (r["stokes"], r["ratio"]),
                    textcoords="offset points", xytext=(5, -12), fontsize=7)
    # Below the axes: inside, it covers points wherever the curves and the runs lie.
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.18), ncol=2, fontsize=8)
    ax.set_title("Sphere–wall rebound in a viscous fluid: effective restitution against St")
    fig.tight_layout()
    fig.savefig(args.output, dpi=120, bbox_inches="tight")
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
