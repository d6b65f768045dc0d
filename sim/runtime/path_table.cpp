// SPDX-License-Identifier: Apache-2.0
// Path grammar and the per-instance string <-> XrPath table (see path_table.hpp).
#include "sim/runtime/path_table.hpp"

namespace gazelod::xrrt {

namespace {

bool is_path_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
}

}  // namespace

bool is_well_formed_name(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s) {
    if (!is_path_char(c)) return false;
  }
  return s != "." && s != ".." && s.find_first_not_of('.') != std::string_view::npos;
}

bool is_well_formed_path(std::string_view s) {
  if (s.size() < 2 || s.size() >= XR_MAX_PATH_LENGTH || s.front() != '/' || s.back() == '/') return false;
  std::size_t start = 1;
  while (start <= s.size()) {
    std::size_t end = s.find('/', start);
    if (end == std::string_view::npos) end = s.size();
    if (!is_well_formed_name(s.substr(start, end - start))) return false;
    start = end + 1;
  }
  return true;
}

XrPath PathTable::intern(std::string_view s) {
  auto it = by_string_.find(std::string(s));
  if (it != by_string_.end()) return it->second;
  strings_.emplace_back(s);
  const XrPath path = strings_.size();
  by_string_.emplace(strings_.back(), path);
  return path;
}

const std::string* PathTable::find(XrPath path) const {
  if (path == XR_NULL_PATH || path > strings_.size()) return nullptr;
  return &strings_[path - 1];
}

}  // namespace gazelod::xrrt
