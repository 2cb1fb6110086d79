// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INTERNAL_ISOTROPIC_EMBEDDING_H
#define CGAL_LATTICE_MESHER_3_INTERNAL_ISOTROPIC_EMBEDDING_H

#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/internal/particle_neighbors.h>

#include <Eigen/Eigenvalues>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

// S = (B^T B)^1/2, the metric part of B = Q S: the rotation Q changes no length, so a cross
// field (S = I) has the Euclidean metric and needs no embedding.
inline Mat3 metric_root(const Mat3& b)
{
  const Eigen::SelfAdjointEigenSolver<Mat3> es(b.transpose() * b);
  return es.eigenvectors() * es.eigenvalues().cwiseMax(0.).cwiseSqrt().asDiagonal() * es.eigenvectors().transpose();
}

// Where a Delaunay tetrahedralization sees the field's metric: positions y_i minimizing
// sum over the isotropic neighbour pairs (i, j) of |y_i - y_j - S_ij (x_i - x_j)|^2, S_ij the
// metric root at the pair's midpoint. Exact, up to the midpoint rule, when the metric is
// flat (a constant stretch, fig8's layered stretch: one map makes it Euclidean); the closest
// single map otherwise (fig9's curved metric). A Euclidean Delaunay of particles whose
// spacing differs 80-fold between directions connects each to far neighbours that no local
// flip undoes. When the metric is the same everywhere, returns x mapped by its root (x itself
// for a cross field), which is exact, and sets `uniform`.
template <typename K, typename FrameField>
std::vector<Vec3> isotropic_embedding(const std::vector<Vec3>& x, const FrameField& field, double radius,
                                      int threads, bool& uniform)
{
  const std::size_t n = x.size();
  const Particle_frames frames = compute_particle_frames<K>(x, field, threads);
  std::vector<Mat3> s(n);
  for(std::size_t i = 0; i < n; ++i) s[i] = metric_root(frames.B[i]);
  uniform = true;
  for(std::size_t i = 1; i < n && uniform; ++i) uniform = (s[i] - s[0]).norm() <= 1e-9 * s[0].norm();
  std::vector<Vec3> y(n);
  if(uniform || n < 2) {
    // a multiple of the identity (any cross field) changes no Delaunay test: keep x bit for bit
    const bool scaled_identity = n == 0 || (s[0] - s[0].trace() / 3. * Mat3::Identity()).norm() <= 1e-9 * s[0].norm();
    for(std::size_t i = 0; i < n; ++i) y[i] = scaled_identity ? x[i] : Vec3(s[0] * x[i]);
    return y;
  }

  const Neighbor_graph g = build_neighbor_graph<K>(x, frames, field, radius, threads);
  // Normal equations L Y = D of the least squares, L the graph Laplacian. A small pull of each
  // particle towards S_i x_i fixes the free translation (and an isolated particle).
  const double pull = 1e-6;
  std::vector<Eigen::Triplet<double> > t;
  t.reserve(n + 4 * g.pairs.size());
  Eigen::MatrixXd rhs(n, 3);
  for(std::size_t i = 0; i < n; ++i) {
    t.emplace_back(int(i), int(i), pull);
    rhs.row(i) = pull * (s[i] * x[i]).transpose();
  }
  for(std::size_t p = 0; p < g.pairs.size(); ++p) {
    const int i = g.pairs[p][0], j = g.pairs[p][1];
    const Vec3 d = metric_root(g.pair_map[p]) * (x[i] - x[j]);
    t.emplace_back(i, i, 1.); t.emplace_back(j, j, 1.);
    t.emplace_back(i, j, -1.); t.emplace_back(j, i, -1.);
    rhs.row(i) += d.transpose();
    rhs.row(j) -= d.transpose();
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> L{Eigen::Index(n), Eigen::Index(n)};
  L.setFromTriplets(t.begin(), t.end());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double, Eigen::RowMajor>, Eigen::Lower | Eigen::Upper> cg(L);
  cg.setTolerance(1e-10);
  cg.setMaxIterations(int(10 * n) + 1000);
  Eigen::MatrixXd guess(n, 3);
  for(std::size_t i = 0; i < n; ++i) guess.row(i) = (s[i] * x[i]).transpose();
  const Eigen::MatrixXd Y = cg.solveWithGuess(rhs, guess);
  for(std::size_t i = 0; i < n; ++i) y[i] = Y.row(i).transpose();
  return y;
}

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_ISOTROPIC_EMBEDDING_H
