// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/audit.hpp"

#include "apps/gazelod/run/in_view.hpp"
#include "auxiliary/time.hpp"
#include "auxiliary/angles.hpp"
#include "lod/select.hpp"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gazelod::cli {
namespace {

double ratio(double num, double den) {
  return den > 0.0 ? num / den : 0.0;
}

std::uint64_t triangles_at(const std::vector<lod::LodLevel>& chain, std::uint8_t level) {
  if (chain.empty()) return 0;
  return chain[std::min<std::size_t>(level, chain.size() - 1)].triangles;
}

nlohmann::json bound_point_json(const OfflinePoint& p, const AuditSummary& s) {
  if (!p.available) return {{"available", false}, {"reason", p.reason}};
  const double object_s = s.switches_fixation.object_s;
  return {{"available", true},
          {"triangles", p.triangles},
          {"over_oracle", ratio(static_cast<double>(p.triangles), static_cast<double>(s.oracle_triangles))},
          // No sequence within the switches draws fewer than this (the exact optimum lies between).
          {"triangles_lower_bound", p.lower_triangles},
          {"over_oracle_lower_bound", ratio(p.lower_triangles, static_cast<double>(s.oracle_triangles))},
          {"switches", p.switches},
          {"per_object_s", ratio(static_cast<double>(p.switches), object_s)},
          {"degraded", p.degraded},
          {"degraded_share", ratio(static_cast<double>(p.degraded), static_cast<double>(s.object_frames))},
          {"price_triangles", p.price_triangles}};
}

// summary.json's "offline_optimum" (run/offline_bound.hpp): null unless asked for.
nlohmann::json bound_json(const AuditSummary& s) {
  if (s.bound_max_switches < 0) return nullptr;
  nlohmann::json j = {{"max_switches", s.bound_max_switches},
                      {"better_policy", bound_point_json(s.bound_policy, s)},
                      {"perfect_tracker", bound_point_json(s.bound_oracle, s)}};
  if (s.bound_target_switches >= 0)
    j["at_switch_target"] = {{"switches_per_object_s", kTargetSwitchesPerObjectS},
                             {"max_switches", s.bound_target_switches},
                             {"better_policy", bound_point_json(s.bound_policy_at_target, s)},
                             {"perfect_tracker", bound_point_json(s.bound_oracle_at_target, s)}};
  return j;
}

void add_rate(SwitchRate& r, const AuditFrame& f) {
  r.switches += f.switches;
  r.object_s += f.object_s;
}

nlohmann::json rate_json(const SwitchRate& r) {
  return {{"switches", r.switches}, {"object_seconds", r.object_s}, {"per_object_second", r.per_object_s}};
}

}  // namespace

bool in_suppression(const sim::EyeTruth& truth, std::int64_t t_ns, std::int64_t after_saccade_ns) {
  if (truth.in_saccade || truth.in_blink) return true;
  if (truth.last_saccade_end_ns == INT64_MIN || t_ns < truth.last_saccade_end_ns) return false;
  return t_ns - truth.last_saccade_end_ns < after_saccade_ns;
}

AuditFrame audit_frame(const AuditFrameInput& in) {
  AuditFrame f;
  f.available = true;
  f.suppressed = in.suppressed;
  f.pursuit = in.pursuit_object >= 0;
  if (in.chains == nullptr) return f;
  const std::size_t n = std::min({in.drawn.size(), in.oracle.size(), in.in_view.size(), in.chains->size()});
  for (std::size_t i = 0; i < n; ++i) {
    if (!in.in_view[i]) continue;
    ++f.in_view;
    const std::vector<lod::LodLevel>& chain = (*in.chains)[i];
    const std::uint8_t d = in.drawn[i], o = in.oracle[i];
    f.drawn_triangles += triangles_at(chain, d);
    f.oracle_triangles += triangles_at(chain, o);
    if (d > o) {
      ++f.degraded;
      const std::uint32_t excess = static_cast<std::uint32_t>(d - o);
      f.excess_levels += excess;
      f.excess_max = std::max(f.excess_max, excess);
    }
    if (i < in.previous.size() && in.previous[i] != d) {
      ++f.switches;
      if (switch_visible(in.previous[i], d, o)) ++f.visible_switches;
    }
    if (i < in.previous_oracle.size() && in.previous_oracle[i] != o) ++f.oracle_switches;
    if (in.pursuit_object >= 0 && i == static_cast<std::size_t>(in.pursuit_object)) f.pursued = d > o ? 1 : 0;
  }
  f.object_s = static_cast<double>(f.in_view) * std::max(0.0, in.frame_s);
  return f;
}

