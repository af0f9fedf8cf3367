#!/usr/bin/env bash
# Fuzzes the configuration reader (docs/fuzzing.md).
#
#   bash workflows/fuzz.sh [SECONDS]   build build-fuzz/ (clang, libFuzzer, ASan, UBSan, every library
#                                      instrumented), fuzz for SECONDS (default 600) from the committed
#                                      corpus, then merge what it found into tests/pipeline/fuzz_corpus
#                                      (minimised: only inputs that add coverage are kept)
#   workflows/fuzz.sh --run-only FUZZER SECONDS
#                                      fuzz with an existing binary in a scratch copy, keep nothing
#                                      (the slow ctest fuzz_cfg_bounded of the fuzz build)
#
# A crash, sanitizer report or leak stops the fuzzer with a non-zero status and
# leaves the input as crash-* / leak-* in the working directory; the script
# exits non-zero. tests/pipeline/fuzz_cfg.dict lists the schema's keys and words
# (regenerate by hand when the schema grows). Needs clang and libclang-rt-14-dev (Debian), not in deps.sh:
# the default build and test suite do not.
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
corpus="$src/tests/pipeline/fuzz_corpus"
seeds=("$src/tests/pipeline/corpus" "$src/tests/pipeline/data" "$src/configs")

fuzz() { # fuzz BINARY SECONDS WORKDIR
  local bin="$1" secs="$2" work="$3"
  mkdir -p "$work/grown" "$work/artifacts"
  cp -r "$corpus/." "$work/grown/" 2>/dev/null || true
  # -timeout: an input that takes 10 s to read is a bug; -max_len: configurations are small files
  (cd "$work" && "$bin" -max_total_time="$secs" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$work/artifacts/" -print_final_stats=1 -dict="$src/tests/pipeline/fuzz_cfg.dict" "$work/grown" "${seeds[@]}" 2>&1) \
    | tee "$work/fuzz.log" | grep -E "^#[0-9]+[[:space:]]+(INITED|DONE)|^stat::|ERROR|SUMMARY|crash-|leak-|timeout-" || true
  if ls "$work/artifacts" | grep -q .; then
    echo "fuzz: inputs that fail are in $work/artifacts:" >&2
    ls "$work/artifacts" >&2
    return 1
  fi
}

if [ "${1:-}" = "--run-only" ]; then
  work="$(mktemp -d)"
  fuzz "$2" "${3:-120}" "$work"
  rm -rf "$work"
  exit 0
fi

secs="${1:-600}"
command -v clang >/dev/null || { echo "fuzz: needs clang (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }
cmake -S "$src" -B "$src/build-fuzz" -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGF_FUZZ=ON \
      -DGF_WITH_OPENMP=OFF -DGF_WITH_MPI=OFF >/dev/null
cmake --build "$src/build-fuzz" --target fuzz_cfg -j2
bin="$src/build-fuzz/tests/pipeline/fuzz_cfg"
work="$src/build-fuzz/fuzz-work"
rm -rf "$work"
fuzz "$bin" "$secs" "$work"
# keep the smallest set of inputs that reaches the same coverage
mkdir -p "$work/merged"
"$bin" -merge=1 -max_len=4096 "$work/merged" "$work/grown" >"$work/merge.log" 2>&1
rm -rf "$corpus"
mkdir -p "$corpus"
cp "$work/merged/"* "$corpus/"
echo "fuzz: tests/pipeline/fuzz_corpus holds $(ls "$corpus" | wc -l) inputs ($(du -sh "$corpus" | cut -f1))"
