"""`fddem plot RUN_DIR [-o OUT] [--movie] [--svg] [--times T …]` (the fddem program runs
`python3 -m fddem plot …`): the figures that fit the run, and with --movie an MP4.

Exit statuses as the fddem program's: 0 done, 1 internal error, 2 bad input (not a run
directory, a missing dependency), with one line on stderr naming what is wrong.
"""

import argparse
import os
import shutil
import sys
import time

from . import io

EXIT_BAD_INPUT = 2
PARAVIEW_SCRIPT = "open_in_paraview.py"


def fail(message):
    print(f"fddem plot: {message}", file=sys.stderr)
    return EXIT_BAD_INPUT


def parser():
    p = argparse.ArgumentParser(
        prog="fddem plot",
        description="Write the figures that fit a run (PNG; SVG too with --svg) into OUT, "
                    "and with --movie an MP4 of the flow and the bodies.")
    p.add_argument("run", metavar="RUN_DIR", help="a run directory (fddem run … -o RUN_DIR)")
    p.add_argument("-o", "--output", metavar="OUT", help="figure directory (default RUN_DIR/plots)")
    p.add_argument("--movie", action="store_true", help="also write OUT/movie.mp4 (needs ffmpeg)")
    p.add_argument("--fps", type=int, help="movie frames per second (default: about 8 s long)")
    p.add_argument("--svg", action="store_true", help="also write each figure as SVG")
    p.add_argument("--dpi", type=int, help="PNG resolution (default 130)")
    p.add_argument("--times", type=float, nargs="+", metavar="T",
                   help="times of the flow snapshots (default: up to six spread over the run)")
    p.add_argument("--only", nargs="+", metavar="NAME",
                   help="only these figures (overview, solver, snapshots, …)")
    p.add_argument("-q", "--quiet", action="store_true", help="no list of files, no progress bar")
    return p


def install_paraview_script(run_dir):
    """Give a run written before fddem wrote the ParaView script one (never overwrites)."""
    target = os.path.join(run_dir, PARAVIEW_SCRIPT)
    if not os.path.exists(target) and os.access(run_dir, os.W_OK):
        shutil.copyfile(os.path.join(os.path.dirname(__file__), "paraview_state.py"), target)


def plot_command(argv):
    options = parser().parse_args(argv)
    try:
        io.check_run_directory(options.run)
    except io.NotARunError as e:
        return fail(str(e))
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return fail("needs matplotlib (Debian package python3-matplotlib; tools/install-deps.sh)")
    from . import figures, movie
    from .run import Run

    start = time.monotonic()
    run = Run(options.run)
    out = options.output or os.path.join(options.run, "plots")
    formats = ("png", "svg") if options.svg else ("png",)
    report = (lambda path: None) if options.quiet else (lambda path: print(path))
    written = figures.plot_run(run, out, formats, options.times, options.only, report,
                               options.dpi)
    if options.movie:
        path = os.path.join(out, "movie.mp4")
        try:
            frames = movie.write_movie(run, path, options.fps, progress=not options.quiet)
        except RuntimeError as e:
            return fail(str(e))
        report(path)
        written.append(path)
        if not options.quiet:
            print(f"movie: {frames} frames", file=sys.stderr)
    install_paraview_script(options.run)
    if not options.quiet:
        files = f"{len(written)} file" + ("" if len(written) == 1 else "s")
        print(f"fddem plot: {files} in {out} ({time.monotonic() - start:.1f} s)", file=sys.stderr)
    return 0


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] != "plot":
        print("usage: python3 -m fddem plot RUN_DIR [-o OUT] [--movie] [--svg] [--times T …]",
              file=sys.stderr)
        return EXIT_BAD_INPUT
    try:
        return plot_command(argv[1:])
    except SystemExit as e:  # argparse: --help (0) or a bad option (2)
        return e.code if isinstance(e.code, int) else EXIT_BAD_INPUT
    except KeyboardInterrupt:
        return 130
