// SPDX-License-Identifier: Apache-2.0
// The plugin over the simulated runtime, checked against the simulator's own gaze: the object
// under the gaze gets the finest LOD the acuity requires, and after a saccade the old fovea's
// objects drop and the new fovea's rise within one frame of the sample that shows the landing.
//
// Design of the scene (so a change is certain, from the acuity model alone):
// display xi = 3600 px / (2 * 60 deg) = 30 c/deg; objects 5 m away with radius 0.05 m
// (diameter 1.146 deg); levels remove 40, 25 and 15 c/deg. At the fovea (E = 0, still head)
// acuity = min(60, 30) = 30: level 1 (40) is invisible, level 2 (25) visible -> LOD 1. Saccades
// of 18-20 deg leave the old fovea at E >= 18 - 0.57 - 1.5 (tracker error) - 2.12 (grid
// half-diagonal) = 13.8 deg, where H = 60 * 7.49 / (0.3 * 13.8 + 1)^2 = 17 c/deg: level 2 (25)
// becomes invisible -> LOD 2 or coarser. Fixation frames are those where the gaze moved
// under 0.02 deg since the previous frame (1.8 deg/s at 90 Hz: G(1.8) = 50 c/deg, no limit)
// and the conditioner reports a fixation with vision not suppressed.
#include "run_test_util.hpp"

#include "apps/xr_host/xr_app.hpp"
#include "plugin/lod_plugin.hpp"
#include "sim/simulator.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace gazelod::test {
namespace {

constexpr double kRad = 3.14159265358979323846 / 180.0;
constexpr double kDistanceM = 5.0, kRadiusM = 0.05;

double angle_deg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) / kRad;
}

glm::dvec3 dir_from_yaw_pitch(double yaw_deg, double pitch_deg) {
  const double y = yaw_deg * kRad, p = pitch_deg * kRad;
  return {-std::sin(y) * std::cos(p), std::sin(p), -std::cos(y) * std::cos(p)};
}

std::string scenario_json() {
  const double diameter_deg =
      2.0 * std::atan2(kRadiusM, std::sqrt(kDistanceM * kDistanceM - kRadiusM * kRadiusM)) / kRad;
  nlohmann::json objects = nlohmann::json::array();
  int n = 0;
  for (int yaw = -33; yaw <= 33; yaw += 3)
    for (int pitch = -33; pitch <= 33; pitch += 3) {
      const glm::dvec3 p = dir_from_yaw_pitch(yaw, pitch) * kDistanceM;
      nlohmann::json lods = nlohmann::json::array();
      const double cpd[4] = {0.0, 40.0, 25.0, 15.0};
      for (int k = 0; k < 4; ++k)
        lods.push_back({{"triangles", 4000 >> (2 * k)},
                        {"vertices", 2000 >> (2 * k)},
                        {"detail_kind", "removed_cycles_per_diameter"},
                        {"detail", cpd[k] * diameter_deg}});
      objects.push_back({{"name", "o" + std::to_string(n++)},
                         {"position_m", {p.x, p.y, p.z}},
                         {"radius_m", kRadiusM},
                         {"lods", lods}});
    }
  nlohmann::json j = {
      {"version", 1},
      {"name", "saccade-grid"},
      {"display", {{"width_px", 3600}, {"height_px", 3600}, {"fov_h_deg", 60}, {"fov_v_deg", 60}, {"refresh_hz", 90}}},
      {"duration_s", 30},
      {"seed", 3},
      {"scene", {{"objects", objects}}},
      {"effects",
       {{{"type", "saccades"},
         {"amplitude_min_deg", 18},
         {"amplitude_max_deg", 20},
         {"range_deg", 25},
         {"fixation_min_ms", 200},
         {"fixation_max_ms", 300}}}}};
  return j.dump();
}

struct Frame {
  std::vector<std::uint8_t> lod, lod_size_only;
  glm::dvec3 gaze_world{0.0, 0.0, -1.0};
  bool gaze_valid = false;
  bool fixation = false;  // the conditioner's fixation, vision not suppressed
};

