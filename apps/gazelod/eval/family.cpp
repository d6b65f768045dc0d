// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/family.hpp"
#include "apps/gazelod/commands/out_folder.hpp"
#include "apps/gazelod/eval/family_against.hpp"
#include "apps/gazelod/eval/work.hpp"
#include "apps/gazelod/run/report.hpp"
#include "apps/gazelod/run/session.hpp"
#include "apps/gazelod/run/signals.hpp"
#include "auxiliary/atomic_file.hpp"
#include "auxiliary/time.hpp"
#include "sim/scenario_family.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <optional>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace gazelod::cli {

namespace {

double visible(const AuditSummary& a) {
  return a.visible_switches_fixation.per_object_s;
}
double oracle_own(const AuditSummary& a) {
  return a.oracle_switches_fixation.per_object_s;
}
double bound_policy(const AuditSummary& a) {
  return bound_ratio(a.bound_policy, a);
}
double bound_oracle(const AuditSummary& a) {
  return bound_ratio(a.bound_oracle, a);
}
double bound_policy_at_target(const AuditSummary& a) {
  return bound_ratio(a.bound_policy_at_target, a);
}
double bound_oracle_at_target(const AuditSummary& a) {
  return bound_ratio(a.bound_oracle_at_target, a);
}

struct Metric {
  const char* name;
  double (*value)(const AuditSummary&);
  double target;  // <= 0: none
  double scale;   // printed value = value * scale
  const char* unit;
};
constexpr Metric kMetrics[] = {
    {"visible degradations (fixation object-frames)", degraded_figure, kTargetDegradedShare, 100.0, "%"},
    {"triangles drawn / oracle", triangle_figure, kTargetTriangleRatio, 1.0, ""},
    {"switches per object-second outside suppression", switch_figure, kTargetSwitchesPerObjectS, 1.0, ""},
    {"  of which visible (the change above threshold)", visible, 0.0, 1.0, ""},
    {"  the oracle's own (what the true gaze requires)", oracle_own, 0.0, 1.0, ""},
};
// With --bound: what a policy that knew each run's future could have drawn at the same switches.
constexpr Metric kBoundMetrics[] = {
    {"triangles / oracle for a better policy: the future known, the same switches", bound_policy, kTargetTriangleRatio,
     1.0, ""},
    {"  the same with a perfect tracker (under the oracle's levels)", bound_oracle, kTargetTriangleRatio, 1.0, ""},
    {"triangles / oracle for a better policy at the switch target's pop rate", bound_policy_at_target,
     kTargetTriangleRatio, 1.0, ""},
    {"  the same with a perfect tracker", bound_oracle_at_target, kTargetTriangleRatio, 1.0, ""},
};

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

std::vector<FamilyMember> run_family(std::uint64_t first, int count, double duration_s, const FamilySettings& settings,
                                     const std::string& work_dir,
                                     const std::function<void(const std::string&)>& progress) {
  const std::string why = lod::validate_switch_config(settings.switching);
  if (!why.empty()) throw UsageError("--set: " + why);
  // Each setting is range-checked as it is given; the conditioner's own rules are checked on
  // the result, before any seed runs (a refused setting, never a default in its place).
  if (const std::string bad = gaze::validate_conditioner_config(settings.conditioning); !bad.empty())
    throw UsageError("--set: conditioner." + bad);
  WorkDir work(work_dir, "gazelod-eval-family");
  // Ctrl-C or SIGTERM stops between seeds, or the seed's run at its next frame: no report (a
  // family cut short is no distribution), the work folder removed as the stack unwinds.
  StopOnSignal stop;
  const auto stop_if_asked = [&](int done) {
    if (const int sig = stop.requested()) {
      stop.acted_on();
      throw UsageError("stopped by " + std::string(StopOnSignal::name(sig)) + " after " + std::to_string(done) +
                           " of " + std::to_string(count) + " seeds; no report written",
                       128 + sig);
    }
  };
  std::vector<FamilyMember> members;
  for (int k = 0; k < count; ++k) {
    stop_if_asked(k);
    const std::uint64_t seed = first + static_cast<std::uint64_t>(k);
    sim::FamilyScenario f = sim::family_scenario(seed, duration_s, settings.ideal, settings.tracker_offset_deg);
    if (settings.recording) {
      f.json = with_recording(f.json, *settings.recording);
      f.summary = recording_summary(f.summary, *settings.recording);
    }
    const std::filesystem::path dir = work.path() / ("seed-" + std::to_string(seed));
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    try {
      aux::write_file_atomic((dir / "family.json").string(), f.json);
    } catch (const aux::WriteError& e) {
      throw UsageError(std::string("--work: ") + e.what(), 1);
    }
    RunOptions o;
    o.scenario_path = (dir / "family.json").string();
    o.out_dir = dir;
    o.render = false;
    o.quiet = true;
    o.write_reports = false;
    o.switching = settings.switching;
    o.conditioning = settings.conditioning;
    o.offline_bound = settings.offline_bound;
    o.criteria = settings.criteria;
    RunSummary summary;
    o.result = &summary;
    std::ostringstream out, err;
    const int rc = run_session(o, Io{out, err});
    stop_if_asked(k);
    if (rc != 0) throw UsageError("family seed " + std::to_string(seed) + ": the run failed: " + err.str(), rc);
    if (!summary.audit.available)
      throw UsageError("family seed " + std::to_string(seed) + ": no audit: " + summary.audit.reason, 1);
    // Zeros over nothing would read as a perfect score (a recording that is all blinks).
    if (summary.audit.object_frames == 0)
      throw UsageError("family seed " + std::to_string(seed) + ": no object in view outside suppression", 1);
    const AuditSummary& b = summary.audit;
    if (settings.offline_bound && !(b.bound_policy.available && b.bound_oracle.available &&
                                    b.bound_policy_at_target.available && b.bound_oracle_at_target.available))
      throw UsageError("family seed " + std::to_string(seed) + ": no offline optimum: " + b.bound_policy.reason +
                           b.bound_oracle.reason + b.bound_policy_at_target.reason + b.bound_oracle_at_target.reason,
                       1);
    members.push_back({seed, f.summary, summary.audit});
    const AuditSummary& a = summary.audit;
    progress("[" + std::to_string(k + 1) + "/" + std::to_string(count) + "] seed " + std::to_string(seed) + " (" +
             f.summary + "): degraded " + fmt("%.2f%%", 100.0 * a.degraded_share) + ", triangles/oracle " +
             fmt("%.2f", a.triangle_ratio) + ", switches " + fmt("%.2f", a.switches_fixation.per_object_s) +
             " (oracle " + fmt("%.2f", a.oracle_switches_fixation.per_object_s) + ")");
  }
  return members;
}

std::string family_markdown(const std::vector<FamilyMember>& members, const FamilySettings& settings,
                            const std::string& command, double duration_s) {
  std::ostringstream md;
  md << "<!-- written by: " << command << " -->\n\n";
  md << "Seeds " << (members.empty() ? 0 : members.front().seed) << " to "
     << (members.empty() ? 0 : members.back().seed) << " (" << members.size() << " scenarios of "
     << fmt("%g", duration_s) << " s)";
  if (!settings.changed.empty()) {
    md << "; settings changed:";
    for (const std::string& c : settings.changed) md << " `" << c << "`";
  }
  md << ".\n\n| figure | median | 90th percentile | worst (seed) | target | within target "
        "|\n|---|---:|---:|---:|---:|---:|\n";
  std::vector<Metric> metrics(std::begin(kMetrics), std::end(kMetrics));
  if (settings.offline_bound) metrics.insert(metrics.end(), std::begin(kBoundMetrics), std::end(kBoundMetrics));
  for (const Metric& m : metrics) {
    const Spread s = spread(members, m.value, m.target > 0 ? m.target : 1e300);
    md << "| " << m.name << " | " << fmt("%.3f", s.median * m.scale) << m.unit << " | " << fmt("%.3f", s.p90 * m.scale)
       << m.unit << " | " << fmt("%.3f", s.worst * m.scale) << m.unit << " (" << s.worst_seed << ") | ";
    if (m.target > 0)
      md << "<= " << fmt("%g", m.target * m.scale) << m.unit << " | " << s.within_target << " / " << members.size();
    else
      md << " | ";
    md << " |\n";
  }
  md << "\nWithin all three targets at once: " << within_all_targets(members) << " / " << members.size() << ".\n";
  const bool bound = settings.offline_bound;
  if (bound)
    md << "With the future known, at the switch target's pop rate and never coarser than the oracle: "
       << within_all_targets_known(members) << " / " << members.size() << " (a better policy), "
       << within_all_targets_known(members, true) << " / " << members.size() << " (a perfect tracker too).\n";
  md << "\n| seed | scenario | degraded | triangles / oracle"
     << (bound ? " (the future known, the same switches: a better policy; a perfect tracker; at the switch "
                 "target: a better policy)"
               : "")
     << " | switches (visible; oracle's own) |\n|---:|---|---:|---:|---:|\n";
  for (const FamilyMember& m : members) {
    const AuditSummary& a = m.audit;
    md << "| " << m.seed << " | " << m.summary << " | " << fmt("%.2f%%", 100.0 * a.degraded_share) << " | "
       << fmt("%.2f", a.triangle_ratio);
    if (bound)
      md << " (" << fmt("%.2f", bound_policy(a)) << "; " << fmt("%.2f", bound_oracle(a)) << "; "
         << fmt("%.2f", bound_policy_at_target(a)) << ")";
    md << " | " << fmt("%.2f", a.switches_fixation.per_object_s) << " ("
       << fmt("%.2f", a.visible_switches_fixation.per_object_s) << "; "
       << fmt("%.2f", a.oracle_switches_fixation.per_object_s) << ") |\n";
  }
  return md.str();
}

std::string family_json(const std::vector<FamilyMember>& members, const FamilySettings& settings, double duration_s) {
  nlohmann::json j;
  j["settings_changed"] = settings.changed;
  j["duration_s"] = duration_s;
  nlohmann::json spreads = nlohmann::json::object();
  std::vector<Metric> metrics(std::begin(kMetrics), std::end(kMetrics));
  if (settings.offline_bound) metrics.insert(metrics.end(), std::begin(kBoundMetrics), std::end(kBoundMetrics));
  for (const Metric& m : metrics) {
    const Spread s = spread(members, m.value, m.target > 0 ? m.target : 1e300);
    nlohmann::json e = {{"median", s.median}, {"p90", s.p90}, {"worst", s.worst}, {"worst_seed", s.worst_seed}};
    if (m.target > 0) e["target"] = m.target, e["within_target"] = s.within_target;
    std::string key = m.name;
    spreads[key.substr(key.find_first_not_of(' '))] = e;
  }
  j["distribution"] = spreads;
  j["within_all_targets"] = within_all_targets(members);
  if (settings.offline_bound)
    j["within_all_targets_known_future"] = {{"better_policy", within_all_targets_known(members)},
                                            {"perfect_tracker", within_all_targets_known(members, true)}};
  j["members"] = nlohmann::json::array();
  for (const FamilyMember& m : members)
    j["members"].push_back({{"seed", m.seed}, {"scenario", m.summary}, {"audit", audit_json(m.audit)}});
  return aux::json_text(j, 2) + "\n";
}

namespace {

struct FamilyFlags {
  std::string out = "gazelod-eval-family";
  std::string work;
  std::string seeds = "2000-2099";
  double duration_s = 20.0;
  std::vector<std::string> set;
  std::string ideal;
  double tracker_offset_deg = 0.0;
  bool list = false;
  bool bound = false;
  std::string against;
  bool against_given = false;  // --against, even empty (refused then, not ignored)
  std::string recording;
  bool recording_given = false;  // --recording, even empty (refused then)
  std::string recording_format = "auto";
  std::string criteria;  // "": all, or size,eccentricity with a recording
};

// "A-B" (inclusive) or "A".
std::pair<std::uint64_t, int> seed_range(const std::string& text) {
  const std::size_t dash = text.find('-');
  const auto parse = [&](const std::string& t) {
    if (t.empty() || t.size() > 12 || t.find_first_not_of("0123456789") != std::string::npos)
      throw UsageError("--seeds: expected A-B or A (non-negative integers), got '" + text + "'");
    return std::stoull(t);
  };
  const std::uint64_t a = parse(text.substr(0, dash));
  const std::uint64_t b = dash == std::string::npos ? a : parse(text.substr(dash + 1));
  if (b < a) throw UsageError("--seeds: the range ends before it starts: '" + text + "'");
  if (b - a >= 10000) throw UsageError("--seeds: at most 10000 seeds at a time, got '" + text + "'");
  return {a, static_cast<int>(b - a + 1)};
}

int run_eval_family(const FamilyFlags& flags, Io io) {
  FamilySettings settings;
  for (const std::string& s : flags.set) apply_setting(s, settings);
  if (!sim::parse_ideal_tracker(flags.ideal, settings.ideal))
    throw UsageError(std::string("--ideal: expected ") + sim::kIdealTrackerNames + ", got '" + flags.ideal + "'");
  if (settings.ideal.any()) settings.changed.push_back("ideal=" + flags.ideal);
  settings.tracker_offset_deg = flags.tracker_offset_deg;
  settings.offline_bound = flags.bound;
  if (flags.tracker_offset_deg > 0.0)
    settings.changed.push_back("tracker_offset_deg=" + fmt("%g", flags.tracker_offset_deg));
  if (flags.list) {
    io.out << settings_list(settings);
    return 0;
  }
  const auto [first, count] = seed_range(flags.seeds);
  apply_recording_flags(flags.recording_given ? &flags.recording : nullptr, flags.recording_format, flags.criteria,
                        settings);
  const double duration_s =
      settings.recording ? recording_duration_s(flags.duration_s, *settings.recording) : flags.duration_s;
  // An earlier run to compare with: read and checked before any seed runs.
  std::optional<FamilyBaseline> base;
  if (flags.against_given) {
    base = read_family_baseline(flags.against);
    check_same_run(*base, first, count, duration_s, settings.recording ? "recording=" + settings.recording->path : "");
  }
  const auto started = std::chrono::steady_clock::now();
  const auto progress = [&](const std::string& line) {
    const auto s = std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - started).count();
    io.err << "gazelod eval family [" << s << " s]: " << line << "\n" << std::flush;
  };
  // --out first, held against another gazelod writing there: a folder that cannot be made
  // would otherwise be found after every seed ran.
  const OutFolder out_folder = hold_out_folder(flags.out, "eval family", io.err);
  const std::vector<FamilyMember> members = run_family(first, count, duration_s, settings, flags.work, progress);
  std::string command = "gazelod eval family --seeds " + flags.seeds;
  if (flags.duration_s != 20.0) command += " --duration " + fmt("%g", flags.duration_s);
  for (const std::string& s : flags.set) command += " --set " + s;
  if (settings.ideal.any()) command += " --ideal " + flags.ideal;
  if (flags.tracker_offset_deg > 0.0) command += " --tracker-offset " + fmt("%g", flags.tracker_offset_deg);
  if (flags.bound) command += " --bound";
  if (flags.recording_given) command += " --recording " + flags.recording;
  if (flags.recording_format != "auto") command += " --recording-format " + flags.recording_format;
  if (!flags.criteria.empty()) command += " --criteria " + flags.criteria;
  if (base) command += " --against " + flags.against;
  std::string md = family_markdown(members, settings, command, duration_s);
  std::string json = family_json(members, settings, duration_s);
  if (base) {
    md += against_markdown(members, *base);
    nlohmann::json j = nlohmann::json::parse(json);
    j["against"] = against_json(members, *base);
    json = aux::json_text(j, 2) + "\n";
  }
  write_report(flags.out, {{"family.md", md}, {"family.json", json}});
  io.out << md << "\nfiles: " << (std::filesystem::path(flags.out) / "family.md").string() << ", family.json\n";
  return 0;
}

}  // namespace

