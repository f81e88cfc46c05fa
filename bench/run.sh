#!/usr/bin/env bash
# fddem's benchmark table, one command. Builds the release preset, then:
#  1. the kernel micro-benchmarks (Google Benchmark: momentum assembly, sweep, Poisson solves);
#  2. the lid-driven cavity (Re 100, Δt at lid Courant 0.5) on 64², 128², 256², 512² for a fixed
#     simulated time, through `fddem run`: time per step, outer iterations per step, share of
#     time in pressure and momentum, peak memory;
#  3. with --openfoam: the side-by-side comparison with OpenFOAM's icoFoam on the same cavity
#     (Re 100, N², Δt = 0.5/N, t = 20) using shared/peers/openfoam-cavity/run.sh, printing the
#     wall-time ratio and both codes' centreline deviation from Ghia et al. (1982).
#  4. with --paper: the paper's particle cases end to end (Fig. 5 disk in a box, Figs. 9-13
#     eighteen disks, both at h = 1/64; the DKT benchmark): wall time, time per step, outer
#     iterations per step, share of time in fluid, coupling and contact, largest overlap.
#  5. with --steady: time to the steady state, side by side with OpenFOAM's simpleFoam on the
#     cavities Re 100 and Re 1000 at 128² (the shipped case files: pseudo-time), plus fddem's
#     time-marched variant (time.steady = false); R rounds, each running every timed row once in
#     turn, so that every wall-time ratio is taken within a round (median over the rounds);
#     then one iteratively tight reference run per code, against which each row's iteration
#     error is measured. Prints steps, outer iterations, wall seconds, max |u - Ghia|,
#     max |v - Ghia| and the ratios.
#  6. with --3d: the 3D sphere cases (issue 14): ten Cate E4 (d/h = 8.25) to t = 0.2 s, or end
#     to end with --3d full, and the fixed sphere at Re 20 for 20 steps: time per step, outer
#     iterations per step, ns per cell and outer iteration, the share of each phase, peak memory
#     per cell.
#  6b. with --cube3d [R]: the fluid alone in 3D, side by side with OpenFOAM's icoFoam
#     (shared/peers/openfoam-cavity/run3d.sh): the lid-driven cube, Re 100, Δt = 0.5/N, 50 steps,
#     at 64³ and 128³, one thread each, R rounds (default 3) each running every row once in turn,
#     so that each wall-time ratio is taken within a round (median over the rounds). fddem at
#     simple.tolerance 1e-4 (as the 2D comparison), at the default 1e-5, and with the projection
#     step (simple.algorithm = "projection", predictor to 1e-5). Then, at 64³ only,
#     each code's time error: its centreline u at t = 50 Δt against its own run with Δt/4 (fddem's
#     iterated to 1e-8), so that the ratio compares runs of like accuracy. Also the 3D pressure
#     solve: FFTW's cosine transforms against hypre on the same cube (10 steps, pressure seconds
#     per outer iteration). About 25 minutes with R = 3.
#  7. with --mpi [P]: strong and weak scaling over MPI ranks p = 1, 2, 4, … ≤ P (default 4;
#     issue 15), through `mpirun -n p fddem run` on the lid-driven cube (docs/examples/
#     cavity3d.toml, Re 100, hypre, 10 steps): strong on 48³ cells, weak on 32³ cells per rank
#     (the box grown along x, then y, then z). Prints the stepping time per step, the speed-up
#     and the parallel efficiency, and the machine's core count: rows with more ranks than
#     cores are oversubscribed and say nothing about scaling. With --mpi-large also the
#     issue's strong-scaling rows on 1 and 2 ranks: the cube at 128³ (5 steps) and ten Cate E4
#     at d/h = 15.75 (105 × 105 × 168 cells, 3 steps), and 200 spheres (the soak, 5 steps) with
#     the sequential and the simultaneous sweep over the bodies (coupling.body_sweep).
#  7b. with --mpi-memory [N]: the peak resident memory of every rank (GNU time's %M, per
#     process), the lid-driven cube at N³ (default 96), 3 steps and the closing outputs (line
#     samples, summary, a checkpoint), on one process and on 2 ranks: no rank should hold the
#     whole grid (issue 15; before the thirty-eighth session rank 0 kept a one-process mirror).
#  8. with --no-base: without the kernel and cavity tables (1-2), e.g. `--no-base --mpi 4`.
# The kernel table includes contact detection (cell list vs brute force) for 1e3-1e5 disks.
# Options: --openfoam [N] (default N = 256), --paper, --steady [R] (default R = 3 rounds),
# --3d [full], --cube3d [R] (default R = 3 rounds), --mpi [P] (default P = 4), --mpi-large,
# --mpi-memory [N] (default N = 96), --no-base, --quick (smaller table),
# --threads T (default 1).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
cd "$root"
openfoam=0
openfoam_n=256
paper=0
three_d=0
three_d_full=0
cube3d=0
cube3d_rounds=3
steady=0
steady_rounds=3
mpi=0
mpi_ranks=4
mpi_large=0
mpi_memory=0
mpi_memory_n=96
base=1
quick=0
threads=1
while [ $# -gt 0 ]; do
    case "$1" in
        --openfoam) openfoam=1; if [[ "${2:-}" =~ ^[0-9]+$ ]]; then openfoam_n="$2"; shift; fi ;;
        --quick) quick=1 ;;
        --paper) paper=1 ;;
        --3d) three_d=1; if [ "${2:-}" = full ]; then three_d_full=1; shift; fi ;;
        --cube3d) cube3d=1; if [[ "${2:-}" =~ ^[0-9]+$ ]]; then cube3d_rounds="$2"; shift; fi ;;
        --steady) steady=1; if [[ "${2:-}" =~ ^[0-9]+$ ]]; then steady_rounds="$2"; shift; fi ;;
        --mpi) mpi=1; if [[ "${2:-}" =~ ^[0-9]+$ ]]; then mpi_ranks="$2"; shift; fi ;;
        --mpi-large) mpi=1; mpi_large=1 ;;
        --mpi-memory) mpi_memory=1; if [[ "${2:-}" =~ ^[0-9]+$ ]]; then mpi_memory_n="$2"; shift; fi ;;
        --no-base) base=0 ;;
        --threads) threads="$2"; shift ;;
        *) echo "bench/run.sh: unknown option '$1'" >&2; exit 2 ;;
    esac
    shift