TEST(PluginSaccade, FoveaFollowsTheGazeWithinOneFrame) {
  const auto dir = scratch_dir();
  const auto file = dir / "saccade.json";
  std::ofstream(file) << scenario_json();
  use_simulated_runtime(file.string());
  sim::Simulator simulator(sim::load_scenario_file(file.string()));

  xr_host::XrApp app(true);
  ASSERT_TRUE(app.eye_gaze_enabled());
  PluginConfig cfg;
  auto plugin =
      LodPlugin::create(xrGetInstanceProcAddr, app.instance(), app.system(), app.session(), app.local_space(), cfg);
  std::vector<glm::dvec3> centers;
  for (const sim::SceneObject& o : simulator.scenario().objects) {
    plugin->add_object({o.position_m, o.radius_m, o.velocity_m_s, o.lods, o.importance});
    centers.push_back(o.position_m);
  }

  std::vector<Frame> frames;
  XrTime base = 0;
  while (frames.size() < 400 && app.poll_events([&](XrSessionState s, XrTime t) { plugin->on_session_state(s, t); })) {
    if (!app.session_running()) continue;
    const XrFrameState fs = app.wait_frame();
    app.begin_frame();
    if (base == 0) base = app.scenario_time_base();
    const FrameDecisions& d = plugin->begin_frame(fs.predictedDisplayTime);
    const FrameDiagnostics& diag = plugin->diagnostics();
    Frame f;
    f.lod.assign(d.lod.begin(), d.lod.end());
    f.lod_size_only.assign(diag.lod_size_only.begin(), diag.lod_size_only.end());
    f.gaze_world = diag.gaze_direction_world;
    f.gaze_valid = d.gaze_valid;
    f.fixation = diag.eye_motion == gaze::EyeMotion::fixation && !diag.gaze_suppressed;
    // In a fixation the gaze the plugin used is the tracker sample the simulator gives for that
    // time (a noise-free tracker: the fixation's smoothing leaves it exact; still head: head
    // space = world), once the fixation has lasted a few samples (the classifier needs them to
    // tell a saccade's onset or landing from a fixation). In a saccade the conditioner holds its
    // last estimate (vision is suppressed).
    const gaze::GazeSample truth = simulator.tracker_at(fs.predictedDisplayTime - base);
    const std::int64_t t_scenario = fs.predictedDisplayTime - base;
    const bool steady = angle_deg(truth.direction, simulator.tracker_at(t_scenario - 40'000'000).direction) < 1e-9;
    if (f.gaze_valid && steady && diag.eye_motion == gaze::EyeMotion::fixation) {
      EXPECT_LT(angle_deg(truth.direction, diag.gaze_direction_head), 0.01) << "frame " << frames.size();
    }
    frames.push_back(std::move(f));
    app.end_frame(fs.predictedDisplayTime, {});
    plugin->end_frame(1.0);
  }
  ASSERT_EQ(frames.size(), 400u);
  ASSERT_NE(base, 0);

  const auto nearest = [&](const glm::dvec3& gaze) {
    std::size_t best = 0;
    double best_a = 1e9;
    for (std::size_t i = 0; i < centers.size(); ++i) {
      const double a = angle_deg(gaze, centers[i]);
      if (a < best_a) best_a = a, best = i;
    }
    return best;
  };

  int saccades = 0, fixation_frames = 0;
  std::size_t last_fixation = 0;  // 0: none yet
  for (std::size_t k = 1; k + 1 < frames.size(); ++k) {
    const Frame& f = frames[k];
    if (!f.gaze_valid || !frames[k - 1].gaze_valid) continue;
    const double step = angle_deg(frames[k - 1].gaze_world, f.gaze_world);
    // During a saccade the conditioner holds its last estimate (the gaze does not move but
    // it is no fixation): only the conditioner's unsuppressed fixations count.
    if (step < 0.02 && !f.fixation) continue;
    if (step < 0.02) {
      // Fixating: the object under the gaze is at the finest LOD the acuity requires (the
      // display limit alone), which for this design is level 1.
      const std::size_t o = nearest(f.gaze_world);
      EXPECT_EQ(f.lod[o], f.lod_size_only[o]) << "frame " << k;
      EXPECT_EQ(f.lod[o], 1) << "frame " << k;
      ++fixation_frames;
      last_fixation = k;
      continue;
    }
    if (step < 2.0 || last_fixation == 0) continue;
    // A saccade starts between k-1 and k: find its landing L, the first frame whose gaze
    // moved less than 0.02 deg since the frame before.
    std::size_t land = k + 1;
    while (land < frames.size() && angle_deg(frames[land - 1].gaze_world, frames[land].gaze_world) >= 0.02) ++land;
    if (land >= frames.size()) break;
    const Frame& before = frames[last_fixation];
    const Frame& after = frames[land];
    const std::size_t old_fovea = nearest(before.gaze_world), new_fovea = nearest(after.gaze_world);
    if (old_fovea == new_fovea || angle_deg(before.gaze_world, after.gaze_world) < 18.0) {
      k = last_fixation = land;
      continue;
    }
    ++saccades;
    EXPECT_EQ(before.lod[old_fovea], 1) << "saccade at frame " << k;
    EXPECT_GE(after.lod[old_fovea], 2) << "old fovea must drop by landing frame " << land;
    EXPECT_GE(before.lod[new_fovea], 2) << "saccade at frame " << k;
    EXPECT_EQ(after.lod[new_fovea], 1) << "new fovea must rise by landing frame " << land;
    k = last_fixation = land;
  }
  EXPECT_GE(saccades, 5) << "the scenario should contain several 18-20 deg saccades";
  EXPECT_GE(fixation_frames, 200);
}

}  // namespace
}  // namespace gazelod::test
