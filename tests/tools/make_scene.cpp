// Writes a test scene as a LAMMPS/LIGGGHTS data file (atom style sphere /
// granular: id type diameter density x y z): matrix spheres (type 1) on a
// jittered lattice with radii uniform in [rmin, rmax], never overlapping,
// whole lattice cells per box length (so it is periodic too), and bars of
// rebar spheres (type 2) along straight segments.
//
// usage: make_scene OUT --box XLO XHI YLO YHI ZLO ZHI --radius RMIN RMAX
//                   [--spacing S] [--fcc] [--seed N] [--offset DX DY DZ]
//                   [--bar X0 Y0 Z0 X1 Y1 Z1 R STEP]... [--hoop CX CY CZ AXIS RING R STEP]...
// A bar's spheres are STEP apart from X0 to X1 (STEP < 2R: overlapping
// chain). A hoop is a closed ring of radius RING around axis x|y|z.
// --fcc puts four spheres per cell (face-centred cubic, denser: about 0.45
// with radii in [rmax/2, rmax]); the default is one (simple cubic).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "periodic_box.h"

namespace {

struct Atom {
  int type;
  double r, x, y, z;
};

[[noreturn]] void usage(const char *why)
{
  std::fprintf(stderr, "make_scene: %s\n", why);
  std::exit(2);
}

double num(int argc, char **argv, int i)
{
  if (i >= argc) usage("missing value");
  char *end;
  const double v = std::strtod(argv[i], &end);
  if (*end) usage("not a number");
  return v;
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc < 2) usage("no output file");
  // An option where the file belongs is a mistake, not a file name.
  if (argv[1][0] == '-') usage("the first argument is the output file, not an option");
  double box[6] = {0, 1, 0, 1, 0, 1}, rmin = 0.02, rmax = 0.04, spacing = 0, offset[3] = {0, 0, 0};
  unsigned seed = 1;
  bool fcc = false;
  std::vector<Atom> atoms;
  std::vector<std::vector<double>> bars, hoops;
  for (int i = 2; i < argc; ++i) {
    const std::string k = argv[i];
    if (k == "--box") {
      for (int j = 0; j < 6; ++j) box[j] = num(argc, argv, ++i);
    } else if (k == "--radius") {
      rmin = num(argc, argv, ++i);
      rmax = num(argc, argv, ++i);
    } else if (k == "--spacing") {
      spacing = num(argc, argv, ++i);
    } else if (k == "--fcc") {
      fcc = true;
    } else if (k == "--seed") {
      seed = static_cast<unsigned>(num(argc, argv, ++i));
    } else if (k == "--offset") {
      for (double &o : offset) o = num(argc, argv, ++i);
    } else if (k == "--bar") {
      std::vector<double> b;
      for (int j = 0; j < 8; ++j) b.push_back(num(argc, argv, ++i));
      bars.push_back(b);
    } else if (k == "--hoop") {
      std::vector<double> h;
      for (int j = 0; j < 3; ++j) h.push_back(num(argc, argv, ++i));
      if (++i >= argc) usage("missing axis");
      h.push_back(argv[i][0] - 'x');
      for (int j = 0; j < 3; ++j) h.push_back(num(argc, argv, ++i));
      hoops.push_back(h);
    } else {
      usage(("unknown option " + k).c_str());
    }
  }
  if (!(rmin > 0) || rmax < rmin) usage("bad radius range");
  // Nearest lattice neighbours are spacing (sc) or spacing / sqrt(2) (fcc)
  // apart: room for two rmax spheres either way.
  if (spacing <= 0) spacing = 2 * rmax * 1.05 * (fcc ? std::sqrt(2.0) : 1.0);
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  const int nbasis = fcc ? 4 : 1;
  const double room = fcc ? spacing / std::sqrt(2.0) : spacing;    // nearest-neighbour distance
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  int cells[3];
  double step[3];
  for (int d = 0; d < 3; ++d) {
    cells[d] = static_cast<int>((box[2 * d + 1] - box[2 * d]) / spacing);
    if (cells[d] < 1) usage("box thinner than the lattice spacing");
    step[d] = (box[2 * d + 1] - box[2 * d]) / cells[d];
  }
  for (int i = 0; i < cells[0]; ++i)
    for (int j = 0; j < cells[1]; ++j)
      for (int k = 0; k < cells[2]; ++k)
        for (int b = 0; b < nbasis; ++b) {
          const double r = rmin + (rmax - rmin) * u(rng);
          const int ijk[3] = {i, j, k};
          // Each sphere may move by its share of the room to its nearest
          // neighbour (per axis, so at most sqrt(3) of that in all): never
          // an overlap.
          const double slack = std::max(0.0, room / 2 - r) / std::sqrt(3.0) * 0.999;
          double c[3];
          for (int d = 0; d < 3; ++d)
            c[d] = box[2 * d] + (ijk[d] + (fcc ? 0.25 : 0.5) + basis[b][d]) * step[d] +
                   slack * (2 * u(rng) - 1);
          atoms.push_back({1, r, c[0], c[1], c[2]});
        }
  for (const auto &b : bars)
    tools::for_bar_centres(b, [&](const double *p) {
      atoms.push_back({2, b[6], p[0], p[1], p[2]});
    });
  for (const auto &h : hoops) {
    const int axis = static_cast<int>(h[3]);
    const int n = std::max(3, static_cast<int>(std::round(2 * M_PI * h[4] / h[6])));
    for (int s = 0; s < n; ++s) {
      const double a = 2 * M_PI * s / n;
      double p[3] = {h[0], h[1], h[2]};
      p[(axis + 1) % 3] += h[4] * std::cos(a);
      p[(axis + 2) % 3] += h[4] * std::sin(a);
      atoms.push_back({2, h[5], p[0], p[1], p[2]});
    }
  }
  FILE *f = std::fopen(argv[1], "w");
  if (!f) usage("cannot write the output file");
  std::fprintf(f, "reinforce/invert test scene (make_scene)\n\n%zu atoms\n2 atom types\n\n",
               atoms.size());
  const char *axes[3][2] = {{"xlo", "xhi"}, {"ylo", "yhi"}, {"zlo", "zhi"}};
  for (int d = 0; d < 3; ++d)
    std::fprintf(f, "%.17g %.17g %s %s\n", box[2 * d] + offset[d], box[2 * d + 1] + offset[d],
                 axes[d][0], axes[d][1]);
  std::fprintf(f, "\nAtoms\n\n");
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom &a = atoms[i];
    const double density = a.type == 1 ? 2500 : 7800;
    std::fprintf(f, "%zu %d %.17g %g %.17g %.17g %.17g\n", i + 1, a.type, 2 * a.r, density,
                 a.x + offset[0], a.y + offset[1], a.z + offset[2]);
  }
  std::fclose(f);
  return 0;
}
