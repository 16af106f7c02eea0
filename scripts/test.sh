#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, runs every test.
#
#  1. the main build (Release): unit tests, input-script tests serially and
#     under mpirun with 2 and 4 processes;
#  2. an AddressSanitizer + UndefinedBehaviorSanitizer build of the core and
#     the LAMMPS fix: the core tests and MPI scenes;
#  3. a clang build of the libFuzzer targets, each run for a fixed number of
#     executions.
# The later parts' builds (and the source-built hosts') run in the
# background while the first part's tests run; ctest runs twice as many
# jobs as cores (REINFORCE_TEST_JOBS sets it). REINFORCE_QUICK=1 runs only
# the first.
#
# It stops with a non-zero status when the install or the build fails (no
# test is run on binaries left from before). Only REINFORCE_SKIP leaves a
# host (lammps, liggghts) or a part (sanitizer, fuzz, source) out, by name:
# REINFORCE_SKIP=liggghts. Every host not skipped is configured ON
# explicitly (-DREINFORCE_LAMMPS=ON -DREINFORCE_LIGGGHTS=ON, whatever the
# build directory's CMake cache holds), and the command fails, naming it,
# when such a host is configured OFF anyway (by REINFORCE_CMAKE_ARGS) or was
# not built. Each part must also run at least a minimum of tests of each of
# its families (scripts/test_families.txt, checked by count_families.sh on
# `ctest -N` with the part's selection, the arguments given to this command
# included): a family short fails the command by name. The end lists the
# tests run per part and names every part skipped; the closing line, read by
# CI, is
#   total: N passed, M failed
set -uo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# skip_reason NAME: prints why NAME (a host, or a part: sanitizer, fuzz,
# source) is left out on purpose, or nothing. Only REINFORCE_SKIP does it: a
# REINFORCE_<HOST>=OFF in REINFORCE_CMAKE_ARGS or in a CMake cache left from
# an earlier configure never skips a host.
skip_reason() {
  local h=$1
  if [[ ",${REINFORCE_SKIP:-}," =~ [,[:space:]]$h[,[:space:]] ]]; then
    echo "REINFORCE_SKIP=${REINFORCE_SKIP}"
  fi
}
upper() { tr '[:lower:]' '[:upper:]' <<<"$1"; }

# The hosts not skipped are configured ON explicitly, before the caller's
# REINFORCE_CMAKE_ARGS (a later -D wins: an OFF there fails the host check).
host_on=(-DREINFORCE_QUALITY_TESTS=ON)    # an OFF left in a cache must not drop them
for h in lammps liggghts; do
  [ -n "$(skip_reason "$h")" ] || host_on+=("-DREINFORCE_$(upper "$h")=ON")
done
# setup.sh runs as its own process: sourced after `||`, bash would ignore its
# `set -e`, and its options would leak into this script.
if ! REINFORCE_CMAKE_ARGS="${host_on[*]} ${REINFORCE_CMAKE_ARGS:-}" bash "$top/scripts/setup.sh"; then
  echo "test: FAILED: setup (package install, configure or build) failed: no test was run"
  echo "total: 0 passed, 1 failed"
  exit 1
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export REINFORCE_BUILD="${REINFORCE_BUILD_DIR:-$top/build}"
# Twice the cores: most tests wait more than they compute (MPI start-up,
# oversubscribed processes), and ctest counts a test's PROCESSORS.
jobs=${REINFORCE_TEST_JOBS:-$((2 * $(nproc)))}
passed=0 failed=0
parts=()       # one line per part run: "name: N tests, P passed, F failed (groups)"
skipped=()     # one line per part or host left out, with the reason

