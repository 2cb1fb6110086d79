// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INTERNAL_CROSS_FIELD_SOLVER_H
#define CGAL_LATTICE_MESHER_3_INTERNAL_CROSS_FIELD_SOLVER_H

// A smooth octahedral frame field on the vertices of a tetrahedral mesh whose frames have an axis
// along the boundary normal: Ray et al.'s representation and linear initialization (2016) with
// the boundary constraint imposed exactly (2 free coefficients per boundary vertex, as Palmer et
// al. 2020), then Palmer et al.'s modified MBO iterations (solve (M + tau_k L) q = M p under the
// constraints, project onto the frames; tau_k = tau_0 / k^3, tau_0 = 50 / lambda_1), on the
// graph Laplacian of the mesh's edges, each weighted by the number of tetrahedra around it.

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/internal/octahedral_frames.h>

#include <CGAL/assertions.h>

#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

// What constrains a vertex's frame: nothing (inside), a direction of the frame (an axis or a
// face diagonal) along `axis` (a boundary normal), or the whole frame (a crease or a corner).
struct Frame_constraint
{
  enum Kind { FREE, AXIS, FULL } kind = FREE;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  Frame_direction direction = Frame_direction::AXIS;
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();
};

// The constraints of the boundary vertices of a mesh of `domain`: the area-weighted normals of
// their boundary faces, patch by patch (`boundary_patches`, one patch without them). One patch:
// the frame's `direction` along the domain's normal there (the faces' if it points inward). Two
// (a crease): the frame with an axis along the crease whose two directions across it are
// nearest to both normals: axes at 45 degrees from the normals' bisector, or face diagonals
// (axes along the bisector and across it), each |alpha / 2 - 45| degrees from the normals
// alpha apart. Three (a corner): the frame nearest to the corner's three edges, the creases
// n_i x n_j, for face diagonals too: no three of them are orthogonal, and a box corner is filled
// by whole {100} layers.
// A vertex on more patches, or whose normals are about parallel, is free.
template <typename Point_3, typename Domain>
std::vector<Frame_constraint> boundary_frame_constraints(const Tetrahedral_mesh_3<Point_3>& mesh, const Domain& domain,
                                                         bool align_to_features = true,
                                                         Frame_direction direction = Frame_direction::AXIS)
{
  std::vector<std::map<int, Eigen::Vector3d> > normals(mesh.points.size());
  for(std::size_t k = 0; k < mesh.boundary_faces.size(); ++k) {
    const std::array<int, 3>& f = mesh.boundary_faces[k];
    const Eigen::Vector3d a = to_eigen(mesh.points[f[0]]), b = to_eigen(mesh.points[f[1]]), c = to_eigen(mesh.points[f[2]]);
    const Eigen::Vector3d n = (b - a).cross(c - a);   // twice the area, outward
    const int patch = align_to_features ? label(mesh.boundary_patches, std::ptrdiff_t(k)) : 1;
    for(int v : f) {
      auto it = normals[std::size_t(v)].emplace(patch, Eigen::Vector3d::Zero()).first;
      it->second += n;
    }
  }
  const double parallel = 1e-3;   // |sin| of 0.06 degrees
  std::vector<Frame_constraint> constraints(mesh.points.size());
  for(std::size_t v = 0; v < mesh.points.size(); ++v) {
    std::vector<Eigen::Vector3d> n;
    for(const auto& p : normals[v]) if(p.second.norm() > 0.) n.push_back(p.second.normalized());
    Frame_constraint& c = constraints[v];
    if(n.size() == 1) {   // the surface's own normal, which the faces' only approximate
      const Eigen::Vector3d normal = to_eigen(domain.project_on_surface(mesh.points[v]).direction);
      c.kind = Frame_constraint::AXIS;
      c.direction = direction;
      c.axis = normal.norm() > 0. && normal.dot(n[0]) > 0. ? Eigen::Vector3d(normal.normalized()) : n[0];
    }
    else if(n.size() == 2) {
      const Eigen::Vector3d t = n[0].cross(n[1]);
      if(t.norm() < parallel) continue;
      const Eigen::Vector3d b = (n[0] + n[1]).normalized(), e = t.normalized().cross(b);
      Eigen::Matrix3d m;
      if(direction == Frame_direction::AXIS) m << (b + e) / std::sqrt(2.), (b - e) / std::sqrt(2.), t.normalized();
      else m << b, e, t.normalized();
      c.kind = Frame_constraint::FULL;
      c.frame = frame_rotation_of_axes(m);
    }
    else if(n.size() == 3) {
      Eigen::Matrix3d m;
      m << n[0].cross(n[1]), n[1].cross(n[2]), n[2].cross(n[0]);
      if(m.colwise().norm().minCoeff() < parallel) continue;
      m.colwise().normalize();
      if(std::abs(m.determinant()) < 0.1) continue;   // about coplanar edges: no frame fits them
      c.kind = Frame_constraint::FULL;
      c.frame = frame_rotation_of_axes(m);
    }
  }
  return constraints;
}

