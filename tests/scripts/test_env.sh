# Sourced by the test scripts, after `set -euo pipefail`, as
#   . "$(dirname "${BASH_SOURCE[0]}")/[../scripts/]test_env.sh" NAME
# Open MPI may run as root and oversubscribe (2 cores, tests up to 8
# processes); `work` is a fresh directory named after NAME, removed on exit;
# split_lists parses the scripts' "-- A -- B -- C" arguments; read_errors
# and left_alone_line read a log's ERROR lines and a fix's "left alone" line.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "${TMPDIR:-/tmp}/${1:-test}.XXXXXX")
# Open MPI's session directory of this test's runs inside it, not in the
# /tmp/ompi.HOST.UID tree every mpirun on the machine shares: a run finishing
# there removes the shared top directory when it looks empty, under another
# run that is creating its own in it (that run stops at start-up with status
# 1, before the host has written a line), and a run killed there leaves
# files that a later run with the same job family (from its pid) meets.
export OMPI_MCA_orte_tmpdir_base="$work"

# show_runs: what the runs under $work printed (every file named log or
# stdout: the host's log, a run's stdout and stderr), or that there is
# none. On a failing exit it comes before the directory is removed, so a
# failed test says why even when the failure was a run that stopped early.
show_runs() {
  local files f
  files=$(find "$work" -type f \( -name log -o -name stdout \) 2>/dev/null | sort)
  grep -q '/log$' <<<"$files" || echo "---- no host log was written under $work"
  grep -q '/stdout$' <<<"$files" || echo "---- no run's stdout was kept under $work (printed above, if any)"
  while read -r f; do
    [ -n "$f" ] || continue
    if [ -s "$f" ]; then
      echo "---- ${f#"$work"/} (its last 60 lines):"
      tail -n 60 "$f"
    else
      echo "---- ${f#"$work"/}: empty"
    fi
  done <<<"$files"
}
trap 'status=$?; [ "$status" -eq 0 ] || show_runs; rm -rf "$work"; exit "$status"' EXIT

# split_lists -- A... -- B... -- C...: the three lists as the arrays
# list_a, list_b and list_c (a missing one empty).
split_lists() {
  list_a=() list_b=() list_c=()
  [ "${1:-}" = "--" ] && shift
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do list_a+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do list_b+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  list_c=("$@")
}

# read_errors LOG: errors (how many ERROR lines LOG has), line (the first)
# and message (that line but for "ERROR: " and the source location
# "(file:line)", the text an exact-message check compares).
read_errors() {
  errors=$(grep -c '^ERROR' "$1" || true)
  line=$(grep '^ERROR' "$1" | head -1 || true)
  message=$(sed -E 's/^ERROR: //; s/ \([^()]*:[0-9]+\)$//' <<<"$line")
}

# left_alone_line LOG FIX: the one line of LOG saying the fix left alone
# atoms that are rebar of fix FIX; with none or several, every "left alone"
# line to stderr and status 1.
left_alone_line() {
  local line
  line=$(grep -E "^fix reinforce/invert: left alone [0-9]+ atoms that overlap the bars: they are rebar of fix $2\$" "$1" || true)
  if [ -n "$line" ] && [ "$(grep -c . <<<"$line")" -eq 1 ]; then
    echo "$line"
    return 0
  fi
  grep 'left alone' "$1" >&2 || true
  return 1
}
