// Stand-in for the fmt headers that liblammps-dev does not ship.
//
// LAMMPS 2021 bundles fmt 7 and compiles it into liblammps.so under the
// namespace fmt::v7_lmp, but its installed headers (pointers.h, utils.h,
// error.h) include "fmt/format.h" and name fmt::make_args_checked in their
// formatting templates. This header sits first on our include path, pulls in
// Debian's fmt 9 as a header-only library (no libfmt to link) and declares
// fmt::make_args_checked, which fmt 9 no longer has, so those templates parse.
//
// The formatting overloads of LAMMPS's messaging (error->all(FLERR, fmt,
// args...), utils::logmesg(lmp, fmt, args...)) still cannot be used: they
// would pass fmt 9 types to functions compiled against fmt 7 and fail to
// link. Call only the std::string overloads and build the strings ourselves.
#pragma once

#ifndef FMT_HEADER_ONLY
#define FMT_HEADER_ONLY
#endif

#include_next <fmt/format.h>

namespace fmt {
// Declared, never defined: any use is a link error, as it should be.
template <typename... Args, typename S>
format_args make_args_checked(const S &format, const Args &...args);
}    // namespace fmt
