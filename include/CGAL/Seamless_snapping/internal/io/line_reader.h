// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_LINE_READER_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_LINE_READER_H

// The lines of a stream, as std::getline(is, line) gives them (split at '\n', which is not part of the
// line; a last line without '\n' counts, an empty stream has no line; '\r' and '\0' are ordinary
// characters), but read in blocks of 1 MiB with istream::read() and handed out as [begin, end) ranges
// into the block: no std::string per line, no locale or sentry per line. The OBJ reader spent about
// as much time in std::getline as in parsing the numbers. Memory: one block (larger only for a line
// longer than a block, up to max_line_bytes: a longer line stops the reading, so that a stream without
// '\n', e.g. /dev/zero, does not fill the memory).

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <istream>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {
namespace internal {

// the longest line for_each_line() reads (no text record of a mesh file comes near it)
constexpr std::size_t max_line_bytes = std::size_t(1) << 26;

// Calls use(begin, end, line_number) for each line (line numbers from 1) until it returns false.
// Returns the number of lines handed out; `read_error` = the stream went bad (istream::bad()) while reading;
// `too_long` = the next line is longer than max_line_bytes (it is not handed out, and reading stops).
// At most `limit` bytes of the stream are read (the part of a file before a given offset).
template <class Use>
std::size_t for_each_line(std::istream& is, const Use& use, bool& read_error, bool& too_long,
                          std::size_t limit = std::size_t(-1))
{
  std::vector<char> block(std::size_t(1) << 20);
  std::size_t kept = 0, lineno = 0;   // kept: bytes of an unfinished line at the start of the block
  read_error = too_long = false;
  for(;;) {
    if(kept == block.size()) {        // a line longer than the block
      if(block.size() >= max_line_bytes) { too_long = true; return lineno; }
      block.resize(2 * block.size());
    }
    is.read(block.data() + kept, std::streamsize((std::min)(block.size() - kept, limit)));
    const std::size_t got = std::size_t(is.gcount());
    limit -= got;
    const std::size_t size = kept + got;
    const bool last = got == 0 || !is || limit == 0;
    const char* p = block.data();
    const char* const end = p + size;
    for(;;) {
      const char* nl = static_cast<const char*>(std::memchr(p, '\n', std::size_t(end - p)));
      if(nl == nullptr) break;
      if(!use(p, nl, ++lineno)) return lineno;
      p = nl + 1;
    }
    kept = std::size_t(end - p);
    if(last) {
      read_error = is.bad();
      if(kept > 0 && !read_error && !use(p, end, ++lineno)) return lineno;
      return lineno;
    }
    std::memmove(block.data(), p, kept);
  }
}

} // namespace internal
} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_LINE_READER_H
