// Grows a random dense polydisperse packing of matrix spheres (type 1),
// optionally around bars of rebar spheres (type 2), and writes it as a
// LAMMPS/LIGGGHTS data file in make_scene's format (atom style sphere /
// granular: id type diameter density x y z). Standalone C++17, no host
// headers. Usage and method: tests/tools/README.md.
//
//   grow_packing OUT --box XLO XHI YLO YHI ZLO ZHI --radius RMIN RMAX --phi PHI
//                [--boundary f|p f|p f|p] [--seed N]
//                [--bar X0 Y0 Z0 X1 Y1 Z1 R STEP]... [--around-bars]
//                [--max-seconds S] [--omega W] [--quiet]
//
// Radii: the N quantiles of the uniform law on [RMIN, RMAX] by number, sphere
// id k (1..N) has radius RMIN + (RMAX - RMIN) (k - 1) / (N - 1); the places
// are random. N: the number whose quantile radii hold a matrix volume
// closest to PHI x V, where
//   V = box volume                                     (default: matrix alone)
//   V = box volume - volume of the union of the rebar spheres  (--around-bars)
// Bars (make_scene's --bar: spheres STEP apart from X0 to X1, both ends
// included; a sphere that lands on another of the same bar through a
// periodic boundary is dropped) are written after the matrix. Without
// --around-bars they play no part in the growth (the packing a user has
// before adding bars); with it they are present and frozen from the start
// (the packing a user would grow around the bars).
//
// Method (collective rearrangement by growth): random centres at a small
// scale (solid fraction 0.2), then stages that scale every radius by a common
// factor (the solid fraction grows by an adaptive step), each followed by
// Gauss-Seidel sweeps over a Verlet pair list (cell grid, never all pairs)
// that push each overlapping pair apart along the line of centres, half each
// (a matrix sphere on a rebar sphere or a wall moves the whole way), until
// the largest overlap is below 1e-3 of the current rmin. A push is W times
// the overlap plus a clearance of 1e-5 rmin (over-relaxation, W = 1.6 by
// default: near jamming it needs 4 to 5 times fewer sweeps than W = 1; W = 1.8
// can oscillate against walls). The last stage sets the final radii and
// sweeps until every matrix-matrix and matrix-rebar overlap is at most
// 0.5e-6 min(r_i, r_j) and every sphere is wholly inside the walls; it gives
// up after --max-seconds (default 300: exit 1, JAMMED, nothing written).
// One process, one seed: same bytes. GROW_PACKING_VERBOSE=1 prints each
// stage on stderr.
//
// Exit status: 0 written, 1 could not reach the tolerance in time (jammed),
// 2 bad usage.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "periodic_box.h"

namespace {

[[noreturn]] void usage(const std::string &why)
{
  std::fprintf(stderr, "grow_packing: %s\n", why.c_str());
  std::exit(2);
}

double num(int argc, char **argv, int i)
{
  if (i >= argc) usage("missing value");
  char *end;
  const double v = std::strtod(argv[i], &end);
  if (*end || !std::isfinite(v)) usage(std::string("not a number: ") + argv[i]);
  return v;
}

using tools::kFourThirdsPi;
using tools::Rng;
using Box = tools::PeriodicBox;

// A uniform cell grid over the box.
struct Grid {
  int n[3] = {1, 1, 1};
  double size[3] = {1, 1, 1};
  std::vector<int> head, next;
  const Box *box = nullptr;

