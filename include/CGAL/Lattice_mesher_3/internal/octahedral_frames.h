// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INTERNAL_OCTAHEDRAL_FRAMES_H
#define CGAL_LATTICE_MESHER_3_INTERNAL_OCTAHEDRAL_FRAMES_H

// Octahedral frames {+-a1, +-a2, +-a3} as degree-4 spherical harmonics: the band-4 part of
// f(u) = sum_k (a_k . u)^4 in the 9 real orthonormal harmonics of degree 4 (index m + 4,
// m = -4..4, sin(|m| phi) for m < 0, no Condon-Shortley phase), the representation of the cross
// field methods of Huang et al. 2011, Ray et al. 2016 and Palmer et al. 2020. A frame is a point
// of the octahedral variety {D(R) q0}, where q0 is the axis-aligned frame and D(R) the band-4
// Wigner matrix of the rotation R: the coefficients of u -> f(R^T u).

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

typedef Eigen::Matrix<double, 9, 1> Sh9;
typedef Eigen::Matrix<double, 9, 9> Sh9_matrix;

// The axis-aligned frame: (0, 0, 0, 0, sqrt(7/12), 0, 0, 0, sqrt(5/12)).
inline Sh9 axis_aligned_frame()
{
  Sh9 q = Sh9::Zero();
  q[4] = std::sqrt(7. / 12.);
  q[8] = std::sqrt(5. / 12.);
  return q;
}

// The 9 harmonics at u (homogeneous polynomials, on the unit sphere for |u| = 1).
inline Sh9 degree_4_harmonics(const Eigen::Vector3d& u)
{
  const double x = u[0], y = u[1], z = u[2], r2 = u.squaredNorm(), pi = 3.14159265358979323846;
  Sh9 y9;
  y9[0] = .75 * std::sqrt(35. / pi) * x * y * (x * x - y * y);
  y9[1] = .75 * std::sqrt(35. / (2. * pi)) * y * z * (3. * x * x - y * y);
  y9[2] = .75 * std::sqrt(5. / pi) * x * y * (7. * z * z - r2);
  y9[3] = .75 * std::sqrt(5. / (2. * pi)) * y * z * (7. * z * z - 3. * r2);
  y9[4] = 3. / 16. * std::sqrt(1. / pi) * (35. * z * z * z * z - 30. * z * z * r2 + 3. * r2 * r2);
  y9[5] = .75 * std::sqrt(5. / (2. * pi)) * x * z * (7. * z * z - 3. * r2);
  y9[6] = 3. / 8. * std::sqrt(5. / pi) * (x * x - y * y) * (7. * z * z - r2);
  y9[7] = .75 * std::sqrt(35. / (2. * pi)) * x * z * (x * x - 3. * y * y);
  y9[8] = 3. / 16. * std::sqrt(35. / pi) * (x * x * x * x - 6. * x * x * y * y + y * y * y * y);
  return y9;
}

// The generators L_x, L_y, L_z of the action: D(exp([w]x)) = exp(w_x L_x + w_y L_y + w_z L_z).
inline const std::array<Sh9_matrix, 3>& rotation_generators()
{
  static const std::array<Sh9_matrix, 3> generators = [] {
    std::array<Sh9_matrix, 3> g;
    for(Sh9_matrix& m : g) m.setZero();
    const double s2 = std::sqrt(2.), s72 = std::sqrt(3.5), h = 3. / std::sqrt(2.), s10 = std::sqrt(10.);
    auto set = [](Sh9_matrix& m, int i, int j, double v) { m(i, j) = v; m(j, i) = -v; };
    set(g[0], 0, 7, -s2);  set(g[0], 1, 6, -s72); set(g[0], 1, 8, -s2); set(g[0], 2, 5, -h);
    set(g[0], 2, 7, -s72); set(g[0], 3, 4, -s10); set(g[0], 3, 6, -h);
    set(g[1], 0, 1, s2);   set(g[1], 1, 2, s72);  set(g[1], 2, 3, h);   set(g[1], 4, 5, -s10);
    set(g[1], 5, 6, -h);   set(g[1], 6, 7, -s72); set(g[1], 7, 8, -s2);
    for(int i = 0; i < 4; ++i) set(g[2], i, 8 - i, double(4 - i));
    return g;
  }();
  return generators;
}

