// Measures the quality of a reinforced scene: the matrix solid fraction
// against the distance from the nearest rebar surface (profile), its bulk
// value, the shell ratio, and, against the scene before the fix and a
// reference grown around the same bars, the removed ratio, the
// Kolmogorov-Smirnov statistic of the matrix radii and the spheres that
// moved. Standalone C++17, no host headers. Usage, definitions and sampling
// errors: tests/tools/README.md.
//
//   scene_quality --after A [--before B] [--reference R] [--rebar-type 2]
//                 [--rmin R] [--rmax R] [--bin W] [--out X] [--bulk-from X]
//                 [--wall-zone X] [--points N] [--tol 1e-6] [--boundary f|p f|p f|p]
//                 [--union-samples N] [--quiet-profile]
//                 assertions: [--shell-vs-reference LO HI] [--bin-diff MAX OUT]
//                 [--ks-max K] [--moved-within D] [--shell-max-over-reference X]
//                 [--expect-union V] [--check-sampling]
//
// Inputs are LAMMPS/LIGGGHTS text dumps (write_dump all custom F id type x y
// z radius ... format float %.17g; the last snapshot; the BOX BOUNDS flags
// give the boundary) or data files in make_scene / grow_packing's format
// (atom style sphere: id type diameter density x y z; boundary from
// --boundary, default f f f). Distances X, OUT are in units of rmax; D is a
// length, or a multiple of rmax written like 4rmax.
// Exit status: 0 every assertion passed, 1 one failed, 2 bad usage or input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "periodic_box.h"

namespace {

using tools::kFourThirdsPi;
using tools::Rng;
constexpr double kFar = std::numeric_limits<double>::infinity();

[[noreturn]] void bad(const std::string &why)
{
  std::fprintf(stderr, "scene_quality: %s\n", why.c_str());
  std::exit(2);
}

double to_double(const std::string &s, const std::string &what)
{
  char *end;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end || !std::isfinite(v)) bad(what + ": not a number: " + s);
  return v;
}

struct Atom {
  long id;
  int type;
  double x[3];
  double r;
};

struct Scene : tools::PeriodicBox {
  std::string path;
  std::vector<Atom> atoms;
  double volume() const { return len(0) * len(1) * len(2); }
};

Scene read_scene(const std::string &path, const bool *data_periodic)
{
  std::ifstream in(path);
  if (!in) bad("cannot read " + path);
  Scene s;
  s.path = path;
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  bool dump = false;
  for (const auto &l : lines)
    if (l.rfind("ITEM:", 0) == 0) {
      dump = true;
      break;
    }
  if (dump) {
    // The last snapshot.
    std::size_t start = 0;
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i].rfind("ITEM: TIMESTEP", 0) == 0) start = i;
    std::map<std::string, int> col;
    bool have_box = false;
    for (std::size_t i = start; i < lines.size(); ++i) {
      const std::string &l = lines[i];
      if (l.rfind("ITEM: BOX BOUNDS", 0) == 0) {
        std::istringstream h(l.substr(16));
        std::string flag;
        for (int k = 0; k < 3; ++k) {
          if (h >> flag) s.periodic[k] = flag == "pp";
          if (i + 1 + k >= lines.size()) bad(path + ": truncated box");
          std::istringstream b(lines[i + 1 + k]);
          if (!(b >> s.lo[k] >> s.hi[k])) bad(path + ": bad box line");
        }
        if (l.find("xy") != std::string::npos) bad(path + ": triclinic box");
        have_box = true;
      } else if (l.rfind("ITEM: ATOMS", 0) == 0) {
        std::istringstream h(l.substr(11));
        std::string name;
        int c = 0;
        while (h >> name) col[name] = c++;
        for (const char *need : {"id", "type", "x", "y", "z", "radius"})
          if (!col.count(need)) bad(path + ": no " + need + " column");
        for (std::size_t j = i + 1; j < lines.size(); ++j) {
          if (lines[j].rfind("ITEM:", 0) == 0) break;
          std::istringstream a(lines[j]);
          std::vector<std::string> w;
          std::string t;
          while (a >> t) w.push_back(t);
          if (w.empty()) continue;
          if (w.size() < col.size()) bad(path + ": short atom line");
          Atom at;
          at.id = std::atol(w[col["id"]].c_str());
          at.type = std::atoi(w[col["type"]].c_str());
          at.x[0] = to_double(w[col["x"]], path);
          at.x[1] = to_double(w[col["y"]], path);
          at.x[2] = to_double(w[col["z"]], path);
          at.r = to_double(w[col["radius"]], path);
          s.atoms.push_back(at);
        }
        break;
      }
    }
    if (!have_box) bad(path + ": no BOX BOUNDS");
  } else {
    // A data file: header box lines, then the Atoms section.
    int found = 0;
    std::size_t i = 0;
    for (; i < lines.size(); ++i) {
      const std::string &l = lines[i];
      const char *axes[3] = {"xlo xhi", "ylo yhi", "zlo zhi"};
      for (int k = 0; k < 3; ++k)
        if (l.find(axes[k]) != std::string::npos) {
          std::istringstream b(l);
          if (!(b >> s.lo[k] >> s.hi[k])) bad(path + ": bad box line");
          found |= 1 << k;
        }
      std::istringstream w(l);
      std::string first;
      if (w >> first && first == "Atoms") break;
    }
    if (found != 7 || i == lines.size())
      bad(path + ": not a dump nor a data file with a box and Atoms");
    for (++i; i < lines.size(); ++i) {
      std::istringstream a(lines[i]);
      std::vector<std::string> w;
      std::string t;
      while (a >> t) w.push_back(t);
      if (w.empty()) {
        if (!s.atoms.empty()) break;
        continue;
      }
      if (w.size() < 7) break;    // the next section's header
      Atom at;
      at.id = std::atol(w[0].c_str());
      at.type = std::atoi(w[1].c_str());
      at.r = 0.5 * to_double(w[2], path);
      for (int k = 0; k < 3; ++k) at.x[k] = to_double(w[4 + k], path);
      s.atoms.push_back(at);
    }
    for (int k = 0; k < 3; ++k) s.periodic[k] = data_periodic[k];
  }
  for (int k = 0; k < 3; ++k)
    if (!(s.hi[k] > s.lo[k])) bad(path + ": empty box");
  std::sort(s.atoms.begin(), s.atoms.end(),
            [](const Atom &a, const Atom &b) { return a.id < b.id; });
  return s;
}

