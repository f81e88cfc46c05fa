#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to the default test run: installs the build
# dependencies (as root), builds the release preset with -Werror and runs the unit,
# verification and regression tests (under 15 minutes on two cores). With --sanitize it also
# builds the dev preset (ASan + UBSan) and runs the unit tests under the sanitizers, then fuzzes
# the case reader for 60 s (tools/fuzz.sh: clang + libFuzzer, only the reader is built).
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/install-deps.sh
jobs="$(nproc)"
if command -v clang-format >/dev/null; then
    echo "== format check"
    git ls-files '*.cpp' '*.hpp' | xargs clang-format --dry-run --Werror
fi
echo "== release build"
cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs"
echo "== tests: unit|verification|regression"
ctest --preset release -j "$jobs"
echo "== fddem validate --quick (report: build/release/validation/report.md)"
./build/release/app/fddem validate --quick -o build/release/validation
if [ "${1:-}" = "--sanitize" ]; then
    echo "== dev build (ASan + UBSan)"
    cmake --preset dev >/dev/null
    cmake --build --preset dev -j "$jobs"
    echo "== unit tests under ASan + UBSan"
    ctest --preset dev -j "$jobs"
    echo "== fuzzing the case reader (60 s)"
    ./tools/fuzz.sh 60
fi
