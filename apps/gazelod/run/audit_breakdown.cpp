// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/audit_breakdown.hpp"

#include "gaze/gaze_conditioner.hpp"
#include "lod/acuity.hpp"
#include "lod/criterion.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace gazelod::cli {
namespace {

constexpr const char* kGazeNames[kTrueGazeCount] = {"fixation", "vor", "carried", "pursuit", "saccade", "blink"};
constexpr const char* kClassNames[kObjectClassCount] = {"near_in_cone", "near_outside", "far_in_cone", "far_outside"};

std::uint64_t triangles_at(const std::vector<lod::LodLevel>& chain, std::uint8_t level) {
  if (chain.empty()) return 0;
  return chain[std::min<std::size_t>(level, chain.size() - 1)].triangles;
}

double ratio(double num, double den) {
  return den > 0.0 ? num / den : 0.0;
}

nlohmann::json cell_json(const BreakdownCell& c) {
  return {{"object_frames", c.object_frames},
          {"degraded", c.degraded},
          {"drawn_triangles", c.drawn_triangles},
          {"oracle_triangles", c.oracle_triangles},
          {"excess_held_triangles", c.excess_held},
          {"excess_selected_triangles", c.excess_selected},
          {"switches", c.switches},
          {"visible_switches", c.visible_switches},
          {"oracle_switches", c.oracle_switches},
          {"object_seconds", c.object_s}};
}

template <std::size_t N>
nlohmann::json group_json(const std::array<BreakdownCell, N>& cells, auto name_of) {
  nlohmann::json g = nlohmann::json::object();
  for (std::size_t i = 0; i < N; ++i) g[name_of(i)] = cell_json(cells[i]);
  return g;
}

const char* criterion_name(std::size_t i) {
  return lod::to_string(static_cast<lod::Criterion>(i));
}
const char* estimate_name(std::size_t i) {
  return gaze::to_string(static_cast<gaze::EyeMotion>(i));
}

}  // namespace

const char* to_string(TrueGaze g) {
  const auto i = static_cast<std::size_t>(g);
  return i < kTrueGazeCount ? kGazeNames[i] : "?";
}

const char* to_string(ObjectClass c) {
  const auto i = static_cast<std::size_t>(c);
  return i < kObjectClassCount ? kClassNames[i] : "?";
}

TrueGaze classify_true_gaze(const sim::EyeTruth& truth, bool suppressed, double head_speed_dps,
                            double gaze_world_speed_dps) {
  if (truth.in_blink) return TrueGaze::blink;
  if (truth.in_saccade || suppressed) return TrueGaze::saccade;
  if (truth.pursuit_object >= 0) return TrueGaze::pursuit;
  if (!(head_speed_dps >= kHeadStillDps)) return TrueGaze::fixation;
  return gaze_world_speed_dps < 0.5 * head_speed_dps ? TrueGaze::vor : TrueGaze::carried;
}