done
export OMP_NUM_THREADS="$threads"
python=/usr/bin/python3 # Debian's, which has numpy; a pyenv python3 on PATH may not

./tools/install-deps.sh >/dev/null
cmake --preset release >/dev/null
cmake --build --preset release --target fddem fddem_bench >/dev/null
fddem="$root/build/release/app/fddem"
out="$root/bench/results"
mkdir -p "$out"

# Installs Debian's openfoam if needed, copies the peer folder (shared/peers/openfoam-cavity) to a
# fresh writable place under bench/results and prints its path.
openfoam_peer() {
    if ! command -v icoFoam >/dev/null; then
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq openfoam >/dev/null
    fi
    local peer="$out/openfoam-cavity"
    rm -rf "$peer" && cp -r "$root/../shared/peers/openfoam-cavity" "$peer"
    echo "$peer"
}

if [ "$base" = 1 ]; then
    echo "== kernels (OMP_NUM_THREADS=$threads)"
    "$root/build/release/bench/fddem_bench" --benchmark_min_time=0.2 2>/dev/null |
        grep -E '^(Benchmark|-|momentum|poisson|contact)'

    echo
    echo "== lid-driven cavity, Re 100, dt = 0.5/N (OMP_NUM_THREADS=$threads)"
    grids="64 128 256 512"
    end=1.0
    [ "$quick" = 1 ] && grids="64 128 256" && end=0.5
    rows=()
    for n in $grids; do
        dir="$out/cavity_n$n"
        dt=$($python -c "print(0.5/$n)")
        "$fddem" run cases/verification/cavity_re100/case.toml -o "$dir" --force -q \
            --set "domain.cells=[$n,$n]" --set "time.dt=$dt" --set "time.end=$end" \
            --set "time.steady=false" --set "time.steady_tolerance=1e-12" --set "output.field_interval=0" \
            --set "simple.tolerance=1e-4" --set 'simple.fft_planning="measure"'
        rows+=("$n:$dir")
    done
    $python "$here/table.py" cavity "${rows[@]}"
