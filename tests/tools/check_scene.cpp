// Checks a scene written by LAMMPS or LIGGGHTS before and after fix
// reinforce/invert. Input: text dumps written by
//   dump ID all custom N FILE id type x y z radius [mass]
//   dump_modify ID sort id format float %.17g      (sorting optional)
// (write_dump works too). A file with several snapshots: the last is used.
// Standalone C++17, no host headers. Usage and checks: tests/tools/README.md.
//
//   check_scene --before B --after A [--rebar-type T[,T...]] [--tol 1e-6]
//               [--overlap-tol 1e-12] [--rmin R] [--rmax R] [--deleted N] [--kept-ok]
//               [--overlap-ok-before | --clean-before] [--zone W]
//               [--wall-plane PX PY PZ NX NY NZ]... [--wall-stl FILE]...
//               [--wall-cylinder x|y|z C1 C2 R inside|outside]...
//               [--inside-box XLO XHI YLO YHI ZLO ZHI]...
//       the wall options: every moved matrix sphere wholly on the matrix
//       side of each wall (within tol of its radius), one check line each
//   check_scene --same A B        the two dumps hold identical atoms (text)
//   check_scene --stats D [--rebar-type T] [--rmin R]
//       one line: atoms N matrix M max_matrix_rebar X max_matrix_matrix Y
//       (largest overlaps / rmin; the format is parsed by bench/run.sh)
//   check_scene --packing D [--rebar-type T] [--rmin R]
//       describes a packing (counts, radii, solid fraction, overlaps, wall
//       penetration), no test
//   check_scene --compare-grid D
//       the cell grid finds exactly the contacts brute force finds
//   --brute (any mode): find pairs by trying every pair, not the grid
//
// Overlap of spheres i, j: d = r_i + r_j - |x_i - x_j| (minimum image in
// periodic dimensions, "pp" in the BOX BOUNDS line); a pair overlaps when
// d > tol * min(r_i, r_j), a pair of a moved sphere when d > overlap-tol *
// min(r_i, r_j) (the fix leaves them exact but for rounding) beyond what
// the pair overlapped before, when neither sphere was a target (a pair of
// matrix spheres, or a matrix sphere within tol of a bar: the packing's
// own). The last line, "DONE: N checks failed", follows every check.
// Exit status: 0 every check passed, 1 a check failed, 2 bad usage or
// unreadable input.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "vec3.h"

namespace {

struct Atom {
  long id = 0;
  int type = 0;
  double x[3] = {0, 0, 0};
  double r = 0;
  double mass = NAN;    // when the dump has a mass column
  std::string text;     // id, type, x, y, z and radius as written, for --same
};

struct Dump {
  std::string path;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool periodic[3] = {false, false, false};
  bool fixed[3] = {false, false, false};    // "ff": a wall at each face
  bool has_mass = false;
  std::vector<Atom> atoms;    // sorted by id
  std::unordered_map<long, std::size_t> index;

  double length(int k) const { return hi[k] - lo[k]; }
  const Atom *find(long id) const
  {
    auto it = index.find(id);
    return it == index.end() ? nullptr : &atoms[it->second];
  }
  // Displacement a - b, minimum image in periodic dimensions.
  void delta(const double *a, const double *b, double *d) const
  {
    for (int k = 0; k < 3; ++k) {
      d[k] = a[k] - b[k];
      if (periodic[k]) d[k] -= length(k) * std::round(d[k] / length(k));
    }
  }
  double overlap(const Atom &a, const Atom &b) const
  {
    double d[3];
    delta(a.x, b.x, d);
    return a.r + b.r - std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  }
};

[[noreturn]] void bad(const std::string &why)
{
  std::fprintf(stderr, "check_scene: %s\n", why.c_str());
  std::exit(2);
}

double to_double(const std::string &s, const std::string &what)
{
  char *end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end || !std::isfinite(v)) bad(what + ": not a finite number: '" + s + "'");
  return v;
}

long to_long(const std::string &s, const std::string &what)
{
  char *end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end) bad(what + ": not an integer: '" + s + "'");
  return v;
}

// A bound: a finite number, or INF / -INF (any case): no bound.
double to_bound(const std::string &s, const std::string &what)
{
  std::string l = s;
  for (char &ch : l) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (l == "inf" || l == "+inf") return INFINITY;
  if (l == "-inf") return -INFINITY;
  return to_double(s, what);
}

std::vector<std::string> split(const std::string &line)
{
  std::istringstream in(line);
  std::vector<std::string> f;
  for (std::string w; in >> w;) f.push_back(w);
  return f;
}

