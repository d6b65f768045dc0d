// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/compare/runs.hpp"

#include "lod/acuity.hpp"
#include "lod/display.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace gazelod::cli {
namespace {

const nlohmann::json& at(const nlohmann::json& j, const std::string& key, const std::string& path,
                         const std::string& source) {
  if (!j.is_object() || !j.contains(key))
    throw UsageError(source + ": " + path + key + ": missing (was it written by this gazelod?)", 1);
  return j.at(key);
}

double number(const nlohmann::json& j, const std::string& key, const std::string& path, const std::string& source) {
  const nlohmann::json& v = at(j, key, path, source);
  if (!v.is_number()) throw UsageError(source + ": " + path + key + ": must be a number", 1);
  return v.get<double>();
}

SetResult set_from(const nlohmann::json& j, const std::string& path, const std::string& source) {
  SetResult r;
  const double t = number(j, "triangles", path, source);
  if (t < 0.0) throw UsageError(source + ": " + path + "triangles: negative", 1);
  r.triangles = static_cast<std::uint64_t>(t);
  r.average_lod = number(j, "average_lod", path, source);
  return r;
}

double ratio(double num, double den) {
  return den > 0.0 ? num / den : 0.0;
}

std::int64_t count(const nlohmann::json& j, const std::string& key, const std::string& path,
                   const std::string& source) {
  const double v = number(j, key, path, source);
  if (v < 0.0) throw UsageError(source + ": " + path + key + ": negative", 1);
  return static_cast<std::int64_t>(v);
}

SwitchRate rate_from(const nlohmann::json& j, const std::string& path, const std::string& source) {
  SwitchRate r;
  r.switches = count(j, "switches", path, source);
  r.object_s = number(j, "object_seconds", path, source);
  r.per_object_s = number(j, "per_object_second", path, source);
  return r;
}

// summary.json's "audit" (run/audit.cpp's audit_json) back into its figures.
AuditSummary audit_from(const nlohmann::json& summary, const std::string& source) {
  AuditSummary a;
  if (!summary.contains("audit")) {
    a.reason = "not in the run's summary";
    return a;
  }
  const nlohmann::json& j = summary.at("audit");
  const nlohmann::json& available = at(j, "available", "audit.", source);
  if (!available.is_boolean()) throw UsageError(source + ": audit.available: must be true or false", 1);
  if (!available.get<bool>()) {
    const nlohmann::json& reason = at(j, "reason", "audit.", source);
    a.reason = reason.is_string() ? reason.get<std::string>() : "unavailable";
    return a;
  }
  a.available = true;
  a.frames = count(j, "frames", "audit.", source);
  const nlohmann::json& w = at(j, "suppression_window", "audit.", source);
  a.after_saccade_ms = number(w, "after_saccade_ms", "audit.suppression_window.", source);
  a.suppressed_frames = count(w, "frames", "audit.suppression_window.", source);
  const std::string vd = "audit.visible_degradations.";
  const nlohmann::json& v = at(j, "visible_degradations", "audit.", source);
  a.object_frames = count(v, "object_frames", vd, source);
  a.degraded = count(v, "degraded", vd, source);
  a.degraded_share = number(v, "share", vd, source);
  a.excess_mean = number(v, "excess_levels_mean", vd, source);
  a.excess_max = static_cast<std::uint32_t>(count(v, "excess_levels_max", vd, source));
  const nlohmann::json& sd = at(j, "suppressed_degradations", "audit.", source);
  a.object_frames_suppressed = count(sd, "object_frames", "audit.suppressed_degradations.", source);
  a.degraded_suppressed = count(sd, "degraded", "audit.suppressed_degradations.", source);
  const nlohmann::json& t = at(j, "triangles_in_view", "audit.", source);
  a.drawn_triangles = static_cast<std::uint64_t>(count(t, "drawn", "audit.triangles_in_view.", source));
  a.oracle_triangles = static_cast<std::uint64_t>(count(t, "oracle", "audit.triangles_in_view.", source));
  a.triangle_ratio = number(t, "drawn_over_oracle", "audit.triangles_in_view.", source);
  const nlohmann::json& sw = at(j, "switches", "audit.", source);
  a.switches_fixation = rate_from(at(sw, "outside_suppression", "audit.switches.", source),
                                  "audit.switches.outside_suppression.", source);
  a.switches_suppressed =
      rate_from(at(sw, "inside_suppression", "audit.switches.", source), "audit.switches.inside_suppression.", source);
  const nlohmann::json& p = at(j, "pursuit", "audit.", source);
  a.pursuit_frames = count(p, "frames", "audit.pursuit.", source);
  a.pursuit_degraded = count(p, "degraded", "audit.pursuit.", source);
  a.pursuit_degraded_share = number(p, "share", "audit.pursuit.", source);
  // Summaries from before the visible / oracle switch counts and the breakdown have none.
  if (sw.contains("visible_outside_suppression"))
    a.visible_switches_fixation =
        rate_from(sw.at("visible_outside_suppression"), "audit.switches.visible_outside_suppression.", source);
  if (sw.contains("oracle_outside_suppression"))
    a.oracle_switches_fixation =
        rate_from(sw.at("oracle_outside_suppression"), "audit.switches.oracle_outside_suppression.", source);
  if (j.contains("breakdown")) {
    try {
      a.breakdown = breakdown_from_json(j.at("breakdown"));
    } catch (const std::invalid_argument& e) {
      throw UsageError(source + ": audit.breakdown." + e.what(), 1);
    }
  }
  return a;
}

}  // namespace

