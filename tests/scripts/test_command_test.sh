#!/usr/bin/env bash
# The test command's own test (scripts/test.sh and scripts/setup.sh), run in
# scratch copies so that nothing of the real build is touched; a few
# seconds. Each case runs the test command and asserts its exit status and
# the lines it must print:
#  * a failed package install (apt-get faked to fail), a failed configure, a
#    failed build (the real core with an #error): non-zero, "setup: FAILED",
#    no test run, and the closing total line;
#  * a missing host (a fake project that builds lmp_reinforce but not
#    liggghts_reinforce): non-zero, the host named; skipped by name
#    (REINFORCE_SKIP=liggghts): zero, the skip named, the host's tests not
#    run. Nothing else skips it: -DREINFORCE_LIGGGHTS=OFF in
#    REINFORCE_CMAKE_ARGS fails the command, naming REINFORCE_SKIP; an OFF
#    left in the build's CMake cache is configured ON again (the host's tests
#    run, or the host is missing);
#  * a family of tests short of its minimum (scripts/test_families.txt; the
#    fake project's own table): non-zero, the family named;
#  * a failing test: counted (the command goes on to the end: per-part
#    counts, "total: N passed, M failed"), non-zero.
#   test_command_test.sh
set -uo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
# The caller's settings (an outer test command) must not leak in.
unset "${!REINFORCE_@}"
w=$(mktemp -d "${TMPDIR:-/tmp}/test_command.XXXXXX")
trap 'rm -rf "$w"' EXIT
failed=0 cases=0

# Fake package tools: every package installed (bin_ok), or none, with
# apt-get install failing (bin_broken_apt). sudo runs the command.
mkdir -p "$w/bin_ok" "$w/bin_broken_apt"
printf '#!/bin/sh\nexit 0\n' >"$w/bin_ok/dpkg"
printf '#!/bin/sh\nexit 1\n' >"$w/bin_broken_apt/dpkg"
printf '#!/bin/sh\n[ "$1" = update ] && exit 0\necho "E: Unable to locate package (fake)" >&2\nexit 100\n' \
  >"$w/bin_broken_apt/apt-get"
