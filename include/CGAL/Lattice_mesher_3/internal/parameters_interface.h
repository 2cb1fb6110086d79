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
CGAL_add_named_parameter(final_gradient_tolerance_t, final_gradient_tolerance, final_gradient_tolerance)
CGAL_add_named_parameter(maximum_number_of_iterations_t, maximum_number_of_iterations, maximum_number_of_iterations)
CGAL_add_named_parameter(stall_tolerance_t, stall_tolerance, stall_tolerance)
CGAL_add_named_parameter(boundary_distance_ratio_t, boundary_distance_ratio, boundary_distance_ratio)
CGAL_add_named_parameter(free_particles_join_boundary_t, free_particles_join_boundary, free_particles_join_boundary)
CGAL_add_named_parameter(flatness_ratio_t, flatness_ratio, flatness_ratio)
CGAL_add_named_parameter(wedge_angle_t, wedge_angle, wedge_angle)
CGAL_add_named_parameter(shape_tolerance_t, shape_tolerance, shape_tolerance)
CGAL_add_named_parameter(floor_angle_t, floor_angle, floor_angle)
CGAL_add_named_parameter(target_angle_t, target_angle, target_angle)
CGAL_add_named_parameter(boundary_flatness_t, boundary_flatness, boundary_flatness)
CGAL_add_named_parameter(number_of_passes_t, number_of_passes, number_of_passes)
CGAL_add_named_parameter(maximum_ring_size_t, maximum_ring_size, maximum_ring_size)
CGAL_add_named_parameter(selection_angle_t, selection_angle, selection_angle)
CGAL_add_named_parameter(worst_angle_t, worst_angle, worst_angle)
CGAL_add_named_parameter(worst_weight_t, worst_weight, worst_weight)
CGAL_add_named_parameter(target_radius_ratio_t, target_radius_ratio, target_radius_ratio)
CGAL_add_named_parameter(radius_ratio_weight_t, radius_ratio_weight, radius_ratio_weight)
CGAL_add_named_parameter(lattice_tolerance_t, lattice_tolerance, lattice_tolerance)
CGAL_add_named_parameter(around_vertices_t, around_vertices, around_vertices)
CGAL_add_named_parameter(boundary_angle_t, boundary_angle, boundary_angle)
CGAL_add_named_parameter(boundary_turn_angle_t, boundary_turn_angle, boundary_turn_angle)
CGAL_add_named_parameter(short_edge_ratio_t, short_edge_ratio, short_edge_ratio)
CGAL_add_named_parameter(peel_angle_t, peel_angle, peel_angle)
CGAL_add_named_parameter(sliver_angle_t, sliver_angle, sliver_angle)
CGAL_add_named_parameter(align_to_features_t, align_to_features, align_to_features)
