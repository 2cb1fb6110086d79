// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of Lattice_mesher_3, in CGAL's X-macro format
//   CGAL_add_named_parameter(<tag type>, <tag value>, <function name>)
// These are the lines that would be appended to CGAL's own list upon merging.
// CGAL parameters reused as they are (not redeclared): geom_traits, visitor, random_seed, do_flip.
// Names avoid the CGAL 5.5 Boost.Parameter keywords of Mesh_3 (edge_size, time_limit, ...).
//
// No include guard on purpose (X-macro file).
CGAL_add_named_parameter(edge_length_t, edge_length, edge_length)
CGAL_add_named_parameter(number_of_vertices_t, number_of_vertices, number_of_vertices)
CGAL_add_named_parameter(lattice_t, lattice_param, lattice)
CGAL_add_named_parameter(number_of_threads_t, number_of_threads, number_of_threads)
CGAL_add_named_parameter(max_rounds_t, max_rounds, max_rounds)
CGAL_add_named_parameter(feature_angle_t, feature_angle, feature_angle)
CGAL_add_named_parameter(coarse_levels_t, coarse_levels, coarse_levels)
CGAL_add_named_parameter(sigma_ratio_t, sigma_ratio, sigma_ratio)
CGAL_add_named_parameter(neighbor_radius_ratio_t, neighbor_radius_ratio, neighbor_radius_ratio)
CGAL_add_named_parameter(gradient_tolerance_t, gradient_tolerance, gradient_tolerance)
CGAL_add_named_parameter(number_of_smoothing_rounds_t, number_of_smoothing_rounds, number_of_smoothing_rounds)
CGAL_add_named_parameter(size_field_t, size_field, size_field)
CGAL_add_named_parameter(cells_across_t, cells_across, cells_across)
CGAL_add_named_parameter(surface_tolerance_t, surface_tolerance, surface_tolerance)
CGAL_add_named_parameter(grading_t, grading, grading)
CGAL_add_named_parameter(min_edge_length_t, min_edge_length, min_edge_length)
