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
#include <Eigen/SVD>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <algorithm>
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
// for a cross field), which is exact, and when it is conformal (a multiple of the identity, a
// size times a cross field) x itself; both set `uniform`.
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
  // a multiple of the identity (any cross field, any size) changes no Delaunay test of nearby
  // points: where it varies (a size that follows the shape) the particles are graded as the
  // points of any graded mesh, whose Euclidean Delaunay tetrahedralization is the usual one
  auto scaled_identity = [](const Mat3& m) { return (m - m.trace() / 3. * Mat3::Identity()).norm() <= 1e-9 * m.norm(); };
  bool conformal = true;
  for(std::size_t i = 0; i < n && conformal; ++i) conformal = scaled_identity(s[i]);
  std::vector<Vec3> y(n);
  if(uniform || conformal || n < 2) {
    // keep x bit for bit when the metric is conformal
    for(std::size_t i = 0; i < n; ++i) y[i] = conformal ? x[i] : Vec3(s[0] * x[i]);
    uniform = true;   // no embedding: nothing can fold
    return y;
  }

  const Neighbor_graph g = build_neighbor_graph<K>(x, frames, field, radius, threads);
  std::vector<Vec3> d(g.pairs.size());   // the isotropic pair vectors, up to a rotation
  for(std::size_t p = 0; p < g.pairs.size(); ++p)
    d[p] = metric_root(g.pair_map[p]) * (x[g.pairs[p][0]] - x[g.pairs[p][1]]);

  // Normal equations L Y = D of the least squares, L the graph Laplacian. A small pull of each
  // particle towards S_i x_i fixes the free translation (and an isolated particle).
  const double pull = 1e-6;
  std::vector<Eigen::Triplet<double> > t;
  t.reserve(n + 4 * g.pairs.size());
  for(std::size_t i = 0; i < n; ++i) t.emplace_back(int(i), int(i), pull);
  for(const auto& e : g.pairs) {
    t.emplace_back(e[0], e[0], 1.); t.emplace_back(e[1], e[1], 1.);
    t.emplace_back(e[0], e[1], -1.); t.emplace_back(e[1], e[0], -1.);
  }
  // Eigen runs the CG's sparse products (row-major: it transposes a column-major matrix given
  // as Lower | Upper) on all OpenMP threads unless told otherwise, and its threads spin-wait
  // for busy cores (fig8 BCC on a machine loaded by a build: 17 s instead of 0.4 s). It gets
  // the caller's thread count for the solves; the products are the same for any count (row by row).
  struct Eigen_threads
  {
    int saved = Eigen::nbThreads();
    explicit Eigen_threads(int t) { Eigen::setNbThreads((std::max)(t, 1)); }
    ~Eigen_threads() { Eigen::setNbThreads(saved); }
  } eigen_threads(threads);
  Eigen::SparseMatrix<double> L{Eigen::Index(n), Eigen::Index(n)};
  L.setFromTriplets(t.begin(), t.end());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg(L);
  cg.setTolerance(1e-10);
  cg.setMaxIterations(int(10 * n) + 1000);

  // A metric that is not flat (fig9's) has no map whose differential is S everywhere, but one
  // whose differential is S up to a rotation varying from place to place is much closer: as
  // rigid as possible (Sorkine & Alexa 2007), alternating the best rotation R_i of each
  // particle's star with the least squares of |y_i - y_j - (R_i + R_j)/2 d_ij|^2.
  std::vector<Mat3> R(n, Mat3::Identity());
  Eigen::MatrixXd Y(n, 3), rhs(n, 3);
  for(std::size_t i = 0; i < n; ++i) Y.row(i) = (s[i] * x[i]).transpose();
  const int iterations = 8;
  for(int it = 0; it <= iterations; ++it) {
    for(std::size_t i = 0; i < n; ++i) rhs.row(i) = pull * (s[i] * x[i]).transpose();
    for(std::size_t p = 0; p < g.pairs.size(); ++p) {
      const int i = g.pairs[p][0], j = g.pairs[p][1];
      const Vec3 r = 0.5 * (R[i] + R[j]) * d[p];
      rhs.row(i) += r.transpose();
      rhs.row(j) -= r.transpose();
    }
    Y = cg.solveWithGuess(rhs, Y);
    if(it == iterations) break;
#pragma omp parallel for num_threads(threads) schedule(static)
    for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(n); ++i) {
      Mat3 a = Mat3::Zero();
      for(int e = g.offsets[i]; e < g.offsets[i + 1]; ++e) {
        const int p = g.pair_of[e];
        a += (Y.row(g.pairs[p][0]) - Y.row(g.pairs[p][1])).transpose() * d[p].transpose();
      }
      const Eigen::JacobiSVD<Mat3> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
      Mat3 u = svd.matrixU();
      if((u * svd.matrixV().transpose()).determinant() < 0.) u.col(2) = -u.col(2);
      R[i] = u * svd.matrixV().transpose();
    }
  }
  for(std::size_t i = 0; i < n; ++i) y[i] = Y.row(i).transpose();
  return y;
}

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_ISOTROPIC_EMBEDDING_H
