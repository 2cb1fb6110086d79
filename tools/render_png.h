// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

// lattice-mesh --png: a picture of a tetrahedral mesh as the paper's figures show one, drawn
// offscreen by VTK in a translation unit of its own (no CGAL here, no VTK in the callers).

#ifndef LATTICE_MESHER_3_TOOLS_RENDER_PNG_H
#define LATTICE_MESHER_3_TOOLS_RENDER_PNG_H

#include <array>
#include <string>
#include <vector>

namespace render_png {

struct Picture_options
{
  int width = 1600, height = 800;  ///< pixels
  double bad_angle = 40.;          ///< tetrahedra with a smaller theta_min are drawn red
};

/// Throws std::runtime_error when the program was built without VTK: the check that `--png` can
/// be honoured, before any work.
void check_available();

/// Writes `file`, a PNG with two views of the same size side by side under one oblique camera
/// (parallel projection, from +z, +x and above): on the left the boundary of the mesh (its
/// triangles flat shaded, edges drawn); on the right the tetrahedra whose centroid lies below the
/// plane z = the bounding box's centre, whole, coloured by `theta_min` (degrees, one per
/// tetrahedron; viridis from `options.bad_angle` to 70.53), those below `options.bad_angle` red;
/// the colour bar in a column of its own on the right. Draws without a display: the OpenGL
/// context comes from EGL (Mesa's llvmpipe where there is no GPU).
/// Throws std::invalid_argument if `theta_min` has not one value per tetrahedron or a vertex
/// index is out of range, std::runtime_error if there is no OpenGL context to draw with or the
/// file cannot be written.
void write_png(const std::string& file, const std::vector<std::array<double, 3> >& points,
               const std::vector<std::array<int, 4> >& tets, const std::vector<double>& theta_min,
               const Picture_options& options = Picture_options());

} // namespace render_png

#endif // LATTICE_MESHER_3_TOOLS_RENDER_PNG_H
