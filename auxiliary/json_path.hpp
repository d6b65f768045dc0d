// SPDX-License-Identifier: Apache-2.0
// JSON paths in the error messages of the hand-written inputs' readers (scenarios, the layer's
// configuration, budget instances): one spelling of a path and of the error line, so that every
// reader points at the offending value the same way.
//
//   json_error_line("scenario.json", json_element_path("effects", 2) ... )
//     -> "scenario.json: effects[2].amplitude_deg: must be in [0, 90], got 120"
//
// Each reader keeps its own exception type and its own messages; only the framing is here.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

namespace gazelod::aux {

// The path that names the document itself.
inline constexpr std::string_view kJsonTopLevel = "(top level)";

// "object.key", or "key" for a member of the document ("" object path).
std::string json_member_path(std::string_view object_path, std::string_view key);
// "array[index]".
std::string json_element_path(std::string_view array_path, std::size_t index);

// "SOURCE: PATH: MESSAGE", the line every reader's error is (SOURCE: the file, or what stands
// for it, such as "--instance: f.json" or "GAZELOD_LAYER_CONFIG=f.json").
std::string json_error_line(std::string_view source, std::string_view path, std::string_view message);

// "LINE:COLUMN" (both from 1) of a byte offset into `text`, for a syntax error's position:
// "scenario.json:3:14: JSON syntax error: ...".
std::string json_line_column(std::string_view text, std::size_t byte);

// "boolean", "number", "string", "array", "object" or "null", for "expected ..., got TYPE".
std::string json_type_name(const nlohmann::json& v);

// The first key of `object` (in nlohmann's order, the sorted one) that is not in `known`, or
// nullptr: the readers refuse unknown keys rather than ignore a misspelt one.
const std::string* first_unknown_key(const nlohmann::json& object, std::initializer_list<std::string_view> known);

// "a, b, c": the known keys, for "unknown key (known: a, b, c)".
std::string joined_keys(std::initializer_list<std::string_view> keys);

}  // namespace gazelod::aux