EvalSubcommand add_eval_family(CLI::App& eval) {
  auto flags = std::make_shared<FamilyFlags>();
  CLI::App* app = eval.add_subcommand(
      "family", "The visibility audit's distribution over a seeded family of random, plausible scenarios");
  app->add_option("--seeds", flags->seeds,
                  "Seed range A-B (default 2000-2099, the held-out seeds; tuning used 1000-1039)");
  app->add_option("--duration", flags->duration_s, "Seconds per scenario (default 20)")->check(CLI::Range(1.0, 600.0));
  app->add_option("--set", flags->set, "NAME=VALUE: a switch-policy or conditioner setting (repeatable)");
  app->add_option("--ideal", flags->ideal,
                  "What-if: each seed with parts of its tracker made ideal, to measure what they cost: latency (0 "
                  "ms), noise (0 deg), rate (1000 Hz), comma-separated, or all");
  app->add_option("--tracker-offset", flags->tracker_offset_deg,
                  "What-if: each seed's tracker off by this many degrees (a calibration error, in a direction drawn "
                  "per seed), to measure what the plugin's accuracy margin covers")
      ->check(CLI::Range(0.0, 30.0));
  app->add_flag("--bound", flags->bound,
                "Also each seed's offline optimum: the fewest triangles at the policy's own switches with the run's "
                "future known, never coarser than the plugin's perceptual level nor the oracle's (a better policy), "
                "and than the oracle's alone (a perfect tracker too; run/offline_bound.hpp); and both again at the "
                "switch target's pop rate, with the seeds where they meet all three targets");
  app->add_option("--recording", flags->recording,
                  "A gaze trace (any layout `gazelod trace` reads) replayed as every seed's true eye, and head when "
                  "it has poses, under the seeds' own displays, trackers and fields (docs/evaluation.md, \"Real "
                  "eyes\")");
  app->add_option("--recording-format", flags->recording_format,
                  "The recording's layout: auto (default: from its header) or any `gazelod trace --format`");
  app->add_option("--criteria", flags->criteria,
                  "all, none, or a comma list of size,eccentricity,velocity (default: all; with --recording "
                  "size,eccentricity, since a recording's noise is no eye's velocity)");
  app->add_option("--against", flags->against,
                  "An earlier run's family.json of the same seeds: which seeds entered or left each target, and "
                  "how each figure's distribution moved");
  app->add_flag("--list-settings", flags->list, "Print the settings --set understands, with their values");
  app->add_option("--out", flags->out, "Folder for family.md and family.json");
  app->add_option("--work", flags->work, "Folder for each seed's scenario (default: a temporary one, removed)");
  return {app, [flags, app](Io io) {
            flags->against_given = app->count("--against") > 0;
            flags->recording_given = app->count("--recording") > 0;
            return run_eval_family(*flags, io);
          }};
}

}  // namespace gazelod::cli
