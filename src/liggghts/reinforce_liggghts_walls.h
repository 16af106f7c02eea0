// The walls of LIGGGHTS's fix wall/gran as the engine sees them: primitive
// planes and cylinders, and the triangles of its meshes (fix mesh/surface),
// gathered over the processes, with the periodic images of the triangles
// the processes' views reach.
#pragma once

#include "reinforce_boundaries.h"

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class Domain;
class FixMeshSurface;
class FixWallGran;
class PrimitiveWall;

// A primitive wall's type (PRIMITIVE_WALL_DEFINITIONS::WallType) and its
// parameters, which LIGGGHTS keeps private (reinforce_primitive_wall_access.cpp).
int primitive_wall_shape(const PrimitiveWall &wall, std::vector<double> &param);

class LiggghtsWalls {
public:
  void clear();
  // Adds the walls of one wall/gran fix; returns what it read, for the log,
  // or "" when the fix has no wall this can describe. Collective.
  std::string read(FixWallGran &wall, MPI_Comm world);
  // The walls for the engine; `reach`: how far each process's ghosts reach
  // past its subdomain in each dimension.
  std::shared_ptr<const reinforce::Boundaries> in_view(const Domain &domain, const double reach[3]);

private:
  std::string add_primitive(const PrimitiveWall &wall);
  int add_mesh(FixMeshSurface &mesh, MPI_Comm world);

  std::vector<reinforce::Plane> planes;
  std::vector<reinforce::Cylinder> cylinders;
  std::vector<reinforce::Triangle> triangles;
  std::vector<const FixMeshSurface *> meshes;    // read this invocation: a mesh of two fixes, once
  std::shared_ptr<const reinforce::Boundaries> view;
  double view_margin = -1;    // how far beyond the box `view` holds triangle images
};

}    // namespace LAMMPS_NS
