// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

// The sizing stage: the graded envelope of size samples against its definition, the thickness
// samples of known shapes, and the frame field scaled by a size.

#include <CGAL/Lattice_mesher_3/sizing_fields.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/Implicit_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>

#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace LM = CGAL::Lattice_mesher_3;
typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef LM::Graded_sizing_field_3<K> Sizing;
typedef CGAL::Lattice_mesher_traits_3<K> Traits;

namespace {

// min over the samples of h_s + g |x - p_s|, capped: the definition, by brute force
double envelope(const std::vector<std::pair<Point_3, double> >& samples, double g, double cap, const Point_3& x)
{
  double h = cap;
  for(const auto& s : samples) h = (std::min)(h, s.second + g * std::sqrt(CGAL::squared_distance(x, s.first)));
  return h;
}

std::vector<std::pair<Point_3, double> > random_samples(CGAL::Random& rng, int n)
{
  std::vector<std::pair<Point_3, double> > samples;
  for(int i = 0; i < n; ++i)
    samples.emplace_back(Point_3(rng.get_double(0, 10), rng.get_double(0, 10), rng.get_double(0, 3)),
                         rng.get_double(.05, 1.5));
  return samples;
}

} // namespace

// The field is the envelope: never below it, above it only where the winning sample of a point
// is none of those its cell looks at (a sample that wins around itself but at none of the grid
// nodes near it), and then by a few percent; so it also grows by at most the grading, up to
// such steps.
TEST(Sizing, GradedFieldIsTheEnvelopeOfItsSamples)
{
  CGAL::Random rng(3);
  const auto samples = random_samples(rng, 300);
  const double g = .3, cap = 1.;
  const Sizing h(samples, g, cap);
  EXPECT_EQ(h.max_size(), cap);
  EXPECT_NEAR(h.min_size(), envelope(samples, 0., cap, Point_3(0, 0, 0)), 1e-15);
  int above = 0;
  double worst = 0.;
  auto check = [&](const Point_3& x) {
    const double exact = envelope(samples, g, cap, x), value = h(x);
    EXPECT_GE(value, exact - 1e-12) << x;
    EXPECT_LE(value, cap) << x;
    if(value > exact + 1e-12) { ++above; worst = (std::max)(worst, value / exact - 1.); }
    return value;
  };
  for(const auto& s : samples) check(s.first);
  for(int i = 0; i < 20000; ++i) {
    const Point_3 x(rng.get_double(-2, 12), rng.get_double(-2, 12), rng.get_double(-2, 5));
    const double value = check(x);
    const Vector_3 step(rng.get_double(-.1, .1), rng.get_double(-.1, .1), rng.get_double(-.1, .1));
    EXPECT_LE(std::abs(h(x + step) - value), g * std::sqrt(step.squared_length()) + .1 * value + 1e-12) << x;
  }
  EXPECT_LT(above, 400) << "points (of 20,300) where the grid missed the winning sample";
  EXPECT_LT(worst, .1);
}

TEST(Sizing, GradedFieldEdgeCases)
{
  const std::vector<std::pair<Point_3, double> > none;
  const Sizing empty(none, .3, 2.);
  EXPECT_EQ(empty(Point_3(1, 2, 3)), 2.);
  EXPECT_EQ(empty.number_of_samples(), 0u);
  // samples at or above the cap are dropped
  const std::vector<std::pair<Point_3, double> > two = { { Point_3(0, 0, 0), 3. }, { Point_3(1, 0, 0), .5 } };
  const Sizing large(two, .5, 2.);
  EXPECT_EQ(large.number_of_samples(), 1u);
  EXPECT_NEAR(large(Point_3(1, 0, 0)), .5, 1e-15);
  EXPECT_NEAR(large(Point_3(2, 0, 0)), 1., 1e-12);
  EXPECT_EQ(large(Point_3(100, 0, 0)), 2.);
  EXPECT_THROW(Sizing(none, 0., 1.), std::invalid_argument);
  EXPECT_THROW(Sizing(none, .3, 0.), std::invalid_argument);
  const std::vector<std::pair<Point_3, double> > bad = { { Point_3(0, 0, 0), -1. } };
  EXPECT_THROW(Sizing(bad, .3, 1.), std::invalid_argument);
  const std::vector<std::pair<Point_3, double> > nan = { { Point_3(std::nan(""), 0, 0), 1. } };
  EXPECT_THROW(Sizing(nan, .3, 2.), std::invalid_argument);
}

