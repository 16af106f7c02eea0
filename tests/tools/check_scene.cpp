// Checks a scene written by LAMMPS or LIGGGHTS before and after fix
// reinforce/invert (text dumps: `dump ... custom ... id type x y z radius
// [mass]`, sorted or not; the last snapshot of a file is used).
//
//   check_scene --before B --after A [--rebar-type T] [--tol 1e-6]
//               [--rmin R --rmax R] [--deleted N] [--kept-ok]
//       asserts: no moved sphere overlaps any sphere by more than
//       tol * min(r_i, r_j); no matrix sphere overlaps a rebar sphere
//       (unless --kept-ok: targets left in place); moved radii in
//       [rmin, rmax]; rebar untouched; no new atoms, types unchanged;
//       before = after + deleted (and deleted = N if given).
//   check_scene --same A B      the two dumps hold identical atoms (text)
//   check_scene --stats D [--rebar-type T] [--rmin R]
//       prints the largest overlaps (matrix-rebar, matrix-matrix), no test
//
// Periodic dimensions (BOX BOUNDS flag p) use the minimum image. Exit
// status 0 = every check passed, 1 = a check failed, 2 = bad usage/input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

struct Atom {
  long id = 0;
  int type = 0;
  double x[3] = {0, 0, 0};
  double r = 0;
  std::string text;    // the dump line, for --same
};

struct Dump {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool periodic[3] = {false, false, false};
  std::vector<Atom> atoms;    // sorted by id
};

[[noreturn]] void bad(const std::string &why)
{
  std::fprintf(stderr, "check_scene: %s\n", why.c_str());
  std::exit(2);
}

Dump read_dump(const std::string &path)
{
  std::ifstream in(path);
  if (!in) bad("cannot read " + path);
  Dump last;
  std::string line;
  bool any = false;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM: NUMBER OF ATOMS", 0) == 0) {
      Dump d;
      long n = 0;
      if (!(in >> n)) bad(path + ": bad atom count");
      std::getline(in, line);
      std::getline(in, line);
      if (line.rfind("ITEM: BOX BOUNDS", 0) != 0) bad(path + ": no BOX BOUNDS");
      std::istringstream flags(line.substr(16));
      for (int k = 0; k < 3; ++k) {
        std::string f;
        flags >> f;
        d.periodic[k] = f == "pp";
      }
      for (int k = 0; k < 3; ++k) {
        std::getline(in, line);
        std::istringstream b(line);
        if (!(b >> d.lo[k] >> d.hi[k])) bad(path + ": bad box bounds");
      }
      std::getline(in, line);
      if (line.rfind("ITEM: ATOMS", 0) != 0) bad(path + ": no ATOMS header");
      std::istringstream cols(line.substr(11));
      std::map<std::string, int> col;
      std::string name;
      for (int c = 0; cols >> name; ++c) col[name] = c;
      for (const char *need : {"id", "type", "x", "y", "z", "radius"})
        if (!col.count(need)) bad(path + ": dump lacks column " + need);
      for (long a = 0; a < n; ++a) {
        if (!std::getline(in, line)) bad(path + ": truncated");
        std::istringstream v(line);
        std::vector<std::string> f;
        std::string w;
        while (v >> w) f.push_back(w);
        if (static_cast<int>(f.size()) < static_cast<int>(col.size())) bad(path + ": short line");
        Atom at;
        at.id = std::stol(f[col["id"]]);
        at.type = std::stoi(f[col["type"]]);
        at.x[0] = std::stod(f[col["x"]]);
        at.x[1] = std::stod(f[col["y"]]);
        at.x[2] = std::stod(f[col["z"]]);
        at.r = std::stod(f[col["radius"]]);
        std::ostringstream t;
        for (const std::string &s : f) t << s << ' ';
        at.text = t.str();
        d.atoms.push_back(at);
      }
      std::sort(d.atoms.begin(), d.atoms.end(),
                [](const Atom &a, const Atom &b) { return a.id < b.id; });
      last = d;
      any = true;
    }
  }
  if (!any) bad(path + ": no snapshot");
  return last;
}

