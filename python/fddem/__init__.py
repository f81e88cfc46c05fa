"""fddem's Python side: read a run directory (numpy, and pandas DataFrames where pandas is
installed) and plot it (`fddem plot RUN_DIR`, or `python3 -m fddem plot RUN_DIR`).

    import fddem
    run = fddem.Run("runs/fig09_eighteen_disks")
    rows = run.particles()          # particles.csv: a DataFrame (numpy arrays without pandas)
    frame = run.field(-1)           # the last field frame: x, y, z, velocity, p, vorticity
    print(run.title, rows.groupby("id")["y"].min().max(), frame["velocity"].shape)
"""

from .io import (  # noqa: F401
    NotARunError,
    check_run_directory,
    has_pandas,
    read_case,
    read_case_source,
    read_case_title,
    read_csv_columns,
    read_particle_rows,
    read_particles,
    read_pvd,
    read_samples,
    read_solver,
    read_summary,
    read_vtp,
    read_vtr,
)
from .run import Run  # noqa: F401
