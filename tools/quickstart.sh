#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a finished run of the default case:
# installs the build dependencies (as root), builds the release preset, runs the lid-driven
# cavity at Re = 100 into runs/cavity_re100. Pass another case file to run that instead.
set -euo pipefail
cd "$(dirname "$0")/.."
case_file="${1:-cases/verification/cavity_re100/case.toml}"
./tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target fddem
./build/release/app/fddem run "$case_file" --force