void add_breakdown_frame(const BreakdownFrameInput& in, AuditBreakdown& b) {
  if (in.chains == nullptr) return;
  const std::size_t n =
      std::min({in.drawn.size(), in.perceptual.size(), in.oracle.size(), in.oracle_limited_by.size(), in.in_view.size(),
                in.eccentricity_deg.size(), in.distance_m.size(), in.chains->size()});
  BreakdownCell& by_gaze = b.gaze[static_cast<std::size_t>(in.gaze) % kTrueGazeCount];
  const double dt = std::max(0.0, in.frame_s);
  for (std::size_t i = 0; i < n; ++i) {
    if (!in.in_view[i]) continue;
    const std::vector<lod::LodLevel>& chain = (*in.chains)[i];
    const std::uint8_t d = in.drawn[i], o = in.oracle[i], p = in.perceptual[i];
    const bool near = in.distance_m[i] < kNearM;
    const bool in_cone = in.eccentricity_deg[i] <= static_cast<float>(lod::kEccentricitySeamDeg);
    const auto cls = static_cast<std::size_t>(near ? (in_cone ? ObjectClass::near_in_cone : ObjectClass::near_outside)
                                                   : (in_cone ? ObjectClass::far_in_cone : ObjectClass::far_outside));
    BreakdownCell& by_class = b.objects[cls];
    BreakdownCell& by_estimate = b.estimate[std::min<std::size_t>(in.estimate, b.estimate.size() - 1)];
    BreakdownCell& by_criterion = b.criterion[std::min<std::size_t>(in.oracle_limited_by[i], b.criterion.size() - 1)];

    BreakdownCell delta;
    delta.object_frames = 1;
    delta.degraded = d > o ? 1 : 0;
    delta.drawn_triangles = triangles_at(chain, d);
    delta.oracle_triangles = triangles_at(chain, o);
    if (d < o) {
      // Excess = T(d) - T(o), split at min(p, o): held by the policy above it, chosen below.
      const std::uint64_t split = triangles_at(chain, std::min(p, o));
      delta.excess_held = delta.drawn_triangles - std::min(delta.drawn_triangles, split);
      delta.excess_selected = split - std::min(split, delta.oracle_triangles);
    }
    if (i < in.previous.size() && in.previous[i] != d) {
      delta.switches = 1;
      delta.visible_switches = switch_visible(in.previous[i], d, o) ? 1 : 0;
    }
    if (i < in.previous_oracle.size() && in.previous_oracle[i] != o) delta.oracle_switches = 1;
    delta.object_s = dt;
    for (BreakdownCell* c : {&by_gaze, &by_class, &by_estimate, &by_criterion}) {
      c->object_frames += delta.object_frames;
      c->degraded += delta.degraded;
      c->drawn_triangles += delta.drawn_triangles;
      c->oracle_triangles += delta.oracle_triangles;
      c->excess_held += delta.excess_held;
      c->excess_selected += delta.excess_selected;
      c->switches += delta.switches;
      c->visible_switches += delta.visible_switches;
      c->oracle_switches += delta.oracle_switches;
      c->object_s += delta.object_s;
    }
  }
}

nlohmann::json breakdown_json(const AuditBreakdown& b) {
  return {{"by_true_gaze", group_json(b.gaze, [](std::size_t i) { return kGazeNames[i]; })},
          {"by_object", group_json(b.objects, [](std::size_t i) { return kClassNames[i]; })},
          {"by_plugin_estimate", group_json(b.estimate, estimate_name)},
          {"by_oracle_criterion", group_json(b.criterion, criterion_name)}};
}

void print_breakdown(const AuditBreakdown& b, std::ostream& out) {
  std::uint64_t excess = 0;
  std::int64_t frames = 0;
  for (const BreakdownCell& c : b.gaze) excess += c.excess_held + c.excess_selected, frames += c.object_frames;
  if (frames == 0) return;
  out << "breakdown       share of object-frames, drawn/oracle triangles, share of the excess (held by the\n"
         "                switch policy + chosen by the selection), degraded, switches per object-second\n"
         "                (visible; the oracle's own)\n";
  const auto row = [&](const char* group, const char* name, const BreakdownCell& c) {
    if (c.object_frames == 0) return;
    char line[256];
    std::snprintf(
        line, sizeof line,
        "  %-9s %-13s %5.1f%%  %6.3f  excess %4.1f%% + %4.1f%%  degraded %5.2f%%  switches %5.2f (%4.2f; %4.2f)\n",
        group, name, 100.0 * ratio(static_cast<double>(c.object_frames), static_cast<double>(frames)),
        ratio(static_cast<double>(c.drawn_triangles), static_cast<double>(c.oracle_triangles)),
        100.0 * ratio(static_cast<double>(c.excess_held), static_cast<double>(excess)),
        100.0 * ratio(static_cast<double>(c.excess_selected), static_cast<double>(excess)),
        100.0 * ratio(static_cast<double>(c.degraded), static_cast<double>(c.object_frames)),
        ratio(static_cast<double>(c.switches), c.object_s), ratio(static_cast<double>(c.visible_switches), c.object_s),
        ratio(static_cast<double>(c.oracle_switches), c.object_s));
    out << line;
  };
  for (std::size_t i = 0; i < kTrueGazeCount; ++i) row("gaze", kGazeNames[i], b.gaze[i]);
  for (std::size_t i = 0; i < kObjectClassCount; ++i) row("object", kClassNames[i], b.objects[i]);
  for (std::size_t i = 0; i < b.estimate.size(); ++i) row("plugin", estimate_name(i), b.estimate[i]);
  for (std::size_t i = 0; i < b.criterion.size(); ++i) row("oracle by", criterion_name(i), b.criterion[i]);
}

}  // namespace gazelod::cli
