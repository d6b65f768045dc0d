// SPDX-License-Identifier: Apache-2.0
#include "auxiliary/json_strict.hpp"

#include "auxiliary/json_path.hpp"

#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace gazelod::aux {
namespace {

// Where the parser is: one entry per open array or object.
struct Open {
  bool object = false;
  std::set<std::string> keys;  // objects: the keys seen so far
  std::string key;             // objects: the key whose value is being read
  std::size_t index = 0;       // arrays: the element being read
};

std::string path_of(const std::vector<Open>& open) {
  std::string p;
  for (const Open& o : open) {
    if (o.object) {
      if (o.key.empty()) continue;  // no key read yet in this object
      p = json_member_path(p, o.key);
    } else {
      p = json_element_path(p, o.index);
    }
  }
  return p;
}

// A SAX pass that builds nothing: it follows the nesting, the keys of each open object and the
// index in each open array, and throws at a repeated key or past the depth. (nlohmann's
// parser callback would do the same while building, but its end_object scans the enclosing
// array for discarded values: quadratic in an array of objects, 50 s for 200k budget items.)
class Checker {
 public:
  explicit Checker(int max_depth) : max_depth_(max_depth) {}
  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(nlohmann::json::number_integer_t) { return value(); }
  bool number_unsigned(nlohmann::json::number_unsigned_t) { return value(); }
  bool number_float(nlohmann::json::number_float_t, const std::string&) { return value(); }
  bool string(std::string&) { return value(); }
  bool binary(nlohmann::json::binary_t&) { return value(); }
  bool start_object(std::size_t) { return open(true); }
  bool start_array(std::size_t) { return open(false); }
  bool key(std::string& k) {
    Open& o = open_.back();
    o.key = k;
    if (!o.keys.insert(k).second)
      throw JsonStrictError(path_of(open_), "the key appears twice in one object (which one counts is undefined)");
    return true;
  }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  // A syntax error: stop; the parse that follows reports it with its byte.
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) { return false; }

 private:
  bool value() {
    if (!open_.empty() && !open_.back().object) ++open_.back().index;
    return true;
  }
  bool open(bool object) {
    if (static_cast<int>(open_.size()) >= max_depth_)
      // No path: it would be the nesting itself, [0][0][0]... 64 times.
      throw JsonStrictError(
          "", "JSON nesting must be at most " + std::to_string(max_depth_) + " levels of arrays and objects, got more");
    open_.push_back(Open{object, {}, {}, 0});
    return true;
  }
  bool close() {
    open_.pop_back();
    return value();
  }

  int max_depth_;
  std::vector<Open> open_;
};

}  // namespace

nlohmann::json parse_json_strict(std::string_view text, int max_depth) {
  Checker checker(max_depth);
  (void)nlohmann::json::sax_parse(text, &checker);  // throws JsonStrictError; stops at a syntax error
  return nlohmann::json::parse(text);               // the document, or its parse_error with the byte
}

namespace {

// nlohmann's message without its "[json.exception.parse_error.101] parse error at line 1,
// column 5: " prefix (the position is given as LINE:COLUMN after the source).
std::string bare_message(const nlohmann::json::exception& e) {
  std::string m = e.what();
  if (m.starts_with("[json.exception.")) {
    const std::size_t end = m.find("] ");
    if (end != std::string::npos) m.erase(0, end + 2);
  }
  if (m.starts_with("parse error")) {
    const std::size_t colon = m.find(": ");
    if (colon != std::string::npos) m.erase(0, colon + 2);
  }
  return m;
}

}  // namespace

nlohmann::json parse_json_text(std::string_view text, std::string_view source, int max_depth) {
  const std::string src(source);
  try {
    return parse_json_strict(text, max_depth);
  } catch (const JsonStrictError& e) {
    throw JsonTextError(src + ": " + (e.path().empty() ? e.message() : std::string(e.what())));
  } catch (const nlohmann::json::parse_error& e) {
    throw JsonTextError(src + ":" + json_line_column(text, e.byte > 0 ? e.byte - 1 : 0) +
                        ": JSON syntax error: " + bare_message(e));
  } catch (const nlohmann::json::out_of_range& e) {  // 406: a number past a double's range
    // nlohmann names the literal, not where it is: found in the text for the line and column.
    const std::string what = e.what();
    const std::size_t q = what.find("parsing '");
    std::string literal, at;
    if (q != std::string::npos) literal = what.substr(q + 9, what.find('\'', q + 9) - (q + 9));
    if (const std::size_t pos = literal.empty() ? std::string::npos : text.find(literal); pos != std::string::npos)
      at = ":" + json_line_column(text, pos);
    throw JsonTextError(src + at + ": the number " + (literal.empty() ? std::string("here") : literal) +
                        " is past the range of a double");
  } catch (const nlohmann::json::exception& e) {
    throw JsonTextError(src + ": JSON error: " + bare_message(e));
  }
}

}  // namespace gazelod::aux