  void build(const Box &b, double cell, const std::vector<double> &x, int count)
  {
    box = &b;
    for (int k = 0; k < 3; ++k) {
      n[k] = std::max(1, static_cast<int>(b.len(k) / cell));
      n[k] = std::min(n[k], 512);
      size[k] = b.len(k) / n[k];
    }
    head.assign(static_cast<std::size_t>(n[0]) * n[1] * n[2], -1);
    next.assign(count, -1);
    for (int i = count - 1; i >= 0; --i) {
      const int c = cell_of(&x[3 * i]);
      next[i] = head[c];
      head[c] = i;
    }
  }
  int coord(double v, int k) const
  {
    int c = static_cast<int>(std::floor((v - box->lo[k]) / size[k]));
    return std::min(std::max(c, 0), n[k] - 1);
  }
  int cell_of(const double *p) const
  {
    return (coord(p[0], 0) * n[1] + coord(p[1], 1)) * n[2] + coord(p[2], 2);
  }
  // The cells within `reach` cells of p's cell, each once (for_cells_around),
  // in increasing order.
  void around(const double *p, int reach, std::vector<int> &out) const
  {
    out.clear();
    const int c[3] = {coord(p[0], 0), coord(p[1], 1), coord(p[2], 2)};
    tools::for_cells_around(*box, n, c, reach, [&](int cell) { out.push_back(cell); });
    std::sort(out.begin(), out.end());
  }
};

struct Pair {
  int i, j;    // j >= nm: rebar sphere j - nm
};

// Volume of the union of spheres by Monte Carlo inside each sphere, each
// point weighted 1 / (number of spheres holding it): unbiased. Returns the
// estimate; *se gets its standard error.
double union_volume(const Box &box, const std::vector<double> &c, const std::vector<double> &r,
                    int samples, double *se)
{
  const int n = static_cast<int>(r.size());
  if (n == 0) {
    *se = 0;
    return 0;
  }
  double rmax = 0;
  for (double v : r) rmax = std::max(rmax, v);
  Grid g;
  g.build(box, 2 * rmax, c, n);
  Rng rng(987654321);
  std::vector<int> cells;
  double total = 0, var = 0;
  for (int i = 0; i < n; ++i) {
    const double vol = kFourThirdsPi * r[i] * r[i] * r[i];
    double s1 = 0, s2 = 0;
    for (int m = 0; m < samples; ++m) {
      double p[3], q[3];
      rng.in_unit_ball(q);
      for (int k = 0; k < 3; ++k) p[k] = c[3 * i + k] + r[i] * q[k];
      box.wrap(p);
      g.around(p, 1, cells);
      int holders = 0;
      for (int cell : cells)
        for (int j = g.head[cell]; j >= 0; j = g.next[j]) {
          double d[3];
          box.delta(p, &c[3 * j], d);
          if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= r[j] * r[j]) ++holders;
        }
      const double w = 1.0 / std::max(holders, 1);
      s1 += w;
      s2 += w * w;
    }
    const double mean = s1 / samples, v2 = std::max(0.0, s2 / samples - mean * mean);
    total += vol * mean;
    var += vol * vol * v2 / samples;
  }
  *se = std::sqrt(var);
  return total;
}

struct Packer {
  Box box;
  int nm = 0;                    // matrix spheres
  std::vector<double> x, R;      // matrix centres, final radii
  std::vector<double> bx, br;    // rebar centres, radii (frozen)
  bool use_bars = false;
  double rmin = 0, rmax = 0, brmax = 0;
  double s = 1;        // current scale of the matrix radii
  double gap = 0;      // the pushes aim at this clearance
  double omega = 1;    // over-relaxation of the pushes
  std::vector<Pair> pairs;
  std::vector<double> built;    // centres at the last list build
  double s_built = 0, skin = 0;
  Grid grid;
  std::vector<double> allx;    // matrix then rebar centres, for the grid
  long sweeps = 0, builds = 0;

  double radius(int j) const { return j < nm ? s * R[j] : br[j - nm]; }
  const double *centre(int j) const { return j < nm ? &x[3 * j] : &bx[3 * (j - nm)]; }

  void clamp(int i)
  {
    double *p = &x[3 * i];
    const double r = s * R[i];
    for (int k = 0; k < 3; ++k)
      if (!box.periodic[k]) {
        const double lo = box.lo[k] + r * (1 + 1e-10), hi = box.hi[k] - r * (1 + 1e-10);
        p[k] = std::min(std::max(p[k], lo), hi);
      }
    box.wrap(p);
  }