AuditSummary summarize_audit(std::span<const AuditFrame> frames, double after_saccade_ms) {
  AuditSummary s;
  s.after_saccade_ms = after_saccade_ms;
  std::uint64_t excess_sum = 0;
  for (const AuditFrame& f : frames) {
    if (!f.available) continue;
    s.available = true;
    ++s.frames;
    s.drawn_triangles += f.drawn_triangles;
    s.oracle_triangles += f.oracle_triangles;
    if (f.suppressed) {
      ++s.suppressed_frames;
      s.object_frames_suppressed += f.in_view;
      s.degraded_suppressed += f.degraded;
      add_rate(s.switches_suppressed, f);
    } else {
      s.object_frames += f.in_view;
      s.degraded += f.degraded;
      excess_sum += f.excess_levels;
      s.excess_max = std::max(s.excess_max, f.excess_max);
      add_rate(s.switches_fixation, f);
      s.visible_switches_fixation.switches += f.visible_switches;
      s.visible_switches_fixation.object_s += f.object_s;
      s.oracle_switches_fixation.switches += f.oracle_switches;
      s.oracle_switches_fixation.object_s += f.object_s;
    }
    if (f.pursued >= 0) {
      ++s.pursuit_frames;
      s.pursuit_degraded += f.pursued;
    }
  }
  s.degraded_share = ratio(static_cast<double>(s.degraded), static_cast<double>(s.object_frames));
  s.excess_mean = ratio(static_cast<double>(excess_sum), static_cast<double>(s.degraded));
  s.triangle_ratio = ratio(static_cast<double>(s.drawn_triangles), static_cast<double>(s.oracle_triangles));
  for (SwitchRate* r :
       {&s.switches_fixation, &s.switches_suppressed, &s.visible_switches_fixation, &s.oracle_switches_fixation})
    r->per_object_s = ratio(static_cast<double>(r->switches), r->object_s);
  s.pursuit_degraded_share = ratio(static_cast<double>(s.pursuit_degraded), static_cast<double>(s.pursuit_frames));
  return s;
}

nlohmann::json audit_json(const AuditSummary& s) {
  if (!s.available) return {{"available", false}, {"reason", s.reason}};
  return {
      {"available", true},
      {"oracle",
       "lod::select_lods at the simulator's true gaze, head and objects; tracker error 0; "
       "the run's xi and criteria"},
      {"frames", s.frames},
      {"suppression_window",
       {{"saccades", true},
        {"blinks", true},
        {"after_saccade_ms", s.after_saccade_ms},
        {"frames", s.suppressed_frames},
        {"share_of_frames", ratio(static_cast<double>(s.suppressed_frames), static_cast<double>(s.frames))}}},
      {"visible_degradations",
       {{"object_frames", s.object_frames},
        {"degraded", s.degraded},
        {"share", s.degraded_share},
        {"excess_levels_mean", s.excess_mean},
        {"excess_levels_max", s.excess_max}}},
      {"suppressed_degradations", {{"object_frames", s.object_frames_suppressed}, {"degraded", s.degraded_suppressed}}},
      {"triangles_in_view",
       {{"drawn", s.drawn_triangles}, {"oracle", s.oracle_triangles}, {"drawn_over_oracle", s.triangle_ratio}}},
      {"switches",
       {{"outside_suppression", rate_json(s.switches_fixation)},
        {"inside_suppression", rate_json(s.switches_suppressed)},
        {"visible_outside_suppression", rate_json(s.visible_switches_fixation)},
        {"oracle_outside_suppression", rate_json(s.oracle_switches_fixation)},
        {"targets_use", "outside_suppression"}}},
      {"breakdown", breakdown_json(s.breakdown)},
      {"offline_optimum", bound_json(s)},
      {"pursuit",
       {{"frames", s.pursuit_frames}, {"degraded", s.pursuit_degraded}, {"share", s.pursuit_degraded_share}}}};
}