// A slab 1 thick and 8 wide: the samples on its big faces say a third of the thickness, none
// says more; a cube 8 wide says nothing with l* = 2 (its parts are 4 l* across), not even on
// its edges, where the normal of one face runs in the plane of the other.
TEST(Sizing, ThicknessOfASlab)
{
  LM::Polyhedral_lattice_domain_3<K>::Surface_mesh slab = LM::make_cube_surface_3<K>(0., 8.);
  for(auto v : slab.vertices()) {
    const Point_3 p = slab.point(v);
    slab.point(v) = Point_3(p.x(), p.y(), p.z() / 8.);
  }
  const LM::Polyhedral_lattice_domain_3<K> d(slab);
  std::vector<std::pair<Point_3, double> > samples;
  LM::size_samples(LM::thickness_samples(d, .25, .05, 3., 3., 1), 3., 1., std::back_inserter(samples));
  ASSERT_GT(samples.size(), 500u);
  int faces = 0;
  for(const auto& s : samples) {
    const Point_3& p = s.first;
    const bool big_face = (p.z() < 1e-9 || p.z() > 1. - 1e-9) && p.x() > .1 && p.x() < 7.9 && p.y() > .1 && p.y() < 7.9;
    if(big_face) { ++faces; EXPECT_NEAR(s.second, 1. / 3., .05 / 64 + 1e-9) << p; }
    EXPECT_LE(s.second, 1. / 3. + 1e-9) << p;
  }
  EXPECT_GT(faces, 400);
  std::vector<std::pair<Point_3, double> > thick;
  const LM::Polyhedral_lattice_domain_3<K> cube(LM::make_cube_surface_3<K>(0., 8.));
  LM::size_samples(LM::thickness_samples(cube, .5, .1, 6., 6., 1), 3., 2., std::back_inserter(thick));
  EXPECT_TRUE(thick.empty()) << thick.size() << " samples, the first at " << thick.front().first;
}

// Two cubes 4 wide and 0.3 apart: the samples on the facing sides see the gap, no other says
// anything (with l* = 1 the cubes are thick).
TEST(Sizing, GapBetweenParts)
{
  LM::Polyhedral_lattice_domain_3<K>::Surface_mesh two = LM::make_cube_surface_3<K>(0., 4.), second = two;
  for(auto v : second.vertices()) second.point(v) = second.point(v) + Vector_3(4.3, 0., 0.);
  two.join(second);
  const LM::Polyhedral_lattice_domain_3<K> d(two);
  std::vector<std::pair<Point_3, double> > samples;
  LM::size_samples(LM::thickness_samples(d, .5, .05, 3., 3., 2), 3., 1., std::back_inserter(samples));
  int facing = 0;
  for(const auto& s : samples) {
    ASSERT_TRUE(std::abs(s.first.x() - 4.) < 1e-9 || std::abs(s.first.x() - 4.3) < 1e-9) << s.first;
    ++facing;
    EXPECT_NEAR(s.second, .3, .05 / 64 + 1e-9) << s.first;
  }
  EXPECT_GT(facing, 50);
}

// Two feature curves 0.2 apart on the top face of a cube of side 4 (as scribed lines, given as
// curves) ask for an edge of 0.2 between them; the cube's own sharp edges, which meet at right
// angles and lie 4 apart, ask for nothing; nor do two such curves shorter than the reach, nor two
// curves 0.14 apart across the cube's edge, with no face between them.
TEST(Sizing, GapBetweenFeatureCurves)
{
  typedef LM::Polyhedral_lattice_domain_3<K> Domain;
  const Domain::Surface_mesh cube = LM::make_cube_surface_3<K>(0., 4.);
  std::vector<std::pair<Point_3, double> > samples;
  LM::feature_gap_size_samples(Domain(cube), .25, 1., std::back_inserter(samples), 2);
  EXPECT_TRUE(samples.empty()) << samples.size() << " samples, the first at " << samples.front().first;
  const std::vector<Domain::Polyline> lines = { { Point_3(1., .5, 4.), Point_3(1., 3.5, 4.) },
                                                { Point_3(1.2, .5, 4.), Point_3(1.2, 3.5, 4.) } };
  LM::feature_gap_size_samples(Domain(cube, lines), .25, 1., std::back_inserter(samples), 2);
  EXPECT_GT(samples.size(), 30u);
  for(const auto& s : samples) {
    EXPECT_NEAR(s.second, .2, 1e-9) << s.first;
    EXPECT_TRUE(s.first.x() > 1. - 1e-9 && s.first.x() < 1.2 + 1e-9 && std::abs(s.first.z() - 4.) < 1e-9) << s.first;
  }
  const std::vector<Domain::Polyline> short_lines = { { Point_3(1., .5, 4.), Point_3(1., 1.2, 4.) },
                                                      { Point_3(1.2, .5, 4.), Point_3(1.2, 1.2, 4.) } };
  samples.clear();
  LM::feature_gap_size_samples(Domain(cube, short_lines), .25, 1., std::back_inserter(samples), 2);
  EXPECT_TRUE(samples.empty()) << samples.size() << " samples";
  const std::vector<Domain::Polyline> across = { { Point_3(3.9, .5, 4.), Point_3(3.9, 3.5, 4.) },
                                                 { Point_3(4., .5, 3.9), Point_3(4., 3.5, 3.9) } };
  LM::feature_gap_size_samples(Domain(cube, across), .25, 1., std::back_inserter(samples), 2);
  EXPECT_TRUE(samples.empty()) << samples.size() << " samples";
  EXPECT_THROW(LM::feature_gap_size_samples(Domain(cube, lines), 0., 1., std::back_inserter(samples)), std::invalid_argument);
}

