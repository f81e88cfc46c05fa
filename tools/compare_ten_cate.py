#!/usr/bin/python3
"""Compare a ten Cate et al. (2002) run with the experiment (Table 2 and the digitised Fig. 5).

    python3 tools/compare_ten_cate.py RUN_DIR --case E4 [-o ten_cate_e4.png] [RUN_DIR2 ...]

Prints u_max against Table 2, the RMS velocity deviation (relative to u_max) while the gap
exceeds 1 d and the RMS deviation of the distance travelled (in d) while it exceeds 0.1 d; then the
gaps at which the sphere has slowed to 0.9, 0.7 and 0.5 of its largest speed, the run's against the
experiment's (Fig. 5b's w at the gap of Fig. 5a, and at the gap Fig. 5b's own integral gives from
the nominal 8 d: the two bracket it), and how far the digitised figures and Table 2 agree with each
other; with -o, plots w(t) and gap/d(t) of every run given against the digitised curves.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from fddem import ten_cate  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--case", required=True, choices=sorted(ten_cate.CASES))
    parser.add_argument("-o", "--output")
    args = parser.parse_args()
    directory = ten_cate.reference_directory()
    if directory is None:
        sys.exit("compare_ten_cate: the digitised curves are not on this machine "
                 "(../shared/reference/digitized/ten_cate_2002 or $FDDEM_TEN_CATE_REFERENCE)")
    print(f"{'run':40s} {'u_max [m/s]':>12s} {'vs Table 2':>11s} {'RMS w/u_max':>12s} "
          f"{'RMS travel/d':>13s} {'until t [s]':>11s}")
    for run in args.runs:
        r = ten_cate.compare(run, directory, args.case)
        print(f"{run:40s} {r['u_max']:12.5f} {100 * r['u_max_error']:+10.2f}% "
              f"{100 * r['w_rms']:11.2f}% {r['travel_rms']:13.3f} {r['compared_until']:11.3f}")
    print(f"\n{'gap/d where |w| has fallen to':40s} {'0.9 u_max':>10s} {'0.7 u_max':>10s} {'0.5 u_max':>10s}")
    for run in args.runs:
        gaps = ten_cate.compare(run, directory, args.case)["deceleration_gaps"]
        print(f"{run:40s} " + " ".join(f"{g:10.3f}" for g in gaps))
    for source, label in (("5a", "ten Cate et al. (Fig. 5b at Fig. 5a gap)"),
                          ("5b", "ten Cate et al. (Fig. 5b, its own gap)")):
        gaps = ten_cate.reference_deceleration_gaps(directory, args.case, gap_from=source)
        print(f"{label:40s} " + " ".join(f"{g:10.3f}" for g in gaps))
    above = ten_cate.reference_points_above_release_bound(directory, args.case)
    bound = ten_cate.release_acceleration_bound(args.case)
    if len(above):
        print(f"\nFig. 5b points faster than any sphere released from rest at t = 0 (|w| > {bound:.4f} m/s² · t): "
              + ", ".join(f"{-w:.4f} m/s at {t:.3f} s" for t, w in above))
        for run in args.runs:
            r = ten_cate.compare(run, directory, args.case)
            print(f"{run:40s} RMS w/u_max without them {100 * r['w_rms_within_bound']:.2f}% "
                  f"({r['points_above_bound']} left out)")
    c = ten_cate.reference_consistency(directory, args.case)
    print(f"\nthe reference against itself: Fig. 5b peak {c['peak_w']:.5f} m/s ({100 * c['peak_w_error']:+.1f} % "
          f"of Table 2), Fig. 5a plateau speed {c['gap_speed']:.5f} m/s ({100 * c['gap_speed_error']:+.1f} %), "
          f"5a and ∫5b dt differ by up to {c['travel_mismatch']:.2f} d of travel while gap > 1 d")
    if args.output:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (aw, ag) = plt.subplots(1, 2, figsize=(10, 4))
        for run in args.runs:
            ten_cate.plot(run, directory, args.case, aw, ag, label=f"fddem {os.path.basename(run.rstrip('/'))}")
        aw.legend()
        fig.suptitle(f"ten Cate et al. (2002) {args.case}")
        fig.tight_layout()
        fig.savefig(args.output, dpi=120)
        print(args.output)


if __name__ == "__main__":
    main()
