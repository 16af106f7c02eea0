// The walls of LIGGGHTS's fix wall/gran for the engine (reinforce_liggghts_walls.h).

#include "reinforce_liggghts_walls.h"

#include "domain.h"
#include "fix_mesh_surface.h"
#include "fix_wall_gran.h"
#include "primitive_wall_definitions.h"
#include "tri_mesh.h"

#include "reinforce_mpi_hooks.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

void LiggghtsWalls::clear()
{
  planes.clear();
  cylinders.clear();
  triangles.clear();
  meshes.clear();
  view.reset();
  view_margin = -1;
}

std::string LiggghtsWalls::read(FixWallGran &wall, MPI_Comm world)
{
  if (wall.is_mesh_wall()) {
    int read_meshes = 0, read_triangles = 0;
    for (int m = 0; m < wall.n_meshes(); ++m) {
      FixMeshSurface *mesh = wall.mesh_list()[m];
      if (std::find(meshes.begin(), meshes.end(), mesh) != meshes.end()) continue;
      meshes.push_back(mesh);
      read_triangles += add_mesh(*mesh, world);
      read_meshes++;
    }
    // Meshes of an earlier wall fix are honoured already.
    if (read_meshes == 0) return wall.n_meshes() > 0 ? "its meshes (read with an earlier fix)" : "";
    return std::to_string(read_meshes) + (read_meshes == 1 ? " mesh (" : " meshes (") +
           std::to_string(read_triangles) + " triangles)";
  }
  if (wall.primitiveWall()) return add_primitive(*wall.primitiveWall());
  return "";
}

// A primitive wall as a plane or cylinder, with its name for the log (empty
// when its type has no counterpart). The parameters, as
// primitive_wall_definitions.h uses them: a plane's position along its
// axis; a cylinder's radius, then its centre in the two other axes d + 1
// and d + 2 (mod 3): ycylinder R A B is centred at z = A, x = B.
std::string LiggghtsWalls::add_primitive(const PrimitiveWall &wall)
{
  namespace walls = PRIMITIVE_WALL_DEFINITIONS;
  std::vector<double> p;
  const int type = primitive_wall_shape(wall, p);
  reinforce::Boundaries probe;    // refuses degenerate or non-finite walls
  if (type >= walls::XPLANE && type <= walls::ZPLANE && p.size() == 1) {
    const int d = type - walls::XPLANE;
    reinforce::Plane plane;
    plane.point[d] = p[0];
    plane.normal[d] = 1;
    if (!probe.add(plane)) return "";
    planes.push_back(plane);
  } else if (type >= walls::XCYLINDER && type <= walls::ZCYLINDER && p.size() == 3) {
    const int d = type - walls::XCYLINDER;
    reinforce::Cylinder cylinder;
    cylinder.axis[d] = 1;
    cylinder.point[(d + 1) % 3] = p[1];
    cylinder.point[(d + 2) % 3] = p[2];
    cylinder.radius = p[0];
    if (!probe.add(cylinder)) return "";
    cylinders.push_back(cylinder);
  } else {
    return "";
  }
  return std::string("1 primitive wall (") + walls::wallString[type] + ")";
}

// Every triangle of a mesh, the same complete set on every process; returns
// their number. Before the mesh's first setup (FixMesh::setup_pre_force,
// after this fix's setup_pre_exchange at the first run), and for a mesh
// that is never parallel, every process holds all the elements; afterwards
// each holds those it owns (the first sizeLocal) and ghost copies, and the
// owned ones of all processes are gathered. isParallel is the same on
// every process.
int LiggghtsWalls::add_mesh(FixMeshSurface &fix, MPI_Comm world)
{
  TriMesh *mesh = fix.triMesh();
  std::vector<double> mine;
  mine.reserve(9 * static_cast<std::size_t>(mesh->sizeLocal()));
  for (int i = 0; i < mesh->sizeLocal(); ++i)
    for (int j = 0; j < 3; ++j) {
      double p[3];
      mesh->node(i, j, p);
      mine.insert(mine.end(), p, p + 3);
    }
  const std::vector<double> all =
      mesh->isParallel() ? reinforce::mpi_gather_all(mine, world) : mine;
  for (std::size_t k = 0; k + 9 <= all.size(); k += 9)
    triangles.push_back({{all[k], all[k + 1], all[k + 2]},
                         {all[k + 3], all[k + 4], all[k + 5]},
                         {all[k + 6], all[k + 7], all[k + 8]}});
  return static_cast<int>(all.size() / 9);
}

// In a periodic dimension the engine's coordinates reach beyond the box
// (ghost images, new centres next to them), and the walls must be there
// too: triangles get their images within twice the ghost reach of the box
// (which holds every sphere a process sees). Planes and cylinders are taken
// as they are. Built again only when that reach grows (the engine asks
// before and after raising the ghost cutoff); the same on every process.
std::shared_ptr<const reinforce::Boundaries> LiggghtsWalls::in_view(const Domain &domain,
                                                                    const double reach[3])
{
  if (planes.empty() && cylinders.empty() && triangles.empty()) return nullptr;
  double margin = 0;
  for (int d = 0; d < 3 && !triangles.empty(); ++d)
    if (domain.periodicity[d]) margin = std::max(margin, 2 * reach[d]);
  if (view && margin <= view_margin) return view;
  auto walls = std::make_shared<reinforce::Boundaries>();
  for (const reinforce::Plane &p : planes) walls->add(p);
  for (const reinforce::Cylinder &c : cylinders) walls->add(c);
  std::vector<reinforce::Triangle> all = triangles;
  for (int d = 0; d < 3 && margin > 0; ++d) {
    if (!domain.periodicity[d]) continue;
    const double length = domain.prd[d];
    const int shifts = static_cast<int>(std::ceil(margin / length));
    const std::size_t n = all.size();
    for (std::size_t t = 0; t < n; ++t)
      for (int s = -shifts; s <= shifts; ++s) {
        if (s == 0) continue;
        reinforce::Triangle image = all[t];
        for (reinforce::Vec3 *v : {&image.a, &image.b, &image.c}) (*v)[d] += s * length;
        const double lo = std::min({image.a[d], image.b[d], image.c[d]});
        const double hi = std::max({image.a[d], image.b[d], image.c[d]});
        if (hi >= domain.boxlo[d] - margin && lo <= domain.boxhi[d] + margin) all.push_back(image);
      }
  }
  for (const reinforce::Triangle &t : all) walls->add(t);
  view = walls;
  view_margin = margin;
  return view;
}
