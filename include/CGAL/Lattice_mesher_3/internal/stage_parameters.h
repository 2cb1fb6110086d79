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

struct Optimization_options;

namespace internal {

// The settings shared by the stage functions, read from named parameters with the paper's
// defaults; `edge_length` is required.
template <typename Options, typename NamedParameters>
Options stage_options(const NamedParameters& np, const char* stage)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Options o;
  o.edge_length = choose_parameter(get_parameter(np, internal_np::edge_length), 0.);
  if(!(o.edge_length > 0.) || !std::isfinite(o.edge_length))
    throw std::invalid_argument(std::string(stage) + "(): the named parameter edge_length() must be positive and finite");
  o.neighbor_radius = choose_parameter(get_parameter(np, internal_np::neighbor_radius_ratio), o.neighbor_radius);
  o.gradient_tolerance = choose_parameter(get_parameter(np, internal_np::gradient_tolerance), o.gradient_tolerance);
  o.max_iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), o.max_iterations);
  o.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), o.threads);
  return o;
}

template <typename NamedParameters>
Lattice_3 stage_lattice(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Lattice_3 lattice = make_lattice(choose_parameter(get_parameter(np, internal_np::lattice_param), Lattice_type::BCC));
  lattice.sigma_ratio = choose_parameter(get_parameter(np, internal_np::sigma_ratio), lattice.sigma_ratio);
  return lattice;
}

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_STAGE_PARAMETERS_H