fi

if [ "$openfoam" = 1 ]; then
    echo
    echo "== side by side with OpenFOAM icoFoam: cavity Re 100, ${openfoam_n}², dt = 0.5/N, t = 20"
    peer="$(openfoam_peer)"
    n="$openfoam_n"
    dt=$($python -c "print(0.5/$n)") # icoFoam's: endTime/ceil(endTime·N/0.5)
    dir="$out/cavity_fddem_n$n"
    start=$(date +%s.%N)
    "$fddem" run cases/verification/cavity_re100/case.toml -o "$dir" --force -q \
        --set "domain.cells=[$n,$n]" --set "time.dt=$dt" --set "time.end=20.0" \
        --set "time.steady=false" --set "time.steady_tolerance=1e-12" --set "output.field_interval=0" \
        --set "simple.tolerance=1e-4" --set 'simple.fft_planning="measure"'
    fddem_wall=$($python -c "import sys,time; print(f'{time.time()-float(sys.argv[1]):.2f}')" "$start")
    (cd "$peer" && OMP_NUM_THREADS=1 ./run.sh "$n" 100 20 icoFoam >/dev/null)
    $python "$here/table.py" openfoam "$dir" "$fddem_wall" "$peer/results" "$n" \
        "$root/cases/verification/cavity_re100/reference"
fi

if [ "$paper" = 1 ]; then
    echo
    echo "== the paper's particle cases end to end (OMP_NUM_THREADS=$threads)"
    rows=()
    for entry in fig05_disk_in_box:cases/paper/fig05_disk_in_box \
                 fig09_eighteen_disks:cases/paper/fig09_eighteen_disks \
                 dkt_two_disks:cases/benchmarks/dkt_two_disks; do
        name="${entry%%:*}"
        dir="$out/$name"
        "$fddem" run "${entry#*:}/case.toml" -o "$dir" --force -q --set "output.field_interval=0"
        rows+=("$name:$dir")
    done
    $python "$here/table.py" paper "${rows[@]}"
fi

if [ "$three_d" = 1 ]; then
    echo
    echo "== 3D spheres (OMP_NUM_THREADS=$threads)"
    e4_end=0.2
    if [ "$three_d_full" = 1 ]; then e4_end=1.2; fi
    rows=()
    for entry in "ten_cate_e4:cases/validation/ten_cate_e4:time.end=$e4_end" \
                 "sphere_re20:cases/verification/sphere_re20:time.end=2.0"; do
        IFS=: read -r name case_dir end <<<"$entry"
        dir="$out/$name"
        "$fddem" run "$case_dir/case.toml" -o "$dir" --force -q --set "output.field_interval=0" \
            --set "$end"
        rows+=("$name:$dir")
    done
    $python "$here/table.py" three_d "${rows[@]}"
fi