void print_audit(const AuditSummary& s, std::ostream& out, bool breakdown) {
  if (!s.available) {
    out << "audit           unavailable (" << s.reason << ")\n";
    return;
  }
  char line[320];
  std::snprintf(line, sizeof line,
                "audit           oracle at the true gaze; suppression = saccades, blinks, %.0f ms after a saccade "
                "(%.1f%% of frames)\n",
                s.after_saccade_ms,
                100.0 * ratio(static_cast<double>(s.suppressed_frames), static_cast<double>(s.frames)));
  out << line;
  std::snprintf(line, sizeof line,
                "audit           visible degradations %.2f%% of %lld in-view object-frames outside suppression "
                "(excess mean %.2f levels, max %u)\n",
                100.0 * s.degraded_share, static_cast<long long>(s.object_frames), s.excess_mean, s.excess_max);
  out << line;
  std::snprintf(line, sizeof line, "audit           triangles in view drawn / oracle %.3f (%llu / %llu)\n",
                s.triangle_ratio, static_cast<unsigned long long>(s.drawn_triangles),
                static_cast<unsigned long long>(s.oracle_triangles));
  out << line;
  std::snprintf(line, sizeof line,
                "audit           LOD switches per object-second %.3f outside suppression (visible %.3f; the "
                "oracle's own %.3f), %.3f inside\n",
                s.switches_fixation.per_object_s, s.visible_switches_fixation.per_object_s,
                s.oracle_switches_fixation.per_object_s, s.switches_suppressed.per_object_s);
  out << line;
  if (s.pursuit_frames > 0)
    std::snprintf(line, sizeof line,
                  "audit           pursued object coarser than its oracle level in %.1f%% of %lld pursuit frames\n",
                  100.0 * s.pursuit_degraded_share, static_cast<long long>(s.pursuit_frames));
  else
    std::snprintf(line, sizeof line, "audit           no pursuit with its object in view\n");
  out << line;
  if (s.bound_max_switches >= 0) {
    if (s.bound_policy.available && s.bound_oracle.available)
      std::snprintf(line, sizeof line,
                    "offline         the future known, at most the policy's %lld switches: triangles / oracle %.3f "
                    "for a better switch policy, %.3f with a perfect tracker too\n",
                    static_cast<long long>(s.bound_max_switches),
                    ratio(static_cast<double>(s.bound_policy.triangles), static_cast<double>(s.oracle_triangles)),
                    ratio(static_cast<double>(s.bound_oracle.triangles), static_cast<double>(s.oracle_triangles)));
    else
      std::snprintf(line, sizeof line, "offline         no offline optimum (%s)\n",
                    (s.bound_policy.available ? s.bound_oracle : s.bound_policy).reason.c_str());
    out << line;
    if (s.bound_target_switches >= 0 && s.bound_policy_at_target.available && s.bound_oracle_at_target.available) {
      std::snprintf(
          line, sizeof line,
          "offline         at the switch target's %lld (%g per object-second): %.3f for a better switch "
          "policy, %.3f with a perfect tracker too\n",
          static_cast<long long>(s.bound_target_switches), kTargetSwitchesPerObjectS,
          ratio(static_cast<double>(s.bound_policy_at_target.triangles), static_cast<double>(s.oracle_triangles)),
          ratio(static_cast<double>(s.bound_oracle_at_target.triangles), static_cast<double>(s.oracle_triangles)));
      out << line;
    }
  }
  if (breakdown) print_breakdown(s.breakdown, out);
}

