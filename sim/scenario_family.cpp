// SPDX-License-Identifier: Apache-2.0
#include "sim/scenario_family.hpp"

#include "auxiliary/random.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace gazelod::sim {
namespace {

// One draw per named quantity (its own counter), so adding a quantity later leaves the
// others' values for a seed unchanged.
enum Draw : std::uint64_t {
  kDisplay,
  kHead,
  kSweepYaw,
  kSweepPeriod,
  kSweepPitch,
  kTurnRate,
  kTurnTime,
  kTurnSign,
  kWalk,
  kVor,
  kFixMin,
  kFixMax,
  kAmpMax,
  kRange,
  kPursuit,
  kPursuitSpeed,
  kPursuitDist,
  kPursuitStart,
  kPursuitLen,
  kPursuitSide,
  kTrackerRate,
  kLatency,
  kNoise,
  kBlinkRate,
  kBlinkLen,
  kDropouts,
  kDropFraction,
  kField,
  kCount,
  kLevels,
  kTriangles,
  kRatio,
  kTargetRadius,
  kTurn2Time,
  kOffsetDirection,
};
constexpr std::uint64_t kFamilyStream = 0x66616d696c79;  // "family"

// The presets with an eye tracker (gazelod hmds): the family's displays.
constexpr std::array<const char*, 6> kDisplays{"questpro",  "viveproeye", "varjoxr4",
                                               "visionpro", "psvr2",      "pimaxcrystal"};
constexpr std::array<const char*, 4> kHeadProfiles{"still", "sweeps", "sweeps+turns", "walk"};
constexpr std::array<const char*, 3> kFields{"near clutter", "open field", "deep field"};

std::size_t pick(double u, std::size_t n) {
  return std::min(n - 1, static_cast<std::size_t>(u * static_cast<double>(n)));
}

// Level k: triangles / ratio^k; detail sqrt(triangles_k) / 2 cycles per diameter (the
// random_field convention, sim/scenarios/README.md).
nlohmann::json lod_chain(double triangles, int levels, double ratio) {
  nlohmann::json chain = nlohmann::json::array();
  for (int k = 0; k < levels; ++k) {
    const auto t = static_cast<std::int64_t>(std::max(4.0, std::round(triangles / std::pow(ratio, k))));
    chain.push_back(
        {{"triangles", t}, {"vertices", t / 2 + 2}, {"detail", k == 0 ? 0.0 : std::sqrt(static_cast<double>(t)) / 2}});
  }
  return chain;
}

}  // namespace

bool parse_ideal_tracker(const std::string& text, IdealTracker& out) {
  IdealTracker r;
  if (text == "all") {
    r = IdealTracker{true, true, true};
  } else if (!text.empty() && text != "none") {
    std::size_t from = 0;
    while (from <= text.size()) {
      const std::size_t comma = std::min(text.find(',', from), text.size());
      const std::string part = text.substr(from, comma - from);
      if (part == "latency") {
        r.latency = true;
      } else if (part == "noise") {
        r.noise = true;
      } else if (part == "rate") {
        r.rate = true;
      } else {
        return false;
      }
      from = comma + 1;
    }
  }
  out = r;
  return true;
}