// Cell grid over a subset of a scene's atoms.
struct Grid {
  const Scene *s = nullptr;
  std::vector<const Atom *> items;
  int n[3] = {1, 1, 1};
  double size[3] = {1, 1, 1};
  std::vector<int> head, next;

  void build(const Scene &sc, std::vector<const Atom *> what, double cell)
  {
    s = &sc;
    items = std::move(what);
    cell = std::max(cell, 1e-12 * (sc.len(0) + sc.len(1) + sc.len(2)));
    for (int k = 0; k < 3; ++k) {
      n[k] = std::max(1, std::min(256, static_cast<int>(sc.len(k) / cell)));
      size[k] = sc.len(k) / n[k];
    }
    head.assign(static_cast<std::size_t>(n[0]) * n[1] * n[2], -1);
    next.assign(items.size(), -1);
    for (int i = static_cast<int>(items.size()) - 1; i >= 0; --i) {
      double p[3] = {items[i]->x[0], items[i]->x[1], items[i]->x[2]};
      sc.wrap(p);
      const int c = (coord(p[0], 0) * n[1] + coord(p[1], 1)) * n[2] + coord(p[2], 2);
      next[i] = head[c];
      head[c] = i;
    }
  }
  int coord(double v, int k) const
  {
    const int c = static_cast<int>(std::floor((v - s->lo[k]) / size[k]));
    return std::min(std::max(c, 0), n[k] - 1);
  }
  // Calls f(atom) for every item in the cells within `reach` of p's cell.
  template <class F> void visit(const double *p, int reach, F f) const
  {
    const int c[3] = {coord(p[0], 0), coord(p[1], 1), coord(p[2], 2)};
    tools::for_cells_around(*s, n, c, reach, [&](int cell) {
      for (int j = head[cell]; j >= 0; j = next[j]) f(*items[j]);
    });
  }
  int reach_for(double dist) const
  {
    return static_cast<int>(std::ceil(dist / std::min({size[0], size[1], size[2]})));
  }