// The edges of a tetrahedral mesh, each weighted by the number of tetrahedra around it.
typedef std::vector<std::pair<std::pair<int, int>, double> > Weighted_edges;

template <typename Point_3>
Weighted_edges weighted_edges(const Tetrahedral_mesh_3<Point_3>& mesh)
{
  std::map<std::pair<int, int>, double> weights;
  for(const std::array<int, 4>& t : mesh.tets)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) weights[std::minmax(t[i], t[j])] += 1.;
  return Weighted_edges(weights.begin(), weights.end());
}

// The smoothness energy 1/2 sum_ij w_ij |q_i - q_j|^2 of the frames (rotations) at the vertices.
inline double frame_field_energy(const Weighted_edges& edges, const std::vector<Sh9>& q)
{
  double e = 0.;
  for(const auto& edge : edges) e += .5 * edge.second * (q[std::size_t(edge.first.first)] - q[std::size_t(edge.first.second)]).squaredNorm();
  return e;
}

inline double frame_field_energy(const Weighted_edges& edges, const std::vector<Eigen::Matrix3d>& rotations)
{
  std::vector<Sh9> q(rotations.size());
  for(std::size_t v = 0; v < rotations.size(); ++v) q[v] = frame_coefficients(rotations[v]);
  return frame_field_energy(edges, q);
}

// The frame field of a mesh: per vertex a rotation whose columns are the frame's axes, and the
// smoothness energy 1/2 sum_ij w_ij |q_i - q_j|^2 of the projected field after each iteration
// (the first: after the initialization).
struct Cross_field_result
{
  std::vector<Eigen::Matrix3d> rotations;
  std::vector<double> energies;
};