FamilyScenario family_scenario(std::uint64_t seed, double duration_s, IdealTracker ideal,
                               double calibration_offset_deg) {
  const aux::CounterRng r{seed, kFamilyStream};
  const auto u = [&](Draw d, double lo, double hi) { return r.uniform(d, lo, hi); };
  const double T = duration_s > 0.0 ? duration_s : 20.0;
  char text[256];

  const char* display = kDisplays[pick(r.uniform(kDisplay), kDisplays.size())];
  const std::size_t head = pick(r.uniform(kHead), kHeadProfiles.size());
  const bool moving = head != 0;
  const double walk = head == 3 ? u(kWalk, 0.8, 1.6) : 0.0;
  const bool vor = moving && r.uniform(kVor) < 0.75;
  const bool pursuit = r.uniform(kPursuit) < 0.6;
  const double tracker_hz = ideal.rate ? 1000.0 : std::round(u(kTrackerRate, 60.0, 250.0));
  const double latency_ms = ideal.latency ? 0.0 : std::round(u(kLatency, 5.0, 80.0));
  const double noise_deg = ideal.noise ? 0.0 : std::round(u(kNoise, 0.2, 1.5) * 100.0) / 100.0;

  nlohmann::json effects = nlohmann::json::array();
  std::string head_text = kHeadProfiles[head];
  if (moving) {
    effects.push_back({{"type", "head_sweep"},
                       {"yaw_amplitude_deg", std::round(u(kSweepYaw, head == 1 ? 5.0 : 15.0, head == 1 ? 25.0 : 45.0))},
                       {"yaw_period_s", std::round(u(kSweepPeriod, 3.0, 8.0) * 10.0) / 10.0},
                       {"pitch_amplitude_deg", std::round(u(kSweepPitch, 0.0, 10.0))},
                       {"pitch_period_s", 4.0}});
  }
  if (head >= 2) {
    // A fast turn and, a few seconds later, the turn back (so the field stays in view).
    const double rate = std::round(u(kTurnRate, 80.0, 250.0)) * (r.uniform(kTurnSign) < 0.5 ? -1.0 : 1.0);
    const double t1 = std::round(u(kTurnTime, 0.15, 0.45) * T * 10.0) / 10.0;
    const double t2 = std::round((t1 + u(kTurn2Time, 2.0, 5.0)) * 10.0) / 10.0;
    effects.push_back({{"type", "head_turn"}, {"rate_deg_s", rate}, {"duration_s", 0.4}, {"start_s", t1}});
    if (t2 + 0.4 < T)
      effects.push_back({{"type", "head_turn"}, {"rate_deg_s", -rate}, {"duration_s", 0.4}, {"start_s", t2}});
  }
  if (walk > 0.0) {
    std::snprintf(text, sizeof text, " %.1f m/s", walk);
    head_text += text;
  }
  const double fix_min = std::round(u(kFixMin, 150.0, 250.0));
  effects.push_back({{"type", "saccades"},
                     {"fixation_min_ms", fix_min},
                     {"fixation_max_ms", std::round(fix_min + u(kFixMax, 150.0, 550.0))},
                     {"amplitude_min_deg", 2.0},
                     {"amplitude_max_deg", std::round(u(kAmpMax, 8.0, 20.0))},
                     {"range_deg", std::round(u(kRange, 15.0, 25.0))}});
  if (vor) effects.push_back({{"type", "vor"}});

  nlohmann::json objects = nlohmann::json::array();
  std::string pursuit_text;
  if (pursuit) {
    // A target crossing the view at the drawn angular speed at its distance, keeping pace with
    // the walk, pursued for 2-5 s.
    const double speed_dps = u(kPursuitSpeed, 5.0, 30.0);
    const double dist = u(kPursuitDist, 4.0, 15.0);
    const double start = std::round(u(kPursuitStart, 0.2, 0.6) * T * 10.0) / 10.0;
    const double len = std::min(u(kPursuitLen, 2.0, 5.0), T - start);
    const double vx = dist * speed_dps * std::numbers::pi / 180.0 * (r.uniform(kPursuitSide) < 0.5 ? -1.0 : 1.0);
    const double x0 = -vx * (start + len / 2.0);
    objects.push_back({{"name", "target"},
                       {"position_m", {x0, 0.0, -dist}},
                       {"velocity_m_s", {vx, 0.0, -walk}},
                       {"radius_m", std::round(u(kTargetRadius, 0.2, 0.8) * 100.0) / 100.0},
                       {"lods", lod_chain(20000, 4, 4.0)}});
    effects.push_back({{"type", "smooth_pursuit"}, {"object", "target"}, {"start_s", start}, {"end_s", start + len}});
    std::snprintf(text, sizeof text, ", pursuit %.0f deg/s", speed_dps);
    pursuit_text = text;
  }
  effects.push_back({{"type", "tracker_rate"}, {"rate_hz", tracker_hz}});
  effects.push_back({{"type", "tracker_latency"}, {"latency_ms", latency_ms}});
  effects.push_back({{"type", "tracker_noise"}, {"std_deg", noise_deg}});
  effects.push_back({{"type", "blinks"},
                     {"rate_per_min", std::round(u(kBlinkRate, 6.0, 20.0))},
                     {"duration_ms", std::round(u(kBlinkLen, 100.0, 250.0))}});
  if (r.uniform(kDropouts) < 0.3)
    effects.push_back({{"type", "dropouts"}, {"fraction", std::round(u(kDropFraction, 0.01, 0.05) * 1000.0) / 1000.0}});
  // Last: the simulator gives each effect a random stream by its place in the list, so an
  // effect inserted before the blinks and dropouts would move them too.
  const double offset_deg = std::isfinite(calibration_offset_deg) ? std::clamp(calibration_offset_deg, 0.0, 30.0) : 0.0;
  if (offset_deg > 0.0) {
    const double dir = u(kOffsetDirection, 0.0, 2.0 * std::numbers::pi);
    effects.push_back({{"type", "calibration_offset"},
                       {"yaw_deg", std::round(offset_deg * std::cos(dir) * 1000.0) / 1000.0},
                       {"pitch_deg", std::round(offset_deg * std::sin(dir) * 1000.0) / 1000.0}});
  }

  // The field: its depth and size structure, stretched ahead by the walk's distance.
  const std::size_t field = pick(r.uniform(kField), kFields.size());
  const double ahead = walk * T;
  struct Shape {
    double half_width, half_height, z_near, z_far, r_min, r_max;
    int count_lo, count_hi;
  };
  constexpr Shape kShapes[] = {
      {10, 2, 2, 40, 0.1, 0.6, 150, 300}, {25, 4, 5, 150, 0.3, 2.0, 100, 250}, {60, 8, 10, 400, 1.0, 6.0, 100, 200}};
  const Shape& s = kShapes[field];
  const int levels = static_cast<int>(std::floor(u(kLevels, 3.0, 5.999)));
  nlohmann::json generator = {{"type", "random_field"},
                              {"count", static_cast<int>(std::round(u(kCount, s.count_lo, s.count_hi)))},
                              {"min_m", {-s.half_width, -s.half_height, -(s.z_far + ahead)}},
                              {"max_m", {s.half_width, s.half_height, -s.z_near}},
                              {"radius_min_m", s.r_min},
                              {"radius_max_m", s.r_max},
                              {"lod_count", levels},
                              {"triangles", static_cast<std::int64_t>(std::round(u(kTriangles, 5000.0, 40000.0)))},
                              {"triangle_ratio", std::round(u(kRatio, 2.0, 4.0) * 10.0) / 10.0},
                              {"forward_speed_m_s", walk}};

  nlohmann::json sc = {{"version", 1},
                       {"name", "family-" + std::to_string(seed)},
                       {"display", {{"preset", display}, {"eye_tracking_hz", tracker_hz}}},
                       {"duration_s", T},
                       {"seed", seed},
                       {"scene", {{"objects", objects}, {"generators", {generator}}}},
                       {"effects", effects},
                       {"runtime", {{"eye_gaze_supported", true}, {"gaze_delivery", "normal"}, {"paced", true}}}};
  FamilyScenario out;
  out.json = aux::json_text(sc, 2);
  char offset_text[48] = "";
  if (offset_deg > 0.0) std::snprintf(offset_text, sizeof offset_text, " offset %.2f deg", offset_deg);
  std::snprintf(text, sizeof text, "%s, %s%s, %s, %.0f Hz %.0f ms %.2f deg%s, %s", head_text.c_str(),
                moving ? (vor ? "vor" : "eyes carried") : "fixations", pursuit_text.c_str(), display, tracker_hz,
                latency_ms, noise_deg, offset_text, kFields[field]);
  out.summary = text;
  return out;
}

}  // namespace gazelod::sim
