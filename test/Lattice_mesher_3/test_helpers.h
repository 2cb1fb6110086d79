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

#include <gtest/gtest.h>

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

#endif // CGAL_LATTICE_MESHER_3_TEST_HELPERS_H