// lambda_1, the smallest nonzero eigenvalue of the graph Laplacian (unit masses), which sets
// the MBO steps' diffusion: by inverse iteration, orthogonal to the constants of each connected
// component, from the coordinate along which the mesh is longest. That coordinate's Rayleigh
// quotient alone is near lambda_1 for a box, but 7 times it on bunny's background mesh and 11
// times on knot1's, whose first modes run along their lengths; tau_0 would then be as many
// times too small.
template <typename Point_3>
double laplacian_first_eigenvalue(const Tetrahedral_mesh_3<Point_3>& mesh, const Weighted_edges& edges)
{
  const Eigen::Index n = Eigen::Index(mesh.points.size());
  if(n < 2 || edges.empty()) return 1.;
  std::vector<Eigen::Triplet<double> > triplets;
  std::vector<int> component(static_cast<std::size_t>(n));
  for(Eigen::Index v = 0; v < n; ++v) component[std::size_t(v)] = int(v);
  auto root = [&](int v) { while(component[std::size_t(v)] != v) v = component[std::size_t(v)] = component[std::size_t(component[std::size_t(v)])]; return v; };
  for(const auto& edge : edges) {
    const int i = edge.first.first, j = edge.first.second;
    triplets.emplace_back(i, i, edge.second);
    triplets.emplace_back(j, j, edge.second);
    triplets.emplace_back(i, j, -edge.second);
    triplets.emplace_back(j, i, -edge.second);
    component[std::size_t(root(i))] = root(j);
  }
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(triplets.begin(), triplets.end());
  std::vector<int> label(static_cast<std::size_t>(n), -1), number(static_cast<std::size_t>(n), -1);
  std::vector<double> size;   // of each component, numbered from 0
  for(Eigen::Index v = 0; v < n; ++v) {
    int& c = number[std::size_t(root(int(v)))];
    if(c < 0) { c = int(size.size()); size.push_back(0.); }
    label[std::size_t(v)] = c;
    size[std::size_t(c)] += 1.;
  }
  auto deflate = [&](Eigen::VectorXd& x) {   // orthogonal to each component's constant
    std::vector<double> sum(size.size(), 0.);
    for(Eigen::Index v = 0; v < n; ++v) sum[std::size_t(label[std::size_t(v)])] += x[v];
    for(Eigen::Index v = 0; v < n; ++v) x[v] -= sum[std::size_t(label[std::size_t(v)])] / size[std::size_t(label[std::size_t(v)])];
  };
  Eigen::MatrixXd p(n, 3);
  for(Eigen::Index v = 0; v < n; ++v) p.row(v) = to_eigen(mesh.points[std::size_t(v)]).transpose();
  int axis = 0;
  (p.colwise().maxCoeff() - p.colwise().minCoeff()).maxCoeff(&axis);
  Eigen::VectorXd x = p.col(axis);
  deflate(x);
  if(!(x.norm() > 0.)) return 1.;
  x.normalize();
  auto rayleigh = [&](const Eigen::VectorXd& y) { return y.dot(laplacian * y) / y.squaredNorm(); };
  double lambda = rayleigh(x);
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;   // (L x = b is consistent for b deflated)
  cg.setTolerance(1e-6);
  cg.setMaxIterations(1000);
  cg.compute(laplacian);
  for(int iteration = 0; iteration < 30; ++iteration) {
    Eigen::VectorXd y = cg.solveWithGuess(x, x / lambda);
    deflate(y);
    if(!(y.norm() > 0.) || !y.allFinite()) break;
    x = y.normalized();
    const double next = rayleigh(x);
    const bool settled = std::abs(next - lambda) < 1e-3 * lambda;
    lambda = next;
    if(settled) break;
  }
  return lambda > 0. ? lambda : 1.;
}

// Eigen's OpenMP threads set to `n` for the scope: its parallel sparse products (the conjugate
// gradients of lambda_1 and of the MBO steps) otherwise take all the machine's threads,
// whatever the caller asked for.
struct Eigen_threads_scope
{
  int before = Eigen::nbThreads();
  explicit Eigen_threads_scope(int n) { Eigen::setNbThreads(n); }
  ~Eigen_threads_scope() { Eigen::setNbThreads(before); }
  Eigen_threads_scope(const Eigen_threads_scope&) = delete;
  Eigen_threads_scope& operator=(const Eigen_threads_scope&) = delete;
};

