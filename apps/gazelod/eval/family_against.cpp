// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/family_against.hpp"

#include "apps/gazelod/commands/command.hpp"
#include "auxiliary/json_path.hpp"
#include "auxiliary/json_strict.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace gazelod::cli {
namespace {

[[noreturn]] void fail(const std::string& source, std::string_view path, std::string_view message) {
  throw UsageError("--against: " + aux::json_error_line(source, path, message));
}

// The member at `key` of the object at `path`, which must exist.
const nlohmann::json& member(const nlohmann::json& object, const std::string& path, std::string_view key,
                             const std::string& source) {
  const std::string at = aux::json_member_path(path, key);
  if (!object.is_object()) fail(source, path, "expected an object, got " + aux::json_type_name(object));
  const auto it = object.find(std::string(key));
  if (it == object.end()) fail(source, at, "missing (is this a family.json of gazelod eval family?)");
  return *it;
}

// The finite number >= 0 at the end of `keys` from `object` (at `path`).
double figure(const nlohmann::json& object, std::string path, std::initializer_list<std::string_view> keys,
              const std::string& source) {
  const nlohmann::json* v = &object;
  for (const std::string_view k : keys) {
    v = &member(*v, path, k, source);
    path = aux::json_member_path(path, k);
  }
  if (!v->is_number() || !std::isfinite(v->get<double>()) || v->get<double>() < 0.0)
    fail(source, path,
         "expected a number >= 0, got " +
             (v->is_number() ? std::string("a negative or non-finite one") : aux::json_type_name(*v)));
  return v->get<double>();
}

std::string text_of(const std::string& path) {
  if (path.empty()) throw UsageError("--against: expected a family.json, got an empty path");
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw UsageError("--against: " + path + ": no such file");
  if (ec) throw UsageError("--against: " + path + ": " + ec.message());
  if (!std::filesystem::is_regular_file(status))
    throw UsageError("--against: " + path + ": not a regular file (a directory, FIFO or device)");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw UsageError("--against: " + path + ": " + ec.message());
  if (size > kMaxBaselineBytes)
    throw UsageError("--against: " + path + ": larger than " + std::to_string(kMaxBaselineBytes >> 20) +
                     " MiB (a family.json of 10000 seeds is ~60 MB)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("--against: " + path + ": cannot open");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// One target: its figure now and before, per seed.
struct Target {
  const char* name;
  double limit;
  double (*now)(const AuditSummary&);
  double BaselineRow::*before;
  const char* format;  // printf, of value * scale
  double scale;
};
const Target kTargets[] = {
    {"visible degradations (fixation object-frames)", kTargetDegradedShare, degraded_figure,
     &BaselineRow::degraded_share, "%.3f%%", 100.0},
    {"triangles drawn / oracle", kTargetTriangleRatio, triangle_figure, &BaselineRow::triangle_ratio, "%.3f", 1.0},
    {"switches per object-second outside suppression", kTargetSwitchesPerObjectS, switch_figure,
     &BaselineRow::switches_per_object_s, "%.3f", 1.0},
};
constexpr std::size_t kTargetCount = std::size(kTargets);

// Per target (and, last, all three at once): the seeds within before and now.
struct Standing {
  int before = 0, now = 0;
  std::vector<std::uint64_t> entered, left;
};
std::vector<Standing> standings(const std::vector<FamilyMember>& members, const FamilyBaseline& base) {
  bool same = members.size() == base.rows.size();
  for (std::size_t i = 0; same && i < members.size(); ++i) same = members[i].seed == base.rows[i].seed;
  if (!same) throw UsageError("--against: " + base.source + ": not the seeds of this run");
  std::vector<Standing> s(kTargetCount + 1);
  for (std::size_t i = 0; i < members.size(); ++i) {
    const AuditSummary& a = members[i].audit;
    const BaselineRow& b = base.rows[i];
    bool all_before = true, all_now = true;
    for (std::size_t k = 0; k <= kTargetCount; ++k) {
      bool was, is;
      if (k < kTargetCount) {
        was = b.*kTargets[k].before <= kTargets[k].limit;
        is = kTargets[k].now(a) <= kTargets[k].limit;
        all_before = all_before && was;
        all_now = all_now && is;
      } else {
        was = all_before;
        is = all_now;
      }
      s[k].before += was ? 1 : 0;
      s[k].now += is ? 1 : 0;
      if (is && !was) s[k].entered.push_back(members[i].seed);
      if (was && !is) s[k].left.push_back(members[i].seed);
    }
  }
  return s;
}

std::string seed_list(const std::vector<std::uint64_t>& seeds) {
  if (seeds.empty()) return "none";
  std::string out;
  for (const std::uint64_t s : seeds) out += (out.empty() ? "" : ", ") + std::to_string(s);
  return out;
}

Spread spread_before(const FamilyBaseline& base, double BaselineRow::*field, double limit) {
  std::vector<std::pair<std::uint64_t, double>> v;
  for (const BaselineRow& r : base.rows) v.emplace_back(r.seed, r.*field);
  return spread_of(v, limit);
}

}  // namespace

FamilyBaseline read_family_baseline(const std::string& path) {
  const std::string text = text_of(path);
  nlohmann::json doc;
  try {
    doc = aux::parse_json_text(text, path);
  } catch (const aux::JsonTextError& e) {
    throw UsageError(std::string("--against: ") + e.what());
  }
  FamilyBaseline base;
  base.source = path;
  if (!doc.is_object()) fail(path, aux::kJsonTopLevel, "expected an object, got " + aux::json_type_name(doc));
  const nlohmann::json& changed = member(doc, "", "settings_changed", path);
  if (!changed.is_array()) fail(path, "settings_changed", "expected an array, got " + aux::json_type_name(changed));
  for (std::size_t i = 0; i < changed.size(); ++i) {
    if (!changed[i].is_string())
      fail(path, aux::json_element_path("settings_changed", i),
           "expected a string, got " + aux::json_type_name(changed[i]));
    base.settings_changed.push_back(changed[i].get<std::string>());
  }
  const nlohmann::json& duration = member(doc, "", "duration_s", path);
  if (!duration.is_number() || !(duration.get<double>() > 0.0) || !std::isfinite(duration.get<double>()))
    fail(path, "duration_s",
         "expected a number > 0, got " +
             (duration.is_number() ? aux::json_text(duration) : aux::json_type_name(duration)));
  base.duration_s = duration.get<double>();
  const nlohmann::json& members = member(doc, "", "members", path);
  if (!members.is_array() || members.empty())
    fail(path, "members", "expected a non-empty array, got " + aux::json_type_name(members));
  for (std::size_t i = 0; i < members.size(); ++i) {
    const std::string at = aux::json_element_path("members", i);
    const nlohmann::json& seed = member(members[i], at, "seed", path);
    if (!seed.is_number_unsigned())
      fail(path, aux::json_member_path(at, "seed"),
           "expected an integer >= 0, got " + (seed.is_number() ? aux::json_text(seed) : aux::json_type_name(seed)));
    BaselineRow r;
    r.seed = seed.get<std::uint64_t>();
    const std::string audit = aux::json_member_path(at, "audit");
    const nlohmann::json& a = member(members[i], at, "audit", path);
    r.degraded_share = figure(a, audit, {"visible_degradations", "share"}, path);
    r.triangle_ratio = figure(a, audit, {"triangles_in_view", "drawn_over_oracle"}, path);
    r.switches_per_object_s = figure(a, audit, {"switches", "outside_suppression", "per_object_second"}, path);
    if (!base.rows.empty() && r.seed <= base.rows.back().seed)
      fail(path, aux::json_member_path(at, "seed"),
           "seeds must increase (" + std::to_string(r.seed) + " after " + std::to_string(base.rows.back().seed) + ")");
    base.rows.push_back(r);
  }
  return base;
}

void check_same_run(const FamilyBaseline& base, std::uint64_t first, int count, double duration_s,
                    const std::string& recording) {
  std::string base_recording;
  for (const std::string& c : base.settings_changed)
    if (c.starts_with("recording=")) base_recording = c;
  if (base_recording != recording) {
    const auto eyes = [](const std::string& r) { return r.empty() ? std::string("the family's own") : r.substr(10); };
    throw UsageError("--against: " + base.source + ": its eyes were " + eyes(base_recording) + ", this run's " +
                     eyes(recording) + ": the same seeds would be other scenarios");
  }
  if (base.duration_s != duration_s)
    throw UsageError("--against: " + base.source + ": its scenarios last " + fmt("%g", base.duration_s) +
                     " s, this run's " + fmt("%g", duration_s) + " s: the same seeds would be other scenarios");
  const auto range = [](std::uint64_t a, std::uint64_t b, std::size_t n) {
    return std::to_string(a) + "-" + std::to_string(b) + " (" + std::to_string(n) + " seeds)";
  };
  const std::uint64_t last = first + static_cast<std::uint64_t>(count) - 1;
  bool same = base.rows.size() == static_cast<std::size_t>(count);
  for (std::size_t i = 0; same && i < base.rows.size(); ++i) same = base.rows[i].seed == first + i;
  if (!same)
    throw UsageError("--against: " + base.source + ": its seeds are " +
                     (base.rows.empty() ? std::string("none")
                                        : range(base.rows.front().seed, base.rows.back().seed, base.rows.size())) +
                     ", this run's " + range(first, last, static_cast<std::size_t>(count)) +
                     ": compare runs of the same seeds");
}

std::string against_markdown(const std::vector<FamilyMember>& members, const FamilyBaseline& base) {
  std::ostringstream md;
  md << "\n## Against `" << base.source << "`\n\nThat run's settings: ";
  if (base.settings_changed.empty()) md << "the defaults";
  for (std::size_t i = 0; i < base.settings_changed.size(); ++i)
    md << (i ? " " : "") << "`" << base.settings_changed[i] << "`";
  md << ".\n\n| target | within before | within now | entered | left |\n|---|---:|---:|---|---|\n";
  const std::vector<Standing> s = standings(members, base);
  for (std::size_t k = 0; k <= kTargetCount; ++k) {
    md << "| " << (k < kTargetCount ? kTargets[k].name : "all three") << " | " << s[k].before << " | " << s[k].now
       << " | " << seed_list(s[k].entered) << " | " << seed_list(s[k].left) << " |\n";
  }
  md << "\n| figure | median before -> now | 90th percentile | worst (seed) |\n|---|---:|---:|---:|\n";
  for (const Target& t : kTargets) {
    const Spread b = spread_before(base, t.before, t.limit);
    const Spread n = spread(members, t.now, t.limit);
    const auto pair = [&](double x, double y) {
      return fmt(t.format, x * t.scale) + " -> " + fmt(t.format, y * t.scale);
    };
    md << "| " << t.name << " | " << pair(b.median, n.median) << " | " << pair(b.p90, n.p90) << " | "
       << fmt(t.format, b.worst * t.scale) << " (" << b.worst_seed << ") -> " << fmt(t.format, n.worst * t.scale)
       << " (" << n.worst_seed << ") |\n";
  }
  md << "\nSeeds whose standing changed (a target entered or left):\n\n"
        "| seed | degraded before -> now | triangles / oracle | switches |\n|---:|---:|---:|---:|\n";
  int changed = 0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    bool moved = false;
    for (const Target& t : kTargets)
      moved = moved || ((base.rows[i].*t.before <= t.limit) != (t.now(members[i].audit) <= t.limit));
    if (!moved) continue;
    ++changed;
    md << "| " << members[i].seed;
    for (const Target& t : kTargets)
      md << " | " << fmt(t.format, base.rows[i].*t.before * t.scale) << " -> "
         << fmt(t.format, t.now(members[i].audit) * t.scale);
    md << " |\n";
  }
  if (changed == 0) md << "| (none) | | | |\n";
  return md.str();
}

nlohmann::json against_json(const std::vector<FamilyMember>& members, const FamilyBaseline& base) {
  nlohmann::json j;
  j["source"] = base.source;
  j["settings_changed"] = base.settings_changed;
  const std::vector<Standing> s = standings(members, base);
  nlohmann::json targets = nlohmann::json::object();
  for (std::size_t k = 0; k <= kTargetCount; ++k) {
    nlohmann::json e = {
        {"within_before", s[k].before}, {"within_now", s[k].now}, {"entered", s[k].entered}, {"left", s[k].left}};
    if (k < kTargetCount) {
      const Spread b = spread_before(base, kTargets[k].before, kTargets[k].limit);
      e["before"] = {{"median", b.median}, {"p90", b.p90}, {"worst", b.worst}, {"worst_seed", b.worst_seed}};
    }
    targets[k < kTargetCount ? kTargets[k].name : "all three"] = e;
  }
  j["targets"] = targets;
  return j;
}

}  // namespace gazelod::cli