if [ "$cube3d" = 1 ]; then
    echo
    echo "== the fluid alone in 3D, side by side with OpenFOAM icoFoam: lid-driven cube, Re 100,"
    echo "   dt = 0.5/N, 50 steps, $cube3d_rounds round(s), one thread each"
    peer="$(openfoam_peer)"
    # run3d.sh deletes its case; this copy keeps it and writes U in ascii at the last step, for
    # the time-error column. Each edit is checked, so that a changed peer script stops here.
    kept="$peer/run3d_kept.sh"
    sed -e 's/^CASE=\(.*\); trap .*$/CASE=\1; echo "case $CASE"/' \
        -e 's/writeFormat binary/writeFormat ascii/' \
        -e 's/writeInterval 1000000/writeInterval $STEPS/' "$peer/run3d.sh" >"$kept"
    chmod +x "$kept"
    for edit in 'echo "case $CASE"' 'writeFormat ascii' 'writeInterval $STEPS'; do
        grep -qF "$edit" "$kept" || { echo "bench/run.sh: run3d.sh changed ($edit)" >&2; exit 1; }
    done
    dir="$out/cube3d"
    rm -rf "$dir" && mkdir -p "$dir"
    echo "round,n,row,wall_s" >"$dir/walls.csv"
    cube=(docs/examples/cavity3d.toml --force -q --set output.field_interval=0
          --set 'simple.fft_planning="measure"')
    # One fddem row: the cube at N³ into $dir/n$2_$3, its whole process's wall clock appended.
    cube_row() {
        local round="$1" n="$2" row="$3"
        shift 3
        local start
        start=$(date +%s.%N)
        OMP_NUM_THREADS=1 "$fddem" run "${cube[@]}" -o "$dir/n${n}_$row" --set "domain.cells=[$n,$n,$n]" \
            --set "time.dt=$($python -c "print(0.5/$n)")" \
            --set "time.end=$($python -c "print(50*0.5/$n)")" "$@" >"$dir/n${n}_$row.log" 2>&1
        awk -v a="$start" -v b="$(date +%s.%N)" -v r="$round,$n,$row" 'BEGIN { printf "%s,%.3f\n", r, b - a }' \
            >>"$dir/walls.csv"
    }
    # One icoFoam row: its solver's wall clock (run3d.sh's own timing), the case kept as
    # $dir/icofoam_n$2$3.
    foam_row() {
        local round="$1" n="$2" tag="$3"
        shift 3
        local line
        line=$(cd "$peer" && OMP_NUM_THREADS=1 "$kept" "$n" 100 "$@")
        rm -rf "$dir/icofoam_n$n$tag"
        mv "$(sed -n 's/^case //p' <<<"$line")" "$dir/icofoam_n$n$tag"
        echo "$round,$n,icofoam$tag,$(sed -n 's/.*wall_s=\([0-9.]*\).*/\1/p' <<<"$line")" >>"$dir/walls.csv"
    }
    for round in $(seq 1 "$cube3d_rounds"); do
        for n in 64 128; do
            cube_row "$round" "$n" tol1e-4 --set simple.tolerance=1e-4
            cube_row "$round" "$n" tol1e-5
            cube_row "$round" "$n" projection --set 'simple.algorithm="projection"'
            foam_row "$round" "$n" "" 50
        done
    done
    # The time error at 64³: each code against itself at Δt/4 (200 steps), once.
    cube_row 0 64 ref --set simple.tolerance=1e-8 --set simple.max_outer_iterations=200 \
        --set time.dt=0.001953125
    foam_row 0 64 _ref 200 0.001953125
    # The pressure solve in 3D, the same cube: FFTW's direct solve against hypre.
    for n in 64 128; do
        for solver in fft hypre; do
            "$fddem" run "${cube[@]}" -o "$dir/pressure_n${n}_$solver" --set "domain.cells=[$n,$n,$n]" \
                --set time.max_steps=10 --set "simple.pressure_solver=$solver"
        done
    done
    $python "$here/table.py" cube3d "$dir"
fi