class Cross_field_solver
{
public:
  template <typename Point_3>
  Cross_field_solver(const Tetrahedral_mesh_3<Point_3>& mesh, std::vector<Frame_constraint> constraints)
    : n_(mesh.points.size()), constraints_(std::move(constraints))
  {
    edges_ = weighted_edges(mesh);
    lambda1_ = laplacian_first_eigenvalue(mesh, edges_);
    // the unknowns: q_v = B_v x_v + f_v, 9, 2 (an axis along a) or 0 (a fixed frame) per vertex
    basis_.resize(n_);
    offset_.resize(n_ + 1, 0);
    fixed_.assign(n_, Sh9::Zero());
    for(std::size_t v = 0; v < n_; ++v) {
      const Frame_constraint& c = constraints_[v];
      if(c.kind == Frame_constraint::FREE) basis_[v] = Eigen::MatrixXd::Identity(9, 9);
      else if(c.kind == Frame_constraint::AXIS) {
        // the frames with c.direction along c.axis: D(R_n) D(R_z(theta)) f, f the frame with
        // the direction along z, whose pairs of coefficients of its orders turn with theta
        const Sh9_matrix d = wigner(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), c.axis).toRotationMatrix());
        const Sh9& f = frame_with_direction_along_z(c.direction);
        const std::vector<int> orders = frame_orders(f);
        basis_[v].resize(9, 2 * Eigen::Index(orders.size()));
        for(std::size_t i = 0; i < orders.size(); ++i) {
          basis_[v].col(2 * Eigen::Index(i)) = d.col(4 - orders[i]);
          basis_[v].col(2 * Eigen::Index(i) + 1) = d.col(4 + orders[i]);
        }
        fixed_[v] = d.col(4) * f[4];
      }
      else { basis_[v].resize(9, 0); fixed_[v] = frame_coefficients(c.frame); }
      offset_[v + 1] = offset_[v] + int(basis_[v].cols());
    }
  }

  // The initialization and `iterations` MBO steps (fewer if the energy changes by less than
  // 1e-5 of itself), from whose iterate of least energy up to `iterations` sweeps of local
  // relaxation. The energies: after the initialization, each MBO step, the best step, each sweep.
  Cross_field_result solve(int iterations)
  {
    Cross_field_result result;
    Eigen::VectorXd x = minimize(0., std::vector<Sh9>(n_, Sh9::Zero()), Eigen::VectorXd());
    result.rotations.resize(n_);
    for(std::size_t v = 0; v < n_; ++v) result.rotations[v] = project(v, coefficients(v, x), nullptr);
    result.energies.push_back(energy(result.rotations));
    std::vector<Eigen::Matrix3d> best = result.rotations;
    double best_energy = result.energies.back();
    const double tau0 = 50. / lambda1_;
    for(int k = 1; k <= iterations; ++k) {
      std::vector<Sh9> p(n_);
      for(std::size_t v = 0; v < n_; ++v) p[v] = frame_coefficients(result.rotations[v]);
      x = minimize(tau0 / (double(k) * k * k), p, x);
      for(std::size_t v = 0; v < n_; ++v) result.rotations[v] = project(v, coefficients(v, x), &result.rotations[v]);
      result.energies.push_back(energy(result.rotations));
      if(result.energies.back() < best_energy) { best_energy = result.energies.back(); best = result.rotations; }
      // the steps with tau lambda_1 above 1 / 100 diffuse over the whole mesh, as the harmonic
      // field: they may change nothing
      const double previous = result.energies[result.energies.size() - 2], now = result.energies.back();
      if(double(k) * k * k > 5000. && std::abs(previous - now) < 1e-5 * std::abs(previous)) break;
    }
    result.rotations = best;
    result.energies.push_back(best_energy);
    relax(result, iterations);
    return result;
  }

