// Registers fix reinforce/invert with a LIGGGHTS instance before it reads
// its input.
#ifndef REINFORCE_LIGGGHTS_REGISTER_STYLE_H
#define REINFORCE_LIGGGHTS_REGISTER_STYLE_H

namespace LAMMPS_NS {
class LAMMPS;
}

void register_reinforce_invert(LAMMPS_NS::LAMMPS *lmp);

#endif
