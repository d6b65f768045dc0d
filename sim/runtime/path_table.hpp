// SPDX-License-Identifier: Apache-2.0
// XrPath atoms for one instance: the string <-> path table behind xrStringToPath and
// xrPathToString, with the path well-formedness rules of OpenXR 1.0 section 6.1
// ("Path Atom Type": lower-case, digits, '-', '_', '.', separated by '/').
#pragma once

#include "sim/runtime/xr_headers.hpp"

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace gazelod::xrrt {

// True when `s` is a well-formed path string (starts with '/', no empty, "." or ".."
// component, no trailing '/', only [a-z0-9-_.] in components, shorter than XR_MAX_PATH_LENGTH).
bool is_well_formed_path(std::string_view s);
// True when `s` is a valid action or action-set name: one path component.
bool is_well_formed_name(std::string_view s);

class PathTable {
 public:
  // Interns a well-formed string (the caller has checked it).
  XrPath intern(std::string_view s);
  // The string of a path, nullptr when the path was never returned by this instance.
  const std::string* find(XrPath path) const;

 private:
  std::vector<std::string> strings_;  // path value = index + 1
  std::unordered_map<std::string, XrPath> by_string_;
};

}  // namespace gazelod::xrrt
