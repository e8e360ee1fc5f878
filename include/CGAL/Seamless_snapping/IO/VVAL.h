// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_IO_VVAL_H
#define CGAL_SEAMLESS_SNAPPING_IO_VVAL_H

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/Status.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {

namespace internal {

// the text of write_VVAL(), or INVALID_INPUT with `message` for a negative valence
inline Status vval_text(const std::vector<int>& valences, std::string& text, std::string& message)
{
  text = "{\"file_format\":\"VVAL\",\"version\":1}\n" + std::to_string(valences.size()) + "\n";
  for(std::size_t v = 0; v < valences.size(); ++v) {
    if(valences[v] < 0) {
      message = "vertex " + std::to_string(v) + " has the valence " + std::to_string(valences[v]) +
                " (its UV angle sum turns backwards): the VVAL format has no negative valences; nothing was written";
      return INVALID_INPUT;
    }
    text += std::to_string(valences[v]) + "\n";
  }
  return SUCCESS;
}

// write_VVAL()'s message on success
inline std::string vval_written(const std::vector<int>& valences, const std::string& filename)
{
  return std::to_string(valences.size()) + " vertex valences (VVAL) written to " + filename;
}

} // namespace internal

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * writes vertex valences (e.g. `quad_valences()`) in libQEx's VVAL format, the optional third argument of its
 * command-line tool: the first line is exactly `{"file_format":"VVAL","version":1}`, the second the number of
 * vertices, then one non-negative integer per line and vertex, in the order of the vertices of the mesh file
 * that goes with it (for `write_OBJ_with_corner_uvs()`: the order of `vertices(tm)`, its `v` lines). The format
 * is taken from the reader of libQEx's command-line tool (header line, count, whitespace-separated integers);
 * libQEx uses the values of interior vertices only.
 *
 * The file is written atomically (a temporary file next to it, then renamed): on failure `filename` is untouched.
 *
 * \return `SUCCESS`, or `INVALID_INPUT` with `message` when a valence is negative (libQEx stores them unsigned)
 *         or the file cannot be written; on success `message` says what was written.
 */
inline Status write_VVAL(const std::string& filename, const std::vector<int>& valences, std::string& message)
{
  std::string text;
  if(internal::vval_text(valences, text, message) != SUCCESS) return INVALID_INPUT;
  if(internal::write_text_atomically(filename, text, message) != SUCCESS) return INVALID_INPUT;
  message = internal::vval_written(valences, filename);
  return SUCCESS;
}

} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_IO_VVAL_H