if [ "$mpi" = 1 ]; then
    echo
    echo "== MPI scaling, lid-driven cube (OMP_NUM_THREADS=$threads, $(nproc --all) cores)"
    launch=(mpirun --oversubscribe)
    if [ "$(id -u)" = 0 ]; then launch+=(--allow-run-as-root); fi
    # The pressure by hypre on the blocks (rows strong, weak, strong_cube128, strong_e4_16) and
    # by the direct FFT solver, FFTW-MPI's slabs on several ranks (the same rows, *_fft).
    cube_fft=(docs/examples/cavity3d.toml --force -q --set time.max_steps=10
              --set output.field_interval=0 --set simple.pressure_solver=fft)
    cube=("${cube_fft[@]}" --set simple.pressure_solver=hypre)
    rows=()
    p=1
    while [ "$p" -le "$mpi_ranks" ]; do
        dir="$out/mpi_strong_$p"
        "${launch[@]}" -n "$p" "$fddem" run "${cube[@]}" -o "$dir" --set "domain.cells=[48,48,48]"
        rows+=("strong:$p:$dir")
        dir="$out/mpi_strong_fft_$p"
        "${launch[@]}" -n "$p" "$fddem" run "${cube_fft[@]}" -o "$dir" \
            --set "domain.cells=[48,48,48]"
        rows+=("strong_fft:$p:$dir")
        # Weak: 32³ cells per rank, the box doubled along x, then y, then z.
        nx=1; ny=1; nz=1; q=$p; axis=0
        while [ "$q" -gt 1 ]; do
            case $axis in 0) nx=$((nx * 2)) ;; 1) ny=$((ny * 2)) ;; 2) nz=$((nz * 2)) ;; esac
            q=$((q / 2)); axis=$(((axis + 1) % 3))
        done
        dir="$out/mpi_weak_$p"
        "${launch[@]}" -n "$p" "$fddem" run "${cube[@]}" -o "$dir" \
            --set "domain.cells=[$((32 * nx)),$((32 * ny)),$((32 * nz))]" \
            --set "domain.size=[$nx,$ny,$nz]"
        rows+=("weak:$p:$dir")
        dir="$out/mpi_weak_fft_$p"
        "${launch[@]}" -n "$p" "$fddem" run "${cube_fft[@]}" -o "$dir" \
            --set "domain.cells=[$((32 * nx)),$((32 * ny)),$((32 * nz))]" \
            --set "domain.size=[$nx,$ny,$nz]"
        rows+=("weak_fft:$p:$dir")
        p=$((p * 2))
    done
    if [ "$mpi_large" = 1 ]; then
        for p in 1 2; do
            dir="$out/mpi_cube128_$p"
            "${launch[@]}" -n "$p" "$fddem" run "${cube[@]}" -o "$dir" \
                --set "domain.cells=[128,128,128]" --set time.max_steps=5
            rows+=("strong_cube128:$p:$dir")
            dir="$out/mpi_cube128_fft_$p"
            "${launch[@]}" -n "$p" "$fddem" run "${cube_fft[@]}" -o "$dir" \
                --set "domain.cells=[128,128,128]" --set time.max_steps=5
            rows+=("strong_cube128_fft:$p:$dir")
            dir="$out/mpi_e4_16_$p"
            "${launch[@]}" -n "$p" "$fddem" run cases/validation/ten_cate_e4/case.toml -o "$dir" \
                --force -q --set "domain.cells=[105,105,168]" --set time.max_steps=3 \
                --set output.field_interval=0 --set simple.pressure_solver=hypre
            rows+=("strong_e4_16:$p:$dir")
            dir="$out/mpi_e4_16_fft_$p"
            "${launch[@]}" -n "$p" "$fddem" run cases/validation/ten_cate_e4/case.toml -o "$dir" \
                --force -q --set "domain.cells=[105,105,168]" --set time.max_steps=3 \
                --set output.field_interval=0 --set simple.pressure_solver=fft
            rows+=("strong_e4_16_fft:$p:$dir")
            # Many bodies: the soak's 200 spheres (cases/validation/sphere_pile_soak, 64 × 64 ×
            # 96 cells), 5 steps, coupling.body_sweep sequential (one sum and one halo exchange
            # per body and outer iteration) against simultaneous (one of each per outer
            # iteration).
            for sweep in sequential simultaneous; do
                dir="$out/mpi_pile_${sweep}_$p"
                "${launch[@]}" -n "$p" "$fddem" run cases/validation/sphere_pile_soak/case.toml \
                    -o "$dir" --force -q --set time.max_steps=5 --set time.min_end=0 \
                    --set output.field_interval=0 --set coupling.body_sweep=$sweep
                rows+=("pile_${sweep:0:3}:$p:$dir")
            done
        done
    fi
    $python "$here/table.py" mpi "$(nproc --all)" "${rows[@]}"
