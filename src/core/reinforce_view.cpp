#include "reinforce_view.h"

#include "reinforce_packing_scan.h"

#include <algorithm>

namespace reinforce {

std::vector<Particle> make_view(const AtomArrays &a, double margin, const Domain &domain,
                                std::vector<int> &local)
{
  std::vector<unsigned char> rebar(a.nall);
  for (int i = 0; i < a.nall; ++i) rebar[i] = (a.mask[i] & a.rebar_bit) != 0;
  local = spheres_near_rebar(a.nall, a.x, a.radius, rebar.data(), margin);
  local.erase(
      std::remove_if(local.begin(), local.end(),
                     [&](int i) {
                       for (int d = 0; d < 3; ++d)
                         if (!(a.x[i][d] >= domain.view_lo[d] && a.x[i][d] <= domain.view_hi[d]))
                           return true;
                       return false;
                     }),
      local.end());
  std::vector<Particle> view;
  view.reserve(local.size());
  for (int i : local) {
    Particle p;
    p.x = {a.x[i][0], a.x[i][1], a.x[i][2]};
    p.r = a.radius[i];
    p.id = a.id(i);
    p.role = rebar[i] ? Role::Rebar : (a.pending[i] ? Role::Target : Role::Matrix);
    p.owned = i < a.nlocal;
    p.other_rebar = !rebar[i] && (a.mask[i] & a.frozen_bits) != 0;
    p.pushable = (a.mask[i] & a.group_bit) != 0 && !p.other_rebar;
    view.push_back(p);
  }
  return view;
}

}    // namespace reinforce
