// SPDX-License-Identifier: Apache-2.0
#include "sim/json_fields.hpp"

#include "auxiliary/json_path.hpp"
#include "sim/simulator.hpp"

#include <cmath>
#include <sstream>

namespace gazelod::sim {

void throw_at(const std::string& source, const std::string& path, const std::string& message) {
  throw ScenarioError(aux::json_error_line(source, path.empty() ? aux::kJsonTopLevel : path, message));
}

JsonFields::JsonFields(const nlohmann::json& object, std::string path, std::string source)
    : obj_(object), path_(std::move(path)), source_(std::move(source)) {
  if (!obj_.is_object()) throw_at(source_, path_, "expected an object, got " + aux::json_type_name(obj_));
}

std::string JsonFields::key_path(const std::string& key) const {
  return aux::json_member_path(path_, key);
}

bool JsonFields::has(const std::string& key) const {
  return obj_.contains(key);
}

void JsonFields::fail(const std::string& key, const std::string& message) const {
  throw_at(source_, key.empty() ? path_ : key_path(key), message);
}

const nlohmann::json* JsonFields::find(const std::string& key) {
  const auto it = obj_.find(key);
  if (it == obj_.end()) return nullptr;
  used_.insert(key);
  return &*it;
}

const nlohmann::json* JsonFields::child(const std::string& key) {
  return find(key);
}

std::string format_number(double x) {
  std::ostringstream s;
  s << x;  // 6 significant digits, as %g
  std::string t = s.str();
  // "1e+06" -> "1e6", "1e-05" -> "1e-5": the way the README writes limits.
  const std::size_t e = t.find('e');
  if (e == std::string::npos) return t;
  std::size_t d = e + 1;
  std::string out(t, 0, d);
  if (d < t.size() && (t[d] == '+' || t[d] == '-')) {
    if (t[d] == '-') out.push_back('-');
    ++d;
  }
  while (d + 1 < t.size() && t[d] == '0') ++d;
  out.append(t, d, std::string::npos);
  return out;
}

namespace {
// Built with append: gcc 12 warns (-Wrestrict, falsely) on "[" + std::string(...).
std::string range_text(const std::string& lo, const std::string& hi) {
  std::string s("[");
  s.append(lo).append(", ").append(hi).append("]");
  return s;
}
std::string range_text(double lo, double hi) {
  return range_text(format_number(lo), format_number(hi));
}
std::string range_text(std::int64_t lo, std::int64_t hi) {
  return range_text(std::to_string(lo), std::to_string(hi));
}
}  // namespace

double JsonFields::number(const std::string& key, double fallback, double lo, double hi) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_number()) fail(key, "expected a number, got " + aux::json_type_name(*v));
  const double x = v->get<double>();
  if (!std::isfinite(x) || x < lo || x > hi) {
    fail(key, "must be in " + range_text(lo, hi) + ", got " + format_number(x));
  }
  return x;
}

double JsonFields::required_number(const std::string& key, double lo, double hi) {
  if (!has(key)) fail(key, "missing (a number in " + range_text(lo, hi) + ")");
  return number(key, 0.0, lo, hi);
}

std::int64_t JsonFields::integer(const std::string& key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_number_integer())
    fail(key, "expected an integer, got " + (v->is_number() ? v->dump() : aux::json_type_name(*v)));
  if (v->is_number_unsigned() && v->get<std::uint64_t>() > static_cast<std::uint64_t>(hi))
    fail(key, "must be in " + range_text(lo, hi) + ", got " + v->dump());
  const std::int64_t x = v->get<std::int64_t>();
  if (x < lo || x > hi) fail(key, "must be in " + range_text(lo, hi) + ", got " + v->dump());
  return x;
}

std::uint64_t JsonFields::unsigned_integer(const std::string& key, std::uint64_t fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_number_unsigned())  // nlohmann keeps non-negative integers unsigned
    fail(key, "expected a non-negative integer, got " + (v->is_number() ? v->dump() : aux::json_type_name(*v)));
  return v->get<std::uint64_t>();
}

bool JsonFields::boolean(const std::string& key, bool fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_boolean()) fail(key, "expected true or false, got " + aux::json_type_name(*v));
  return v->get<bool>();
}

std::string JsonFields::string(const std::string& key, const std::string& fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_string()) fail(key, "expected a string, got " + aux::json_type_name(*v));
  return v->get<std::string>();
}

std::string JsonFields::required_string(const std::string& key) {
  if (!has(key)) fail(key, "missing (a string)");
  return string(key, "");
}

glm::dvec3 JsonFields::vec3(const std::string& key, glm::dvec3 fallback, double lo, double hi) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_array() || v->size() != 3) fail(key, "expected [x, y, z], got " + aux::json_type_name(*v));
  glm::dvec3 out;
  for (int i = 0; i < 3; ++i) {
    const nlohmann::json& e = (*v)[static_cast<std::size_t>(i)];
    const std::string p = aux::json_element_path(key, static_cast<std::size_t>(i));
    if (!e.is_number()) fail(p, "expected a number, got " + aux::json_type_name(e));
    out[i] = e.get<double>();
    if (!std::isfinite(out[i]) || out[i] < lo || out[i] > hi) {
      fail(p, "must be in " + range_text(lo, hi) + ", got " + format_number(out[i]));
    }
  }
  return out;
}

void JsonFields::finish() const {
  for (const auto& [key, value] : obj_.items()) {
    (void)value;
    if (!used_.count(key)) fail(key, "unknown key");
  }
}

}  // namespace gazelod::sim
