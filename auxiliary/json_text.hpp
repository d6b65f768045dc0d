// SPDX-License-Identifier: Apache-2.0
// JSON as text, for every report and printout. A string that is not UTF-8 (a scenario named
// after a Latin-1 file name, a USB device's product string) is written with U+FFFD in place of
// its bad bytes: nlohmann's plain dump() threw type_error 316 ("invalid UTF-8 byte") after the
// rest of the report had been written, and the command failed with that raw text.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace gazelod::aux {

inline std::string json_text(const nlohmann::json& v, int indent = -1) {
  return v.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace gazelod::aux
