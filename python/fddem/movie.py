"""An MP4 of a run: the flow speed on the display plane (2D: the flow; 3D: the vertical
mid-plane) at every field frame, the bodies cut by that plane, and the paths the bodies have
taken so far. matplotlib draws, Debian's ffmpeg encodes (H.264, yuv420p: plays everywhere).
"""

import shutil
import sys
import time as clock

import numpy as np

from . import figures, plots, slices


class ProgressBar:
    """`[#####-----]  12/40 frames  3.1 s` on a terminal (redrawn in place); on a pipe, a line
    at every tenth of the way."""

    def __init__(self, total, stream=sys.stderr, width=30):
        self.total, self.stream, self.width = total, stream, width
        self.is_terminal = stream.isatty()
        self.start = clock.monotonic()
        self.last_tenth = -1

    def update(self, done):
        elapsed = clock.monotonic() - self.start
        filled = int(self.width * done / max(self.total, 1))
        text = (f"movie [{'#' * filled}{'-' * (self.width - filled)}] {done:>4}/{self.total} "
                f"frames  {elapsed:5.1f} s")
        if self.is_terminal:
            self.stream.write("\r" + text + ("\n" if done == self.total else ""))
            self.stream.flush()
        elif 10 * done // max(self.total, 1) > self.last_tenth:
            self.last_tenth = 10 * done // max(self.total, 1)
            self.stream.write(text + "\n")


def write_movie(run, path, fps=None, dpi=140, progress=True):
    """Render the run's field frames to `path` (MP4). Returns the number of frames."""
    if shutil.which("ffmpeg") is None:
        raise RuntimeError("--movie needs ffmpeg (Debian package ffmpeg; tools/install-deps.sh)")
    n_frames = len(run.frame_times)
    if n_frames == 0:
        raise RuntimeError(f"{run.path}: no field frames to animate (fields.pvd is empty)")
    plt = figures.pyplot()
    from matplotlib.animation import FFMpegWriter

    normal = figures.display_normal(run)
    planes = [figures.plane_at_frame(run, k, normal) for k in range(n_frames)]
    # One colour scale for the whole movie, from the frames' 99.5th percentiles: a brief spike
    # (a collision squeezing the fluid out of a gap) must not darken every other frame.
    vmax = max(float(np.percentile(p["speed"], 99.5)) for p, _, _ in planes) or 1.0
    histories = run.body_histories()
    colours = plots.body_colours(sorted(histories))
    a, b = planes[0][0]["axes"]
    names = "xyz"

    width, height = figures._panel_size(run, 5.0)
    # H.264 in yuv420p needs even pixel counts.
    pixels = [2 * round(inches * dpi / 2) for inches in (width + 1.6, height + 0.7)]
    fig, ax = plt.subplots(figsize=(pixels[0] / dpi, pixels[1] / dpi), dpi=dpi)
    plane, cuts, time = planes[0]
    image = plots.flow_field(ax, plane, run.units, (), vmax=vmax, streamlines=False)
    fig.colorbar(image, ax=ax, shrink=0.85, extend="max",
                 label=run.units.label("|u|", "velocity"))
    trails = {body: ax.plot([], [], color=colours[body], lw=0.6, alpha=0.7)[0]
              for body in histories}
    title = ax.set_title(run.title + "\n", fontsize=9)
    fig.tight_layout()
    patches = []
    fps = fps or int(np.clip(round(n_frames / 8.0), 4, 25))  # about 8 s, 4-25 frames/s
    writer = FFMpegWriter(fps=fps, codec="libx264", extra_args=["-pix_fmt", "yuv420p"],
                          metadata={"title": run.title, "comment": "fddem plot --movie"})
    bar = ProgressBar(n_frames) if progress else None
    with writer.saving(fig, path, dpi):
        for k, (plane, cuts, time) in enumerate(planes):
            image.set_data(plane["speed"])
            for patch in patches:
                patch.remove()
            patches = plots.draw_bodies(ax, cuts)
            for body, h in histories.items():
                shown = h["time"] <= time + 1e-12
                trails[body].set_data(h[names[a]][shown], h[names[b]][shown])
            where = "" if run.dimension == 2 else (
                f", plane {slices.AXIS_NAMES[normal]} = {plane['position']:.3g}")
            title.set_text(f"{run.title}\nt = {time:.3f} {run.units.unit('time')}{where}")
            writer.grab_frame()
            if bar:
                bar.update(k + 1)
    plt.close(fig)
    return n_frames
