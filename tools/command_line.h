// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

// The command-line scaffolding shared by lattice-mesh and lattice-benchmark: options that need a
// value, numbers that must be numbers, one input file. Every misuse is a std::invalid_argument
// naming the option.

#ifndef LATTICE_MESHER_3_TOOLS_COMMAND_LINE_H
#define LATTICE_MESHER_3_TOOLS_COMMAND_LINE_H

#include <cmath>
#include <stdexcept>
#include <string>

namespace command_line {

inline double to_number(const std::string& flag, const std::string& v)
{
  std::size_t used = 0;
  double x = 0.;
  try { x = std::stod(v, &used); } catch(const std::exception&) { used = 0; }
  if(used != v.size() || !std::isfinite(x))
    throw std::invalid_argument(flag + " expects a number, got '" + v + "'");
  return x;
}

class Arguments
{
public:
  Arguments(int argc, char** argv) : argc_(argc), argv_(argv) {}

  /// the next argument, false at the end
  bool next(std::string& a)
  {
    if(++i_ >= argc_) return false;
    a = argv_[i_];
    return true;
  }
  /// the value of option `a`, the argument after it
  std::string value(const std::string& a)
  {
    if(i_ + 1 >= argc_) throw std::invalid_argument(a + " needs a value");
    return argv_[++i_];
  }
  double number(const std::string& a) { return to_number(a, value(a)); }
  /// a whole number in [lo, hi]: a count or a seed given as 2.5 or -1 is a mistake, not a
  /// value to round or wrap
  long long integer(const std::string& a, long long lo, long long hi)
  {
    const std::string v = value(a);
    const double x = to_number(a, v);
    if(x != std::floor(x) || x < double(lo) || x > double(hi))
      throw std::invalid_argument(a + " expects a whole number from " + std::to_string(lo) + " to " +
                                  std::to_string(hi) + ", got '" + v + "'");
    return static_cast<long long>(x);
  }
  /// `a` is no known option: the input file if there is none yet
  static void positional(const std::string& a, std::string& input)
  {
    if(!a.empty() && a[0] == '-') throw std::invalid_argument("unknown option " + a);
    if(!input.empty()) throw std::invalid_argument("more than one input file: '" + input + "' and '" + a + "'");
    input = a;
  }

private:
  int argc_;
  char** argv_;
  int i_ = 0;
};

} // namespace command_line

#endif // LATTICE_MESHER_3_TOOLS_COMMAND_LINE_H