// D(R_z(a)): rotations by k a of the pairs (i, 8 - i), k = 4 - i.
inline Sh9_matrix wigner_z(double a)
{
  Sh9_matrix d = Sh9_matrix::Zero();
  d(4, 4) = 1.;
  for(int i = 0; i < 4; ++i) {
    const double c = std::cos((4 - i) * a), s = std::sin((4 - i) * a);
    d(i, i) = c;        d(i, 8 - i) = s;
    d(8 - i, i) = -s;   d(8 - i, 8 - i) = c;
  }
  return d;
}

// D(R_x(pi / 2)).
inline const Sh9_matrix& wigner_x90()
{
  static const Sh9_matrix x90 = [] {
    Sh9_matrix m = Sh9_matrix::Zero();
    const double s2 = std::sqrt(2.), s7 = std::sqrt(7.), s14 = std::sqrt(14.), s5 = std::sqrt(5.), s35 = std::sqrt(35.);
    m(0, 5) = s14 / 4.;  m(0, 7) = -s2 / 4.;
    m(1, 1) = -.75;      m(1, 3) = s7 / 4.;
    m(2, 5) = s2 / 4.;   m(2, 7) = s14 / 4.;
    m(3, 1) = s7 / 4.;   m(3, 3) = .75;
    m(4, 4) = 3. / 8.;   m(4, 6) = s5 / 4.;   m(4, 8) = s35 / 8.;
    m(5, 0) = -s14 / 4.; m(5, 2) = -s2 / 4.;
    m(6, 4) = s5 / 4.;   m(6, 6) = .5;        m(6, 8) = -s7 / 4.;
    m(7, 0) = s2 / 4.;   m(7, 2) = -s14 / 4.;
    m(8, 4) = s35 / 8.;  m(8, 6) = -s7 / 4.;  m(8, 8) = 1. / 8.;
    return m;
  }();
  return x90;
}

// D(R) from the ZYZ Euler angles of R = R_z(alpha) R_y(beta) R_z(gamma), with
// D(R_y(beta)) = X90^T D(R_z(beta)) X90.
inline Sh9_matrix wigner(const Eigen::Matrix3d& r)
{
  const double beta = std::acos((std::max)(-1., (std::min)(1., r(2, 2))));
  double alpha, gamma = 0.;
  if(std::abs(std::sin(beta)) > 1e-12) {
    alpha = std::atan2(r(1, 2), r(0, 2));
    gamma = std::atan2(r(2, 1), -r(2, 0));
  }
  else alpha = r(2, 2) > 0. ? std::atan2(r(1, 0), r(0, 0)) : std::atan2(-r(1, 0), -r(0, 0));
  const Sh9_matrix& x90 = wigner_x90();
  return wigner_z(alpha) * x90.transpose() * wigner_z(beta) * x90 * wigner_z(gamma);
}

// The frame whose axes are the columns of the rotation r.
inline Sh9 frame_coefficients(const Eigen::Matrix3d& r) { return wigner(r) * axis_aligned_frame(); }

