#!/usr/bin/env bash
# The checker's own tests: every check passes a good scene and fails a bad
# one, for the right reason (the exact FAIL line) and with exit status 1.
#
#   tests/tools/test_check_scene.sh [path/to/check_scene]
#
# Without an argument it compiles check_scene.cpp with g++ into a temporary
# directory. The scenes are the small hand-made dumps in testdata/ (box
# 0..10, rebar type 2, matrix radii 0.5 and 1; README.md describes each).
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
td=$here/testdata
if [ $# -ge 1 ]; then
  check=$1
else
  tmp=$(mktemp -d)
  g++ -std=c++17 -O2 -Wall -Wextra -o "$tmp/check_scene" "$here/check_scene.cpp" || exit 1
  check=$tmp/check_scene
fi

failed=0 cases=0
# expect STATUS PATTERN -- ARGS...: runs the checker, which must exit with
# STATUS and print a line matching PATTERN (grep -E).
expect() {
  local status=$1 pattern=$2
  shift 3
  cases=$((cases + 1))
  local out rc
  out=$("$check" "$@" 2>&1)
  rc=$?
  if [ "$rc" -ne "$status" ] || ! grep -Eq -- "$pattern" <<<"$out"; then
    failed=$((failed + 1))
    echo "not ok: check_scene $* (exit $rc, wanted $status and /$pattern/)"
    sed 's/^/    /' <<<"$out"
  else
    echo "ok: check_scene ${*//$td\//} -> $(grep -E -m1 -- "$pattern" <<<"$out")"
  fi
}
B=(--before "$td/before.dump")

# overlap of a moved sphere
expect 0 '^PASS: moved spheres overlap nothing' -- "${B[@]}" --after "$td/after_ok.dump" --deleted 0
expect 1 '^FAIL: moved spheres overlap nothing.*\(1 pairs' -- "${B[@]}" --after "$td/after_overlap.dump"
# ... across a periodic boundary (x is pp)
expect 0 '^PASS: moved spheres overlap nothing' -- --before "$td/before_periodic.dump" --after "$td/after_periodic_ok.dump"
expect 1 '^FAIL: moved spheres overlap nothing.*\(1 pairs' -- --before "$td/before_periodic.dump" --after "$td/after_periodic.dump"
# the packing's own overlaps: ignored where both spheres stay (by default,
# or said with --overlap-ok-before); --clean-before fails them
expect 0 '^INFO: 1 overlapping pairs of unmoved matrix spheres' -- --before "$td/before_packing.dump" --after "$td/after_packing_ok.dump"
expect 0 '^INFO: the packing before has 1 matrix-matrix overlaps above tol' -- --before "$td/before_packing.dump" --after "$td/after_packing_ok.dump" --overlap-ok-before
expect 1 '^FAIL: the packing before has no matrix-matrix overlap above tol \(1 pairs' -- --before "$td/before_packing.dump" --after "$td/after_packing_ok.dump" --clean-before
expect 0 '^PASS: the packing before has no matrix-matrix overlap above tol \(0 pairs' -- "${B[@]}" --after "$td/after_ok.dump" --clean-before
expect 1 '^FAIL: moved spheres overlap nothing.*\(1 pairs' -- --before "$td/before_packing.dump" --after "$td/after_packing_overlap.dump"
# a target left on the bar
expect 1 '^FAIL: no matrix sphere overlaps a bar \(1 unmoved' -- "${B[@]}" --after "$td/after_kept.dump"
expect 0 '^INFO: 1 kept targets still overlap a bar' -- "${B[@]}" --after "$td/after_kept.dump" --kept-ok
expect 0 '^INFO: 1 kept targets.*2 overlapping pairs with them ignored' -- "${B[@]}" --after "$td/after_kept_neighbour.dump" --kept-ok
expect 1 '^FAIL: moved spheres overlap nothing' -- "${B[@]}" --after "$td/after_kept_neighbour.dump"
# the overlap of a moved sphere with a kept target, as a figure (0.2 / rmin 0.5)
expect 0 '^SUMMARY .* kept 1 .*max_overlap_kept 0.4 ' -- "${B[@]}" --after "$td/after_kept_neighbour.dump" --kept-ok
expect 0 '^SUMMARY .* kept 1 .*max_overlap_kept 0 ' -- "${B[@]}" --after "$td/after_kept.dump" --kept-ok
# two moved spheres overlapping each other (0.1 = 0.2 rmin), nothing else
expect 1 '^FAIL: moved spheres overlap nothing.*\(1 pairs; largest 0.2 of rmin' -- "${B[@]}" --after "$td/after_two_moved_overlap.dump"
expect 1 '^FAIL: moved spheres overlap nothing.*\(1 pairs; largest 0.2 of rmin' -- "${B[@]}" --after "$td/after_two_moved_overlap.dump" --brute
# radius range: given, or the matrix range before by default
expect 0 '^PASS: moved radii in \[0.5, 1\] \(0 outside' -- "${B[@]}" --after "$td/after_ok.dump" --rmin 0.5 --rmax 1
expect 0 '^PASS: moved radii in \[0.5, 1\] \(the matrix range before\)' -- "${B[@]}" --after "$td/after_ok.dump"
expect 1 '^FAIL: moved radii in \[0.5, 1\] \(1 outside' -- "${B[@]}" --after "$td/after_radius.dump" --rmin 0.5 --rmax 1
expect 1 '^FAIL: moved radii in \[0.5, 0.8\] \(1 outside' -- "${B[@]}" --after "$td/after_ok.dump" --rmin 0.5 --rmax 0.8
# density (mass / volume) of moved spheres: radius 1 -> 0.8 with mass 1 -> 0.512, or mass unchanged
expect 0 '^PASS: moved spheres kept their density \(mass / volume\) \(0 of 1 changed; 1 with a new radius' -- "${B[@]}" --after "$td/after_mass_ok.dump"
expect 1 '^FAIL: moved spheres kept their density \(mass / volume\) \(1 of 1 changed' -- "${B[@]}" --after "$td/after_mass_wrong.dump"
# walls (ff dimensions)
expect 0 '^PASS: moved spheres wholly inside the walls' -- "${B[@]}" --after "$td/after_ok.dump"
expect 1 '^FAIL: moved spheres wholly inside the walls.*\(1 reach out' -- "${B[@]}" --after "$td/after_outside.dump"
# walls given on the command line: each is one line; only moved matrix
# spheres count (the target relocated to (5, 7, 5), radius 1; the unmoved
# sphere 3 at z = 2 lies below the planes z = 4 and 4.5 and is not failed)
expect 0 '^PASS: moved spheres clear of the walls \(plane through \(0, 0, 4\) normal \(0, 0, 1\): 0 of 1 moved' -- "${B[@]}" --after "$td/after_ok.dump" --wall-plane 0 0 4 0 0 1
expect 1 '^FAIL: moved spheres clear of the walls \(plane through \(0, 0, 4.5\) normal \(0, 0, 1\): 1 of 1 moved.*worst: id 2 reaches 0.5 of its radius' -- "${B[@]}" --after "$td/after_ok.dump" --wall-plane 0 0 4.5 0 0 1
# ... the normal points to the matrix side (any length)
expect 0 '^PASS: moved spheres clear of the walls \(plane through \(0, 0, 6\) normal \(0, 0, -3\)' -- "${B[@]}" --after "$td/after_ok.dump" --wall-plane 0 0 6 0 0 -3
expect 1 '^FAIL: moved spheres clear of the walls \(plane .*normal \(0, 0, -1\): 1 of 1 moved.*reaches 0.5 of its' -- "${B[@]}" --after "$td/after_ok.dump" --wall-plane 0 0 5.5 0 0 -1
# ... one line per wall, each failing on its own
expect 1 '^FAIL: moved spheres clear of the walls \(plane through \(0, 0, 4.5\)' -- "${B[@]}" --after "$td/after_ok.dump" --wall-plane 0 0 4 0 0 1 --wall-plane 0 0 4.5 0 0 1
expect 1 '^PASS: moved spheres clear of the walls \(plane through \(0, 0, 4\)' -- "${B[@]}" --after "$td/after_ok.dump" --wall-plane 0 0 4 0 0 1 --wall-plane 0 0 4.5 0 0 1
# a cylinder: inside or outside; the centre in the two other coordinates (x, y, z order)
expect 0 '^PASS: moved spheres clear of the walls \(cylinder along z through \(5, 5\) radius 3, spheres inside: 0 of 1' -- "${B[@]}" --after "$td/after_ok.dump" --wall-cylinder z 5 5 3 inside
expect 1 '^FAIL: moved spheres clear of the walls \(cylinder along z through \(5, 5\) radius 2.5, spheres inside: 1 of 1.*reaches 0.5 of' -- "${B[@]}" --after "$td/after_ok.dump" --wall-cylinder z 5 5 2.5 inside
expect 0 '^PASS: moved spheres clear of the walls \(cylinder along z through \(5, 5\) radius 1, spheres outside: 0 of 1' -- "${B[@]}" --after "$td/after_ok.dump" --wall-cylinder z 5 5 1 outside
expect 1 '^FAIL: moved spheres clear of the walls \(cylinder along z .*radius 1.5, spheres outside: 1 of 1.*reaches 0.5 of' -- "${B[@]}" --after "$td/after_ok.dump" --wall-cylinder z 5 5 1.5 outside
expect 0 '^PASS: moved spheres clear of the walls \(cylinder along x through \(7, 5\) radius 1, spheres inside' -- "${B[@]}" --after "$td/after_ok.dump" --wall-cylinder x 7 5 1 inside
expect 1 '^FAIL: moved spheres clear of the walls \(cylinder along x .*radius 0.9, spheres inside: 1 of 1.*reaches 0.1 of' -- "${B[@]}" --after "$td/after_ok.dump" --wall-cylinder x 7 5 0.9 inside
expect 1 '^FAIL: moved spheres clear of the walls \(cylinder along y through \(5, 5\) radius 1, spheres outside: 1 of 1.*reaches 2 of' -- "${B[@]}" --after "$td/after_ok.dump" --wall-cylinder y 5 5 1 outside
# a block region: wholly inside (INF: no bound)
expect 0 '^PASS: moved spheres clear of the walls \(inside box \[-inf, inf\] x \[6, inf\] x \[-inf, inf\]: 0 of 1' -- "${B[@]}" --after "$td/after_ok.dump" --inside-box -INF INF 6 INF -inf inf
expect 1 '^FAIL: moved spheres clear of the walls \(inside box \[0, 10\] x \[0, 7.5\] x \[0, 10\]: 1 of 1.*reaches 0.5 of' -- "${B[@]}" --after "$td/after_ok.dump" --inside-box 0 10 0 7.5 0 10
expect 1 '^FAIL: moved spheres clear of the walls \(inside box .*: 1 of 1.*reaches 0.2 of' -- "${B[@]}" --after "$td/after_ok.dump" --inside-box 4.2 10 0 10 0 10
# an STL (ASCII, keywords in any case): the exact distance to the face, an
# edge or a vertex, and the path of the centre (before to after) through a
# triangle; a periodic move takes the minimum image
expect 0 '^PASS: moved spheres clear of the walls \(STL .*wall_y8.5.stl, 2 triangles: 0 of 1 moved.*0 moved across a triangle; closest: id 2, clear by 0.5' -- "${B[@]}" --after "$td/after_ok.dump" --wall-stl "$td/wall_y8.5.stl"
expect 1 '^FAIL: moved spheres clear of the walls \(STL .*wall_y7.5.stl, 2 triangles: 1 of 1 moved.*, 0 moved across a triangle; worst: id 2 reaches 0.5 of' -- "${B[@]}" --after "$td/after_ok.dump" --wall-stl "$td/wall_y7.5.stl"
expect 1 '^FAIL: moved spheres clear of the walls \(STL .*wall_y6.stl, 2 triangles: 0 of 1 moved.*, 1 moved across a triangle' -- "${B[@]}" --after "$td/after_ok.dump" --wall-stl "$td/wall_y6.stl"
expect 0 '^PASS: moved spheres clear of the walls \(STL .*wall_y6_beside.stl.*0 of 1 moved.*0 moved across a triangle' -- "${B[@]}" --after "$td/after_ok.dump" --wall-stl "$td/wall_y6_beside.stl"
expect 1 '^FAIL: moved spheres clear of the walls \(STL .*wall_vertex.stl, 1 triangles: 1 of 1.*reaches 0.151 of' -- "${B[@]}" --after "$td/after_ok.dump" --wall-stl "$td/wall_vertex.stl"
expect 0 '^PASS: moved spheres clear of the walls \(STL .*wall_vertex_clear.stl, 1 triangles: 0 of 1.*clear by 0.131 of' -- "${B[@]}" --after "$td/after_ok.dump" --wall-stl "$td/wall_vertex_clear.stl"
expect 1 '^FAIL: moved spheres clear of the walls \(STL .*wall_edge.stl, 1 triangles: 1 of 1.*reaches 0.5 of' -- "${B[@]}" --after "$td/after_ok.dump" --wall-stl "$td/wall_edge.stl"
# ... the path lying in the triangle's plane, through it (the end clear by 0.097 r)
expect 1 '^FAIL: moved spheres clear of the walls \(STL .*wall_in_plane.stl, 1 triangles: 0 of 1 moved.*, 1 moved across a triangle; closest: id 2, clear by 0.0966' -- "${B[@]}" --after "$td/after_ok.dump" --wall-stl "$td/wall_in_plane.stl"
expect 1 '^FAIL: moved spheres clear of the walls \(STL .*wall_x0.5.stl.*0 of 1 moved.*, 1 moved across a triangle' -- --before "$td/before_wrap.dump" --after "$td/after_wrap.dump" --wall-stl "$td/wall_x0.5.stl"
expect 0 '^PASS: moved spheres clear of the walls \(STL .*wall_x5.stl.*0 of 1 moved.*, 0 moved across a triangle' -- --before "$td/before_wrap.dump" --after "$td/after_wrap.dump" --wall-stl "$td/wall_x5.stl"
# no moved sphere: nothing to fail
expect 0 '^PASS: moved spheres clear of the walls \(plane .*: 0 of 0 moved matrix spheres reach through by more than tol\)$' -- "${B[@]}" --after "$td/after_deleted.dump" --wall-plane 0 0 9 0 0 1
# several rebar types (two crossing bars, types 2 and 3): with both, the bars'
# overlap is no matrix on a bar, and a moved sphere of either bar fails
expect 1 '^FAIL: no matrix sphere overlaps a bar \(1 unmoved' -- --before "$td/before_two_bars.dump" --after "$td/after_two_bars_ok.dump"
expect 0 '^PASS: no matrix sphere overlaps a bar \(0 unmoved' -- --before "$td/before_two_bars.dump" --after "$td/after_two_bars_ok.dump" --rebar-type 2,3
expect 0 '^PASS: rebar untouched \(0 missing, 0 moved' -- --before "$td/before_two_bars.dump" --after "$td/after_two_bars_moved.dump"
expect 1 '^FAIL: rebar untouched \(0 missing, 1 moved' -- --before "$td/before_two_bars.dump" --after "$td/after_two_bars_moved.dump" --rebar-type 2,3
expect 1 '^FAIL: rebar untouched \(0 missing, 1 moved' -- --before "$td/before_two_bars.dump" --after "$td/after_two_bars_moved.dump" --rebar-type 2 --rebar-type 3
expect 0 '^atoms 4 matrix 2 max_matrix_rebar 0.5 max_matrix_matrix 0$' -- --stats "$td/before_two_bars.dump" --rebar-type 3,2 --rmin 1
expect 0 '^atoms 4 matrix 3 ' -- --stats "$td/before_two_bars.dump" --rmin 1
# rebar untouched
expect 0 '^PASS: rebar untouched' -- "${B[@]}" --after "$td/after_ok.dump"
expect 1 '^FAIL: rebar untouched \(0 missing, 1 moved' -- "${B[@]}" --after "$td/after_rebar_moved.dump"
expect 1 '^FAIL: rebar untouched \(1 missing' -- "${B[@]}" --after "$td/after_rebar_deleted.dump"
expect 1 "^FAIL: rebar untouched \(0 missing, 1 moved, 1 new" -- "${B[@]}" --after "$td/after_new.dump" --rebar-type 1
# conservation of atoms
expect 0 '^PASS: atoms before = after \+ deleted \(4 = 3 \+ 1' -- "${B[@]}" --after "$td/after_deleted.dump" --deleted 1
expect 0 '^SUMMARY atoms_before 4 atoms_after 3 moved 0 deleted 1' -- "${B[@]}" --after "$td/after_deleted.dump"
expect 1 '^FAIL: atoms before = after \+ deleted \(4 = 3 \+ 0 expected' -- "${B[@]}" --after "$td/after_deleted.dump" --deleted 0
expect 1 '^FAIL: atoms before = after \+ deleted \(4 = 4 \+ 1 expected' -- "${B[@]}" --after "$td/after_ok.dump" --deleted 1
expect 1 '^FAIL: no new or retyped atoms \(1 new' -- "${B[@]}" --after "$td/after_new.dump"
# several snapshots: the last counts
expect 0 '^SUMMARY atoms_before 4 atoms_after 4 moved 1 deleted 0' -- "${B[@]}" --after "$td/after_multi.dump"
# --same: identical text of id type x y z radius, any order of lines or columns
expect 0 '^PASS: identical atoms' -- --same "$td/after_ok.dump" "$td/after_ok_shuffled.dump"
expect 0 '^PASS: identical atoms' -- --same "$td/after_ok.dump" "$td/after_multi.dump"
expect 1 "^FAIL: identical atoms.*first difference: '2 1 5 7 5 1' vs '2 1 5 6.5 5 1'" -- --same "$td/after_ok.dump" "$td/after_overlap.dump"
expect 1 '^FAIL: identical atoms.*4 vs 3 atoms' -- --same "$td/after_ok.dump" "$td/after_deleted.dump"
# --stats (one line, parsed by bench/run.sh) and --packing
expect 0 '^atoms 4 matrix 3 max_matrix_rebar 1 max_matrix_matrix 0$' -- --stats "$td/before.dump" --rmin 0.5
expect 0 '^largest overlap / rmin: matrix-matrix 0.2, matrix-rebar 1' -- --packing "$td/before_packing.dump"
# The cell grid against brute force on random scenes of thousands of
# spheres (polydisperse, overlapping, walls and periodic dimensions, a box
# only two cells wide, a sparse scene whose cells are enlarged, atoms just
# outside a periodic box): the same contacts, the same overlaps. With cells
# too small (--grid-scale 0.4) the comparison must fail.
# random_dump FILE SEED N FLAGS LX LY LZ RLO RHI NBIG RBIG
random_dump() {
  awk -v seed="$2" -v n="$3" -v flags="$4" -v lx="$5" -v ly="$6" -v lz="$7" \
      -v rlo="$8" -v rhi="$9" -v nbig="${10}" -v rbig="${11}" 'BEGIN {
    srand(seed); split(flags, f, " "); len[1] = lx; len[2] = ly; len[3] = lz
    total = n + nbig + 8
    printf "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS %s\n", total, flags
    printf "0 %s\n0 %s\n0 %s\nITEM: ATOMS id type x y z radius\n", lx, ly, lz
    for (i = 1; i <= n + nbig; i++)
      printf "%d %d %.17g %.17g %.17g %.17g\n", i, 1 + (i % 5 == 0), rand() * lx, rand() * ly, rand() * lz,
             (i > n ? rbig : rlo + (rhi - rlo) * rand())
    # planted contacts: a pair across each face (periodic: through it), and
    # atoms a little outside the box
    id = n + nbig
    for (k = 1; k <= 3; k++) {
      for (m = 1; m <= 3; m++) p[m] = len[m] / 2
      p[k] = 0.01 * rhi; q = len[k] - 0.01 * rhi
      printf "%d 1 %.17g %.17g %.17g %.17g\n", ++id, p[1], p[2], p[3], rhi
      p[k] = f[k] == "pp" ? q : p[k] + rhi
      printf "%d 1 %.17g %.17g %.17g %.17g\n", ++id, p[1], p[2], p[3], rhi
    }
    printf "%d 1 %.17g %.17g %.17g %.17g\n", ++id, lx + 0.001 * rhi, ly / 3, lz / 3, rhi
    printf "%d 1 %.17g %.17g %.17g %.17g\n", ++id, -0.001 * rhi, ly / 3, lz / 3, rhi
  }' >"$1"
}
rnd=$(mktemp -d)
trap 'rm -rf "$rnd" ${tmp:+"$tmp"}' EXIT
random_dump "$rnd/walls.dump" 1 5000 "ff ff ff" 6 6 6 0.05 0.3 0 0
random_dump "$rnd/periodic.dump" 2 5000 "pp pp pp" 6 6 6 0.05 0.3 20 1.0
random_dump "$rnd/two_cells.dump" 3 3000 "pp ff pp" 2.5 8 6 0.1 0.5 0 0
random_dump "$rnd/sparse.dump" 4 2000 "pp ff ff" 1000 1000 1000 0.01 0.05 0 0
random_dump "$rnd/wide_radii.dump" 5 4000 "ff pp ff" 8 8 8 0.01 0.2 30 2.0
for scene in walls periodic two_cells sparse wide_radii; do
  expect 0 "^PASS: the grid finds the [1-9][0-9]* contacts brute force finds.*\(0 missed, 0 extra, 0 twice, 0 with" \
    -- --compare-grid "$rnd/$scene.dump"