  // The offsets of the cells within `cut` of a cell, nearest first, each
  // with its gap: the least distance between a point of the centre cell and
  // one of the offset cell (a lower bound on the distance to its items).
  struct Offset {
    int d[3];
    double gap;
  };
  std::vector<Offset> offsets_within(double cut) const
  {
    std::vector<Offset> out;
    const int r = reach_for(cut);
    for (int a = -r; a <= r; ++a)
      for (int b = -r; b <= r; ++b)
        for (int c = -r; c <= r; ++c) {
          const int d[3] = {a, b, c};
          double g2 = 0;
          for (int k = 0; k < 3; ++k) {
            const double g = std::max(0, std::abs(d[k]) - 1) * size[k];
            g2 += g * g;
          }
          if (std::sqrt(g2) <= cut) out.push_back({{a, b, c}, std::sqrt(g2)});
        }
    std::stable_sort(out.begin(), out.end(),
                     [](const Offset &x, const Offset &y) { return x.gap < y.gap; });
    return out;
  }
  // The cell reached from cell c by offset o, or -1 outside a
  // non-periodic box.
  int offset_cell(const int *c, const Offset &o) const
  {
    int cell[3];
    for (int k = 0; k < 3; ++k) {
      cell[k] = c[k] + o.d[k];
      if (cell[k] < 0 || cell[k] >= n[k]) {
        if (!s->periodic[k]) return -1;
        cell[k] = ((cell[k] % n[k]) + n[k]) % n[k];
      }
    }
    return (cell[0] * n[1] + cell[1]) * n[2] + cell[2];
  }
  // For every cell, the index of the first of the offsets that reaches an
  // occupied cell (offsets.size(): none), where nearest_surface starts.
  std::vector<int> first_occupied(const std::vector<Offset> &offsets) const
  {
    std::vector<int> first(head.size());
    int c[3];
    for (c[0] = 0; c[0] < n[0]; ++c[0])
      for (c[1] = 0; c[1] < n[1]; ++c[1])
        for (c[2] = 0; c[2] < n[2]; ++c[2]) {
          std::size_t i = 0;
          for (; i < offsets.size(); ++i) {
            const int cell = offset_cell(c, offsets[i]);
            if (cell >= 0 && head[cell] >= 0) break;
          }
          first[(c[0] * n[1] + c[1]) * n[2] + c[2]] = static_cast<int>(i);
        }
    return first;
  }
  // The least distance from p to an item's surface (|p - x| - r), kFar when
  // none lies within the offsets' cut. Exact: the cells are visited nearest
  // first from the first occupied one, and the visit stops once no farther
  // cell can hold a nearer surface (gap - rmax_items >= the best so far).
  double nearest_surface(const double *p, const std::vector<Offset> &offsets,
                         const std::vector<int> &first, double rmax_items) const
  {
    const int c[3] = {coord(p[0], 0), coord(p[1], 1), coord(p[2], 2)};
    double best = kFar;
    for (std::size_t i = first[(c[0] * n[1] + c[1]) * n[2] + c[2]]; i < offsets.size(); ++i) {
      if (offsets[i].gap - rmax_items >= best) break;
      const int cell = offset_cell(c, offsets[i]);
      if (cell < 0) continue;
      for (int j = head[cell]; j >= 0; j = next[j]) {
        double d[3];
        s->delta(p, items[j]->x, d);
        best = std::min(best, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - items[j]->r);
      }
    }
    return best;
  }
};

struct Options {
  int rebar_type = 2;
  double rmin = -1, rmax = -1, bin = -1, out = 6, bulk_from = 4, wall_zone = 1, tol = 1e-6;
  long points = 2000000;
  int union_samples = 20000;
  bool quiet_profile = false;
};

struct Profile {
  std::vector<long> n, solid;    // per bin
  long shell_n = 0, shell_solid = 0, bulk_n = 0, bulk_solid = 0;
  long all_n = 0, all_solid = 0;    // every point outside the bars (wall zone included)
  double bin_phi(std::size_t k) const { return n[k] ? double(solid[k]) / n[k] : 0; }
  double shell() const { return shell_n ? double(shell_solid) / shell_n : 0; }
  double bulk() const { return bulk_n ? double(bulk_solid) / bulk_n : 0; }
  double shell_ratio() const { return bulk() > 0 ? shell() / bulk() : 0; }
  static double se(double p, long n) { return n ? std::sqrt(p * (1 - p) / n) : 0; }
  double shell_ratio_se() const
  {
    if (!(shell() > 0) || !(bulk() > 0)) return 0;
    const double a = se(shell(), shell_n) / shell(), b = se(bulk(), bulk_n) / bulk();
    return shell_ratio() * std::sqrt(a * a + b * b);
  }
};