run_ctest() {    # run_ctest BUILD_DIR [ctest args]; the part's name: $part (default: the directory's)
  local dir=$1 out name=${part:-$(basename "$1")}
  shift
  out=$(mktemp)
  (cd "$dir" && ctest --output-on-failure -j"$jobs" "$@") 2>&1 | tee "$out"
  local line total=0 fails=1
  line=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+' "$out" | tail -1)
  if [ -n "$line" ]; then
    fails=$(sed -E 's/.* ([0-9]+) tests failed out of ([0-9]+).*/\1/' <<<"$line")
    total=$(sed -E 's/.* tests failed out of ([0-9]+).*/\1/' <<<"$line")
  fi
  passed=$((passed + total - fails))
  failed=$((failed + fails))
  # Tests run per group (the name's prefix; unit tests are Suite.Name).
  local groups
  groups=$(sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: ([^ ]+) .*/\1/p' "$out" |
           sed -E 's/^[A-Za-z0-9]+\..*/unit/; s/^(check_scene|lammps|liggghts|stability|fuzz|src_lammps|src_liggghts|quality|layout|docs)_.*/\1/' |
           sort | uniq -c | awk '{printf "%s%s %d", (NR > 1 ? ", " : ""), $2, $1}')
  parts+=("$name: $total tests, $((total - fails)) passed, $fails failed${groups:+ ($groups)}")
  # Where the part's time went: its 20 slowest tests.
  echo "== the 20 slowest tests of part $name (seconds)"
  sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: ([^ ]+) .* ([0-9.]+) sec$/\2 \1/p' "$out" |
    sort -rn | head -20 | awk '{printf "  %8.2f  %s\n", $1, $2}'

  [ -n "$line" ] || parts+=("$name: FAILED: ctest reported no result (no test found?)")
  rm -f "$out"
}