done
expect 1 '^FAIL: the grid finds the [0-9]+ contacts brute force finds.*\([1-9][0-9]* missed' \
  -- --compare-grid "$rnd/walls.dump" --grid-scale 0.4
expect 1 '^FAIL: the grid finds the [0-9]+ contacts brute force finds.*\([1-9][0-9]* missed' \
  -- --compare-grid "$rnd/periodic.dump" --grid-scale 0.4
# the full check by brute force gives what the grid gives
cmp <("$check" --before "$rnd/walls.dump" --after "$rnd/periodic.dump" 2>&1) \
    <("$check" --before "$rnd/walls.dump" --after "$rnd/periodic.dump" --brute 2>&1) >/dev/null &&
  echo "ok: the full check, grid and --brute: the same output" ||
  { failed=$((failed + 1)); echo "not ok: the full check differs with --brute"; }
cases=$((cases + 1))

# bad usage and unreadable input: exit status 2
expect 2 'unknown option --frobnicate' -- --frobnicate
expect 2 'cannot read' -- --before "$td/no_such.dump" --after "$td/after_ok.dump"
expect 2 'need --before and --after' -- --before "$td/before.dump"
expect 2 'a facet needs exactly three vertices' -- "${B[@]}" --after "$td/after_ok.dump" --wall-stl "$td/wall_bad.stl"
expect 2 'no facet' -- "${B[@]}" --after "$td/after_ok.dump" --wall-stl "$td/before.dump"
expect 2 'axis must be x, y or z' -- "${B[@]}" --after "$td/after_ok.dump" --wall-cylinder w 0 0 1 inside
expect 2 'expected inside or outside' -- "${B[@]}" --after "$td/after_ok.dump" --wall-cylinder z 0 0 1 in
expect 2 'the normal must not be zero' -- "${B[@]}" --after "$td/after_ok.dump" --wall-plane 0 0 0 0 0 0
expect 2 'low bound must be below' -- "${B[@]}" --after "$td/after_ok.dump" --inside-box 0 10 5 5 0 10
expect 2 'missing value for --inside-box' -- "${B[@]}" --after "$td/after_ok.dump" --inside-box 0 10 0

echo "$((cases - failed)) of $cases cases passed"
[ "$failed" -eq 0 ]