// Reads the last snapshot of a LAMMPS text dump.
Dump read_dump(const std::string &path)
{
  std::ifstream in(path);
  if (!in) bad("cannot read " + path);
  Dump last;
  bool any = false;
  std::string line;
  long lineno = 0;
  auto next_line = [&](const char *what) {
    if (!std::getline(in, line)) bad(path + ": truncated (expected " + what + ")");
    ++lineno;
    return line;
  };
  while (std::getline(in, line)) {
    ++lineno;
    if (line.rfind("ITEM: NUMBER OF ATOMS", 0) != 0) continue;
    Dump d;
    d.path = path;
    const long n = to_long(split(next_line("atom count")).at(0), path + ": atom count");
    next_line("BOX BOUNDS");
    if (line.rfind("ITEM: BOX BOUNDS", 0) != 0) bad(path + ": no BOX BOUNDS after the atom count");
    const std::vector<std::string> flags = split(line.substr(16));
    if (flags.size() != 3)
      bad(path + ": triclinic or malformed BOX BOUNDS (orthogonal boxes only)");
    for (int k = 0; k < 3; ++k) {
      d.periodic[k] = flags[k] == "pp";
      d.fixed[k] = flags[k] == "ff";
    }
    for (int k = 0; k < 3; ++k) {
      const std::vector<std::string> b = split(next_line("box bounds"));
      if (b.size() != 2) bad(path + ": bad box bounds line " + std::to_string(lineno));
      d.lo[k] = to_double(b[0], path + ": box");
      d.hi[k] = to_double(b[1], path + ": box");
      if (!(d.hi[k] > d.lo[k])) bad(path + ": empty box");
    }
    next_line("ATOMS header");
    if (line.rfind("ITEM: ATOMS", 0) != 0) bad(path + ": no ATOMS header");
    const std::vector<std::string> names = split(line.substr(11));
    std::map<std::string, std::size_t> col;
    for (std::size_t c = 0; c < names.size(); ++c) col[names[c]] = c;
    for (const char *need : {"id", "type", "x", "y", "z", "radius"})
      if (!col.count(need)) bad(path + ": dump lacks column " + need);
    const std::size_t cid = col["id"], ctype = col["type"], cx = col["x"], cy = col["y"],
                      cz = col["z"], cr = col["radius"];
    d.has_mass = col.count("mass") > 0;
    const std::size_t cm = d.has_mass ? col["mass"] : 0;
    d.atoms.reserve(static_cast<std::size_t>(std::max(0L, n)));
    for (long a = 0; a < n; ++a) {
      const std::vector<std::string> f = split(next_line("an atom line"));
      if (f.size() != names.size())
        bad(path + ": line " + std::to_string(lineno) + " has " + std::to_string(f.size()) +
            " columns, the header names " + std::to_string(names.size()));
      Atom at;
      const std::string where = path + ":" + std::to_string(lineno);
      at.id = to_long(f[cid], where);
      at.type = static_cast<int>(to_long(f[ctype], where));
      at.x[0] = to_double(f[cx], where);
      at.x[1] = to_double(f[cy], where);
      at.x[2] = to_double(f[cz], where);
      at.r = to_double(f[cr], where);
      if (!(at.r > 0)) bad(where + ": radius must be positive");
      if (d.has_mass) at.mass = to_double(f[cm], where);
      at.text = f[cid] + ' ' + f[ctype] + ' ' + f[cx] + ' ' + f[cy] + ' ' + f[cz] + ' ' + f[cr];
      d.atoms.push_back(std::move(at));
    }
    std::sort(d.atoms.begin(), d.atoms.end(),
              [](const Atom &a, const Atom &b) { return a.id < b.id; });
    for (std::size_t i = 0; i < d.atoms.size(); ++i)
      if (!d.index.emplace(d.atoms[i].id, i).second)
        bad(path + ": atom id " + std::to_string(d.atoms[i].id) + " appears twice");
    last = std::move(d);
    any = true;
  }
  if (!any) bad(path + ": no snapshot (no 'ITEM: NUMBER OF ATOMS')");
  return last;
}

// How pairs are found: the cell grid (default), or every pair (--brute).
// grid_scale multiplies the cell size: it is a knob for the checker's own
// test (--compare-grid must fail when cells are too small to hold every
// contact), never for use.
bool brute_force = false;
double grid_scale = 1.0;

// The atom types that are rebar (--rebar-type, a comma list or repeated;
// default 2). All other types are matrix.
std::vector<int> rebar_types = {2};
bool is_rebar(int type)
{
  return std::find(rebar_types.begin(), rebar_types.end(), type) != rebar_types.end();
}

// Calls f(i, j, overlap) once for every pair i < j closer than r_i + r_j
// (overlap > 0), minimum image in periodic dimensions, through a cell grid
// of cell size >= 2 * the largest radius (or, with --brute, by trying every
// pair).
template <class F> void for_each_contact(const Dump &d, F &&f)
{
  const std::vector<Atom> &a = d.atoms;
  if (a.empty()) return;
  if (brute_force) {
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = i + 1; j < a.size(); ++j) {
        const double o = d.overlap(a[i], a[j]);
        if (o > 0) f(i, j, o);
      }
    return;
  }
  double rmax = 0, lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = a[0].x[k];
  for (const Atom &at : a) {
    rmax = std::max(rmax, at.r);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], at.x[k]);
      hi[k] = std::max(hi[k], at.x[k]);
    }
  }
  double cell = 2 * rmax * grid_scale;
  long n[3];
  double origin[3], size[3];
  for (;;) {
    double cells = 1;
    for (int k = 0; k < 3; ++k) {
      if (d.periodic[k]) {
        origin[k] = d.lo[k];
        n[k] = std::max(1L, static_cast<long>(d.length(k) / cell));
        size[k] = d.length(k) / static_cast<double>(n[k]);
      } else {
        origin[k] = lo[k];
        size[k] = cell;
        n[k] = static_cast<long>((hi[k] - lo[k]) / cell) + 1;
      }
      cells *= static_cast<double>(n[k]);
    }
    if (cells <= 4.0 * static_cast<double>(a.size()) + 1000) break;
    cell *= 1.5;    // very sparse scene: fewer, larger cells
  }
  auto coord = [&](const double *x, int k) {
    long c = static_cast<long>(std::floor((x[k] - origin[k]) / size[k]));
    if (d.periodic[k]) c = ((c % n[k]) + n[k]) % n[k];
    return std::min(std::max(c, 0L), n[k] - 1);
  };
  const std::size_t ncells = static_cast<std::size_t>(n[0] * n[1] * n[2]);
  std::vector<long> head(ncells, -1), next(a.size(), -1);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t c = static_cast<std::size_t>(
        (coord(a[i].x, 2) * n[1] + coord(a[i].x, 1)) * n[0] + coord(a[i].x, 0));
    next[i] = head[c];
    head[c] = static_cast<long>(i);
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::vector<long> range[3];
    for (int k = 0; k < 3; ++k) {
      const long c = coord(a[i].x, k);
      for (long dc = -1; dc <= 1; ++dc) {
        long v = c + dc;
        if (d.periodic[k])
          v = ((v % n[k]) + n[k]) % n[k];
        else if (v < 0 || v >= n[k])
          continue;
        if (std::find(range[k].begin(), range[k].end(), v) == range[k].end()) range[k].push_back(v);
      }
    }
    for (long cz : range[2])
      for (long cy : range[1])
        for (long cx : range[0])
          for (long j = head[static_cast<std::size_t>((cz * n[1] + cy) * n[0] + cx)]; j >= 0;
               j = next[static_cast<std::size_t>(j)]) {
            if (j <= static_cast<long>(i)) continue;
            const double o = d.overlap(a[i], a[static_cast<std::size_t>(j)]);
            if (o > 0) f(i, static_cast<std::size_t>(j), o);
          }
  }
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

std::string str(long v)
{
  return std::to_string(v);
}

