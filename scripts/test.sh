#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, runs every test.
#
#  1. the main build (Release): unit tests, input-script tests serially and
#     under mpirun with 2 and 4 processes;
#  2. an AddressSanitizer + UndefinedBehaviorSanitizer build of the core and
#     the LAMMPS fix: the core tests and MPI scenes;
#  3. a clang build of the libFuzzer targets, each run for a fixed number of
#     executions.
# REINFORCE_QUICK=1 runs only the first.
set -uo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/scripts/setup.sh" || exit 1
jobs=${REINFORCE_TEST_JOBS:-2}
passed=0 failed=0

run_ctest() {    # run_ctest BUILD_DIR [ctest args]
  local dir=$1 out
  shift
  out=$(mktemp)
  (cd "$dir" && ctest --output-on-failure -j"$jobs" "$@") 2>&1 | tee "$out"
  local line
  line=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+' "$out" | tail -1)
  if [ -z "$line" ]; then
    failed=$((failed + 1))
  else
    local total fails
    fails=$(sed -E 's/.* ([0-9]+) tests failed out of ([0-9]+).*/\1/' <<<"$line")
    total=$(sed -E 's/.* tests failed out of ([0-9]+).*/\1/' <<<"$line")
    passed=$((passed + total - fails))
    failed=$((failed + fails))
  fi
  rm -f "$out"
}

echo "== main build: all tests"
run_ctest "$REINFORCE_BUILD" "$@"

if [ "${REINFORCE_QUICK:-0}" != 1 ]; then
  echo "== sanitizer build (ASan + UBSan): core tests and MPI scenes"
  san="$top/build-sanitize"
  if cmake -S "$top" -B "$san" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DREINFORCE_SANITIZE=ON \
       -DREINFORCE_LIGGGHTS=OFF >/dev/null &&
     cmake --build "$san" -j"$(nproc)" --target core_tests lmp_reinforce make_scene check_scene; then
    # Open MPI's own allocations are not ours to judge: no leak check.
    ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
      run_ctest "$san" -R "${REINFORCE_SANITIZE_TESTS:-^Kernel|^Engine|^Fix|^Rounds|^Summary|^Invocation|^stability_periodic_2x2x1_np4$|^stability_stiff}"
  else
    echo "sanitizer build failed"; failed=$((failed + 1))
  fi

  echo "== fuzz build (clang, libFuzzer)"
  fuzz="$top/build-fuzz"
  if CC=clang CXX=clang++ cmake -S "$top" -B "$fuzz" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
       -DREINFORCE_FUZZ=ON -DREINFORCE_TESTS=OFF -DREINFORCE_LAMMPS=OFF -DREINFORCE_LIGGGHTS=OFF \
       >/dev/null && cmake --build "$fuzz" -j"$(nproc)"; then
    run_ctest "$fuzz"
  else
    echo "fuzz build failed"; failed=$((failed + 1))
  fi
fi

echo "total: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