// Points: one per cell of a regular grid of about `points` cells, at a
// pseudo-random place in its cell (stratified sampling; the same points for
// every scene of the same box).
Profile profile(const Scene &s, const Options &o)
{
  std::vector<const Atom *> matrix, rebar;
  double mrmax = 0, brmax = 0;
  for (const Atom &a : s.atoms) {
    if (a.type == o.rebar_type) {
      rebar.push_back(&a);
      brmax = std::max(brmax, a.r);
    } else {
      matrix.push_back(&a);
      mrmax = std::max(mrmax, a.r);
    }
  }
  Grid gm, gb;
  gm.build(s, matrix, 2 * std::max(mrmax, 1e-300));
  const double search = std::max(o.out, o.bulk_from) * o.rmax;    // beyond: "far"
  // The rebar in cells of a quarter of the reach, searched nearest first
  // from the first occupied cell: with many rebar spheres (fibres) most
  // points stop after a few cells, and far from the bars none is visited.
  gb.build(s, rebar, 0.25 * (search + brmax));
  const std::vector<Grid::Offset> rebar_cells = gb.offsets_within(search + brmax);
  const std::vector<int> rebar_first = gb.first_occupied(rebar_cells);
  const int mreach = gm.reach_for(mrmax);
  const std::size_t nbins = static_cast<std::size_t>(std::ceil(o.out * o.rmax / o.bin - 1e-9));
  Profile p;
  p.n.assign(nbins, 0);
  p.solid.assign(nbins, 0);
  const double h = std::cbrt(s.volume() / o.points);
  int cells[3];
  double step[3];
  for (int k = 0; k < 3; ++k) {
    cells[k] = std::max(1, static_cast<int>(std::round(s.len(k) / h)));
    step[k] = s.len(k) / cells[k];
  }
  Rng rng(20260911);
  const double wall = o.wall_zone * o.rmax;
  for (int i = 0; i < cells[0]; ++i)
    for (int j = 0; j < cells[1]; ++j)
      for (int k = 0; k < cells[2]; ++k) {
        const double pt[3] = {s.lo[0] + (i + rng.uniform()) * step[0],
                              s.lo[1] + (j + rng.uniform()) * step[1],
                              s.lo[2] + (k + rng.uniform()) * step[2]};
        double dist = gb.nearest_surface(pt, rebar_cells, rebar_first, brmax);
        if (dist > search) dist = kFar;
        if (dist < 0) continue;    // inside a bar
        bool solid = false;
        gm.visit(pt, mreach, [&](const Atom &m) {
          if (solid) return;
          double d[3];
          s.delta(pt, m.x, d);
          solid = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < m.r * m.r;
        });
        ++p.all_n;
        p.all_solid += solid;
        bool in_wall = false;
        for (int a = 0; a < 3; ++a)
          if (!s.periodic[a] && (pt[a] - s.lo[a] < wall || s.hi[a] - pt[a] < wall)) in_wall = true;
        if (in_wall) continue;
        const std::size_t b = dist == kFar ? nbins : static_cast<std::size_t>(dist / o.bin);
        if (b < nbins) {
          ++p.n[b];
          p.solid[b] += solid;
        }
        if (dist <= 2 * o.rmax) {
          ++p.shell_n;
          p.shell_solid += solid;
        }
        if (dist > o.bulk_from * o.rmax) {
          ++p.bulk_n;
          p.bulk_solid += solid;
        }
      }
  return p;
}

// Volume of the union of the rebar spheres: Monte Carlo inside each sphere,
// a point weighted 1 / (spheres holding it). Unbiased; *se its standard error.
double union_volume(const Scene &s, int rebar_type, int samples, double *se)
{
  std::vector<const Atom *> rebar;
  double brmax = 0;
  for (const Atom &a : s.atoms)
    if (a.type == rebar_type) {
      rebar.push_back(&a);
      brmax = std::max(brmax, a.r);
    }
  *se = 0;
  if (rebar.empty()) return 0;
  Grid g;
  g.build(s, rebar, 2 * brmax);
  const int reach = g.reach_for(2 * brmax);
  Rng rng(987654321);
  double total = 0, var = 0;
  std::vector<const Atom *> near;
  for (const Atom *a : rebar) {
    // A sphere holding a point of a overlaps a: those (a among them) are
    // the only ones to test, found once (a margin of 1e-9 for rounding).
    near.clear();
    g.visit(a->x, reach, [&](const Atom &b) {
      double d[3];
      s.delta(a->x, b.x, d);
      const double reach_ab = (a->r + b.r) * (1 + 1e-9);
      if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= reach_ab * reach_ab) near.push_back(&b);
    });
    double s1 = 0, s2 = 0;
    for (int m = 0; m < samples; ++m) {
      double q[3], p[3];
      rng.in_unit_ball(q);
      for (int k = 0; k < 3; ++k) p[k] = a->x[k] + a->r * q[k];
      s.wrap(p);
      int holders = 0;
      for (const Atom *b : near) {
        double d[3];
        s.delta(p, b->x, d);
        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= b->r * b->r) ++holders;
      }
      const double w = 1.0 / std::max(holders, 1);
      s1 += w;
      s2 += w * w;
    }
    const double vol = kFourThirdsPi * a->r * a->r * a->r, mean = s1 / samples;
    total += vol * mean;
    var += vol * vol * std::max(0.0, s2 / samples - mean * mean) / samples;
  }
  *se = std::sqrt(var);
  return total;
}