# Per part: tests run, and what was skipped (printed just above the total).
summary() {
  echo "== tests run per part"
  local p
  for p in "${parts[@]}"; do echo "  $p"; done
  if [ ${#skipped[@]} -eq 0 ]; then
    echo "  skipped: nothing"
  else
    for p in "${skipped[@]}"; do echo "  skipped: $p"; done
  fi
}

# check_families PART DIR [HOST...] -- [ctest selection]: each family of
# PART (scripts/test_families.txt; those of the HOSTs given, and those of no
# host) has at least its minimum of tests among the ones the part runs
# (`ctest -N` in DIR with the selection). Each family short is a failure,
# named on a "test: FAILED: part PART: family ..." line.
check_families() {
  local p=$1 dir=$2 hs=() list short
  shift 2
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do hs+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  list=$(mktemp)
  (cd "$dir" && ctest -N "$@") >"$list" 2>&1
  bash "$top/scripts/count_families.sh" "$p" "${hs[@]}" <"$list"
  short=$?
  rm -f "$list"
  if [ "$short" -ne 0 ]; then
    failed=$((failed + short))
    parts+=("$p: FAILED: families short of tests, or no family table (the test: FAILED lines above)")
  fi
}

# Every host expected (not skipped by name) must be configured ON and built;
# its families of tests are then checked with the part's.
host_exe=(lammps src/lammps/lmp_reinforce liggghts src/liggghts/liggghts_reinforce)
exclude=() hosts=()
for ((k = 0; k < ${#host_exe[@]}; k += 2)); do
  h=${host_exe[k]} exe=$REINFORCE_BUILD/${host_exe[k + 1]}
  why=$(skip_reason "$h")
  if [ -n "$why" ]; then
    # the stability and quality tests, the benchmark's quick case and the
    # LIGGGHTS-against-LAMMPS comparisons run lmp_reinforce too (their
    # families in test_families.txt name the host lammps): left out with
    # it, and named in the summary
    also=()
    [ "$h" = lammps ] && also=("^stability_" "^bench_quick$" "^quality_" "^liggghts_same_stats_as_lammps")
    exclude+=("^${h}_" "${also[@]}")
    names=$(printf '%s\n' "^${h}_" "${also[@]}" | sed -E 's/^\^//; s/([^$])$/\1*/; s/\$$//' | paste -sd, - |
              sed 's/,/, /g')
    skipped+=("$h tests: $names (skipped on purpose: $why)")
    continue
  fi
  H=$(upper "$h")
  v=$(sed -n "s/^REINFORCE_${H}:[A-Z]*=//p" "$REINFORCE_BUILD/CMakeCache.txt" 2>/dev/null | tail -1)
  if ! [[ "$v" =~ ^(ON|1|YES|TRUE|Y|on|yes|true|y)$ ]]; then
    echo "test: FAILED: host $h expected but configured REINFORCE_${H}=${v:-unset} in $REINFORCE_BUILD" \
         "(REINFORCE_CMAKE_ARGS=${REINFORCE_CMAKE_ARGS:-}): only REINFORCE_SKIP=$h leaves a host out"
    parts+=("$h: FAILED: host configured OFF, its tests did not run")
    failed=$((failed + 1))
  elif [ ! -x "$exe" ]; then
    echo "test: FAILED: host $h expected but $exe was not built (not found at configure time?)." \
         "Install it, or skip it by name: REINFORCE_SKIP=$h"
    parts+=("$h: FAILED: host missing, its tests did not run")
    failed=$((failed + 1))
  else
    hosts+=("$h")    # its families are checked below
  fi
done

# The later parts (sanitizer, fuzz, source) are decided now, and their
# builds run in the background, one after the other and at a lower
# priority, while the main part's tests run: those mostly wait (MPI start-up,
# one another), leaving the cores idle. Each part waits for its own build.
run_sanitizer=0 run_fuzz=0 run_source=0
if [ "${REINFORCE_QUICK:-0}" = 1 ]; then
  skipped+=("sanitizer (REINFORCE_QUICK=1)" "fuzz (REINFORCE_QUICK=1)")
else
  for p in sanitizer fuzz; do
    if why=$(skip_reason "$p") && [ -n "$why" ]; then
      skipped+=("$p (skipped on purpose: $why)")
    else
      eval "run_$p=1"
    fi
  done
fi
# Part "source" runs when a tree is named: REINFORCE_LAMMPS_SOURCE and/or
# REINFORCE_LIGGGHTS_SOURCE, each a source tree or its .tar.gz (.ci/run names
# ../shared/hosts). A named tree that does not build fails the command.
if [ -z "${REINFORCE_LAMMPS_SOURCE:-}${REINFORCE_LIGGGHTS_SOURCE:-}" ]; then
  skipped+=("source (no host tree named: set REINFORCE_LAMMPS_SOURCE, REINFORCE_LIGGGHTS_SOURCE to a source tree or its .tar.gz)")
elif [ "${REINFORCE_QUICK:-0}" = 1 ]; then
  skipped+=("source (REINFORCE_QUICK=1)")
elif why=$(skip_reason source) && [ -n "$why" ]; then
  skipped+=("source (skipped on purpose: $why)")
else
  run_source=1
fi

san="$top/build-sanitize"
san_args=(-DREINFORCE_LIGGGHTS=OFF) san_targets=(core_tests make_scene check_scene) san_hosts=()
san_tests="^Kernel|^Engine|^Fix|^Schedule|^Summary|^Invocation|^CellGrid|^RoundRecords|^Totals|^Regrowth|^ExactSum|^stability_periodic_2x2x1_np4$|^stability_stiff|^lammps_identical_keep_2x2x1_np4$|^lammps_scene_eight_thin_subdomains_search_0.02_np8$|^lammps_identical_regrow_2x2x1_np4$"
if [ -n "$(skip_reason lammps)" ]; then
  san_args+=(-DREINFORCE_LAMMPS=OFF) san_tests="^Kernel|^Engine|^Fix|^Schedule|^Summary|^Invocation|^CellGrid|^RoundRecords|^Totals|^Regrowth|^ExactSum"
  [ "$run_sanitizer" = 0 ] || skipped+=("sanitizer: LAMMPS scenes (lammps skipped)")
else
  # ON explicitly: an OFF left in build-sanitize's cache must not drop the scenes
  san_args+=(-DREINFORCE_LAMMPS=ON) san_targets+=(lmp_reinforce) san_hosts+=(lammps)
fi
fuzz="$top/build-fuzz"
build_jobs=${REINFORCE_BUILD_JOBS:-$(nproc)}
# Through ccache as the main build (setup.sh).
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/reinforce-ccache}" CCACHE_BASEDIR="$top"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
build_sanitizer() {
  cmake -S "$top" -B "$san" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DREINFORCE_SANITIZE=ON "${launcher[@]}" \
    "${san_args[@]}" >/dev/null &&
    cmake --build "$san" -j"$build_jobs" --target "${san_targets[@]}"
}
build_fuzz() {
  CC=clang CXX=clang++ cmake -S "$top" -B "$fuzz" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DREINFORCE_FUZZ=ON -DREINFORCE_TESTS=OFF -DREINFORCE_LAMMPS=OFF -DREINFORCE_LIGGGHTS=OFF "${launcher[@]}" >/dev/null &&
    cmake --build "$fuzz" -j"$build_jobs"
}
build_source() { bash "$top/tests/source_hosts/prepare.sh" "$top/build-source"; }
ahead=$(mktemp -d)
(
  renice -n 10 -p "$BASHPID" >/dev/null 2>&1 || true    # inherited by the builds
  for p in sanitizer fuzz source; do
    v=run_$p
    [ "${!v}" = 1 ] || continue
    "build_$p" >"$ahead/$p.log" 2>&1
    echo $? >"$ahead/$p.rc"
  done
) &
ahead_pid=$!
# await PART: prints its build's output; its status is the build's.
await() {
  while [ ! -f "$ahead/$1.rc" ] && kill -0 "$ahead_pid" 2>/dev/null; do sleep 1; done
  cat "$ahead/$1.log" 2>/dev/null
  [ -f "$ahead/$1.rc" ] && return "$(cat "$ahead/$1.rc")"
  return 1
}

echo "== main build: all tests"
exclude_re=$(IFS='|'; echo "${exclude[*]}")
check_families main "$REINFORCE_BUILD" "${hosts[@]}" -- ${exclude_re:+-E "$exclude_re"} "$@"
part=main run_ctest "$REINFORCE_BUILD" ${exclude_re:+-E "$exclude_re"} "$@"

if [ "$run_sanitizer" = 1 ]; then
  echo "== sanitizer build (ASan + UBSan): core tests and MPI scenes"
  if await sanitizer; then
    check_families sanitizer "$san" "${san_hosts[@]}" -- -R "${REINFORCE_SANITIZE_TESTS:-$san_tests}"
    # Open MPI's own allocations are not ours to judge: no leak check.
    ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
      part=sanitizer run_ctest "$san" -R "${REINFORCE_SANITIZE_TESTS:-$san_tests}"
  else
    echo "sanitizer build failed"; failed=$((failed + 1)); parts+=("sanitizer: FAILED: build failed")
  fi
fi

if [ "$run_fuzz" = 1 ]; then
  echo "== fuzz build (clang, libFuzzer)"
  if await fuzz; then
    check_families fuzz "$fuzz" --
    part=fuzz run_ctest "$fuzz"
  else
    echo "fuzz build failed"; failed=$((failed + 1)); parts+=("fuzz: FAILED: build failed")
  fi
fi

# ---- part "source": hosts built from source (tests/source_hosts) -----------
if [ "$run_source" = 1 ]; then
  echo "== source-built hosts: LAMMPS (plugin, in-tree package, bigbig), LIGGGHTS (drop-in)"
  if await source; then
    src_hosts=()
    [ -z "${REINFORCE_LAMMPS_SOURCE:-}" ] || src_hosts+=(lammps_source)
    [ -z "${REINFORCE_LIGGGHTS_SOURCE:-}" ] || src_hosts+=(liggghts_source)
    check_families source "$top/build-source" "${src_hosts[@]}" -- -R '^src_'
    part=source run_ctest "$top/build-source" -R '^src_'
  else
    echo "source-built hosts: build failed"; failed=$((failed + 1))
    parts+=("source: FAILED: a named host tree did not unpack, configure or build (above)")
  fi
fi
wait "$ahead_pid" 2>/dev/null
rm -rf "$ahead"
# ---- end of part "source" ----------------------------------------------------

# More parts go above this line: `part=NAME run_ctest DIR [ctest args]` lists
# NAME with its counts in the summary; a part left out: skipped+=("NAME (why)").
summary; echo "total: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
