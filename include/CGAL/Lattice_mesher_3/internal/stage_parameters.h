// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INTERNAL_STAGE_PARAMETERS_H
#define CGAL_LATTICE_MESHER_3_INTERNAL_STAGE_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#ifndef CGAL_LATTICE_MESHER_3_NP_HOOK
#error "Lattice_mesher_3: the np_hook/ include directory must come before CGAL's (see CMakeLists.txt)"
#endif

#include <CGAL/Lattice_mesher_3/Lattice_3.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Lattice_mesher_3 {

namespace internal {

// `value` becomes the named parameter `tag` of `np` if it is given, and keeps its default otherwise.
template <typename NamedParameters, typename Tag, typename T>
void read_parameter(const NamedParameters& np, Tag tag, T& value)
{
  value = parameters::choose_parameter(parameters::get_parameter(np, tag), value);
}

// The named parameter edge_length() of a stage function that requires it.
template <typename NamedParameters>
double required_edge_length(const NamedParameters& np, const char* stage)
{
  const double l = parameters::choose_parameter(parameters::get_parameter(np, internal_np::edge_length), 0.);
  if(!(l > 0.) || !std::isfinite(l))
    throw std::invalid_argument(std::string(stage) + "(): the named parameter edge_length() must be positive and finite");
  return l;
}

inline Lattice_3 as_lattice(Lattice_type type) { return make_lattice(type); }
inline const Lattice_3& as_lattice(const Lattice_3& lattice) { return lattice; }

// The named parameter lattice(), a `Lattice_type` or a `Lattice_3` (BCC if absent), with the
// named parameter sigma_ratio() if given.
template <typename NamedParameters>
Lattice_3 stage_lattice(const NamedParameters& np)
{
  Lattice_3 lattice = as_lattice(parameters::choose_parameter(parameters::get_parameter(np, internal_np::lattice_param),
                                                              Lattice_type::BCC));
  read_parameter(np, internal_np::sigma_ratio, lattice.sigma_ratio);
  return lattice;
}

// The lattice whose tetrahedra the flips match and the smoothing keeps, and its cube edge l*:
// none without l* (0), nor for the hole-less kernel, which forms no lattice. `o` has the
// members `lattice` and `edge_length`.
template <typename Options>
void set_lattice_to_keep(Options& o, const Lattice_3& lattice, double edge_length)
{
  if(edge_length > 0. && lattice.has_holes()) { o.lattice = lattice; o.edge_length = edge_length; }
}

// The same from the named parameters `lattice` and `edge_length` of a mesh stage.
template <typename Options, typename NamedParameters>
void read_lattice_to_keep(Options& o, const NamedParameters& np, const char* stage)
{
  const double l = parameters::choose_parameter(parameters::get_parameter(np, internal_np::edge_length), 0.);
  if(!(l >= 0.) || !std::isfinite(l))
    throw std::invalid_argument(std::string(stage) + "(): the named parameter edge_length() must be at least 0 and finite");
  set_lattice_to_keep(o, stage_lattice(np), l);
}

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_STAGE_PARAMETERS_H
