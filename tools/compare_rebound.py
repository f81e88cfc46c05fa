#!/usr/bin/python3
"""Compare rebound runs with Gondret, Lance & Petit's (2002) measured trajectory.

    python3 tools/compare_rebound.py RUN_DIR [RUN_DIR ...] --case st152 [-o fig.png] [--label NAME ...]

For each run (cases/validation/gondret_rebound_st152, ..._st27) and for the digitised data
(cases/validation/rebound_stokes/), measured the same way (python/fddem/rebound.py): the first
contact t_c, the impact velocity v_in and rebound velocity v_out (slopes of fits to the
trajectory at 0.02 d ≤ gap ≤ 1 d: v_in at t_c, v_out at the separation, when the gap opens
again; the rebound's slope at t_c is printed as well), e_eff = −v_out/v_in, the peaks of the rebounds (gap/d and
t − t_c) and the mean deceleration of the rise from the separation to the first peak; for a run also |w| at the touch and at the separation and their ratio (the contact
model with the lubrication correction alone), the impulses of the contact, lubrication and
resolved forces over that contact and the lubrication's work there, the largest overlap, and the RMS of gap/d at the
data's times. With -o, gap/d against t − t_c of every run over the data.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from fddem import rebound  # noqa: E402
from fddem.figures import comparison_parser, run_labels  # noqa: E402


def _number(x, fmt):
    return "n/a" if x is None else format(x, fmt)


def describe(name, r):
    peaks = ", ".join(f"{g:.3f} at {t * 1e3:.1f} ms" for t, g in r["peaks"]) or "none"
    print(f"  {name:9s} v_in {_number(r['v_in'], '.4f')} m/s, v_out {_number(r['v_out'], '.4f')} m/s "
          f"(at t_c {_number(r.get('v_out_at_touch'), '.4f')}), "
          f"e_eff {_number(r['e_eff'], '.3f')}; peaks (gap/d at t − t_c): {peaks}; "
          f"rise deceleration {_number(r.get('rise_deceleration'), '.2f')} m/s²")


def main():
    parser = comparison_parser(__doc__.splitlines()[0])
    parser.add_argument("--case", choices=sorted(rebound.CASES), required=True)
    args = parser.parse_args()
    labels = run_labels(parser, args)
    spec = rebound.CASES[args.case]
    print(f"{args.case}: d = {spec['diameter']} m, published impact {spec['impact']} m/s, "
          f"St {spec['stokes']:g}, published peaks gap/d {spec['peaks']}")
    for n, (run, label) in enumerate(zip(args.runs, labels)):
        try:
            c = rebound.compare(run, args.case)
        except (OSError, KeyError, ValueError) as error:
            sys.exit(f"compare_rebound: {run}: {error}")
        if n == 0:
            describe("data", c["reference"])
        r = c["run"]
        print(f"{label}: first contact at t = {r['t_contact']:.5f} s; |w| at the touch "
              f"{r['touch']:.4f} m/s, w at the separation {_number(r['separation'], '.4f')} m/s "
              f"(ratio {_number(r['e_contact'], '.3f')}); largest overlap {r['overlap']:.4f} d; "
              f"RMS of gap/d at {c['points']} data times {_number(c['rms'], '.3f')}")
        describe("fddem", r)
        i = r["impulses"]
        if i is not None:
            print(f"  first contact, {i['duration'] * 1e3:.2f} ms: impulses [N s] contact "
                  f"{i['contact_fz']:.3e}, lubrication {i['lubrication_fz']:.3e}, resolved fluid "
                  f"{i['fz']:.3e}, buoyant weight {i['weight']:.3e}; m Δw {i['momentum_change']:.3e}; "
                  f"lubrication work {i['lubrication_work']:.3e} J against {i['kinetic_energy']:.3e} J "
                  f"kinetic energy at the touch")
    if args.output:
        from fddem.figures import save_one_panel

        print(save_one_panel(args.output, lambda axes: rebound.plot(axes, args.runs, args.case, labels),
                             f"Sphere bouncing on a wall in a liquid, St {spec['stokes']:g}"))


if __name__ == "__main__":
    main()
