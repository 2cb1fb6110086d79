// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_GAUSSIAN_HOLE_KERNEL_3_H
#define CGAL_LATTICE_MESHER_3_GAUSSIAN_HOLE_KERNEL_3_H

#include <CGAL/Lattice_mesher_3/Lattice_3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3Kernel

The Gaussian Hole Kernel (GHK) of a lattice: the energy of a particle pair as a function of
their isotropic-space offset v' = B_ij (p_i - p_j), in units of the target edge length l*:

    E(v') = G(v') - (1/N_or) sum_k G(v' - O_k),   G(d) = exp(-|d|^2 / 2 sigma^2)

The positive bump keeps neighbours apart; the holes at the one-ring offsets O_k pull them into
lattice positions. With no holes this is the isotropic Gaussian kernel of Particle2013.

Each Gaussian is cut at c = 4 sigma and corrected there to vanish with its first derivative,
G(d) - G(c) + (|d|^2 - c^2) G(c) / 2 sigma^2, so that the energy stays C1 and L-BFGS converges
to tight tolerances (a plain cut leaves gradient jumps of ~4e-4 that stall it). The correction is
of relative size 3e-4 (method.md: pruning changes nothing measurable) and the cut skips most
exponentials, since few holes lie within 4 sigma of v'.
*/
class Gaussian_hole_kernel_3
{
public:
  typedef Eigen::Vector3d Vector; ///< the type of the isotropic-space offsets v'

  /// the kernel of `lattice`: its holes O_k and its sigma
  explicit Gaussian_hole_kernel_3(const Lattice_3& lattice)
    : holes_(lattice.holes),
      hole_weight_(lattice.holes.empty() ? 0. : 1. / double(lattice.holes.size())),
      sigma_(lattice.sigma()),
      support_radius_(hole_radius(lattice.holes) + cutoff_sigmas * lattice.sigma())
  {
    inv_two_sigma2_ = 1. / (2. * sigma_ * sigma_);
    inv_sigma2_ = 1. / (sigma_ * sigma_);
    cutoff2_ = cutoff_sigmas * cutoff_sigmas * sigma_ * sigma_;
    shift_ = std::exp(-cutoff2_ * inv_two_sigma2_);
  }

  /// E(v')
  double energy(const Vector& v) const
  {
    double e = gaussian(v);
    for(const Vector& h : holes_)
      e -= hole_weight_ * gaussian(v - h);
    return e;
  }

  /// E(v'), and `force` = f' = -dE/dv'.
  double energy_and_force(const Vector& v, Vector& force) const
  {
    force.setZero();
    double e = 0.;
    accumulate(v, 1., e, force);
    for(const Vector& h : holes_)
      accumulate(v - h, -hole_weight_, e, force);
    return e;
  }

  /// sigma, in units of l*
  double sigma() const { return sigma_; }
  /// |v'| beyond which E and f' vanish, in units of l*
  double support_radius() const { return support_radius_; }

private:
  static constexpr double cutoff_sigmas = 4.;

  static double hole_radius(const std::vector<Vector>& holes)
  {
    double r = 0.;
    for(const Vector& h : holes) r = (std::max)(r, h.norm());
    return r;
  }

  double gaussian(const Vector& d) const
  {
    const double d2 = d.squaredNorm();
    return d2 < cutoff2_ ? std::exp(-d2 * inv_two_sigma2_) - shift_ + (d2 - cutoff2_) * shift_ * inv_two_sigma2_ : 0.;
  }

  // e += w G(d); f += -w dG/dd = w (G0(d) - G0(c)) d / sigma^2, G0 the uncorrected Gaussian
  void accumulate(const Vector& d, double w, double& e, Vector& f) const
  {
    const double d2 = d.squaredNorm();
    if(d2 >= cutoff2_) return;
    const double g = std::exp(-d2 * inv_two_sigma2_);
    e += w * (g - shift_ + (d2 - cutoff2_) * shift_ * inv_two_sigma2_);
    f += (w * (g - shift_) * inv_sigma2_) * d;
  }

  std::vector<Vector> holes_;
  double hole_weight_;
  double sigma_;
  double support_radius_;
  double inv_two_sigma2_ = 0., inv_sigma2_ = 0., cutoff2_ = 0., shift_ = 0.;
};

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_GAUSSIAN_HOLE_KERNEL_3_H