for d in bin_ok bin_broken_apt; do printf '#!/bin/sh\nexec "$@"\n' >"$w/$d/sudo"; done
chmod +x "$w"/bin_*/*

# A fake project: lmp_reinforce and a passing lammps_ test always, and a
# unit test (none with -DFAKE_NO_UNIT=ON); with -DFAKE_LIGGGHTS=ON also
# liggghts_reinforce and a liggghts_ test (failing with
# -DFAKE_LIGGGHTS_FAILS=ON); -DFAKE_BROKEN=ON: the configure fails. Its
# family table asks for one test of each.
fake=$w/fake
mkdir -p "$fake/scripts"
cp "$top/scripts/setup.sh" "$top/scripts/test.sh" "$top/scripts/count_families.sh" "$fake/scripts/"
cat >"$fake/scripts/test_families.txt" <<'EOF'
# part host min regex family (the fake project's)
main  -         1  ^[A-Z][A-Za-z0-9]*\.  fake unit tests
main  lammps    1  ^lammps_             fake lammps tests
main  liggghts  1  ^liggghts_           fake liggghts tests
EOF
cat >"$fake/CMakeLists.txt" <<'EOF'
cmake_minimum_required(VERSION 3.16)
project(fake NONE)
option(REINFORCE_LAMMPS "" ON)
option(REINFORCE_LIGGGHTS "" ON)
option(FAKE_LIGGGHTS "" OFF)
option(FAKE_LIGGGHTS_FAILS "" OFF)
option(FAKE_BROKEN "" OFF)
option(FAKE_NO_UNIT "" OFF)
option(FAKE_LAMMPS_USERS "" OFF)
if(FAKE_BROKEN)
  message(FATAL_ERROR "deliberately broken configure")
endif()
enable_testing()
function(fake_exe path)
  file(WRITE ${CMAKE_BINARY_DIR}/${path} "#!/bin/sh\n")
  file(CHMOD ${CMAKE_BINARY_DIR}/${path} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
endfunction()
fake_exe(src/lammps/lmp_reinforce)
add_test(NAME lammps_fake COMMAND true)
if(NOT FAKE_NO_UNIT)
  add_test(NAME Unit.Fake COMMAND true)
endif()
# Tests outside lammps_ that run lmp_reinforce: failing, so that running
# them when lammps is skipped fails the case.
if(FAKE_LAMMPS_USERS)
  foreach(t stability_fake bench_quick quality_fake liggghts_same_stats_as_lammps_fake)
    add_test(NAME ${t} COMMAND false)
  endforeach()
endif()
if(REINFORCE_LIGGGHTS AND FAKE_LIGGGHTS)
  fake_exe(src/liggghts/liggghts_reinforce)
  if(FAKE_LIGGGHTS_FAILS)
    add_test(NAME liggghts_fake COMMAND false)
  else()
    add_test(NAME liggghts_fake COMMAND true)
  endif()
endif()
EOF

# The real core, deliberately broken: the first source file does not compile.
real=$w/real
mkdir -p "$real/src"
cp -r "$top/CMakeLists.txt" "$top/cmake" "$top/scripts" "$top/bench" "$real/"
cp -r "$top/src/core" "$top/src/layout" "$real/src/"
first=$(sed -n 's|^ *\(src/core/[a-z_]*\.cpp\)$|\1|p; s|^add_library(reinforce_core STATIC *\(src/core/[a-z_]*\.cpp\).*|\1|p' \
        "$real/CMakeLists.txt" | head -1)
[ -n "$first" ] || first=src/core/reinforce_tangent_sphere.cpp
sed -i '1i #error deliberately broken by tests/scripts/test_command_test.sh' "$real/$first"

# expect NAME STATUS(0|nonzero) DIR BIN [VAR=value ...] -- PATTERN... [-- !PATTERN...]
# Runs DIR/scripts/test.sh with PATH=BIN:$PATH and the variables; each
# PATTERN (grep -E) must match a line of its output, each !PATTERN none.
expect() {
  local name=$1 want=$2 dir=$3 bin=$4
  shift 4
  local vars=()
  while [ "$1" != "--" ]; do vars+=("$1"); shift; done
  shift
  cases=$((cases + 1))
  local out rc bad=""
  out=$(env PATH="$w/$bin:$PATH" REINFORCE_QUICK=1 REINFORCE_BUILD_JOBS=1 \
        REINFORCE_BUILD_DIR="$w/build_$name" "${vars[@]}" bash "$dir/scripts/test.sh" 2>&1)
  rc=$?
  if [ "$want" = 0 ] && [ "$rc" -ne 0 ]; then bad="exit $rc, wanted 0"; fi
  if [ "$want" != 0 ] && [ "$rc" -eq 0 ]; then bad="exit 0, wanted non-zero"; fi
  local p
  for p in "$@"; do
    if [ "${p:0:1}" = '!' ]; then
      grep -Eq -- "${p:1}" <<<"$out" && bad+="${bad:+; }printed /${p:1}/"
    else
      grep -Eq -- "$p" <<<"$out" || bad+="${bad:+; }no line /$p/"
    fi
  done
  [ "$(tail -1 <<<"$out" | grep -Ec '^total: [0-9]+ passed, [0-9]+ failed$')" -eq 1 ] ||
    bad+="${bad:+; }the last line is not 'total: N passed, M failed'"
  if [ -n "$bad" ]; then
    failed=$((failed + 1))
    echo "not ok: $name: $bad"
    sed 's/^/    /' <<<"$out" | tail -40
  else
    echo "ok: $name (exit $rc): $(tail -1 <<<"$out")"
  fi
}

# 1. A failed install, configure or build stops the command: no test runs.
expect install_fails nonzero "$fake" bin_broken_apt -- \
  '^setup: FAILED: apt-get install' '^test: FAILED: setup' '^total: 0 passed, 1 failed$' '!^== main build'
expect configure_fails nonzero "$fake" bin_ok REINFORCE_CMAKE_ARGS=-DFAKE_BROKEN=ON -- \
  '^setup: FAILED: cmake configure' '^total: 0 passed, 1 failed$' '!^== main build'
expect build_fails nonzero "$real" bin_ok \
  "REINFORCE_CMAKE_ARGS=-DREINFORCE_LAMMPS=OFF -DREINFORCE_LIGGGHTS=OFF -DREINFORCE_TESTS=OFF" -- \
  'deliberately broken' '^setup: FAILED: build in' '^test: FAILED: setup' '^total: 0 passed, 1 failed$' \
  '!^== main build'
# 2. A missing host fails the command, unless skipped by name.
expect host_missing nonzero "$fake" bin_ok -- \
  '^test: FAILED: host liggghts expected but .*liggghts_reinforce was not built.*REINFORCE_SKIP=liggghts' \
  '^  main: 2 tests, 2 passed, 0 failed \(lammps 1, unit 1\)' '^  liggghts: FAILED: host missing' \
  '^  skipped: sanitizer \(REINFORCE_QUICK=1\)' '^total: 2 passed, 1 failed$'
expect host_skipped_by_name 0 "$fake" bin_ok REINFORCE_SKIP=liggghts -- \
  '^  main: 2 tests, 2 passed, 0 failed' \
  '^  skipped: liggghts tests: liggghts_\* \(skipped on purpose: REINFORCE_SKIP=liggghts\)' '^total: 2 passed, 0 failed$'
# Only REINFORCE_SKIP skips: an OFF in REINFORCE_CMAKE_ARGS fails the command...
expect host_off_in_cmake nonzero "$fake" bin_ok REINFORCE_CMAKE_ARGS=-DREINFORCE_LIGGGHTS=OFF -- \
  '^test: FAILED: host liggghts expected but configured REINFORCE_LIGGGHTS=OFF .*only REINFORCE_SKIP=liggghts' \
  '^  liggghts: FAILED: host configured OFF' '!^  skipped: liggghts' '^total: 2 passed, 1 failed$'
expect host_off_in_cmake_skipped 0 "$fake" bin_ok REINFORCE_SKIP=liggghts REINFORCE_CMAKE_ARGS=-DREINFORCE_LIGGGHTS=OFF -- \
  '^  skipped: liggghts tests: liggghts_\* \(skipped on purpose: REINFORCE_SKIP=liggghts\)' '^total: 2 passed, 0 failed$'
# ... and an OFF left in the build's cache by an earlier configure is
# configured ON again: the host's tests run, or its absence fails the command.
cmake -S "$fake" -B "$w/build_stale_cache_built" -DREINFORCE_LIGGGHTS=OFF -DFAKE_LIGGGHTS=ON >/dev/null
expect stale_cache_built 0 "$fake" bin_ok -- \
  '^  main: 3 tests, 3 passed, 0 failed \(lammps 1, liggghts 1, unit 1\)' '^total: 3 passed, 0 failed$' \
  '!^  skipped: liggghts'
cmake -S "$fake" -B "$w/build_stale_cache_missing" -DREINFORCE_LIGGGHTS=OFF >/dev/null
expect stale_cache_missing nonzero "$fake" bin_ok -- \
  '^test: FAILED: host liggghts expected but .*liggghts_reinforce was not built.*REINFORCE_SKIP=liggghts' \
  '!^  skipped: liggghts' '^total: 2 passed, 1 failed$'
expect host_present 0 "$fake" bin_ok REINFORCE_CMAKE_ARGS=-DFAKE_LIGGGHTS=ON -- \
  '^  main: 3 tests, 3 passed, 0 failed \(lammps 1, liggghts 1, unit 1\)' '^total: 3 passed, 0 failed$' \
  '!^  skipped: liggghts'
# A host built but skipped by name: its tests are not run.
expect host_built_skipped 0 "$fake" bin_ok REINFORCE_SKIP=liggghts \
  "REINFORCE_CMAKE_ARGS=-DFAKE_LIGGGHTS=ON -DFAKE_LIGGGHTS_FAILS=ON" -- \
  '^total: 2 passed, 0 failed$' '!liggghts_fake'
# Skipping lammps also leaves out the other tests that run lmp_reinforce.
expect lammps_skipped_all_its_users 0 "$fake" bin_ok REINFORCE_SKIP=lammps \
  "REINFORCE_CMAKE_ARGS=-DFAKE_LIGGGHTS=ON -DFAKE_LAMMPS_USERS=ON" -- \
  '^  skipped: lammps tests: lammps_\*, stability_\*, bench_quick, quality_\*, liggghts_same_stats_as_lammps\* \(skipped on purpose: REINFORCE_SKIP=lammps\)' \
  '^  main: 2 tests, 2 passed, 0 failed \(liggghts 1, unit 1\)' '^total: 2 passed, 0 failed$' \
  '!Test +#[0-9]+: ((stability|quality|liggghts_same_stats_as_lammps)_fake|bench_quick)'
# 3. A family of tests short of its minimum fails the command, named (the
# fake's unit test not registered; liggghts skipped, so that nothing else
# fails).
expect family_short nonzero "$fake" bin_ok REINFORCE_SKIP=liggghts REINFORCE_CMAKE_ARGS=-DFAKE_NO_UNIT=ON -- \
  "^test: FAILED: part main: family 'fake unit tests' .*: 0 tests, expected at least 1$" \
  '^  family main: fake lammps tests: 1 tests' '!family main: fake liggghts' \
  '^  main: FAILED: families short' '^total: 1 passed, 1 failed$'
# 4. A failing test is counted, and the command goes on to its summary.
expect test_fails nonzero "$fake" bin_ok "REINFORCE_CMAKE_ARGS=-DFAKE_LIGGGHTS=ON -DFAKE_LIGGGHTS_FAILS=ON" -- \
  '^  main: 3 tests, 2 passed, 1 failed' '^== tests run per part' '^total: 2 passed, 1 failed$'

echo "$((cases - failed)) of $cases cases passed"
[ "$failed" -eq 0 ] && echo "PASS: the test command stops on a failed setup and on a missing host"
[ "$failed" -eq 0 ]