// Newton's method on SO(3) for max_R q/|q| . D(R) q0, perturbing R on the left, from r: a Newton
// step where the Hessian is negative definite, else a gradient step (Ray et al.'s 1/8), steps
// capped at 0.5 radian.
inline Eigen::Matrix3d refine_frame_rotation(const Sh9& q, Eigen::Matrix3d r)
{
  const double norm = q.norm();
  if(!(norm > 0.)) return r;
  const Sh9 target = q / norm;
  const std::array<Sh9_matrix, 3>& l = rotation_generators();
  const Sh9 q0 = axis_aligned_frame();
  for(int it = 0; it < 100; ++it) {
    const Sh9 a = wigner(r) * q0;
    Eigen::Vector3d g;
    Eigen::Matrix3d h;
    std::array<Sh9, 3> la;
    for(int k = 0; k < 3; ++k) { la[k] = l[k] * a; g[k] = target.dot(la[k]); }
    if(g.norm() < 1e-12) break;
    for(int k = 0; k < 3; ++k)
      for(int m = 0; m < 3; ++m) h(k, m) = .5 * (target.dot(l[k] * la[m]) + target.dot(l[m] * la[k]));
    Eigen::Vector3d w = g / 8.;
    const Eigen::LLT<Eigen::Matrix3d> llt(-h);
    if(llt.info() == Eigen::Success) w = llt.solve(g);
    if(w.norm() > .5) w *= .5 / w.norm();
    r = Eigen::AngleAxisd(w.norm(), w.norm() > 0. ? Eigen::Vector3d(w / w.norm()) : Eigen::Vector3d::UnitX()).toRotationMatrix() * r;
  }
  return r;
}