// Calls f(i, j, overlap) for every pair closer than r_i + r_j (i < j),
// minimum image in periodic dimensions, via a cell grid.
template <class F> void for_each_contact(const Dump &d, F &&f)
{
  const std::vector<Atom> &a = d.atoms;
  double rmax = 0;
  for (const Atom &at : a) rmax = std::max(rmax, at.r);
  if (a.empty() || !(rmax > 0)) return;
  const double cell = 2 * rmax;
  long n[3];
  double size[3];
  for (int k = 0; k < 3; ++k) {
    const double len = d.hi[k] - d.lo[k];
    n[k] = d.periodic[k] ? std::max(1L, static_cast<long>(len / cell)) : 0;
    size[k] = d.periodic[k] ? len / n[k] : cell;
  }
  auto coord = [&](const double *x, int k) {
    long c = static_cast<long>(std::floor((x[k] - d.lo[k]) / size[k]));
    if (d.periodic[k]) c = ((c % n[k]) + n[k]) % n[k];
    return c;
  };
  auto key = [](long i, long j, long k) {
    return (i * 73856093L) ^ (j * 19349663L) ^ (k * 83492791L);
  };
  std::unordered_map<long, std::vector<int>> grid;
  for (std::size_t i = 0; i < a.size(); ++i)
    grid[key(coord(a[i].x, 0), coord(a[i].x, 1), coord(a[i].x, 2))].push_back(static_cast<int>(i));
  for (std::size_t i = 0; i < a.size(); ++i) {
    long c[3];
    for (int k = 0; k < 3; ++k) c[k] = coord(a[i].x, k);
    std::vector<long> range[3];
    for (int k = 0; k < 3; ++k) {
      for (long dc = -1; dc <= 1; ++dc) {
        long v = c[k] + dc;
        if (d.periodic[k]) v = ((v % n[k]) + n[k]) % n[k];
        if (std::find(range[k].begin(), range[k].end(), v) == range[k].end()) range[k].push_back(v);
      }
    }
    for (long ci : range[0])
      for (long cj : range[1])
        for (long ck : range[2]) {
          auto it = grid.find(key(ci, cj, ck));
          if (it == grid.end()) continue;
          for (int j : it->second) {
            if (j <= static_cast<int>(i)) continue;
            double dist2 = 0;
            for (int k = 0; k < 3; ++k) {
              double dx = a[i].x[k] - a[j].x[k];
              if (d.periodic[k]) {
                const double len = d.hi[k] - d.lo[k];
                dx -= len * std::round(dx / len);
              }
              dist2 += dx * dx;
            }
            const double overlap = a[i].r + a[j].r - std::sqrt(dist2);
            if (overlap > 0) f(static_cast<int>(i), j, overlap);
          }
        }
  }
}

const Atom *find(const Dump &d, long id)
{
  auto it = std::lower_bound(d.atoms.begin(), d.atoms.end(), id,
                             [](const Atom &a, long v) { return a.id < v; });
  return it != d.atoms.end() && it->id == id ? &*it : nullptr;
}

int failures = 0;
void check(bool ok, const std::string &what)
{
  std::printf("%s: %s\n", ok ? "PASS" : "FAIL", what.c_str());
  if (!ok) ++failures;
}

std::string num(double v)
{
  char b[64];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

}    // namespace

