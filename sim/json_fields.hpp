// SPDX-License-Identifier: Apache-2.0
// Reading one JSON object of a scenario with errors that name the source and the JSON path
// ("scenario.json: effects[2].amplitude_deg: must be in [0, 90], got 120"; paths and the error
// line as every reader writes them, auxiliary/json_path.hpp). Every key must be read or the
// object is refused by finish() (unknown keys are errors, not silently ignored).
#pragma once

#include <nlohmann/json.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace gazelod::sim {

class JsonFields {
 public:
  // `object` must outlive this reader. Throws ScenarioError when it is not a JSON object.
  JsonFields(const nlohmann::json& object, std::string path, std::string source);

  const std::string& path() const { return path_; }
  const std::string& source() const { return source_; }
  std::string key_path(const std::string& key) const;
  bool has(const std::string& key) const;

  // Numbers in [lo, hi]; `fallback` when absent. required_* throw when absent.
  double number(const std::string& key, double fallback, double lo, double hi);
  double required_number(const std::string& key, double lo, double hi);
  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t lo, std::int64_t hi);
  std::uint64_t unsigned_integer(const std::string& key, std::uint64_t fallback);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  std::string required_string(const std::string& key);
  // [x, y, z], each finite and within [lo, hi].
  glm::dvec3 vec3(const std::string& key, glm::dvec3 fallback, double lo = -1e6, double hi = 1e6);
  // A raw child (marked as read), or nullptr when absent.
  const nlohmann::json* child(const std::string& key);

  // Throws naming the first key that no accessor read.
  void finish() const;
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  const nlohmann::json* find(const std::string& key);
  const nlohmann::json& obj_;
  std::string path_, source_;
  std::set<std::string> used_;
};

// A number for messages, as the README writes limits: 6 significant digits, exponents
// without "+" or leading zeros ("1e6", "1e-5", "0.001").
std::string format_number(double x);

// Throws ScenarioError "<source>: <path>: <message>".
[[noreturn]] void throw_at(const std::string& source, const std::string& path, const std::string& message);

}  // namespace gazelod::sim