// Same place and size: equal radius, and equal position up to 1e-12 of the
// box length (a periodic wrap of an unmoved atom does not count as a move).
bool same_place(const Dump &box, const Atom &a, const Atom &b)
{
  if (a.r != b.r) return false;
  double d[3];
  box.delta(a.x, b.x, d);
  for (int k = 0; k < 3; ++k)
    if (std::fabs(d[k]) > 1e-12 * box.length(k)) return false;
  return true;
}

// ---------------------------------------------------------------------------
// Walls the moved matrix spheres must stay clear of (--wall-plane,
// --wall-cylinder, --wall-stl, --inside-box): exact geometry, brute force.
using Vec = tools::Vec<double>;
Vec vec(const double *x)
{
  return {x[0], x[1], x[2]};
}

struct Triangle {
  Vec a, b, c;
};

// The point of segment [a, b] closest to p.
Vec closest_on_segment(Vec p, Vec a, Vec b)
{
  const Vec ab = b - a;
  const double len2 = dot(ab, ab);
  if (!(len2 > 0)) return a;
  const double t = std::min(1.0, std::max(0.0, dot(p - a, ab) / len2));
  return a + t * ab;
}

// The exact distance from p to the closed triangle t: the closest point is
// in the face, on an edge or a vertex (Voronoi regions of the triangle, as
// in Ericson, Real-Time Collision Detection, 5.1.5). A degenerate triangle
// (no area) is its three edges.
double point_triangle_distance(Vec p, const Triangle &t)
{
  const Vec ab = t.b - t.a, ac = t.c - t.a, n = cross(ab, ac);
  if (!(dot(n, n) > 0)) {
    double d = INFINITY;
    for (const auto &e :
         {std::make_pair(t.a, t.b), std::make_pair(t.b, t.c), std::make_pair(t.c, t.a)})
      d = std::min(d, norm(p - closest_on_segment(p, e.first, e.second)));
    return d;
  }
  const Vec ap = p - t.a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return norm(p - t.a);    // vertex a
  const Vec bp = p - t.b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return norm(p - t.b);    // vertex b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return norm(p - (t.a + (d1 / (d1 - d3)) * ab));    // edge ab
  const Vec cp = p - t.c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return norm(p - t.c);    // vertex c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return norm(p - (t.a + (d2 / (d2 - d6)) * ac));    // edge ac
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)    // edge bc
    return norm(p - (t.b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (t.c - t.b)));
  // the face: the distance to its plane
  return std::fabs(dot(ap, n)) / norm(n);
}

// 2-d helpers for a segment lying in the plane of a triangle.
double orient2(double ax, double ay, double bx, double by, double cx, double cy)
{
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}
bool segments_meet_2d(const double *p, const double *q, const double *a, const double *b)
{
  const double o1 = orient2(p[0], p[1], q[0], q[1], a[0], a[1]);
  const double o2 = orient2(p[0], p[1], q[0], q[1], b[0], b[1]);
  const double o3 = orient2(a[0], a[1], b[0], b[1], p[0], p[1]);
  const double o4 = orient2(a[0], a[1], b[0], b[1], q[0], q[1]);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  auto on = [](const double *u, const double *v, const double *w, double o) {    // w on [u, v]
    return o == 0 && std::min(u[0], v[0]) <= w[0] && w[0] <= std::max(u[0], v[0]) &&
           std::min(u[1], v[1]) <= w[1] && w[1] <= std::max(u[1], v[1]);
  };
  return on(p, q, a, o1) || on(p, q, b, o2) || on(a, b, p, o3) || on(a, b, q, o4);
}

// Whether q, a point in the plane of t (normal n = (b - a) x (c - a)), lies
// in the closed triangle.
bool in_triangle(Vec q, const Triangle &t, Vec n)
{
  return dot(cross(t.b - t.a, q - t.a), n) >= 0 && dot(cross(t.c - t.b, q - t.b), n) >= 0 &&
         dot(cross(t.a - t.c, q - t.c), n) >= 0;
}

// Whether the closed segment [p0, p1] meets the closed triangle t.
bool segment_crosses_triangle(Vec p0, Vec p1, const Triangle &t)
{
  const Vec n = cross(t.b - t.a, t.c - t.a);
  if (!(dot(n, n) > 0)) return false;    // no area: nothing to cross
  const double d0 = dot(n, p0 - t.a), d1 = dot(n, p1 - t.a);
  if ((d0 > 0 && d1 > 0) || (d0 < 0 && d1 < 0)) return false;
  if (d0 == 0 && d1 == 0) {    // in the triangle's plane: 2-d, dropping the normal's largest axis
    const int drop = std::fabs(n.x) >= std::fabs(n.y) && std::fabs(n.x) >= std::fabs(n.z) ? 0
                     : std::fabs(n.y) >= std::fabs(n.z)                                   ? 1
                                                                                          : 2;
    auto flat = [drop](Vec v, double *out) {
      const double c[3] = {v.x, v.y, v.z};
      for (int k = 0, m = 0; k < 3; ++k)
        if (k != drop) out[m++] = c[k];
    };
    double a[2], b[2], c[2], p[2], q[2];
    flat(t.a, a), flat(t.b, b), flat(t.c, c), flat(p0, p), flat(p1, q);
    if (in_triangle(p0, t, n) || in_triangle(p1, t, n)) return true;
    return segments_meet_2d(p, q, a, b) || segments_meet_2d(p, q, b, c) ||
           segments_meet_2d(p, q, c, a);
  }
  const double s = d0 / (d0 - d1);
  return in_triangle(p0 + s * (p1 - p0), t, n);
}

