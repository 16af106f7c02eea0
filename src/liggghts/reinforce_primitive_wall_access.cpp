// LIGGGHTS 3.8 keeps a primitive wall's type and parameters private in
// PrimitiveWall, with no accessor, and fix reinforce/invert must know the
// wall's geometry to keep relocated spheres clear of it. An explicit
// template instantiation may name a private member (C++17
// [temp.explicit]/12), which lets this one file read the three members;
// the trick is the same as in register_style.cpp, and nothing else in the
// adapter reaches into PrimitiveWall.
#include "reinforce_liggghts_walls.h"
#include "primitive_wall.h"

namespace {

using LAMMPS_NS::PrimitiveWall;
using TypeMember = LAMMPS_NS::PRIMITIVE_WALL_DEFINITIONS::WallType PrimitiveWall::*;
using ParamMember = double *PrimitiveWall::*;
using CountMember = int PrimitiveWall::*;

TypeMember type_member = nullptr;
ParamMember param_member = nullptr;
CountMember count_member = nullptr;

template <TypeMember Type, ParamMember Param, CountMember Count> struct PrimitiveWallAccess {
  PrimitiveWallAccess()
  {
    type_member = Type;
    param_member = Param;
    count_member = Count;
  }
  static PrimitiveWallAccess instance;
};
template <TypeMember Type, ParamMember Param, CountMember Count>
PrimitiveWallAccess<Type, Param, Count> PrimitiveWallAccess<Type, Param, Count>::instance;

template struct PrimitiveWallAccess<&PrimitiveWall::wType, &PrimitiveWall::param,
                                    &PrimitiveWall::nParam>;

}    // namespace

int LAMMPS_NS::primitive_wall_shape(const PrimitiveWall &wall, std::vector<double> &param)
{
  const double *p = wall.*param_member;
  param.assign(p, p + wall.*count_member);
  return wall.*type_member;
}
