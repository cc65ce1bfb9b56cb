#!/usr/bin/env bash
# Install, build everything (library, examples, tests, benchmarks), run all tests.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