int main(int argc, char **argv)
{
  std::string before_path, after_path, same_a, same_b, stats_path;
  int rebar_type = 2;
  double tol = 1e-6, rmin = 0, rmax = 0;
  long expect_deleted = -1;
  bool kept_ok = false;
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) bad("missing value for " + k);
      return argv[++i];
    };
    if (k == "--before")
      before_path = next();
    else if (k == "--after")
      after_path = next();
    else if (k == "--rebar-type")
      rebar_type = std::atoi(next().c_str());
    else if (k == "--tol")
      tol = std::atof(next().c_str());
    else if (k == "--rmin")
      rmin = std::atof(next().c_str());
    else if (k == "--rmax")
      rmax = std::atof(next().c_str());
    else if (k == "--deleted")
      expect_deleted = std::atol(next().c_str());
    else if (k == "--kept-ok")
      kept_ok = true;
    else if (k == "--same") {
      same_a = next();
      same_b = next();
    } else if (k == "--stats")
      stats_path = next();
    else
      bad("unknown option " + k);
  }

  if (!same_a.empty()) {
    const Dump a = read_dump(same_a), b = read_dump(same_b);
    bool same = a.atoms.size() == b.atoms.size();
    for (std::size_t i = 0; same && i < a.atoms.size(); ++i)
      same = a.atoms[i].text == b.atoms[i].text;
    check(same, "identical atoms in " + same_a + " and " + same_b);
    return failures ? 1 : 0;
  }

  if (!stats_path.empty()) {
    const Dump d = read_dump(stats_path);
    double mr = 0, mm = 0, smallest = INFINITY;
    long nm = 0;
    for (const Atom &a : d.atoms) {
      if (a.type != rebar_type) {
        smallest = std::min(smallest, a.r);
        ++nm;
      }
    }
    if (rmin <= 0) rmin = smallest;
    for_each_contact(d, [&](int i, int j, double o) {
      const bool ri = d.atoms[i].type == rebar_type, rj = d.atoms[j].type == rebar_type;
      if (ri && rj) return;
      (ri || rj ? mr : mm) = std::max(ri || rj ? mr : mm, o / rmin);
    });
    std::printf("atoms %zu matrix %ld max_matrix_rebar %.6g max_matrix_matrix %.6g\n",
                d.atoms.size(), nm, mr, mm);
    return 0;
  }

  if (before_path.empty() || after_path.empty())
    bad("need --before and --after (or --same, --stats)");
  const Dump before = read_dump(before_path), after = read_dump(after_path);

  // Which atoms moved (or changed radius); new or retyped atoms.
  std::vector<bool> moved(after.atoms.size(), false);
  long new_atoms = 0, retyped = 0, moved_count = 0;
  for (std::size_t i = 0; i < after.atoms.size(); ++i) {
    const Atom &a = after.atoms[i];
    const Atom *b = find(before, a.id);
    if (!b) {
      ++new_atoms;
      moved[i] = true;
      continue;
    }
    if (b->type != a.type) ++retyped;
    moved[i] = b->r != a.r || b->x[0] != a.x[0] || b->x[1] != a.x[1] || b->x[2] != a.x[2];
    moved_count += moved[i];
  }
  const long deleted =
      static_cast<long>(before.atoms.size()) - static_cast<long>(after.atoms.size()) + new_atoms;

  double worst_moved = 0, worst_matrix_rebar = 0, worst_untouched = 0;
  long moved_overlaps = 0, matrix_rebar_overlaps = 0;
  for_each_contact(after, [&](int i, int j, double o) {
    const Atom &a = after.atoms[i], &b = after.atoms[j];
    const double rel = o / std::min(a.r, b.r);
    const bool ra = a.type == rebar_type, rb = b.type == rebar_type;
    if (ra && rb) return;    // bars may be clumps of overlapping spheres
    if (moved[i] || moved[j]) {
      worst_moved = std::max(worst_moved, rel);
      if (rel > tol) ++moved_overlaps;
    } else if (ra || rb) {
      worst_matrix_rebar = std::max(worst_matrix_rebar, rel);
      if (rel > tol) ++matrix_rebar_overlaps;
    } else {
      worst_untouched = std::max(worst_untouched, rel);    // the packing's own
    }
  });
  check(moved_overlaps == 0, "moved spheres overlap nothing above tol (" +
                                 std::to_string(moved_overlaps) + " pairs; largest " +
                                 num(worst_moved) + " of min radius)");
  if (kept_ok)
    std::printf("INFO: %ld matrix-rebar overlaps left (kept targets allowed)\n",
                matrix_rebar_overlaps);
  else
    check(matrix_rebar_overlaps == 0, "no matrix sphere overlaps a bar (" +
                                          std::to_string(matrix_rebar_overlaps) +
                                          " pairs; largest " + num(worst_matrix_rebar) + ")");

  if (rmax > 0) {
    long out_of_range = 0;
    for (std::size_t i = 0; i < after.atoms.size(); ++i)
      if (moved[i] && after.atoms[i].type != rebar_type &&
          (after.atoms[i].r < rmin * (1 - 1e-12) || after.atoms[i].r > rmax * (1 + 1e-12)))
        ++out_of_range;
    check(out_of_range == 0, "moved radii in [" + num(rmin) + ", " + num(rmax) + "] (" +
                                 std::to_string(out_of_range) + " outside)");
  }

  long rebar_changed = 0, rebar_missing = 0;
  for (const Atom &b : before.atoms) {
    if (b.type != rebar_type) continue;
    const Atom *a = find(after, b.id);
    if (!a)
      ++rebar_missing;
    else if (a->r != b.r || a->x[0] != b.x[0] || a->x[1] != b.x[1] || a->x[2] != b.x[2])
      ++rebar_changed;
  }
  check(rebar_missing == 0 && rebar_changed == 0, "rebar untouched (" +
                                                      std::to_string(rebar_missing) + " missing, " +
                                                      std::to_string(rebar_changed) + " moved)");
  check(new_atoms == 0 && retyped == 0, "no new or retyped atoms (" + std::to_string(new_atoms) +
                                            " new, " + std::to_string(retyped) + " retyped)");
  if (expect_deleted >= 0)
    check(deleted == expect_deleted,
          "atoms before = after + deleted (" + std::to_string(before.atoms.size()) + " = " +
              std::to_string(after.atoms.size()) + " + " + std::to_string(expect_deleted) + ")");
  std::printf(
      "SUMMARY atoms_before %zu atoms_after %zu moved %ld deleted %ld max_overlap_moved %.3g "
      "max_overlap_packing %.3g\n",
      before.atoms.size(), after.atoms.size(), moved_count, deleted, worst_moved, worst_untouched);
  return failures ? 1 : 0;
}