fi

if [ "$mpi_memory" = 1 ]; then
    echo
    echo "== peak memory per rank, lid-driven cube ${mpi_memory_n}³, 3 steps and the closing outputs"
    command -v /usr/bin/time >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -qq time >/dev/null
    launch=(mpirun --oversubscribe)
    if [ "$(id -u)" = 0 ]; then launch+=(--allow-run-as-root); fi
    cube=(docs/examples/cavity3d.toml --force -q --set time.max_steps=3 --set output.field_interval=0
          --set "domain.cells=[$mpi_memory_n,$mpi_memory_n,$mpi_memory_n]" --set simple.pressure_solver=fft)
    peaks=()
    for p in 1 2; do
        log="$out/mpi_memory_$p.log"
        "${launch[@]}" -n "$p" /usr/bin/time -f "peak-kib %M" "$fddem" run "${cube[@]}" \
            -o "$out/mpi_memory_$p" 2>"$log"
        peaks+=("$p:$(grep -o 'peak-kib [0-9]*' "$log" | awk '{print $2}' | sort -n | tr '\n' ',')")
    done
    $python "$here/table.py" mpi_memory "$mpi_memory_n" "${peaks[@]}"
fi

if [ "$steady" = 1 ]; then
    echo
    echo "== time to the steady state, side by side with OpenFOAM simpleFoam: cavity Re 100 and 1000,"
    echo "   128², $steady_rounds round(s) (OMP_NUM_THREADS=$threads for fddem, one process each)"
    peer="$(openfoam_peer)"
    dir="$out/steady"
    rm -rf "$dir" && mkdir -p "$dir"
    echo "round,re,row,wall_s" >"$dir/walls.csv"
    # One fddem run of the cavity at Reynolds number $2 into $dir/re$2_$3, its wall clock (the
    # whole process: set-up, stepping, output) appended to walls.csv as round $1.
    fddem_row() {
        local round="$1" re="$2" row="$3"
        shift 3
        local start
        start=$(date +%s.%N)
        "$fddem" run "cases/verification/cavity_re$re/case.toml" -o "$dir/re${re}_$row" --force -q "$@" \
            >"$dir/re${re}_$row.log" 2>&1
        awk -v a="$start" -v b="$(date +%s.%N)" -v r="$round,$re,$row" 'BEGIN { printf "%s,%.3f\n", r, b - a }' \
            >>"$dir/walls.csv"
    }
    # Timed rows, each round running every one once in turn: the shipped case (pseudo-time); the
    # same with SIMPLE's per-step tolerance 1e-6 (its iteration error then matches simpleFoam's
    # at residual 1e-6); the time-marched variant; simpleFoam (SIMPLEC, residuals 1e-6: the peer's
    # default).
    for round in $(seq 1 "$steady_rounds"); do
        for re in 100 1000; do
            fddem_row "$round" "$re" pseudo
            fddem_row "$round" "$re" pseudo_simple1e-6 --set "simple.tolerance=1e-6"
            fddem_row "$round" "$re" marched --set "time.steady=false"
            (cd "$peer" && OMP_NUM_THREADS=1 ./run.sh 128 "$re" 20000 simpleFoam >/dev/null)
        done
    done
    # The references for the iteration error, once: fddem's pseudo-time with every tolerance
    # 1e3-1e4 times tighter, simpleFoam's residuals at 1e-9 (the peer's accuracy anchor).
    for re in 100 1000; do
        fddem_row 1 "$re" tight --set "simple.tolerance=1e-9" --set "time.steady_tolerance=1e-10"
        (cd "$peer" && OMP_NUM_THREADS=1 TOL=1e-9 TAG=tol1e-9 ./run.sh 128 "$re" 40000 simpleFoam >/dev/null)
    done
    $python "$here/table.py" steady "$dir" "$peer/results" "$root/cases/verification"
fi
