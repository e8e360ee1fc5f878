// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// The model files of a benchmark's command line (bench_snap, bench_exact_study). Not part of the package API.

#ifndef CGAL_SEAMLESS_SNAPPING_BENCHMARK_OBJ_INPUTS_H
#define CGAL_SEAMLESS_SNAPPING_BENCHMARK_OBJ_INPUTS_H

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

// The .obj files named by `inputs` (directories are searched recursively), sorted. Without inputs, the
// directory in the environment variable SS_SHARED_DATA_DIR; when that is unset too, prints `usage` and
// returns false.
inline bool collect_obj_files(std::vector<std::filesystem::path> inputs, const std::string& usage,
                              std::vector<std::filesystem::path>& files)
{
  namespace fs = std::filesystem;
  if(inputs.empty()) {
    const char* env = std::getenv("SS_SHARED_DATA_DIR");
    if(env == nullptr) { std::cerr << usage << "\n"; return false; }
    inputs.emplace_back(env);
  }
  files.clear();
  for(const fs::path& p : inputs) {
    if(fs::is_directory(p)) {
      for(const auto& e : fs::recursive_directory_iterator(p))
        if(e.is_regular_file() && e.path().extension() == ".obj") files.push_back(e.path());
    } else {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end());
  return true;
}

#endif // CGAL_SEAMLESS_SNAPPING_BENCHMARK_OBJ_INPUTS_H