double matrix_volume(const Scene &s, int rebar_type)
{
  double v = 0;
  for (const Atom &a : s.atoms)
    if (a.type != rebar_type) v += kFourThirdsPi * a.r * a.r * a.r;
  return v;
}

std::vector<double> matrix_radii(const Scene &s, int rebar_type)
{
  std::vector<double> r;
  for (const Atom &a : s.atoms)
    if (a.type != rebar_type) r.push_back(a.r);
  std::sort(r.begin(), r.end());
  return r;
}

// Two-sample Kolmogorov-Smirnov statistic: sup |F_a - F_b|.
double ks(const std::vector<double> &a, const std::vector<double> &b)
{
  if (a.empty() || b.empty()) return a.empty() && b.empty() ? 0 : 1;
  std::size_t i = 0, j = 0;
  double worst = 0;
  while (i < a.size() || j < b.size()) {
    const double v = j >= b.size() || (i < a.size() && a[i] <= b[j]) ? a[i] : b[j];
    while (i < a.size() && a[i] <= v) ++i;
    while (j < b.size() && b[j] <= v) ++j;
    worst = std::max(worst, std::fabs(double(i) / a.size() - double(j) / b.size()));
  }
  return worst;
}

std::string fmt(double v, const char *f = "%.6g")
{
  if (!std::isfinite(v)) return "none";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}    // namespace

