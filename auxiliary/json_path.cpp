// SPDX-License-Identifier: Apache-2.0
// JSON paths and error lines (see json_path.hpp).
#include "auxiliary/json_path.hpp"

#include <algorithm>

namespace gazelod::aux {

std::string json_member_path(std::string_view object_path, std::string_view key) {
  std::string s(object_path);
  if (!s.empty()) s.push_back('.');
  return s.append(key);
}

std::string json_element_path(std::string_view array_path, std::size_t index) {
  // Built with append: gcc 12 warns (-Wrestrict, falsely) on "[" + std::string(...).
  std::string s(array_path);
  return s.append("[").append(std::to_string(index)).append("]");
}

std::string json_error_line(std::string_view source, std::string_view path, std::string_view message) {
  std::string s(source);
  return s.append(": ").append(path).append(": ").append(message);
}

std::string json_line_column(std::string_view text, std::size_t byte) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n')
      ++line, col = 1;
    else
      ++col;
  }
  return std::to_string(line) + ":" + std::to_string(col);
}

std::string json_type_name(const nlohmann::json& v) {
  if (v.is_boolean()) return "boolean";
  if (v.is_number()) return "number";
  if (v.is_string()) return "string";
  if (v.is_array()) return "array";
  if (v.is_object()) return "object";
  return "null";
}

const std::string* first_unknown_key(const nlohmann::json& object, std::initializer_list<std::string_view> known) {
  if (!object.is_object()) return nullptr;
  for (auto it = object.begin(); it != object.end(); ++it)
    if (std::find(known.begin(), known.end(), std::string_view(it.key())) == known.end()) return &it.key();
  return nullptr;
}

std::string joined_keys(std::initializer_list<std::string_view> keys) {
  std::string s;
  for (std::string_view k : keys) {
    if (!s.empty()) s.append(", ");
    s.append(k);
  }
  return s;
}

}  // namespace gazelod::aux
