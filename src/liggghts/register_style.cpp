// LIGGGHTS 3.8 keeps Modify::fix_map (style name -> creator) private and has
// no plugin loader. An explicit template instantiation may name a private
// member (C++17 [temp.explicit]/12), which lets this one file reach the map;
// nothing else in the project does this.
#include "register_style.h"

#include "fix_reinforce_invert.h"
#include "lammps.h"
#include "modify.h"

#include <map>
#include <string>

namespace {

using FixCreator = LAMMPS_NS::Fix *(*)(LAMMPS_NS::LAMMPS *, int, char **);
using FixMapMember = std::map<std::string, FixCreator> *LAMMPS_NS::Modify::*;

FixMapMember fix_map_member = nullptr;

template <FixMapMember Member> struct FixMapAccess {
  FixMapAccess() { fix_map_member = Member; }
  static FixMapAccess instance;
};
template <FixMapMember Member> FixMapAccess<Member> FixMapAccess<Member>::instance;

template struct FixMapAccess<&LAMMPS_NS::Modify::fix_map>;

LAMMPS_NS::Fix *create_fix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
  return new LAMMPS_NS::FixReinforceInvert(lmp, narg, arg);
}

}    // namespace

void register_reinforce_invert(LAMMPS_NS::LAMMPS *lmp)
{
  (*(lmp->modify->*fix_map_member))["reinforce/invert"] = &create_fix;
}