// The unit sphere leaves its tangent plane by sqrt(1 + L^2) - 1 at distance L; the tolerance's
// size is where that is the tolerance, sqrt(2 e) to first order.
TEST(Sizing, DeviationOfASphere)
{
  const auto ball = LM::make_sphere_domain_3<K>(Point_3(0., 0., 0.), 1.);
  const auto measures = LM::deviation_samples(ball, .3, .8, 2);
  ASSERT_GT(measures.size(), 50u);
  for(const auto& m : measures) {
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(m.point, Point_3(CGAL::ORIGIN))), 1., 1e-6);
    for(int k = 0; k < LM::Deviation_sample_3<K>::scales; ++k)
      EXPECT_NEAR(m.deviation[std::size_t(k)], std::sqrt(1. + CGAL::square(m.scale(k))) - 1., 1e-6) << k;
  }
  const double e = .01;
  std::vector<std::pair<Point_3, double> > sizes;
  LM::tolerance_size_samples(measures, e, 1., std::back_inserter(sizes));
  ASSERT_EQ(sizes.size(), measures.size());
  // d(h) = e exactly at h = sqrt((1 + e)^2 - 1)
  for(const auto& s : sizes) EXPECT_NEAR(s.second, std::sqrt(CGAL::square(1. + e) - 1.), .02 * s.second);
  sizes.clear();
  LM::tolerance_size_samples(measures, .5, 1., std::back_inserter(sizes));
  EXPECT_TRUE(sizes.empty());   // within the tolerance at the largest scale
}

// A crease leaves the plane linearly: d = c L gives h = e / c; a scale cut by a feature curve
// (-1) is not used, and without any measured scale nothing is written.
TEST(Sizing, ToleranceSizeOfACrease)
{
  LM::Deviation_sample_3<K> m;
  m.point = Point_3(1., 2., 3.);
  m.largest_scale = 1.;
  for(int k = 0; k < m.scales; ++k) m.deviation[std::size_t(k)] = .3 * m.scale(k);
  std::vector<std::pair<Point_3, double> > sizes;
  LM::tolerance_size_samples(std::vector<LM::Deviation_sample_3<K> >{ m }, .06, 2., std::back_inserter(sizes));
  ASSERT_EQ(sizes.size(), 1u);
  EXPECT_NEAR(sizes[0].second, .2, 1e-12);
  m.deviation[0] = -1.;
  sizes.clear();
  LM::tolerance_size_samples(std::vector<LM::Deviation_sample_3<K> >{ m }, .06, 2., std::back_inserter(sizes));
  ASSERT_EQ(sizes.size(), 1u);
  EXPECT_NEAR(sizes[0].second, .2, 1e-12);
  // below every scale: a curvature, d ~ h^2 from the smallest
  sizes.clear();
  LM::tolerance_size_samples(std::vector<LM::Deviation_sample_3<K> >{ m }, .003, 2., std::back_inserter(sizes));
  ASSERT_EQ(sizes.size(), 1u);
  EXPECT_NEAR(sizes[0].second, .125 * std::sqrt(.003 / (.3 * .125)), 1e-12);
  m.deviation.fill(-1.);
  sizes.clear();
  LM::tolerance_size_samples(std::vector<LM::Deviation_sample_3<K> >{ m }, .06, 2., std::back_inserter(sizes));
  EXPECT_TRUE(sizes.empty());
  EXPECT_THROW(LM::tolerance_size_samples(std::vector<LM::Deviation_sample_3<K> >{ m }, 0., 2., std::back_inserter(sizes)),
               std::invalid_argument);
}

// T = min(1, h / (l |T0|)) T0: the cube keeps its directions and proportions and shrinks to h.
TEST(Sizing, SizedFrameField)
{
  Traits::Matrix_3 t0;
  t0 << 2, 0, 0, 0, 1, 0, 0, 0, .5;   // the longest column: 2
  const LM::Constant_frame_field_3<Traits> field(t0);
  auto h = [](const Point_3& p) { return p.x(); };
  const LM::Sized_frame_field_3<LM::Constant_frame_field_3<Traits>, decltype(h)> sized(field, h, .5, .1);
  EXPECT_TRUE(sized.frame(Point_3(2., 0, 0)).isApprox(t0));                  // 2 >= .5 * 2: unscaled
  EXPECT_TRUE(sized.frame(Point_3(.5, 0, 0)).isApprox(.5 * t0));
  EXPECT_TRUE(sized.frame(Point_3(.01, 0, 0)).isApprox(.1 * t0));            // the smallest size
  EXPECT_THROW((LM::Sized_frame_field_3<LM::Constant_frame_field_3<Traits>, decltype(h)>(field, h, 0.)), std::invalid_argument);
}
