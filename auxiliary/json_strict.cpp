#include "auxiliary/json_strict.hpp"

#include <cstddef>
#include <set>
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
      p += (p.empty() ? "" : ".") + o.key;
    } else {
      p += "[" + std::to_string(o.index) + "]";
    }
  }
  return p;
}

}  // namespace

nlohmann::json parse_json_strict(std::string_view text, int max_depth) {
  using Event = nlohmann::json::parse_event_t;
  std::vector<Open> open;
  // A finished value advances the enclosing array's index.
  const auto finished_value = [&open] {
    if (!open.empty() && !open.back().object) ++open.back().index;
  };
  const nlohmann::json::parser_callback_t check = [&](int depth, Event event, nlohmann::json& parsed) {
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        if (depth >= max_depth)
          // No path: it would be the nesting itself, [0][0][0]... 64 times.
          throw JsonStrictError("", "JSON nesting must be at most " + std::to_string(max_depth) +
                                                   " levels of arrays and objects, got more");
        open.push_back(Open{event == Event::object_start, {}, {}, 0});
        break;
      case Event::key: {
        Open& o = open.back();
        o.key = parsed.get<std::string>();
        if (!o.keys.insert(o.key).second)
          throw JsonStrictError(path_of(open), "the key appears twice in one object (which one counts is undefined)");
        break;
      }
      case Event::object_end:
      case Event::array_end:
        open.pop_back();
        finished_value();
        break;
      case Event::value:
        finished_value();
        break;
    }
    return true;
  };
  return nlohmann::json::parse(text, check);
}

}  // namespace gazelod::aux
