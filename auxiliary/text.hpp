// SPDX-License-Identifier: Apache-2.0
// Counted nouns for messages a person reads: "1 mesh", "2 meshes", "0 saccades".
#pragma once

#include <cstdint>
#include <string>

namespace gazelod::aux {

inline std::string counted(std::uint64_t n, const char* singular, const char* plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

}  // namespace gazelod::aux
