#!/usr/bin/env bash
# Fuzzes the case reader for SECONDS (default 60): builds the `fuzz` preset (clang, libFuzzer,
# ASan + UBSan; only the reader and the target) and runs fuzz_case_reader on build/fuzz/corpus,
# seeded with every cases/**/case.toml and fuzz/seeds/*.toml, with the dictionary generated
# from the case schema. The corpus grows across runs (rm -rf build/fuzz/corpus to start over).
# Exit status 0: no finding. Otherwise the offending input is in build/fuzz/findings/
# (crash-*, timeout-*, oom-*, leak-*); rerun it with build/fuzz/fuzz/fuzz_case_reader FILE.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
jobs="${FDDEM_BUILD_JOBS:-$(nproc)}"

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$jobs"

corpus=build/fuzz/corpus
findings=build/fuzz/findings
mkdir -p "$corpus" "$findings"
while IFS= read -r -d '' seed; do
    name="${seed#./}"
    cp "$seed" "$corpus/seed_${name//\//_}"
done < <(find cases fuzz/seeds -name '*.toml' \( -path 'cases/*/case.toml' -o -path 'fuzz/seeds/*' \) -print0)

echo "== fuzzing the case reader for ${seconds} s (corpus: $(ls "$corpus" | wc -l) inputs)"
status=0
build/fuzz/fuzz/fuzz_case_reader "$corpus" \
    -dict=build/fuzz/fuzz/case_reader.dict \
    -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 \
    -artifact_prefix="$findings/" -print_final_stats=1 || status=$?
if [ "$status" -ne 0 ]; then
    echo "fuzz: finding (exit status $status); inputs in $findings/:" >&2
    ls -l "$findings" >&2
    exit 1
fi
echo "== fuzz: no finding in ${seconds} s"