// The rotation nearest to q on the octahedral variety (the Euclidean projection of q / |q|):
// refine_frame_rotation() from five seeds (the identity, pi / 4 about x, y and z, and pi / 4
// about (1, 1, 0)), the best of the five (Ray et al.'s seeds; Newton from the best seed lands in
// the global optimum more often than gradient ascent from the closest one). Returns one of the
// 24 rotations that represent the frame.
inline Eigen::Matrix3d nearest_frame_rotation(const Sh9& q)
{
  const double quarter = 0.78539816339744830962;
  const std::array<Eigen::Matrix3d, 5> seeds = {{
    Eigen::Matrix3d::Identity(),
    Eigen::AngleAxisd(quarter, Eigen::Vector3d::UnitX()).toRotationMatrix(),
    Eigen::AngleAxisd(quarter, Eigen::Vector3d::UnitY()).toRotationMatrix(),
    Eigen::AngleAxisd(quarter, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
    Eigen::AngleAxisd(quarter, Eigen::Vector3d(1., 1., 0.).normalized()).toRotationMatrix() }};
  Eigen::Matrix3d best = Eigen::Matrix3d::Identity();
  double best_dot = -HUGE_VAL;
  for(const Eigen::Matrix3d& seed : seeds) {
    const Eigen::Matrix3d r = refine_frame_rotation(q, seed);
    const double dot = q.dot(frame_coefficients(r));
    if(dot > best_dot) { best_dot = dot; best = r; }
  }
  return best;
}

// The direction of a frame that a boundary normal holds: a cube axis, or a face diagonal ((1, 1,
// 0) / sqrt(2) and its images: the normal of the BCC lattice's {110} planes, made of faces of its
// tetrahedra).
enum class Frame_direction { AXIS, FACE_DIAGONAL };

inline Eigen::Vector3d direction_vector(Frame_direction d)
{
  return d == Frame_direction::AXIS ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d(1., 1., 0.).normalized();
}

// A rotation taking the direction d of the axis-aligned frame to z.
inline Eigen::Matrix3d direction_to_z(Frame_direction d)
{
  if(d == Frame_direction::AXIS) return Eigen::Matrix3d::Identity();
  return Eigen::Quaterniond::FromTwoVectors(direction_vector(d), Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// D(direction_to_z(d)) q0, the frame with d along z, computed once per direction (the projection
// asks for it at every boundary vertex of every iteration). A turn by theta about z turns its
// pair of coefficients (4 - k, 4 + k) by k theta and keeps coefficient 4; as the frame is
// symmetric by a turn of 2 pi / s about z (s = 4, 2), only the orders k that s divides are nonzero.
inline const Sh9& frame_with_direction_along_z(Frame_direction d)
{
  static const std::array<Sh9, 2> frames = { axis_aligned_frame(),
                                             Sh9(wigner(direction_to_z(Frame_direction::FACE_DIAGONAL)) * axis_aligned_frame()) };
  return frames[d == Frame_direction::AXIS ? 0 : 1];
}

// The orders k whose pair of coefficients the frame f has (above rounding).
inline std::vector<int> frame_orders(const Sh9& f)
{
  std::vector<int> orders;
  for(int k = 1; k <= 4; ++k) if(std::hypot(f[4 - k], f[4 + k]) > 1e-9) orders.push_back(k);
  return orders;
}

// The rotation of the frame nearest to q among those with the direction d along the unit vector
// n: R_n R_z(theta) direction_to_z(d), R_n taking z to n. With p = D(R_n)^T q and f the frame
// with d along z, p . D(R_z(theta)) f = c + sum_k a_k cos k theta + b_k sin k theta over f's
// orders k: for one order (an axis) theta = atan2(b_k, a_k) / k; for two (a face diagonal) the
// best of 48 samples over a turn, refined by Newton's method.
inline Eigen::Matrix3d nearest_aligned_frame_rotation(const Sh9& q, const Eigen::Vector3d& n,
                                                      Frame_direction d = Frame_direction::AXIS)
{
  const Eigen::Matrix3d rn = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), n).toRotationMatrix();
  const Sh9 p = wigner(rn).transpose() * q;
  const Sh9& f = frame_with_direction_along_z(d);
  const std::vector<int> orders = frame_orders(f);
  std::vector<double> a, b;
  for(int k : orders) {
    a.push_back(p[4 - k] * f[4 - k] + p[4 + k] * f[4 + k]);
    b.push_back(p[4 - k] * f[4 + k] - p[4 + k] * f[4 - k]);
  }
  double theta = (a[0] == 0. && b[0] == 0.) ? 0. : std::atan2(b[0], a[0]) / orders[0];
  if(orders.size() > 1) {
    // g(theta) and its first two derivatives
    auto g = [&](double t, int derivative) {
      double sum = 0.;
      for(std::size_t i = 0; i < orders.size(); ++i) {
        const double k = orders[i], c = std::cos(k * t), s = std::sin(k * t);
        sum += derivative == 0 ? a[i] * c + b[i] * s : derivative == 1 ? k * (b[i] * c - a[i] * s) : -k * k * (a[i] * c + b[i] * s);
      }
      return sum;
    };
    const double pi = 3.14159265358979323846;
    for(int k = 0; k < 48; ++k)
      if(g(k * pi / 24., 0) > g(theta, 0)) theta = k * pi / 24.;
    for(int it = 0; it < 8 && g(theta, 2) < 0.; ++it) theta -= g(theta, 1) / g(theta, 2);
  }
  return rn * Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix() * direction_to_z(d);
}

// The angle (degrees) between v and the nearest direction d (in either sense) of the frame of
// rotation r.
inline double angle_to_nearest_direction(const Eigen::Matrix3d& r, const Eigen::Vector3d& v,
                                         Frame_direction d = Frame_direction::AXIS)
{
  // the parts along the nearest direction and across it (atan2: exact near 0, where acos is not)
  const Eigen::Vector3d w = (r.transpose() * v).cwiseAbs(), u = direction_vector(d);
  double along = -1., across = 0.;
  for(int k = 0; k < 3; ++k) {
    const Eigen::Vector3d uk(u[k], u[(k + 1) % 3], u[(k + 2) % 3]);   // an image of u facing w
    if(w.dot(uk) > along) { along = w.dot(uk); across = w.cross(uk).norm(); }
  }
  return std::atan2(across, along) * 180. / 3.14159265358979323846;
}

// The rotation of the polar decomposition m = R S (S symmetric positive semi-definite), for m
// of positive determinant: the rotation nearest to m. Newton's iteration X <- (X + X^-T) / 2,
// which converges quadratically from a well-conditioned m (a few steps from a near-rotation,
// several times faster than an SVD); an SVD for an ill-conditioned one.
inline Eigen::Matrix3d rotation_factor(const Eigen::Matrix3d& m)
{
  const double scale = m.norm();
  if(m.determinant() > 1e-3 * scale * scale * scale) {
    Eigen::Matrix3d x = m * (std::sqrt(3.) / scale);
    for(int it = 0; it < 40; ++it) {
      const Eigen::Matrix3d next = .5 * (x + x.inverse().transpose());
      const double change = (next - x).squaredNorm();
      x = next;
      if(change < 1e-20) return x;
    }
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  if((u * svd.matrixV().transpose()).determinant() < 0.) u.col(2) *= -1.;   // a degenerate m
  return u * svd.matrixV().transpose();
}

// The frame of the axes (columns) of m, as a rotation: the rotation factor of m, its last column
// negated first if m is left-handed (a frame's axes have no sign). m must not be singular.
inline Eigen::Matrix3d frame_rotation_of_axes(Eigen::Matrix3d m)
{
  if(m.determinant() < 0.) m.col(2) *= -1.;
  return rotation_factor(m);
}

// A rotation of the cube as a signed permutation: column i of the matrix is the unit vector
// e_(|code[i]| - 1), with the sign of code[i].
typedef std::array<std::int8_t, 3> Cube_rotation_code;

inline Eigen::Matrix3d cube_rotation_matrix(const Cube_rotation_code& code)
{
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  for(int i = 0; i < 3; ++i) g(std::abs(code[std::size_t(i)]) - 1, i) = code[std::size_t(i)] > 0 ? 1. : -1.;
  return g;
}

// m G for the rotation G of `code`, without the product: column i of m G is column
// |code[i]| - 1 of m, signed.
inline Eigen::Matrix3d times_cube_rotation(const Eigen::Matrix3d& m, const Cube_rotation_code& code)
{
  Eigen::Matrix3d out;
  for(int i = 0; i < 3; ++i) {
    const int c = code[std::size_t(i)];
    out.col(i) = c > 0 ? Eigen::Vector3d(m.col(c - 1)) : Eigen::Vector3d(-m.col(-c - 1));
  }
  return out;
}

// The rotation P among the 24 of the cube that maximizes trace(m P): for m = A^T B with A, B
// rotations, B P is the representative of B's frame nearest to A. For each permutation of the
// columns, the signs that match the entries, one flipped (the smallest entry) if the
// determinant would be -1.
inline Cube_rotation_code best_cube_rotation_code(const Eigen::Matrix3d& m)
{
  static const int permutations[6][3] = { {0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2} };
  double best = -HUGE_VAL;
  Cube_rotation_code result = { 1, 2, 3 };
  for(int k = 0; k < 6; ++k) {
    const int* s = permutations[k];
    // P(s[i], i) = sign_i: trace(m P) = sum_i sign_i m(i, s[i])
    double value = 0., smallest = HUGE_VAL;
    int negative = k < 3 ? 0 : 1, weakest = 0;   // odd permutations need an odd number of minus signs
    std::array<int, 3> sign;
    for(int i = 0; i < 3; ++i) {
      const double e = m(i, s[i]);
      sign[std::size_t(i)] = e < 0. ? -1 : 1;
      negative += e < 0. ? 1 : 0;
      value += std::abs(e);
      if(std::abs(e) < smallest) { smallest = std::abs(e); weakest = i; }
    }
    if(negative % 2 == 1) { sign[std::size_t(weakest)] = -sign[std::size_t(weakest)]; value -= 2. * smallest; }
    if(value > best) {
      best = value;
      for(int i = 0; i < 3; ++i) result[std::size_t(i)] = std::int8_t(sign[std::size_t(i)] * (s[i] + 1));
    }
  }
  return result;
}

inline Eigen::Matrix3d best_cube_rotation(const Eigen::Matrix3d& m) { return cube_rotation_matrix(best_cube_rotation_code(m)); }

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_OCTAHEDRAL_FRAMES_H