void check_hmd(const std::string& hmd) {
  if (lod::find_display_preset(hmd) == nullptr)
    throw UsageError("--hmd: unknown display preset '" + hmd + "' (see gazelod hmds)");
}

HmdComparison comparison_from_summary(const std::string& hmd, const nlohmann::json& summary,
                                      const std::string& source) {
  check_hmd(hmd);
  HmdComparison c;
  c.hmd = hmd;
  const lod::DisplaySpec& display = *lod::find_display_preset(hmd);
  c.xi_cpd = lod::xi_cpd(display);
  c.eccentricity_threshold_deg = lod::eccentricity_threshold_deg(c.xi_cpd);
  c.velocity_threshold_dps = lod::velocity_threshold_dps(c.xi_cpd);
  c.frames = static_cast<std::int64_t>(number(summary, "frames", "", source));
  const nlohmann::json& criteria_json = at(summary, "criteria", "", source);
  if (!criteria_json.is_string()) throw UsageError(source + ": criteria: must be a string", 1);
  const std::string criteria = criteria_json.get<std::string>();
  if (criteria != "size,eccentricity,velocity")
    throw UsageError(source + ": criteria: the run must use every criterion, got '" + criteria + "'", 1);
  const nlohmann::json& sets = at(summary, "criteria_sets", "", source);
  for (std::size_t i = 0; i + 1 < kCriteriaSets.size(); ++i)
    c.sets[i] = set_from(at(sets, kCriteriaSets[i], "criteria_sets.", source),
                         std::string("criteria_sets.") + kCriteriaSets[i] + ".", source);
  c.sets.back() = set_from(at(sets, "drawn", "criteria_sets.", source), "criteria_sets.drawn.", source);
  c.lod_map = set_from(at(summary, "lod_map", "", source), "lod_map.", source);

  const double none = static_cast<double>(c.sets[0].triangles);
  const double all = static_cast<double>(c.sets[4].triangles);
  const double reduction = none - all;
  c.share_size = ratio(none - static_cast<double>(c.sets[1].triangles), reduction);
  c.share_eccentricity = ratio(static_cast<double>(c.sets[3].triangles) - all, reduction);
  c.share_velocity = ratio(static_cast<double>(c.sets[2].triangles) - all, reduction);
  c.share_interaction = reduction > 0.0 ? 1.0 - c.share_size - c.share_eccentricity - c.share_velocity : 0.0;
  c.audit = audit_from(summary, source);
  return c;
}

HmdComparison run_comparison(const std::string& hmd, const CompareOptions& o) {
  check_hmd(hmd);
  const std::filesystem::path dir = o.out_dir / hmd;
  std::vector<std::string> args{"run", "--hmd", hmd, "--criteria", "all", "--out", dir.string(), "--quiet"};
  if (!o.scenario_path.empty()) args.insert(args.end(), {"--scenario", o.scenario_path});
  if (o.frames > 0) args.insert(args.end(), {"--frames", std::to_string(o.frames)});
  if (!o.render) args.push_back("--no-render");
  std::ostringstream out, err;
  const int rc = run(args, out, err);
  if (rc != 0) {
    std::string msg = err.str();
    while (!msg.empty() && msg.back() == '\n') msg.pop_back();
    throw UsageError("run for --hmd " + hmd + " failed (exit " + std::to_string(rc) + "): " + msg, rc);
  }
  const auto path = dir / "summary.json";
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read " + path.string(), 1);
  nlohmann::json summary;
  try {
    summary = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(path.string() + ": " + e.what(), 1);
  }
  return comparison_from_summary(hmd, summary, path.string());
}

}  // namespace gazelod::cli