// Reads the triangles of an ASCII STL file (facet ... outer loop, three
// vertex lines, endloop, endfacet; keywords in any case).
std::vector<Triangle> read_stl(const std::string &path)
{
  std::ifstream in(path);
  if (!in) bad("cannot read " + path);
  std::vector<Triangle> tris;
  std::vector<Vec> v;
  bool in_facet = false;
  long lineno = 0;
  for (std::string line; std::getline(in, line);) {
    ++lineno;
    std::vector<std::string> f = split(line);
    if (f.empty()) continue;
    std::string k = f[0];
    for (char &ch : k) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    const std::string where = path + ":" + std::to_string(lineno);
    if (k == "facet") {
      if (in_facet) bad(where + ": facet inside a facet");
      in_facet = true;
      v.clear();
    } else if (k == "vertex") {
      if (!in_facet || f.size() != 4) bad(where + ": expected 'vertex X Y Z' inside a facet");
      v.push_back({to_double(f[1], where), to_double(f[2], where), to_double(f[3], where)});
    } else if (k == "endfacet") {
      if (!in_facet || v.size() != 3)
        bad(where + ": a facet needs exactly three vertices (has " + std::to_string(v.size()) +
            ")");
      tris.push_back({v[0], v[1], v[2]});
      in_facet = false;
    }
  }
  if (in_facet) bad(path + ": unterminated facet");
  if (tris.empty()) bad(path + ": no facet (an ASCII STL is needed)");
  return tris;
}

std::string numg(double v)
{
  char b[64];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

struct Wall {
  enum Kind { Plane, Cylinder, Stl, Box } kind = Plane;
  Vec point, normal;                    // plane: a point, the unit normal (the matrix side)
  int axis = 2;                         // cylinder: 0, 1, 2 = x, y, z
  double c1 = 0, c2 = 0, radius = 0;    // cylinder: the axis through (c1, c2), its radius
  bool inside = true;                   // cylinder: the matrix inside
  std::vector<Triangle> triangles;      // stl
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};    // box (may be infinite)
  std::string label;                              // what the check line calls it

  // How far a sphere (centre x, radius r) reaches through the wall, as a
  // fraction of r: > 0 reaches through, <= 0 clear by that gap.
  double depth(Vec x, double r) const
  {
    switch (kind) {
    case Plane:
      return (r - dot(x - point, normal)) / r;
    case Cylinder: {
      const double c[3] = {x.x, x.y, x.z};
      const int u = axis == 0 ? 1 : 0, w = axis == 2 ? 1 : 2;
      const double rho = std::hypot(c[u] - c1, c[w] - c2);
      return inside ? (rho + r - radius) / r : (radius + r - rho) / r;
    }
    case Stl: {
      double d = INFINITY;
      for (const Triangle &t : triangles) d = std::min(d, point_triangle_distance(x, t));
      return (r - d) / r;
    }
    case Box: {
      const double c[3] = {x.x, x.y, x.z};
      double worst = -INFINITY;
      for (int k = 0; k < 3; ++k)
        worst = std::max({worst, (lo[k] - (c[k] - r)) / r, (c[k] + r - hi[k]) / r});
      return worst;
    }
    }
    return 0;
  }
  bool crossed(Vec from, Vec to) const
  {
    if (kind != Stl) return false;
    for (const Triangle &t : triangles)
      if (segment_crosses_triangle(from, to, t)) return true;
    return false;
  }
};

struct Options {
  std::string before, after, same_a, same_b, stats, packing, compare;
  double tol = 1e-6, rmin = 0, rmax = 0;
  double overlap_tol = 1e-12;    // for the pairs of a moved sphere (--overlap-tol)
  long deleted = -1;
  double zone = 0;    // --zone W: moved non-targets start within W of a target (0: not checked)
  bool kept_ok = false, clean_before = false;
  std::vector<Wall> walls;
};

int run_same(const Options &o)
{
  const Dump a = read_dump(o.same_a), b = read_dump(o.same_b);
  std::string why;
  if (a.atoms.size() != b.atoms.size())
    why = str(static_cast<long>(a.atoms.size())) + " vs " + str(static_cast<long>(b.atoms.size())) +
          " atoms";
  for (std::size_t i = 0; why.empty() && i < a.atoms.size(); ++i)
    if (a.atoms[i].text != b.atoms[i].text)
      why = "first difference: '" + a.atoms[i].text + "' vs '" + b.atoms[i].text + "'";
  check(why.empty(), "identical atoms in " + o.same_a + " and " + o.same_b +
                         (why.empty() ? " (" + str(static_cast<long>(a.atoms.size())) + " atoms)"
                                      : " (" + why + ")"));
  return failures ? 1 : 0;
}

int run_stats(const Options &o, bool describe)
{
  const Dump d = read_dump(describe ? o.packing : o.stats);
  double rmin = o.rmin, smallest = INFINITY, largest = 0, volume = 0;
  long nm = 0;
  for (const Atom &a : d.atoms)
    if (!is_rebar(a.type)) {
      smallest = std::min(smallest, a.r);
      largest = std::max(largest, a.r);
      volume += 4.0 / 3.0 * 3.14159265358979323846 * a.r * a.r * a.r;
      ++nm;
    }
  if (rmin <= 0) rmin = smallest;
  double mr = 0, mm = 0;
  long nmm = 0;
  for_each_contact(d, [&](std::size_t i, std::size_t j, double ov) {
    const bool ri = is_rebar(d.atoms[i].type), rj = is_rebar(d.atoms[j].type);
    if (ri && rj) return;
    if (ri || rj)
      mr = std::max(mr, ov / rmin);
    else {
      mm = std::max(mm, ov / rmin);
      if (ov > o.tol * std::min(d.atoms[i].r, d.atoms[j].r)) ++nmm;
    }
  });
  if (!describe) {
    std::printf("atoms %zu matrix %ld max_matrix_rebar %.6g max_matrix_matrix %.6g\n",
                d.atoms.size(), nm, mr, mm);
    return 0;
  }
  double wall = -INFINITY;    // largest penetration of a matrix sphere through a wall
  for (const Atom &a : d.atoms)
    if (!is_rebar(a.type))
      for (int k = 0; k < 3; ++k)
        if (d.fixed[k]) wall = std::max({wall, d.lo[k] - (a.x[k] - a.r), a.x[k] + a.r - d.hi[k]});
  const double box = d.length(0) * d.length(1) * d.length(2);
  std::printf("atoms %zu matrix %ld\n", d.atoms.size(), nm);
  std::printf("matrix radius min %.17g max %.17g\n", smallest, largest);
  std::printf("box %.17g %.17g %.17g to %.17g %.17g %.17g\n", d.lo[0], d.lo[1], d.lo[2], d.hi[0],
              d.hi[1], d.hi[2]);
  std::printf("solid fraction of the matrix %.6f\n", volume / box);
  std::printf("largest overlap / rmin: matrix-matrix %.3g, matrix-rebar %.3g (rmin %.6g)\n", mm, mr,
              rmin);
  std::printf("matrix-matrix pairs overlapping above tol %.3g: %ld\n", o.tol, nmm);
  if (wall > -INFINITY)
    std::printf("largest reach of a matrix sphere through a wall / rmin: %.3g (%s)\n", wall / rmin,
                wall <= 0 ? "all spheres wholly inside" : "OUTSIDE");
  return 0;
}

