// SPDX-License-Identifier: Apache-2.0
// The embedded default scenario (what `gazelod run` and the simulated runtime use when no file
// is given): Meta Quest Pro (eye-tracked), 20 s at 90 Hz, Reddy 1998's random field of 200
// objects with four LODs walked through at 1.4 m/s, head sweeps and a fast turn, saccades with
// the vestibulo-ocular reflex holding fixations in the world, a pursuit of a moving object, and
// a realistic tracker (90 Hz, latency, noise, blinks).
#include "sim/simulator.hpp"

namespace gazelod::sim {

std::string_view default_scenario_json() {
  static constexpr std::string_view kJson = R"json({
  "version": 1,
  "name": "default",
  "display": "questpro",
  "duration_s": 20,
  "frame_rate_hz": 90,
  "seed": 0,
  "scene": {
    "objects": [
      { "name": "drone", "position_m": [-7, 0.5, -8], "velocity_m_s": [0.5, 0, -1.4], "radius_m": 0.4,
        "lods": [ { "triangles": 20000, "vertices": 10002, "detail": 0 },
                  { "triangles": 5000, "vertices": 2502, "detail": 35.36 },
                  { "triangles": 1250, "vertices": 627, "detail": 17.68 },
                  { "triangles": 312, "vertices": 158, "detail": 8.83 } ] }
    ],
    "generators": [
      { "type": "random_field", "count": 200, "min_m": [-20, -4, -120], "max_m": [20, 4, -5],
        "radius_min_m": 0.2, "radius_max_m": 1.5, "lod_count": 4, "triangles": 20000,
        "triangle_ratio": 4, "forward_speed_m_s": 1.4 }
    ]
  },
  "effects": [
    { "type": "head_sweep", "yaw_amplitude_deg": 20, "yaw_period_s": 6, "pitch_amplitude_deg": 5, "pitch_period_s": 4 },
    { "type": "head_turn", "rate_deg_s": 120, "start_s": 16.5, "duration_s": 0.5 },
    { "type": "saccades", "fixation_min_ms": 180, "fixation_max_ms": 450, "amplitude_min_deg": 2,
      "amplitude_max_deg": 15, "range_deg": 20 },
    { "type": "vor" },
    { "type": "smooth_pursuit", "object": "drone", "gain": 0.9, "start_s": 10, "end_s": 14 },
    { "type": "tracker_rate", "rate_hz": 90 },
    { "type": "tracker_latency", "latency_ms": 12 },
    { "type": "tracker_noise", "std_deg": 0.3 },
    { "type": "blinks", "rate_per_min": 12, "duration_ms": 150 }
  ],
  "runtime": { "eye_gaze_supported": true, "gaze_delivery": "normal", "paced": true }
})json";
  return kJson;
}

}  // namespace gazelod::sim