int main(int argc, char **argv)
{
  Options o;
  std::string after_path, before_path, ref_path;
  bool data_periodic[3] = {false, false, false};
  bool a_shell = false, a_bin = false, a_ks = false, a_moved = false, a_over = false,
       a_union = false, a_sampling = false;
  double shell_lo = 0, shell_hi = 0, bin_max = 0, bin_out = 0, ks_max = 0, over_max = 0,
         union_expect = 0;
  std::string moved_text;
  auto need = [&](int i) {
    if (i >= argc) bad(std::string("missing value after ") + argv[i - 1]);
    return std::string(argv[i]);
  };
  // The options that take only real numbers (none to two, in this order) and
  // may raise a flag (the assertions): one table rather than a branch each.
  struct Plain {
    const char *name;
    bool *flag;
    double *value[2];
  };
  const Plain plain[] = {{"--rmin", nullptr, {&o.rmin}},
                         {"--rmax", nullptr, {&o.rmax}},
                         {"--bin", nullptr, {&o.bin}},
                         {"--out", nullptr, {&o.out}},
                         {"--bulk-from", nullptr, {&o.bulk_from}},
                         {"--wall-zone", nullptr, {&o.wall_zone}},
                         {"--tol", nullptr, {&o.tol}},
                         {"--quiet-profile", &o.quiet_profile, {}},
                         {"--shell-vs-reference", &a_shell, {&shell_lo, &shell_hi}},
                         {"--bin-diff", &a_bin, {&bin_max, &bin_out}},
                         {"--ks-max", &a_ks, {&ks_max}},
                         {"--shell-max-over-reference", &a_over, {&over_max}},
                         {"--expect-union", &a_union, {&union_expect}},
                         {"--check-sampling", &a_sampling, {}}};
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    const Plain *opt = std::find_if(std::begin(plain), std::end(plain),
                                    [&](const Plain &p) { return k == p.name; });
    if (opt != std::end(plain)) {
      if (opt->flag) *opt->flag = true;
      for (double *v : opt->value)
        if (v) *v = to_double(need(++i), k);
    } else if (k == "--after")
      after_path = need(++i);
    else if (k == "--before")
      before_path = need(++i);
    else if (k == "--reference")
      ref_path = need(++i);
    else if (k == "--rebar-type")
      o.rebar_type = std::atoi(need(++i).c_str());
    else if (k == "--points")
      o.points = static_cast<long>(to_double(need(++i), k));
    else if (k == "--union-samples")
      o.union_samples = static_cast<int>(to_double(need(++i), k));
    else if (k == "--boundary") {
      for (bool &p : data_periodic) {
        const std::string b = need(++i);
        if (b != "f" && b != "p") bad("--boundary takes f or p per dimension");
        p = b == "p";
      }
    } else if (k == "--moved-within") {
      a_moved = true;
      moved_text = need(++i);
    } else {
      bad("unknown option " + k + " (usage: tests/tools/README.md)");
    }
  }
  if (after_path.empty()) bad("--after is required");
  if ((a_shell || a_bin || a_over) && ref_path.empty()) bad("this assertion needs --reference");
  if ((a_ks || a_moved) && before_path.empty()) bad("this assertion needs --before");
  if (o.points < 1000 || o.points > 200000000) bad("--points out of [1e3, 2e8]");
  if (o.union_samples < 100) bad("--union-samples below 100");

  const Scene after = read_scene(after_path, data_periodic);
  Scene before, ref;
  if (!before_path.empty()) before = read_scene(before_path, data_periodic);
  if (!ref_path.empty()) ref = read_scene(ref_path, data_periodic);
  // Radius range: the matrix of before (else after), unless given.
  {
    const auto r = matrix_radii(before_path.empty() ? after : before, o.rebar_type);
    if (r.empty()) bad("no matrix sphere");
    if (o.rmin <= 0) o.rmin = r.front();
    if (o.rmax <= 0) o.rmax = r.back();
  }
  if (o.bin <= 0) o.bin = o.rmin;
  if (o.rmax < o.rmin || o.out <= 0 || o.bulk_from <= 0 || o.wall_zone < 0) bad("bad distances");

  double moved_limit = kFar;
  if (a_moved) {
    const std::size_t at = moved_text.find("rmax");
    moved_limit = at == std::string::npos
                      ? to_double(moved_text, "--moved-within")
                      : to_double(moved_text.substr(0, at), "--moved-within") * o.rmax;
  }

  std::vector<std::string> kv;
  auto put = [&](const std::string &k, const std::string &v) { kv.push_back(k + "=" + v); };
  int failed = 0;
  auto verdict = [&](bool ok, const std::string &what) {
    std::printf("%s: %s\n", ok ? "PASS" : "FAIL", what.c_str());
    failed += !ok;
  };

  std::printf("scene_quality: rmin %g rmax %g bin %g, profile out to %g rmax, bulk beyond %g rmax "
              "from the bars, wall zone %g rmax excluded, ~%ld sample points\n",
              o.rmin, o.rmax, o.bin, o.out, o.bulk_from, o.wall_zone, o.points);
  const Profile pa = profile(after, o);
  Profile pr;
  if (!ref_path.empty()) pr = profile(ref, o);

  if (!o.quiet_profile) {
    std::printf("profile (distance from the nearest rebar surface, solid fraction +- standard "
                "error, points)%s\n",
                ref_path.empty() ? "" : "; reference");
    for (std::size_t b = 0; b < pa.n.size(); ++b) {
      std::printf("  [%7.4g, %7.4g) rmax  %.4f +- %.4f  %8ld", b * o.bin / o.rmax,
                  (b + 1) * o.bin / o.rmax, pa.bin_phi(b), Profile::se(pa.bin_phi(b), pa.n[b]),
                  pa.n[b]);
      if (!ref_path.empty())
        std::printf("   ref %.4f +- %.4f  diff %+.4f", pr.bin_phi(b),
                    Profile::se(pr.bin_phi(b), pr.n[b]), pa.bin_phi(b) - pr.bin_phi(b));
      std::printf("\n");
    }
  }
  std::printf("after: bulk %.4f +- %.4f (%ld points), shell (within 2 rmax) %.4f +- %.4f (%ld "
              "points), shell ratio %.4f +- %.4f\n",
              pa.bulk(), Profile::se(pa.bulk(), pa.bulk_n), pa.bulk_n, pa.shell(),
              Profile::se(pa.shell(), pa.shell_n), pa.shell_n, pa.shell_ratio(),
              pa.shell_ratio_se());
  put("bulk", fmt(pa.bulk(), "%.5f"));
  put("shell", fmt(pa.shell(), "%.5f"));
  put("shell_ratio", fmt(pa.shell_ratio(), "%.5f"));
  put("shell_ratio_se", fmt(pa.shell_ratio_se(), "%.2g"));
  if (pa.bulk_n == 0 || pa.shell_n == 0)
    std::printf("WARNING: %s has no point in the %s region\n", after_path.c_str(),
                pa.bulk_n == 0 ? "bulk" : "shell");

  double vu_se = 0;
  const double vu = union_volume(after, o.rebar_type, o.union_samples, &vu_se);
  std::printf("union of the rebar spheres: %.9g +- %.2g (standard error)\n", vu, vu_se);
  put("bars_volume", fmt(vu, "%.9g"));

  // Sampling check: the sampled solid fraction of the box outside the bars
  // against the exact one (matrix volume / (box - bars)); exact only when no
  // matrix sphere overlaps another or a bar or a wall.
  {
    const double exact = matrix_volume(after, o.rebar_type) / (after.volume() - vu);
    const double sampled = pa.all_n ? double(pa.all_solid) / pa.all_n : 0;
    const double se = Profile::se(sampled, pa.all_n);
    std::printf("sampling: solid fraction of the box outside the bars %.5f +- %.5f sampled, %.5f "
                "from the volumes (equal when nothing overlaps)\n",
                sampled, se, exact);
    if (a_sampling)
      verdict(std::fabs(sampled - exact) <= 4 * se + 1e-12,
              "sampled solid fraction within 4 standard errors of the volumes (|" +
                  fmt(sampled - exact, "%.3g") + "| <= 4 x " + fmt(se, "%.2g") + ")");
  }
  if (a_union)
    verdict(std::fabs(vu - union_expect) <= 4 * vu_se + 1e-15 * union_expect,
            "union volume " + fmt(vu, "%.9g") + " within 4 standard errors (" + fmt(vu_se, "%.2g") +
                ") of " + fmt(union_expect, "%.9g"));

  if (!before_path.empty()) {
    const Profile pb = profile(before, o);
    std::printf("before: bulk %.4f, shell %.4f, shell ratio %.4f\n", pb.bulk(), pb.shell(),
                pb.shell_ratio());
    const double vb = matrix_volume(before, o.rebar_type), va = matrix_volume(after, o.rebar_type);
    const double removed = vb - va;
    const double ratio = pb.bulk() > 0 && vu > 0 ? removed / (pb.bulk() * vu) : kFar;
    std::printf("removed: matrix volume %.6g -> %.6g, removed %.6g = %s x (bulk before %.4f x bars "
                "%.6g)\n",
                vb, va, removed, fmt(ratio, "%.4f").c_str(), pb.bulk(), vu);
    put("removed_ratio", fmt(ratio, "%.4f"));
    const double k = ks(matrix_radii(before, o.rebar_type), matrix_radii(after, o.rebar_type));
    std::printf("radii: two-sample Kolmogorov-Smirnov statistic before/after %.5f\n", k);
    put("ks", fmt(k, "%.5f"));
    if (a_ks) verdict(k <= ks_max, "KS statistic " + fmt(k, "%.5f") + " <= " + fmt(ks_max));

    // Targets, moves, deletions.
    std::vector<const Atom *> rebar;
    double brmax = 0;
    for (const Atom &a : before.atoms)
      if (a.type == o.rebar_type) {
        rebar.push_back(&a);
        brmax = std::max(brmax, a.r);
      }
    Grid gb;
    gb.build(before, rebar, o.rmax + brmax);
    const int reach = gb.reach_for(o.rmax + brmax);
    std::unordered_map<long, const Atom *> now;
    for (const Atom &a : after.atoms) now[a.id] = &a;
    auto bar_distance = [&](const Atom &m) {    // centre to nearest rebar surface
      double best = kFar;
      for (const Atom *b : rebar) {
        double d[3];
        before.delta(m.x, b->x, d);
        best = std::min(best, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - b->r);
      }
      return best;
    };
    long targets = 0, deleted = 0, deleted_targets = 0, moved_targets = 0, moved = 0;
    double moved_far = 0, moved_disp = 0;
    long beyond = 0;
    for (const Atom &m : before.atoms) {
      if (m.type == o.rebar_type) continue;
      bool target = false;
      gb.visit(m.x, reach, [&](const Atom &b) {
        double d[3];
        before.delta(m.x, b.x, d);
        const double ov = m.r + b.r - std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (ov > o.tol * std::min(m.r, b.r)) target = true;
      });
      targets += target;
      auto it = now.find(m.id);
      if (it == now.end()) {
        ++deleted;
        deleted_targets += target;
        continue;
      }
      const Atom &a = *it->second;
      double d[3];
      before.delta(a.x, m.x, d);
      bool mv = a.r != m.r;
      for (int q = 0; q < 3; ++q) mv = mv || std::fabs(d[q]) > 1e-12 * before.len(q);
      if (!mv) continue;
      if (target) {
        ++moved_targets;
        continue;
      }
      ++moved;
      moved_disp = std::max(moved_disp, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      const double far = bar_distance(m);
      moved_far = std::max(moved_far, far);
      if (far > moved_limit) ++beyond;
    }
    std::printf("spheres: %ld targets (matrix on a bar by more than %g min r), %ld of them moved, "
                "%ld deleted (%ld of them targets)\n",
                targets, o.tol, moved_targets, deleted, deleted_targets);
    std::printf("non-targets moved: %ld, largest displacement %s (%s rmax), farthest from a bar "
                "(centre to rebar surface, before) %s (%s rmax)\n",
                moved, fmt(moved_disp).c_str(), fmt(moved_disp / o.rmax, "%.3g").c_str(),
                fmt(moved_far).c_str(), fmt(moved_far / o.rmax, "%.3g").c_str());
    put("targets", std::to_string(targets));
    put("deleted", std::to_string(deleted));
    put("moved_nontargets", std::to_string(moved));
    put("moved_max_disp_rmax", fmt(moved_disp / o.rmax, "%.4g"));
    put("moved_max_bar_distance_rmax", fmt(moved_far / o.rmax, "%.4g"));
    if (a_moved)
      verdict(beyond == 0, std::to_string(beyond) + " non-target spheres farther than " +
                               fmt(moved_limit) + " (" + fmt(moved_limit / o.rmax, "%.3g") +
                               " rmax) from every bar moved");
  }

  if (!ref_path.empty()) {
    std::printf("reference %s: bulk %.4f, shell %.4f, shell ratio %.4f +- %.4f\n", ref_path.c_str(),
                pr.bulk(), pr.shell(), pr.shell_ratio(), pr.shell_ratio_se());
    const double diff = pa.shell_ratio() - pr.shell_ratio();
    std::printf("shell ratio: scene %.4f, reference %.4f, difference %+.4f\n", pa.shell_ratio(),
                pr.shell_ratio(), diff);
    put("ref_bulk", fmt(pr.bulk(), "%.5f"));
    put("ref_shell_ratio", fmt(pr.shell_ratio(), "%.5f"));
    put("shell_vs_reference", fmt(diff, "%.5f"));
    const double out = a_bin ? bin_out : 3;
    double worst = 0, worst_at = 0;
    for (std::size_t b = 0; b < pa.n.size() && b < pr.n.size(); ++b) {
      if (b * o.bin >= out * o.rmax - 1e-12 * o.rmax) break;
      const double d = std::fabs(pa.bin_phi(b) - pr.bin_phi(b));
      if (d > worst) {
        worst = d;
        worst_at = b * o.bin / o.rmax;
      }
    }
    std::printf("largest bin difference out to %g rmax: %.4f (bin from %.3g rmax)\n", out, worst,
                worst_at);
    put("bin_diff_max", fmt(worst, "%.5f"));
    if (a_shell)
      verdict(diff >= shell_lo && diff <= shell_hi, "shell ratio minus the reference's " +
                                                        fmt(diff, "%+.4f") + " in [" +
                                                        fmt(shell_lo) + ", " + fmt(shell_hi) + "]");
    if (a_over)
      verdict(diff <= over_max,
              "shell ratio minus the reference's " + fmt(diff, "%+.4f") + " <= " + fmt(over_max));
    if (a_bin)
      verdict(worst <= bin_max, "no profile bin out to " + fmt(bin_out) +
                                    " rmax differs from the "
                                    "reference by more than " +
                                    fmt(bin_max) + " (largest " + fmt(worst, "%.4f") + ")");
  }
  std::printf("QUALITY");
  for (const auto &s : kv) std::printf(" %s", s.c_str());
  std::printf("\n");
  return failed ? 1 : 0;
}