// --compare-grid D: every contact (overlap > 0) of D found by the cell
// grid must be found by brute force and the other way round, with the same
// overlap.
int run_compare(const Options &o)
{
  const Dump d = read_dump(o.compare);
  struct Pair {
    std::size_t i, j;
    double ov;
  };
  auto collect = [&](bool brute) {
    brute_force = brute;
    std::vector<Pair> p;
    for_each_contact(d, [&](std::size_t i, std::size_t j, double ov) { p.push_back({i, j, ov}); });
    std::sort(p.begin(), p.end(),
              [](const Pair &a, const Pair &b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
    return p;
  };
  const std::vector<Pair> grid = collect(false), all = collect(true);
  long missing = 0, extra = 0, differ = 0, twice = 0;
  std::string first;
  std::size_t g = 0, b = 0;
  auto note = [&](const char *what, const Pair &p) {
    if (first.empty())
      first = std::string(what) + " ids " + str(d.atoms[p.i].id) + " " + str(d.atoms[p.j].id) +
              " overlap " + num(p.ov);
  };
  for (std::size_t k = 1; k < grid.size(); ++k)
    if (grid[k].i == grid[k - 1].i && grid[k].j == grid[k - 1].j) ++twice;
  while (g < grid.size() || b < all.size()) {
    if (b == all.size() || (g < grid.size() && (grid[g].i < all[b].i ||
                                                (grid[g].i == all[b].i && grid[g].j < all[b].j)))) {
      ++extra;
      note("grid only:", grid[g++]);
    } else if (g == grid.size() || grid[g].i != all[b].i || grid[g].j != all[b].j) {
      ++missing;
      note("missed by the grid:", all[b++]);
    } else {
      if (grid[g].ov != all[b].ov) {
        ++differ;
        note("different overlap:", all[b]);
      }
      ++g;
      ++b;
    }
  }
  check(missing == 0 && extra == 0 && differ == 0 && twice == 0,
        "the grid finds the " + str(static_cast<long>(all.size())) +
            " contacts brute force finds, in " + str(static_cast<long>(d.atoms.size())) +
            " spheres (" + str(missing) + " missed, " + str(extra) + " extra, " + str(twice) +
            " twice, " + str(differ) + " with another overlap" +
            (first.empty() ? "" : "; first: " + first) + ")");
  return failures ? 1 : 0;
}

int run_check(Options o)
{
  const Dump before = read_dump(o.before), after = read_dump(o.after);

  // The accepted radius range: given, or that of the matrix before (the
  // fix's default).
  const bool given_range = o.rmin > 0 && o.rmax > 0;
  if (!given_range) {
    double lo = INFINITY, hi = 0;
    for (const Atom &a : before.atoms)
      if (!is_rebar(a.type)) {
        lo = std::min(lo, a.r);
        hi = std::max(hi, a.r);
      }
    if (o.rmin <= 0) o.rmin = lo;
    if (o.rmax <= 0) o.rmax = hi;
  }
  const double rmin = o.rmin > 0 && std::isfinite(o.rmin) ? o.rmin : 1;

  // Moved (position or radius changed), new and retyped atoms; deletions.
  std::vector<char> moved(after.atoms.size(), 0);
  long new_atoms = 0, retyped = 0, moved_count = 0, deleted = 0;
  for (std::size_t i = 0; i < after.atoms.size(); ++i) {
    const Atom &a = after.atoms[i];
    const Atom *b = before.find(a.id);
    if (!b) {
      ++new_atoms;
      moved[i] = 1;
      continue;
    }
    if (b->type != a.type) ++retyped;
    moved[i] = !same_place(after, *b, a);
    moved_count += moved[i];
  }
  for (const Atom &b : before.atoms)
    if (!after.find(b.id)) ++deleted;

  // Targets of before: matrix spheres overlapping a rebar sphere. Moved ones
  // were relocated; other moved spheres were pushed to make room.
  std::vector<char> was_target(before.atoms.size(), 0);
  for_each_contact(before, [&](std::size_t i, std::size_t j, double ov) {
    const Atom &a = before.atoms[i], &b = before.atoms[j];
    if (is_rebar(a.type) == is_rebar(b.type) || ov <= o.tol * std::min(a.r, b.r)) return;
    was_target[is_rebar(a.type) ? j : i] = 1;
  });
  auto index_before = [&](const Atom *b) {
    return static_cast<std::size_t>(b - before.atoms.data());
  };
  long moved_targets = 0, moved_others = 0;
  double volume_targets_before = 0, volume_relocated_after = 0;
  auto ball = [](double r) { return 4.0 / 3.0 * 3.14159265358979323846 * r * r * r; };
  for (std::size_t k = 0; k < before.atoms.size(); ++k)
    if (was_target[k] && !after.find(before.atoms[k].id))
      volume_targets_before += ball(before.atoms[k].r);    // deleted
  for (std::size_t i = 0; i < after.atoms.size(); ++i) {
    if (!moved[i]) continue;
    const Atom &a = after.atoms[i];
    const Atom *b = before.find(a.id);
    const bool target = b && was_target[index_before(b)];
    if (target) {
      ++moved_targets;
      volume_targets_before += ball(b->r);
      volume_relocated_after += ball(a.r);
    } else {
      ++moved_others;
    }
  }

  // The regrowth's zone (regrow W): a sphere it moves, not a target, has
  // its centre within W of a seed's, and every seed is a target.
  if (o.zone > 0) {
    long checked = 0, beyond = 0;
    double farthest = 0;
    for (std::size_t i = 0; i < after.atoms.size(); ++i) {
      const Atom *b = before.find(after.atoms[i].id);
      if (!moved[i] || !b || is_rebar(b->type) || was_target[index_before(b)]) continue;
      double nearest = INFINITY;
      for (std::size_t t = 0; t < before.atoms.size(); ++t) {
        if (!was_target[t]) continue;
        double d[3];
        before.delta(b->x, before.atoms[t].x, d);
        nearest = std::min(nearest, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      }
      ++checked;
      beyond += !(nearest < o.zone);
      farthest = std::max(farthest, nearest);
    }
    check(beyond == 0, "moved spheres that were no target start within the zone, " + num(o.zone) +
                           " of a target's centre (" + str(beyond) + " of " + str(checked) +
                           " beyond; farthest " + num(farthest) + ")");
  }

  // Kept targets: matrix spheres left in place that overlap a bar.
  std::vector<char> kept(after.atoms.size(), 0);
  long kept_count = 0;
  double worst_kept = 0;
  for_each_contact(after, [&](std::size_t i, std::size_t j, double ov) {
    const Atom &a = after.atoms[i], &b = after.atoms[j];
    if (is_rebar(a.type) == is_rebar(b.type)) return;
    const std::size_t m = is_rebar(a.type) ? j : i;
    if (moved[m] || ov <= o.tol * std::min(a.r, b.r)) return;
    worst_kept = std::max(worst_kept, ov / rmin);
    if (!kept[m]) ++kept_count;
    kept[m] = 1;
  });

  // Every overlapping pair of the result, sorted into what it means.
  long moved_pairs = 0, packing_pairs = 0, kept_pairs = 0, own_pairs = 0;
  double worst_moved = 0, worst_packing = 0, worst_all = 0, worst_moved_kept = 0, worst_own = 0;
  for_each_contact(after, [&](std::size_t i, std::size_t j, double ov) {
    const Atom &a = after.atoms[i], &b = after.atoms[j];
    const bool ra = is_rebar(a.type), rb = is_rebar(b.type);
    if (ra && rb) return;    // bars may be clumps of overlapping spheres
    worst_all = std::max(worst_all, ov / rmin);
    if (moved[i] || moved[j]) {
      // A pair that overlapped before, at the same radii, neither sphere a
      // target: what it had is the packing's own (a DEM-settled packing has
      // one at every contact, a matrix sphere may touch a bar within tol
      // without being a target); only what a move adds to it is the fix's.
      // A relocated target owns no old contact: the engine places it clear
      // of every present sphere.
      const Atom *pa = before.find(a.id), *pb = before.find(b.id);
      if (pa && pb && pa->r == a.r && pb->r == b.r && !was_target[index_before(pa)] &&
          !was_target[index_before(pb)]) {
        const double had = before.overlap(*pa, *pb);
        if (had > 0) {
          ++own_pairs;
          worst_own = std::max(worst_own, had / rmin);
          ov -= had;
          if (ov <= 0) return;
        }
      }
    }
    if (moved[i] || moved[j]) worst_moved = std::max(worst_moved, ov / rmin);
    // A moved sphere on a kept target (unplaced keep): reported on its own.
    if ((moved[i] && kept[j]) || (moved[j] && kept[i]))
      worst_moved_kept = std::max(worst_moved_kept, ov / rmin);
    // A pair of a moved sphere counts above --overlap-tol, any other above tol.
    const double small = std::min(a.r, b.r);
    const bool of_moved = moved[i] || moved[j];
    if (ov <= (of_moved ? o.overlap_tol : o.tol) * small) return;
    if (o.kept_ok && (kept[i] || kept[j])) {
      ++kept_pairs;
    } else if (!moved[i] && !moved[j] && !ra && !rb) {
      // Both unmoved matrix spheres: the packing's own overlap, if it was
      // there before (same ids, places and radii: recomputed to be sure).
      const Atom *pa = before.find(a.id), *pb = before.find(b.id);
      if (before.overlap(*pa, *pb) > o.tol * std::min(a.r, b.r)) {
        ++packing_pairs;
        worst_packing = std::max(worst_packing, ov / rmin);
      } else {
        ++moved_pairs;
      }
    } else if (!moved[i] && !moved[j]) {
      // an unmoved matrix sphere on a bar: a kept target, counted below
    } else {
      ++moved_pairs;
    }
  });

  check(moved_pairs == 0, "moved spheres overlap nothing above " + num(o.overlap_tol) +
                              " * min radius (" + str(moved_pairs) + " pairs; largest " +
                              num(worst_moved) + " of rmin)");
  if (o.kept_ok) {
    std::printf("INFO: %ld kept targets still overlap a bar (allowed by --kept-ok; largest %s "
                "of rmin; %ld overlapping pairs with them ignored)\n",
                kept_count, num(worst_kept).c_str(), kept_pairs);
    std::printf("INFO: largest overlap of a moved sphere with a kept target: %s of rmin "
                "(max_overlap_kept)\n",
                num(worst_moved_kept).c_str());
  } else
    check(kept_count == 0, "no matrix sphere overlaps a bar (" + str(kept_count) +
                               " unmoved matrix spheres do; largest " + num(worst_kept) +
                               " of rmin; --kept-ok allows targets left in place)");
  std::printf("INFO: %ld overlapping pairs of unmoved matrix spheres were there before (the "
              "packing's own, not checked; largest %s of rmin)\n",
              packing_pairs, num(worst_packing).c_str());
  std::printf(
      "INFO: %ld pairs with a moved matrix sphere overlapped before (the packing's own, "
      "neither a target; largest %s of rmin): only what they overlap beyond it is checked\n",
      own_pairs, num(worst_own).c_str());

  // The packing given to the fix: its own matrix-matrix overlaps.
  long before_pairs = 0;
  double worst_before = 0;
  for_each_contact(before, [&](std::size_t i, std::size_t j, double ov) {
    const Atom &a = before.atoms[i], &b = before.atoms[j];
    if (is_rebar(a.type) || is_rebar(b.type)) return;
    if (ov <= o.tol * std::min(a.r, b.r)) return;
    ++before_pairs;
    worst_before = std::max(worst_before, ov / rmin);
  });
  if (!o.clean_before)
    std::printf("INFO: the packing before has %ld matrix-matrix overlaps above tol (largest %s "
                "of rmin; --clean-before makes them a failure)\n",
                before_pairs, num(worst_before).c_str());
  else
    check(before_pairs == 0, "the packing before has no matrix-matrix overlap above tol (" +
                                 str(before_pairs) + " pairs; largest " + num(worst_before) +
                                 " of rmin)");

  long out_of_range = 0, outside = 0;
  for (std::size_t i = 0; i < after.atoms.size(); ++i) {
    const Atom &a = after.atoms[i];
    if (!moved[i] || is_rebar(a.type)) continue;
    if (a.r < o.rmin * (1 - 1e-12) || a.r > o.rmax * (1 + 1e-12)) ++out_of_range;
    for (int k = 0; k < 3; ++k)
      if (after.fixed[k] &&
          (a.x[k] - a.r < after.lo[k] - o.tol * a.r || a.x[k] + a.r > after.hi[k] + o.tol * a.r)) {
        ++outside;
        break;
      }
  }
  check(out_of_range == 0, "moved radii in [" + num(o.rmin) + ", " + num(o.rmax) + "]" +
                               (given_range ? "" : " (the matrix range before)") + " (" +
                               str(out_of_range) + " outside)");
  check(outside == 0,
        "moved spheres wholly inside the walls (ff dimensions) (" + str(outside) + " reach out)");
  // The walls given: every moved matrix sphere wholly on the matrix side
  // (depth <= tol, i.e. clear by r (1 - tol)), and for an STL, its centre's
  // path from before to after crosses no triangle. The walls are in the
  // dump's coordinates (no periodic images of them).
  for (const Wall &w : o.walls) {
    long checked = 0, through = 0, crossed = 0, worst_id = 0;
    double worst = -INFINITY;
    for (std::size_t i = 0; i < after.atoms.size(); ++i) {
      const Atom &a = after.atoms[i];
      if (!moved[i] || is_rebar(a.type)) continue;
      ++checked;
      const double depth = w.depth(vec(a.x), a.r);
      if (depth > o.tol) ++through;
      if (depth > worst) {
        worst = depth;
        worst_id = a.id;
      }
      // The path: the minimum-image displacement d, from the centre before
      // and (the other image, when it crossed a periodic boundary) to the
      // centre after.
      if (const Atom *b = before.find(a.id)) {
        double d[3];
        after.delta(a.x, b->x, d);
        if (w.crossed(vec(b->x), vec(b->x) + vec(d)) || w.crossed(vec(a.x) - vec(d), vec(a.x)))
          ++crossed;
      }
    }
    check(through == 0 && crossed == 0,
          "moved spheres clear of the walls (" + w.label + ": " + str(through) + " of " +
              str(checked) + " moved matrix spheres reach through by more than tol" +
              (w.kind == Wall::Stl ? ", " + str(crossed) + " moved across a triangle" : "") +
              (!checked    ? ""
               : worst > 0 ? "; worst: id " + str(worst_id) + " reaches " + num(worst) +
                                 " of its radius through"
                           : "; closest: id " + str(worst_id) + ", clear by " + num(0.0 - worst) +
                                 " of its radius") +
              ")");
  }

  long rebar_changed = 0, rebar_missing = 0, rebar_new = 0;
  for (const Atom &b : before.atoms) {
    if (!is_rebar(b.type)) continue;
    const Atom *a = after.find(b.id);
    if (!a || !is_rebar(a->type))
      ++rebar_missing;
    else if (!same_place(after, b, *a))
      ++rebar_changed;
  }
  for (const Atom &a : after.atoms) {
    const Atom *b = before.find(a.id);
    if (is_rebar(a.type) && (!b || !is_rebar(b->type))) ++rebar_new;
  }
  check(rebar_missing == 0 && rebar_changed == 0 && rebar_new == 0,
        "rebar untouched (" + str(rebar_missing) + " missing, " + str(rebar_changed) + " moved, " +
            str(rebar_new) + " new)");
  check(new_atoms == 0 && retyped == 0,
        "no new or retyped atoms (" + str(new_atoms) + " new, " + str(retyped) + " retyped)");
  const long nb = static_cast<long>(before.atoms.size()),
             na = static_cast<long>(after.atoms.size());
  if (o.deleted >= 0)
    check(nb == na + o.deleted && deleted == o.deleted,
          "atoms before = after + deleted (" + str(nb) + " = " + str(na) + " + " + str(o.deleted) +
              " expected; " + str(deleted) + " ids gone)");
  else
    check(nb == na + deleted, "atoms before = after + deleted (" + str(nb) + " = " + str(na) +
                                  " + " + str(deleted) + ")");
  // Moved spheres keep their material density: mass / r^3 as before (when
  // both dumps have a mass column).
  if (before.has_mass && after.has_mass) {
    long weighed = 0, changed = 0, resized = 0;
    double worst_density = 0;
    for (std::size_t i = 0; i < after.atoms.size(); ++i) {
      const Atom &a = after.atoms[i];
      const Atom *b = before.find(a.id);
      if (!moved[i] || !b || is_rebar(a.type)) continue;
      const double da = a.mass / (a.r * a.r * a.r), db = b->mass / (b->r * b->r * b->r);
      const double rel = std::fabs(da - db) / std::max(std::fabs(da), std::fabs(db));
      ++weighed;
      resized += a.r != b->r;
      if (!(rel <= 1e-12)) ++changed;    // NaN (mass 0 / 0) counts as changed
      if (rel > worst_density || std::isnan(rel)) worst_density = rel;
    }
    check(changed == 0, "moved spheres kept their density (mass / volume) (" + str(changed) +
                            " of " + str(weighed) + " changed; " + str(resized) +
                            " with a new radius; largest relative change " + num(worst_density) +
                            ")");
  } else {
    std::printf("INFO: no mass column in both dumps: density not checked\n");
  }
  std::printf("SUMMARY atoms_before %ld atoms_after %ld moved %ld deleted %ld kept %ld "
              "max_overlap_moved %.3g max_overlap_all %.3g max_overlap_packing %.3g "
              "max_overlap_kept %.3g moved_targets %ld moved_others %ld "
              "volume_targets_before %.17g volume_relocated_after %.17g (overlaps / rmin %.6g)\n",
              nb, na, moved_count, deleted, kept_count, worst_moved, worst_all, worst_packing,
              worst_moved_kept, moved_targets, moved_others, volume_targets_before,
              volume_relocated_after, rmin);
  // The closing line, after the last check: a test passes on it, not on a
  // line printed part way.
  std::printf("DONE: %d checks failed\n", failures);
  return failures ? 1 : 0;
}

}    // namespace

int main(int argc, char **argv)
{
  Options o;
  bool rebar_given = false;
  // The options that take one number each.
  const std::map<std::string, double *> numbers = {{"--tol", &o.tol},
                                                   {"--overlap-tol", &o.overlap_tol},
                                                   {"--rmin", &o.rmin},
                                                   {"--rmax", &o.rmax},
                                                   {"--zone", &o.zone}};
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) bad("missing value for " + k);
      return argv[++i];
    };
    if (k == "--before")
      o.before = next();
    else if (k == "--after")
      o.after = next();
    else if (k == "--rebar-type") {
      // a comma list, or the option repeated: the first replaces the default
      if (!rebar_given) rebar_types.clear();
      rebar_given = true;
      std::string list = next();
      for (char &ch : list)
        if (ch == ',') ch = ' ';
      const std::vector<std::string> types = split(list);
      if (types.empty()) bad("--rebar-type needs a type");
      for (const std::string &t : types) rebar_types.push_back(static_cast<int>(to_long(t, k)));
    } else if (k == "--wall-plane") {
      Wall w;
      w.kind = Wall::Plane;
      double v[6];
      for (double &x : v) x = to_double(next(), k);
      w.point = {v[0], v[1], v[2]};
      const Vec n = {v[3], v[4], v[5]};
      if (!(norm(n) > 0)) bad("--wall-plane: the normal must not be zero");
      w.normal = (1 / norm(n)) * n;
      w.label = "plane through (" + numg(v[0]) + ", " + numg(v[1]) + ", " + numg(v[2]) +
                ") normal (" + numg(v[3]) + ", " + numg(v[4]) + ", " + numg(v[5]) + ")";
      o.walls.push_back(w);
    } else if (k == "--wall-cylinder") {
      Wall w;
      w.kind = Wall::Cylinder;
      const std::string axis = next();
      if (axis != "x" && axis != "y" && axis != "z") bad("--wall-cylinder: axis must be x, y or z");
      w.axis = axis[0] - 'x';
      w.c1 = to_double(next(), k);
      w.c2 = to_double(next(), k);
      w.radius = to_double(next(), k);
      if (!(w.radius > 0)) bad("--wall-cylinder: the radius must be > 0");
      const std::string side = next();
      if (side != "inside" && side != "outside") bad("--wall-cylinder: expected inside or outside");
      w.inside = side == "inside";
      w.label = "cylinder along " + axis + " through (" + numg(w.c1) + ", " + numg(w.c2) +
                ") radius " + numg(w.radius) + ", spheres " + side;
      o.walls.push_back(w);
    } else if (k == "--wall-stl") {
      Wall w;
      w.kind = Wall::Stl;
      const std::string path = next();
      w.triangles = read_stl(path);
      w.label = "STL " + path + ", " + str(static_cast<long>(w.triangles.size())) + " triangles";
      o.walls.push_back(w);
    } else if (k == "--inside-box") {
      Wall w;
      w.kind = Wall::Box;
      for (int d = 0; d < 3; ++d) {
        w.lo[d] = to_bound(next(), k);
        w.hi[d] = to_bound(next(), k);
        if (!(w.lo[d] < w.hi[d])) bad("--inside-box: each low bound must be below its high bound");
      }
      w.label = "inside box [" + numg(w.lo[0]) + ", " + numg(w.hi[0]) + "] x [" + numg(w.lo[1]) +
                ", " + numg(w.hi[1]) + "] x [" + numg(w.lo[2]) + ", " + numg(w.hi[2]) + "]";
      o.walls.push_back(w);
    } else if (numbers.count(k))
      *numbers.at(k) = to_double(next(), k);
    else if (k == "--deleted")
      o.deleted = to_long(next(), k);
    else if (k == "--kept-ok")
      o.kept_ok = true;
    else if (k == "--overlap-ok-before")
      o.clean_before = false;    // the default, accepted to say it explicitly
    else if (k == "--clean-before")
      o.clean_before = true;
    else if (k == "--same") {
      o.same_a = next();
      o.same_b = next();
    } else if (k == "--stats")
      o.stats = next();
    else if (k == "--packing")
      o.packing = next();
    else if (k == "--compare-grid")
      o.compare = next();
    else if (k == "--brute")
      brute_force = true;
    else if (k == "--grid-scale")
      grid_scale = to_double(next(), k);
    else if (k == "-h" || k == "--help") {
      std::printf("usage: check_scene --before B --after A [--rebar-type 2[,3...]] [--tol 1e-6]\n"
                  "                   [--rmin R --rmax R] [--deleted N] [--kept-ok] [--zone W]\n"
                  "                   [--overlap-ok-before | --clean-before]\n"
                  "                   [--wall-plane PX PY PZ NX NY NZ]... [--wall-stl FILE]...\n"
                  "                   [--wall-cylinder x|y|z C1 C2 R inside|outside]...\n"
                  "                   [--inside-box XLO XHI YLO YHI ZLO ZHI]... (INF: no bound)\n"
                  "       check_scene --same A B\n"
                  "       check_scene --stats D | --packing D [--rebar-type 2] [--rmin R]\n"
                  "       check_scene --compare-grid D    (grid search against brute force)\n"
                  "       --brute: find pairs by trying every pair (any mode)\n"
                  "see tests/tools/README.md\n");
      return 0;
    } else
      bad("unknown option " + k + " (--help lists them)");
  }
  if (!(o.tol >= 0)) bad("--tol must be >= 0");
  if (!(o.overlap_tol >= 0)) bad("--overlap-tol must be >= 0");
  if (o.rmin > 0 && o.rmax > 0 && o.rmin > o.rmax) bad("--rmin is larger than --rmax");
  if (!(grid_scale > 0)) bad("--grid-scale must be > 0");
  if (!o.same_a.empty()) return run_same(o);
  if (!o.compare.empty()) return run_compare(o);
  if (!o.stats.empty()) return run_stats(o, false);
  if (!o.packing.empty()) return run_stats(o, true);
  if (o.before.empty() || o.after.empty())
    bad("need --before and --after (or --same, --stats, --packing)");
  return run_check(o);
}
