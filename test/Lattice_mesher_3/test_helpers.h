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

#include <functional>
#include <string>
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

#endif // CGAL_LATTICE_MESHER_3_TEST_HELPERS_H