private:
  // Gauss-Seidel sweeps of coordinate descent, after the MBO steps have set the field's layout:
  // as every frame has |q| = 1, the frame of least energy 1/2 sum_j w_ij |q_i - q_j|^2 at a
  // vertex, its neighbours fixed, is the one nearest to a_i = sum_j w_ij q_j (projection of a_i).
  // A vertex takes it only if it fits a_i better than its frame, so the energy never rises. Up to
  // `sweeps` sweeps, until the energy changes by less than 1e-5 of itself.
  void relax(Cross_field_result& result, int sweeps) const
  {
    std::vector<std::vector<std::pair<int, double> > > neighbours(n_);
    for(const auto& edge : edges_) {
      neighbours[std::size_t(edge.first.first)].emplace_back(edge.first.second, edge.second);
      neighbours[std::size_t(edge.first.second)].emplace_back(edge.first.first, edge.second);
    }
    std::vector<Sh9> q(n_);
    for(std::size_t v = 0; v < n_; ++v) q[v] = frame_coefficients(result.rotations[v]);
    for(int sweep = 0; sweep < sweeps; ++sweep) {
      for(std::size_t v = 0; v < n_; ++v) {
        if(constraints_[v].kind == Frame_constraint::FULL) continue;
        Sh9 a = Sh9::Zero();
        for(const auto& n : neighbours[v]) a += n.second * q[std::size_t(n.first)];
        const Eigen::Matrix3d r = project(v, a, &result.rotations[v]);
        const Sh9 candidate = frame_coefficients(r);
        if(candidate.dot(a) > q[v].dot(a)) { q[v] = candidate; result.rotations[v] = r; }
      }
      const double previous = result.energies.back();
      result.energies.push_back(frame_field_energy(edges_, q));
      if(previous - result.energies.back() < 1e-5 * previous) break;
    }
  }

  typedef Eigen::SparseMatrix<double> Sparse;

  Sh9 coefficients(std::size_t v, const Eigen::VectorXd& x) const
  {
    return basis_[v] * x.segment(offset_[v], basis_[v].cols()) + fixed_[v];
  }

  // The nearest frame that meets v's constraint, from the rotation `start` if given.
  Eigen::Matrix3d project(std::size_t v, const Sh9& q, const Eigen::Matrix3d* start) const
  {
    const Frame_constraint& c = constraints_[v];
    if(c.kind == Frame_constraint::FULL) return c.frame;
    if(c.kind == Frame_constraint::AXIS) return nearest_aligned_frame_rotation(q, c.axis, c.direction);
    if(start == nullptr) return nearest_frame_rotation(q);
    // from the previous frame; the five seeds only where q has moved far from it (a cosine
    // below 0.99 to the nearest frame found), near the singularities
    const Eigen::Matrix3d warm = refine_frame_rotation(q, *start);
    const double fit = q.dot(frame_coefficients(warm));
    if(fit >= .99 * q.norm()) return warm;
    const Eigen::Matrix3d cold = nearest_frame_rotation(q);
    return q.dot(frame_coefficients(cold)) > fit ? cold : warm;
  }

  double energy(const std::vector<Eigen::Matrix3d>& rotations) const { return frame_field_energy(edges_, rotations); }

  // argmin_x 1/2 sum_v |q_v - p_v|^2 + tau/2 sum_ij w_ij |q_i - q_j|^2 (tau = 0: the harmonic
  // field, 1/2 sum_ij w_ij |q_i - q_j|^2 alone) with q_v = B_v x_v + f_v: (M + tau L) x =
  // M_p + tau b_L, with L, b_L and M assembled once. Started from `guess`; the conjugate
  // gradient is preconditioned by an incomplete Cholesky factorization where the diffusion
  // dominates (tau lambda_1 > 1), by the diagonal otherwise, where M keeps the system well
  // conditioned.
  Eigen::VectorXd minimize(double tau, const std::vector<Sh9>& p, const Eigen::VectorXd& guess)
  {
    const int size = offset_[n_];
    if(size == 0) return Eigen::VectorXd();
    if(stiffness_.rows() == 0) assemble();
    // M + tau L in place, on the pattern of M + L: a new sum at every step allocated and wrote
    // millions of entries (bunny's background: 3.3 million)
    if(tau > 0.)
      for(Eigen::Index k = 0; k < system_.nonZeros(); ++k)
        system_.valuePtr()[k] = mass_values_[std::size_t(k)] + tau * stiffness_values_[std::size_t(k)];
    const Sparse& a = tau > 0. ? system_ : stiffness_;
    Eigen::VectorXd b = tau > 0. ? Eigen::VectorXd(tau * stiffness_rhs_) : stiffness_rhs_;
    if(tau > 0.)
      for(std::size_t v = 0; v < n_; ++v)
        if(basis_[v].cols() > 0) b.segment(offset_[v], basis_[v].cols()) += basis_[v].transpose() * (p[v] - fixed_[v]);
    const double tolerance = 1e-8;
    if(tau == 0. || tau * lambda1_ > 1.) {
      Eigen::ConjugateGradient<Sparse, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double> > cg;
      cg.setTolerance(tolerance);
      cg.setMaxIterations(2000);
      cg.compute(a);
      return guess.size() == size ? Eigen::VectorXd(cg.solveWithGuess(b, guess)) : Eigen::VectorXd(cg.solve(b));
    }
    Eigen::ConjugateGradient<Sparse, Eigen::Lower | Eigen::Upper> cg;
    cg.setTolerance(tolerance);
    cg.setMaxIterations(2000);
    cg.compute(a);
    return guess.size() == size ? Eigen::VectorXd(cg.solveWithGuess(b, guess)) : Eigen::VectorXd(cg.solve(b));
  }

  // M = diag(B_v^T B_v); L and b_L from the edges: sum_ij w_ij |B_i x_i + f_i - B_j x_j - f_j|^2 / 2
  // = x^T L x / 2 - b_L^T x + const.
  void assemble()
  {
    const int size = offset_[n_];
    std::vector<Eigen::Triplet<double> > triplets;
    stiffness_rhs_ = Eigen::VectorXd::Zero(size);
    auto add_block = [&](std::size_t i, std::size_t j, const Eigen::MatrixXd& m) {
      for(int r = 0; r < m.rows(); ++r)
        for(int c = 0; c < m.cols(); ++c) triplets.emplace_back(offset_[i] + r, offset_[j] + c, m(r, c));
    };
    for(std::size_t v = 0; v < n_; ++v)
      if(basis_[v].cols() > 0) add_block(v, v, basis_[v].transpose() * basis_[v]);
    Sparse mass(size, size);
    mass.setFromTriplets(triplets.begin(), triplets.end());
    triplets.clear();
    for(const auto& edge : edges_) {
      const std::size_t i = std::size_t(edge.first.first), j = std::size_t(edge.first.second);
      const double w = edge.second;
      const Eigen::MatrixXd& bi = basis_[i];
      const Eigen::MatrixXd& bj = basis_[j];
      const Sh9 df = fixed_[i] - fixed_[j];
      if(bi.cols() > 0) { add_block(i, i, w * bi.transpose() * bi); stiffness_rhs_.segment(offset_[i], bi.cols()) -= w * bi.transpose() * df; }
      if(bj.cols() > 0) { add_block(j, j, w * bj.transpose() * bj); stiffness_rhs_.segment(offset_[j], bj.cols()) += w * bj.transpose() * df; }
      if(bi.cols() > 0 && bj.cols() > 0) {
        const Eigen::MatrixXd m = -w * bi.transpose() * bj;
        add_block(i, j, m);
        add_block(j, i, m.transpose());
      }
    }
    stiffness_.resize(size, size);
    stiffness_.setFromTriplets(triplets.begin(), triplets.end());
    // M's and L's values on the pattern of M + L: a sum with the other's zeros has that pattern
    // (Eigen keeps every entry of either operand)
    auto values = [](const Sparse& a) { return std::vector<double>(a.valuePtr(), a.valuePtr() + a.nonZeros()); };
    system_ = mass + stiffness_;
    mass_values_ = values(Sparse(mass + 0. * stiffness_));
    stiffness_values_ = values(Sparse(0. * mass + stiffness_));
    CGAL_assertion(mass_values_.size() == std::size_t(system_.nonZeros()) && stiffness_values_.size() == mass_values_.size());
  }

  std::size_t n_;
  double lambda1_ = 1.;
  std::vector<Frame_constraint> constraints_;
  Weighted_edges edges_;
  std::vector<Eigen::MatrixXd> basis_;
  std::vector<int> offset_;
  std::vector<Sh9> fixed_;
  Sparse stiffness_, system_;
  std::vector<double> mass_values_, stiffness_values_;
  Eigen::VectorXd stiffness_rhs_;
};

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_CROSS_FIELD_SOLVER_H
