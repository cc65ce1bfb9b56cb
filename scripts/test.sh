#!/usr/bin/env bash
# Install, build everything (library, examples, tests, benchmarks), run all tests, then
# every fuzzer for a short time (TVF_FUZZ_SECONDS each, default 10; 0 skips them).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
fuzz_seconds=${TVF_FUZZ_SECONDS:-10}
if [ "$fuzz_seconds" -gt 0 ]; then
  start=$SECONDS
  bash scripts/fuzz.sh "$fuzz_seconds" # a finding fails the run, with its reproducer printed
  echo "fuzzing (build and $fuzz_seconds s per target): $((SECONDS - start)) s"
fi
