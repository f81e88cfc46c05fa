#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a finished run of the default case and a picture
# of it: installs the build dependencies (as root), builds the release preset, runs the
# lid-driven cavity at Re = 100 into runs/cavity_re100 and plots it (`fddem plot`) into
# runs/cavity_re100/plots. Pass another case file to run that instead.
set -euo pipefail
cd "$(dirname "$0")/.."
case_file="${1:-cases/verification/cavity_re100/case.toml}"
run_dir="runs/$(basename "$case_file" .toml)"
if [ "$run_dir" = "runs/case" ]; then
    run_dir="runs/$(basename "$(dirname "$case_file")")"
fi
./tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target fddem
./build/release/app/fddem run "$case_file" -o "$run_dir" --force
./build/release/app/fddem plot "$run_dir" --quiet
echo
echo "figure: $run_dir/plots/overview.png   (all figures: $run_dir/plots/; movie: fddem plot $run_dir --movie)"
