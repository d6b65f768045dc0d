// SPDX-License-Identifier: Apache-2.0
// Parsing JSON that people write by hand (scenarios, configurations, budget instances): RFC
// 8259 leaves a key repeated in one object undefined and nlohmann::json keeps the last one
// silently, so `"duration_s": 2, ..., "duration_s": 3` would run for 3 s without a word. The
// parser here refuses a repeated key, naming its JSON path, and nesting deeper than a limit
// (a deeply nested value costs stack in every later pass over it: dump, destruction).
//
//   nlohmann::json j = aux::parse_json_strict(text);   // throws aux::JsonStrictError
//
// Syntax errors are nlohmann's json::parse_error as before (with its byte offset).
#pragma once

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <string_view>

namespace gazelod::aux {

class JsonStrictError : public std::runtime_error {
 public:
  // what(): "PATH: MESSAGE" ("scene.objects[2].name: the key appears twice in one object").
  JsonStrictError(std::string path, std::string message)
      : std::runtime_error(path + ": " + message), path_(std::move(path)), message_(std::move(message)) {}
  const std::string& path() const { return path_; }  // "" for the document itself (and nesting)
  const std::string& message() const { return message_; }

 private:
  std::string path_, message_;
};

inline constexpr int kDefaultMaxJsonDepth = 64;

// Throws JsonStrictError for a repeated key or nesting past max_depth arrays and objects,
// nlohmann::json::exception for anything else wrong with the text.
nlohmann::json parse_json_strict(std::string_view text, int max_depth = kDefaultMaxJsonDepth);

// Every way the text can fail to be a document, worded one way after `source` (the file, or
// what stands for it), for the readers of hand-written JSON (scenarios, budget instances, the
// layer's configuration, --against):
//   "SOURCE:3:14: JSON syntax error: syntax error while parsing value - ..."
//   "SOURCE:2:20: the number 1e999 is past the range of a double"
//   "SOURCE: scene.objects[2].name: the key appears twice in one object"
//   "SOURCE: JSON nesting must be at most 64 levels ..."
// Each reader kept its own wording (byte offsets, nlohmann's "[json.exception.406]" text, an
// empty path as ": : ").
class JsonTextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// parse_json_strict; throws JsonTextError.
nlohmann::json parse_json_text(std::string_view text, std::string_view source, int max_depth = kDefaultMaxJsonDepth);

}  // namespace gazelod::aux
