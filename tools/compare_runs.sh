#!/usr/bin/env bash
# Runs every case in cases/ for a bounded number of steps with a given fddem binary, so that
# two builds can be compared bit for bit (a refactoring must not change results):
#   tools/compare_runs.sh run FDDEM OUT_DIR      # runs the cases into OUT_DIR/<case>/
#   tools/compare_runs.sh diff DIR_A DIR_B       # particles.csv and solver.csv, wall_seconds aside
# The step limits keep the whole set to a few minutes on one core while covering each case's
# code paths (landing, piles, contacts, inflow/outflow, steady cavities).
set -euo pipefail
cd "$(dirname "$0")/.."
steps_for() {
    case "$1" in
    fig05_disk_in_box | fig09_eighteen_disks) echo 300 ;;
    sedimentation_100_disks) echo 200 ;;
    dkt_two_disks) echo 300 ;;
    fig03_settling_channel | fig04_settling_channel_fine) echo 300 ;;
    dkt_uhlmann2005) echo 400 ;;
    cavity_re100 | cavity_re1000) echo 300 ;;
    *) echo 200 ;;
    esac
}
strip_wall() { # solver.csv without its wall_seconds column
    awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="wall_seconds") w=i} {s=""; for(i=1;i<=NF;i++) if(i!=w) s=s (s==""?"":",") $i; print s}' "$1"
}
mode="$1"
if [ "$mode" = run ]; then
    fddem="$(realpath "$2")"
    out="$3"
    mkdir -p "$out"
    for f in cases/*/*/case.toml; do
        name="$(basename "$(dirname "$f")")"
        start=$(date +%s.%N)
        "$fddem" run "$f" -o "$out/$name" --force --set time.max_steps="$(steps_for "$name")" \
            --set output.field_interval=0 >"$out/$name.log" 2>&1 || echo "  (exit $?)"
        printf '%-32s %6.1f s\n' "$name" "$(echo "$(date +%s.%N) - $start" | bc)"
    done
elif [ "$mode" = diff ]; then
    status=0
    for d in "$2"/*/; do
        name="$(basename "$d")"
        for file in particles.csv solver.csv; do
            a="$2/$name/$file"
            b="$3/$name/$file"
            [ -f "$a" ] || continue
            if cmp -s <(strip_wall "$a") <(strip_wall "$b"); then
                echo "same    $name/$file"
            else
                echo "DIFFER  $name/$file"
                status=1
            fi
        done
    done
    exit $status
fi
