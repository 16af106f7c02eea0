// The few calls that are spelled differently by the LAMMPS-family hosts the
// fix is built for: Debian's LAMMPS 2021, current LAMMPS (29Aug2024 and
// later) and LIGGGHTS 3.8. Each is picked at compile time from what the
// host's headers declare (the overload taking int is tried first, and drops
// out when its call does not compile), so the shared layer is written once.
// Included after the host's headers, by the shared layer's .cpp files only.
#pragma once

#include "comm.h"
#include "domain.h"
#include "error.h"
#include "region.h"

#include <cstdint>
#include <string>
#include <type_traits>

namespace reinforce {
namespace host_api {

// Forward communication of a fix's per-atom data: Comm::forward_comm(Fix *)
// in current LAMMPS, forward_comm_fix(Fix *) in LAMMPS 2021 and LIGGGHTS
// (where forward_comm takes an int, which a pointer does not convert to).
template <class C, class F>
auto forward_comm(C *comm, F *fix, int) -> decltype(comm->forward_comm(fix), void())
{
  comm->forward_comm(fix);
}
template <class C, class F> void forward_comm(C *comm, F *fix, long)
{
  comm->forward_comm_fix(fix);
}

// The region of that ID, or null: Domain::get_region_by_id in current
// LAMMPS, the index of find_region into Domain::regions before it.
template <class D>
auto find_region(D *domain, const std::string &id, int) -> decltype(domain->get_region_by_id(id))
{
  return domain->get_region_by_id(id);
}
template <class D> LAMMPS_NS::Region *find_region(D *domain, const std::string &id, long)
{
  const int i = domain->find_region(id.c_str());
  return i < 0 ? nullptr : domain->regions[i];
}

// ERROR and WARNING lines. LAMMPS takes std::string (and only that overload
// links against Debian's library: its fmt overloads are not exported),
// LIGGGHTS takes const char *.
template <class E>
auto takes_string(E *error, int)
    -> decltype(error->warning(std::string(), 0, std::string()), std::true_type());
template <class E> std::false_type takes_string(E *, long);

template <class E> void error_all(E *error, const char *file, int line, const std::string &message)
{
  if constexpr (decltype(takes_string(error, 0))::value)
    error->all(file, line, message);
  else
    error->all(file, line, message.c_str());
}
template <class E> void warning(E *error, const char *file, int line, const std::string &message)
{
  if constexpr (decltype(takes_string(error, 0))::value)
    error->warning(file, line, message);
  else
    error->warning(file, line, message.c_str());
}

}    // namespace host_api
}    // namespace reinforce
