// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Helpers shared by the test files.

#ifndef CGAL_LATTICE_MESHER_3_TEST_HELPERS_H
#define CGAL_LATTICE_MESHER_3_TEST_HELPERS_H

#include <CGAL/Lattice_mesher_3/Lattice_3.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <system_error>
#include <vector>

// Runs `f`, expects it to throw `Exception`, and checks that the message contains each word.
template <typename Exception = std::exception>
void expect_error(const std::function<void()>& f, const std::vector<std::string>& words)
{
  try {
    f();
    ADD_FAILURE() << "no exception";
  }
  catch(const Exception& e) {
    for(const std::string& w : words)
      EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << "'" << w << "' not in: " << e.what();
  }
  catch(...) {
    ADD_FAILURE() << "wrong exception type";
  }
}

// A scratch directory for the files of a test, removed with it. Its random name keeps it apart
// from the other tests, which ctest may run at the same time.
class Temp_dir
{
public:
  Temp_dir()
    : dir_(std::filesystem::temp_directory_path()
           / ("lattice_mesher_3_test_" + std::to_string(std::random_device()())))
  {
    std::filesystem::create_directories(dir_);
  }
  ~Temp_dir() { std::error_code ignored; std::filesystem::remove_all(dir_, ignored); } // no throw
  Temp_dir(const Temp_dir&) = delete;
  Temp_dir& operator=(const Temp_dir&) = delete;

  // the path of the file `name` in the directory
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // writes `contents` to the file `name`, returns its path
  std::string write(const std::string& name, const std::string& contents) const
  {
    std::ofstream(path(name)) << contents;
    return path(name);
  }

private:
  std::filesystem::path dir_;
};

// A block of cells^3 lattice cubes in the isotropic space, and which of its points are at least
// `margin` away from the block's faces (their whole interaction range lies in the block).
struct Lattice_block
{
  std::vector<Eigen::Vector3d> u;
  std::vector<bool> central;
};

inline Lattice_block lattice_block(const CGAL::Lattice_mesher_3::Lattice_3& l, int cells, double margin)
{
  // the points of one cube: the one-ring offsets folded into [0, 1)^3 (the origin included)
  std::vector<Eigen::Vector3d> basis;
  for(const Eigen::Vector3d& o : l.one_ring) {
    const Eigen::Vector3d b = o.cwiseAbs().unaryExpr([](double c) { return c - std::floor(c); });
    if(std::find(basis.begin(), basis.end(), b) == basis.end()) basis.push_back(b);
  }
  Lattice_block block;
  for(int i = 0; i <= cells; ++i) for(int j = 0; j <= cells; ++j) for(int k = 0; k <= cells; ++k)
    for(const Eigen::Vector3d& b : basis) {
      const Eigen::Vector3d u = Eigen::Vector3d(i, j, k) + b;
      if(u.maxCoeff() > cells) continue;
      block.u.push_back(u);
      block.central.push_back(u.minCoeff() >= margin && u.maxCoeff() <= cells - margin);
    }
  return block;
}

#endif // CGAL_LATTICE_MESHER_3_TEST_HELPERS_H