AuditOracle::AuditOracle(const sim::Scenario& scenario, const EnabledCriteria& criteria,
                         std::vector<std::size_t> objects, std::int64_t after_saccade_ns)
    : criteria_(criteria), after_saccade_ns_(after_saccade_ns) {
  if (objects.empty())
    for (std::size_t i = 0; i < scenario.objects.size(); ++i) objects.push_back(i);
  std::erase_if(objects, [&](std::size_t i) { return i >= scenario.objects.size(); });
  objects_ = std::move(objects);
  const std::size_t n = objects_.size();
  std::size_t levels = 0;
  for (std::size_t i : objects_) levels += scenario.objects[i].lods.size();
  store_.reserve(n, levels);
  for (std::size_t i : objects_) {
    const sim::SceneObject& o = scenario.objects[i];
    store_.add(o.position_m, o.radius_m, o.velocity_m_s, o.lods);
    radii_.push_back(o.radius_m);
  }
  fov_ = scenario.display.views[0].fov;
  for (auto* v : {&lod_, &limited_, &size_only_, &ecc_only_, &vel_only_, &in_view_}) v->assign(n, 0);
  ecc_deg_.assign(n, 0.0f);
  distance_m_.assign(n, 0.0f);
}

std::string AuditOracle::evaluate(sim::Simulator& simulator, std::int64_t t_ns, double xi_cpd) {
  constexpr std::int64_t kHalfStepNs = aux::ns_from_ms(1.0);  // central difference over t +- 1 ms
  const auto world_gaze = [&](std::int64_t t) {
    return simulator.head_at(t).orientation * simulator.true_gaze_at(t).direction;
  };
  const glm::dvec3 before = world_gaze(t_ns - kHalfStepNs), after = world_gaze(t_ns + kHalfStepNs);
  const glm::dvec3 axis = glm::cross(before, after);
  const double sin_angle = glm::length(axis);
  omega_ =
      sin_angle > 0.0
          ? axis / sin_angle * (std::atan2(sin_angle, glm::dot(before, after)) / aux::seconds_from_ns(2 * kHalfStepNs))
          : glm::dvec3(0.0);

  const sim::HeadState head = simulator.head_at(t_ns);
  truth_ = simulator.eye_truth_at(t_ns);
  suppressed_ = in_suppression(truth_, t_ns, after_saccade_ns_);
  const std::span<const sim::ObjectState> objects = simulator.objects_at(t_ns);
  for (std::size_t k = 0; k < objects_.size(); ++k) {
    if (objects_[k] >= objects.size()) continue;
    const sim::ObjectState& o = objects[objects_[k]];
    store_.set_motion(static_cast<std::uint32_t>(k), o.position_m, o.velocity_m_s);
    in_view_[k] = sphere_in_view(o.position_m, radii_[k], head.position_m, head.orientation, fov_) ? 1 : 0;
    distance_m_[k] = static_cast<float>(std::max(0.0, glm::length(o.position_m - head.position_m) - radii_[k]));
  }

  lod::Viewer v;
  v.eye_position_m = head.position_m;
  v.eye_velocity_m_s = head.linear_velocity_m_s;
  v.gaze_direction = head.orientation * simulator.true_gaze_at(t_ns).direction;
  v.head_angular_velocity_rad_s = head.angular_velocity_rad_s;
  v.gaze_angular_velocity_in_head_rad_s = omega_ - head.angular_velocity_rad_s;
  v.xi_cpd = xi_cpd > 0.0 ? xi_cpd : 60.0;
  v.tracker_error_deg = 0.0;
  v.use_size = criteria_.size;
  v.use_eccentricity = criteria_.eccentricity;
  v.use_velocity = criteria_.velocity;
  viewer_ = v;
  const lod::Decisions out{lod_, limited_, size_only_, ecc_only_, vel_only_, ecc_deg_, {}, {}};
  std::string err = lod::select_lods(v, store_.view(), out);
  if (!err.empty()) std::fill(lod_.begin(), lod_.end(), 0);
  true_gaze_ = classify_true_gaze(truth_, suppressed_, glm::length(head.angular_velocity_rad_s) * aux::kDegPerRad,
                                  glm::length(omega_) * aux::kDegPerRad);
  return err;
}

}  // namespace gazelod::cli
