#!/usr/bin/env bash
# Builds the libFuzzer targets of test/fuzz with clang, ASan and UBSan into ./build-fuzz and
# runs each for SECONDS seconds (default 60), one after the other, starting from its seed
# corpus test/fuzz/corpus/<target> (doc/fuzzing.md).
#
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]      e.g. bash scripts/fuzz.sh 300 mesh editor
#
# New inputs are kept in build-fuzz/corpus/<target> (the next run starts from them too);
# crashes, leaks, timeouts and out-of-memory inputs go to build-fuzz/findings/<target>/.
# Prints a table (executions, seconds, executions per second, corpus, findings) and exits 1,
# after printing each reproducer, if any target found something.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
all_targets=(tvf tvfb tvfn tvfc rawfield vtp singularities constraints editor mesh medit curves)
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then targets=("${all_targets[@]}"); fi

# Longest input per target: the largest seed with room to grow, small enough to stay fast.
declare -A max_len=([tvf]=16384 [tvfb]=65536 [tvfn]=65536 [tvfc]=1024 [rawfield]=32768 [vtp]=32768
                    [singularities]=1024 [constraints]=4096 [editor]=4096 [mesh]=4096
                    [medit]=8192 [curves]=8192)

# -O1: the fuzzers need speed more than the last optimisations, and it compiles faster.
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER="${FUZZ_CXX:-clang++}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DTVF_BUILD_FUZZERS=ON -DTVF_BUILD_TESTS=OFF -DTVF_BUILD_EXAMPLES=OFF \
  -DTVF_BUILD_BENCHMARKS=OFF -DTVF_BUILD_TOOL=OFF -DTVF_BUILD_EDITOR=OFF -DTVF_USE_CAIRO=OFF >/dev/null
targets_to_build=()
for t in "${targets[@]}"; do targets_to_build+=(--target "fuzz_$t"); done
cmake --build build-fuzz -j"$(nproc)" "${targets_to_build[@]}"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
# UBSan: halt_on_error and the suppressions are the fuzzers' own defaults (fuzz_support.cpp).
export TMPDIR="$PWD/build-fuzz/tmp" # the targets' input files (readers that take a path)
mkdir -p "$TMPDIR"
failed=()
table="target           executions  seconds  exec/s  corpus  findings"
for t in "${targets[@]}"; do
  [ -n "${max_len[$t]:-}" ] || { echo "fuzz.sh: unknown target '$t' (${all_targets[*]})" >&2; exit 2; }
  corpus="build-fuzz/corpus/$t"
  findings="build-fuzz/findings/$t"
  log="build-fuzz/findings/$t.log"
  mkdir -p "$corpus" "$findings"
  echo "== fuzz_$t: $seconds s"
  status=0
  start=$SECONDS
  # The working corpus first (new inputs go there), the seeds of the repository second.
  build-fuzz/fuzzers/fuzz_"$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=512 -max_len="${max_len[$t]}" \
    -print_final_stats=1 -artifact_prefix="$findings/" "$corpus" "test/fuzz/corpus/$t" >"$log" 2>&1 || status=$?
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  time_taken=$((SECONDS - start)) # less than SECONDS if it stopped at a finding
  found=$(find "$findings" -type f | wc -l)
  table+=$'\n'$(printf "%-16s %10s %8s %7s %7s %9s" "$t" "${executions:-?}" "$time_taken" "${rate:-?}" \
                       "$(find "$corpus" -type f | wc -l)" "$found")
  if [ "$status" -ne 0 ]; then
    failed+=("$t")
    echo "fuzz_$t FAILED (exit $status); the end of its log ($log):"
    grep -v '^#[0-9]' "$log" | tail -60
    for f in $(grep -o "Test unit written to [^ ]*" "$log" | sed 's/Test unit written to //'); do
      echo "-- reproducer $f ($(stat -c %s "$f") bytes; run: build-fuzz/fuzzers/fuzz_$t $f), base64:"
      base64 "$f" | head -c 20000
      echo
    done
  fi
done
echo "$table"
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz.sh: findings in: ${failed[*]}" >&2
  exit 1
fi