  void build_list()
  {
    const int nb = use_bars ? static_cast<int>(br.size()) : 0;
    allx.assign(x.begin(), x.end());
    if (nb) allx.insert(allx.end(), bx.begin(), bx.end());
    skin = 0.3 * s * rmin;
    const double cell = std::max(2 * s * rmax, s * rmax + brmax) + skin;
    grid.build(box, cell, allx, nm + nb);
    pairs.clear();
    std::vector<int> cells;
    for (int i = 0; i < nm; ++i) {
      grid.around(&x[3 * i], 1, cells);
      for (int c : cells)
        for (int j = grid.head[c]; j >= 0; j = grid.next[j]) {
          if (j < nm && j <= i) continue;
          double d[3];
          box.delta(&x[3 * i], centre(j), d);
          const double cut = s * R[i] + radius(j) + skin;
          if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < cut * cut) pairs.push_back({i, j});
        }
    }
    std::sort(pairs.begin(), pairs.end(),
              [](const Pair &a, const Pair &b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
    built = x;
    s_built = s;
    ++builds;
  }

  bool list_stale() const
  {
    double worst = 0;
    for (int i = 0; i < nm; ++i) {
      double d[3];
      box.delta(&x[3 * i], &built[3 * i], d);
      worst = std::max(worst, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    return 2 * std::sqrt(worst) + 2 * (s - s_built) * rmax >= skin;
  }

  // One Gauss-Seidel sweep; returns the largest overlap seen (before its push).
  double sweep()
  {
    double worst = 0;
    for (int i = 0; i < nm; ++i) {    // the walls first: radii grow between sweeps
      const double *c = &x[3 * i];
      for (int k = 0; k < 3; ++k)
        if (!box.periodic[k])
          worst =
              std::max(worst, std::max(box.lo[k] - (c[k] - s * R[i]), c[k] + s * R[i] - box.hi[k]));
      clamp(i);
    }
    for (const Pair &p : pairs) {
      double *a = &x[3 * p.i];
      const double *b = centre(p.j);
      double d[3];
      box.delta(a, b, d);
      const double sum = s * R[p.i] + radius(p.j);
      const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (d2 >= (sum + gap) * (sum + gap)) continue;
      const double dist = std::sqrt(d2);
      const double ov = sum - dist;
      if (ov <= -gap) continue;
      worst = std::max(worst, ov);
      const double push = omega * (ov + gap);
      double u[3];
      if (dist > 1e-300) {
        for (int k = 0; k < 3; ++k) u[k] = d[k] / dist;
      } else {    // same centre: a fixed direction (deterministic)
        u[0] = 0.6;
        u[1] = 0.48;
        u[2] = 0.64;
      }
      if (p.j < nm) {
        double *c = &x[3 * p.j];
        for (int k = 0; k < 3; ++k) {
          a[k] += 0.5 * push * u[k];
          c[k] -= 0.5 * push * u[k];
        }
        clamp(p.i);
        clamp(p.j);
      } else {
        for (int k = 0; k < 3; ++k) a[k] += push * u[k];
        clamp(p.i);
      }
    }
    ++sweeps;
    return worst;
  }

  // Sweeps until the largest overlap is below tol (true) or `limit` sweeps.
  bool relax(double tol, long limit, long *used)
  {
    for (long n = 0; n < limit; ++n) {
      if (list_stale()) build_list();
      const double worst = sweep();
      if (worst < tol) {
        if (used) *used = n + 1;
        return true;
      }
    }
    if (used) *used = limit;
    return false;
  }

  // Exact largest overlap / min(r_i, r_j) over matrix-matrix and matrix-rebar
  // pairs, and / rmin; largest reach through a wall / r.
  void measure(double *rel, double *abs_rmin, double *wall) const
  {
    Grid g;
    std::vector<double> all(x);
    const int nb = use_bars ? static_cast<int>(br.size()) : 0;
    if (nb) all.insert(all.end(), bx.begin(), bx.end());
    g.build(box, std::max(2 * rmax, rmax + brmax), all, nm + nb);
    *rel = *abs_rmin = *wall = 0;
    std::vector<int> cells;
    for (int i = 0; i < nm; ++i) {
      for (int k = 0; k < 3; ++k)
        if (!box.periodic[k]) {
          const double reach =
              std::max(box.lo[k] - (x[3 * i + k] - R[i]), x[3 * i + k] + R[i] - box.hi[k]);
          *wall = std::max(*wall, reach / R[i]);
        }
      g.around(&x[3 * i], 1, cells);
      for (int c : cells)
        for (int j = g.head[c]; j >= 0; j = g.next[j]) {
          if (j < nm && j <= i) continue;
          double d[3];
          const double *cj = j < nm ? &x[3 * j] : &bx[3 * (j - nm)];
          const double rj = j < nm ? R[j] : br[j - nm];
          box.delta(&x[3 * i], cj, d);
          const double ov = R[i] + rj - std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
          if (ov > 0) {
            *rel = std::max(*rel, ov / std::min(R[i], rj));
            *abs_rmin = std::max(*abs_rmin, ov / rmin);
          }
        }
    }
  }
};

}    // namespace

int main(int argc, char **argv)
{
  const auto t0 = std::chrono::steady_clock::now();
  if (argc < 2 || argv[1][0] == '-') usage("no output file (usage: tests/tools/README.md)");
  Box box{{0, 0, 0}, {1, 1, 1}, {false, false, false}};
  double rmin = -1, rmax = -1, phi = -1, max_seconds = 300, omega = 1.6;
  std::uint64_t seed = 1;
  bool around = false, quiet = false, have_box = false;
  const bool verbose = std::getenv("GROW_PACKING_VERBOSE") != nullptr;
  std::vector<std::vector<double>> bars;
  for (int i = 2; i < argc; ++i) {
    const std::string k = argv[i];
    if (k == "--box") {
      for (int d = 0; d < 3; ++d) {
        box.lo[d] = num(argc, argv, ++i);
        box.hi[d] = num(argc, argv, ++i);
      }
      have_box = true;
    } else if (k == "--boundary") {
      for (int d = 0; d < 3; ++d) {
        if (++i >= argc) usage("missing boundary");
        const std::string b = argv[i];
        if (b != "f" && b != "p") usage("boundary is f (walls) or p (periodic)");
        box.periodic[d] = b == "p";
      }
    } else if (k == "--radius") {
      rmin = num(argc, argv, ++i);
      rmax = num(argc, argv, ++i);
    } else if (k == "--phi") {
      phi = num(argc, argv, ++i);
    } else if (k == "--seed") {
      seed = static_cast<std::uint64_t>(num(argc, argv, ++i));
    } else if (k == "--bar") {
      std::vector<double> b;
      for (int j = 0; j < 8; ++j) b.push_back(num(argc, argv, ++i));
      if (!(b[6] > 0) || !(b[7] > 0)) usage("a bar needs R > 0 and STEP > 0");
      bars.push_back(b);
    } else if (k == "--around-bars") {
      around = true;
    } else if (k == "--max-seconds") {
      max_seconds = num(argc, argv, ++i);
    } else if (k == "--omega") {
      omega = num(argc, argv, ++i);
      if (!(omega >= 1) || !(omega < 2)) usage("--omega in [1, 2)");
    } else if (k == "--quiet") {
      quiet = true;
    } else {
      usage("unknown option " + k);
    }
  }
  if (!have_box) usage("--box is required");
  for (int d = 0; d < 3; ++d)
    if (!(box.hi[d] > box.lo[d])) usage("empty box");
  if (!(rmin > 0) || rmax < rmin) usage("--radius RMIN RMAX with 0 < RMIN <= RMAX is required");
  if (!(phi > 0) || phi >= 0.74) usage("--phi in (0, 0.74) is required");
  if (around && bars.empty()) usage("--around-bars without --bar");

  Packer pk;
  pk.box = box;
  pk.rmin = rmin;
  pk.rmax = rmax;
  // Bars exactly as make_scene lays them out.
  for (const auto &b : bars) {
    const std::size_t first = pk.br.size();
    tools::for_bar_centres(b, [&](const double *p) {
      double q[3] = {p[0], p[1], p[2]};
      box.wrap(q);
      bool twin = false;
      for (std::size_t j = first; j < pk.br.size() && !twin; ++j) {
        double d[3];
        box.delta(q, &pk.bx[3 * j], d);
        twin = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) <
               1e-9 * (box.len(0) + box.len(1) + box.len(2));
      }
      if (twin) return;
      pk.bx.insert(pk.bx.end(), q, q + 3);    // wrapped into a periodic box
      pk.br.push_back(b[6]);
      pk.brmax = std::max(pk.brmax, b[6]);
    });
  }
  const double vbox = box.len(0) * box.len(1) * box.len(2);
  double vbars = 0, vbars_se = 0;
  if (around) vbars = union_volume(box, pk.bx, pk.br, 20000, &vbars_se);
  const double vfree = vbox - vbars;
  const double target = phi * vfree;
  // N: the quantile radii whose volume is closest to the target.
  auto quantile_volume = [&](long n) {
    double v = 0;
    for (long k = 0; k < n; ++k) {
      const double r = n > 1 ? rmin + (rmax - rmin) * k / (n - 1) : rmin;
      v += kFourThirdsPi * r * r * r;
    }
    return v;
  };
  const double mean_r3 = rmax > rmin ? (std::pow(rmax, 4) - std::pow(rmin, 4)) / (4 * (rmax - rmin))
                                     : rmin * rmin * rmin;
  long n = std::max(1L, std::lround(target / (kFourThirdsPi * mean_r3)));
  while (n > 1 && quantile_volume(n) > target) --n;
  while (quantile_volume(n + 1) <= target) ++n;
  if (std::fabs(quantile_volume(n + 1) - target) < std::fabs(quantile_volume(n) - target)) ++n;
  if (n > 5000000) usage("more than 5e6 spheres");
  pk.nm = static_cast<int>(n);
  pk.R.resize(n);
  for (long k = 0; k < n; ++k) pk.R[k] = n > 1 ? rmin + (rmax - rmin) * k / (n - 1) : rmin;
  const double vmatrix = quantile_volume(n);
  const double phi_actual = vmatrix / vfree;

  // Random centres, radii at the scale of solid fraction 0.2 (or phi).
  Rng rng(seed);
  const double phi0 = std::min(0.2, phi_actual);
  pk.s = std::cbrt(phi0 / phi_actual);
  pk.x.resize(3 * n);
  for (long i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const double r = box.periodic[k] ? 0 : pk.s * pk.R[i];
      const double room = std::max(0.0, box.len(k) - 2 * r);
      pk.x[3 * i + k] = box.lo[k] + r + room * rng.uniform();
    }
  pk.use_bars = around;
  pk.gap = 1e-5 * rmin;
  pk.omega = omega;
  pk.build_list();

  auto seconds = [&]() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  // Stages: the solid fraction grows by dphi, adapted to the sweeps needed.
  double cur = phi0, dphi = 0.02;
  long stages = 0;
  while (cur < phi_actual) {
    const double nxt = std::min(phi_actual, cur + dphi);
    pk.s = std::cbrt(nxt / phi_actual);
    long used = 0;
    pk.relax(1e-3 * pk.s * rmin, 4000, &used);
    cur = nxt;
    ++stages;
    if (verbose)
      std::fprintf(stderr, "stage %ld: solid fraction %.5f, %ld sweeps, %.2f s\n", stages, cur,
                   used, seconds());
    if (used > 400)
      dphi = std::max(1e-4, dphi * 0.6);
    else if (used < 100)
      dphi = std::min(0.03, dphi * 1.25);
    if (seconds() > max_seconds) break;
  }
  pk.s = 1;
  bool ok = false;
  double rel = 0, abs_rmin = 0, wall = 0;
  while (seconds() < max_seconds) {
    long used = 0;
    const bool done = pk.relax(0.5e-6 * rmin, 2000, &used);
    if (verbose) std::fprintf(stderr, "final: %ld sweeps, %.2f s\n", used, seconds());
    if (!done) continue;
    pk.measure(&rel, &abs_rmin, &wall);
    if (rel <= 0.5e-6 && wall <= 0) {
      ok = true;
      break;
    }
  }
  if (!ok) pk.measure(&rel, &abs_rmin, &wall);
  const double secs = seconds();
  if (!quiet || !ok)
    std::printf("grow_packing: %s %ld matrix + %zu rebar spheres, solid fraction %.6f of %s "
                "(target %.4f), largest overlap / rmin %.3g (/ min(r_i, r_j) %.3g), wall reach / r "
                "%.3g, %ld stages, %ld sweeps, %ld list builds, %.2f s%s\n",
                ok ? "ok" : "JAMMED", n, pk.br.size(), phi_actual, around ? "box - bars" : "box",
                phi, abs_rmin, rel, wall, stages, pk.sweeps, pk.builds, secs, around ? "" : "");
  if (around && !quiet)
    std::printf(
        "grow_packing: union of the rebar spheres %.9g +- %.2g (standard error), box %.9g\n", vbars,
        vbars_se, vbox);
  if (!ok) return 1;

  FILE *f = std::fopen(argv[1], "w");
  if (!f) usage("cannot write the output file");
  const std::size_t nb = pk.br.size();
  std::fprintf(f,
               "reinforce/invert packing (grow_packing, seed %llu, phi %.6f of %s, radii %g-%g)\n\n"
               "%zu atoms\n2 atom types\n\n",
               static_cast<unsigned long long>(seed), phi_actual, around ? "box - bars" : "box",
               rmin, rmax, static_cast<std::size_t>(n) + nb);
  const char *axes[3][2] = {{"xlo", "xhi"}, {"ylo", "yhi"}, {"zlo", "zhi"}};
  for (int d = 0; d < 3; ++d)
    std::fprintf(f, "%.17g %.17g %s %s\n", box.lo[d], box.hi[d], axes[d][0], axes[d][1]);
  std::fprintf(f, "\nAtoms\n\n");
  for (long i = 0; i < n; ++i)
    std::fprintf(f, "%ld 1 %.17g 2500 %.17g %.17g %.17g\n", i + 1, 2 * pk.R[i], pk.x[3 * i],
                 pk.x[3 * i + 1], pk.x[3 * i + 2]);
  for (std::size_t j = 0; j < nb; ++j)
    std::fprintf(f, "%zu 2 %.17g 7800 %.17g %.17g %.17g\n", n + j + 1, 2 * pk.br[j], pk.bx[3 * j],
                 pk.bx[3 * j + 1], pk.bx[3 * j + 2]);
  std::fclose(f);
  return 0;
}
