// SPDX-License-Identifier: Apache-2.0
#include "budget/budget_instance.hpp"

#include "auxiliary/json_path.hpp"
#include "auxiliary/json_strict.hpp"

#include "budget/mckp_hierarchy.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

namespace gazelod::budget {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& path, const std::string& why) {
  throw InstanceError(aux::json_error_line(where, path, why));
}

double number(const json& v, const std::string& where, const std::string& path, bool non_negative) {
  const char* why = non_negative ? "must be a finite number >= 0" : "must be a finite number";
  if (!v.is_number()) fail(where, path, why);
  const double d = v.get<double>();
  if (!std::isfinite(d) || (non_negative && d < 0.0)) fail(where, path, why);
  return d;
}

std::uint32_t index(const json& v, std::size_t bound, const std::string& where, const std::string& path,
                    const char* what) {
  if (!v.is_number_integer() || v.get<long long>() < 0 || static_cast<unsigned long long>(v.get<long long>()) >= bound)
    fail(where, path, std::string("must be ") + what + " index in [0, " + std::to_string(bound) + ")");
  return static_cast<std::uint32_t>(v.get<long long>());
}

budget::MckpItem item(const json& v, const std::string& where, const std::string& path) {
  if (!v.is_object()) fail(where, path, "must be an object {\"profit\": p, \"cost\": w}");
  if (const std::string* key = aux::first_unknown_key(v, {"profit", "cost"}))
    fail(where, aux::json_member_path(path, *key), "unknown key");
  const std::string profit = aux::json_member_path(path, "profit"), cost = aux::json_member_path(path, "cost");
  if (!v.contains("profit")) fail(where, profit, "missing");
  if (!v.contains("cost")) fail(where, cost, "missing");
  return {number(v["profit"], where, profit, true), number(v["cost"], where, cost, true)};
}

// The largest profit and cost any answer can add up to: the sum over subsets (and groups'
// impostors) of their largest item. Both must stay finite, or a solver's sums overflow to
// infinity (an answer with "profit": inf).
void check_sums(const budget::MckpInstance& inst, const std::string& where) {
  double profit = 0.0, cost = 0.0;
  auto add_max = [&](std::span<const budget::MckpItem> items) {
    double p = 0.0, c = 0.0;
    for (const budget::MckpItem& it : items) p = std::max(p, it.profit), c = std::max(c, it.cost);
    profit += p;
    cost += c;
  };
  for (std::size_t k = 0; k < inst.subset_count(); ++k) add_max(inst.subset(k));
  for (const budget::MckpGroup& g : inst.groups) add_max(g.impostors);
  const char* limit = "the largest double, 1.8e308";
  if (!std::isfinite(profit))
    fail(where, "subsets",
         std::string("the largest profits of the subsets (and impostors) must add up to at most ") + limit +
             ", got an overflow; scale the profits down");
  if (!std::isfinite(cost))
    fail(where, "subsets",
         std::string("the largest costs of the subsets (and impostors) must add up to at most ") + limit +
             ", got an overflow; scale the costs and the capacity down");
}

}  // namespace

budget::MckpInstance parse_budget_instance(const json& doc, const std::string& where) {
  if (!doc.is_object())
    fail(where, std::string(aux::kJsonTopLevel), "must be an object with \"capacity\" and \"subsets\"");
  if (const std::string* key = aux::first_unknown_key(doc, {"capacity", "subsets", "groups"}))
    fail(where, *key, "unknown key (expected capacity, subsets, groups)");
  if (!doc.contains("capacity")) fail(where, "capacity", "missing");
  if (!doc.contains("subsets")) fail(where, "subsets", "missing");
  budget::MckpInstance inst;
  inst.capacity = number(doc["capacity"], where, "capacity", true);
  const json& subsets = doc["subsets"];
  if (!subsets.is_array() || subsets.empty()) fail(where, "subsets", "must be a non-empty array of arrays");
  if (subsets.size() >= std::numeric_limits<std::uint32_t>::max() / 2) fail(where, "subsets", "too many");
  std::vector<budget::MckpItem> items;
  for (std::size_t k = 0; k < subsets.size(); ++k) {
    const std::string path = aux::json_element_path("subsets", k);
    const json& s = subsets[k];
    if (!s.is_array() || s.empty()) fail(where, path, "must be a non-empty array of items");
    items.clear();
    for (std::size_t j = 0; j < s.size(); ++j) items.push_back(item(s[j], where, aux::json_element_path(path, j)));
    inst.add_subset(items);
  }
  if (inst.items.size() >= std::numeric_limits<std::uint32_t>::max() / 2) fail(where, "subsets", "too many items");
  if (doc.contains("groups")) {
    const json& groups = doc["groups"];
    if (!groups.is_array()) fail(where, "groups", "must be an array of groups");
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const std::string path = aux::json_element_path("groups", g);
      const json& gj = groups[g];
      if (!gj.is_object()) fail(where, path, "must be an object {\"subsets\", \"groups\", \"impostors\"}");
      budget::MckpGroup grp;
      for (auto it = gj.begin(); it != gj.end(); ++it) {
        const std::string key = it.key();
        const std::string kp = aux::json_member_path(path, key);
        if (key != "subsets" && key != "groups" && key != "impostors")
          fail(where, kp, "unknown key (expected subsets, groups, impostors)");
        if (!it->is_array()) fail(where, kp, "must be an array");
        for (std::size_t a = 0; a < it->size(); ++a) {
          const std::string ap = aux::json_element_path(kp, a);
          if (key == "subsets")
            grp.subsets.push_back(index((*it)[a], inst.subset_count(), where, ap, "a subset"));
          else if (key == "groups")
            grp.groups.push_back(index((*it)[a], groups.size(), where, ap, "a group"));
          else
            grp.impostors.push_back(item((*it)[a], where, ap));
        }
      }
      inst.groups.push_back(std::move(grp));
    }
    const std::string problem = budget::check_hierarchy(inst);
    if (!problem.empty()) throw InstanceError(where + ": " + problem);
  }
  check_sums(inst, where);
  return inst;
}

budget::MckpInstance read_budget_instance(const std::string& path) {
  // Regular files only: a directory failed inside the stream with a libstdc++ message, and a
  // FIFO would block.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw InstanceError("--instance: " + path + ": no such file");
  if (!std::filesystem::is_regular_file(status))
    throw InstanceError("--instance: " + path + ": not a regular file (a directory, FIFO or device)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InstanceError("--instance: cannot open " + path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  json doc;
  try {
    doc = aux::parse_json_text(text, path);
  } catch (const aux::JsonTextError& e) {
    throw InstanceError(e.what());
  }
  return parse_budget_instance(doc, path);
}

}  // namespace gazelod::budget
