// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shadows CGAL's X-macro list of named parameters: this directory precedes CGAL's on the
// include path, so <CGAL/Named_function_parameters.h> finds this file, which forwards to
// CGAL's list and appends the package's entries. The result is what merging the package
// into CGAL would give, so `parameters::edge_length(h).lattice(BCC).geom_traits(gt)` chains
// in any order with CGAL's own parameters.
//
// No include guard on purpose: an X-macro file must expand every time it is included.
#include_next <CGAL/STL_Extension/internal/parameters_interface.h>
#include <CGAL/Lattice_mesher_3/internal/parameters_interface.h>

// Lets package headers check (with #error) that the hook is active.
#define CGAL_LATTICE_MESHER_3_NP_HOOK 1
