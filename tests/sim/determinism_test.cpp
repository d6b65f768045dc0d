// SPDX-License-Identifier: Apache-2.0
// Same seed, same stream, bit for bit, whatever the order of queries; a different seed gives
// a different stream.
#include "sim/simulator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

namespace gazelod::sim {
namespace {

struct Row {
  HeadState head;
  gaze::GazeSample tracker, truth;
  std::vector<ObjectState> objects;
};

Row query(Simulator& sim, std::int64_t t) {
  Row r{sim.head_at(t), sim.tracker_at(t), sim.true_gaze_at(t), {}};
  const auto o = sim.objects_at(t);
  r.objects.assign(o.begin(), o.end());
  return r;
}

template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

bool same_bits(const gaze::GazeSample& a, const gaze::GazeSample& b) {
  return a.t_ns == b.t_ns && same_bits(a.direction, b.direction) && same_bits(a.origin_m, b.origin_m) &&
         a.valid == b.valid && same_bits(a.confidence, b.confidence);
}

Scenario all_effects() {
  return load_scenario_file(std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/all_effects.json");
}

TEST(Determinism, ShuffledQueriesGiveIdenticalBits) {
  Simulator a(all_effects()), b(all_effects());
  std::vector<std::int64_t> times;
  for (std::int64_t t = 0; t < a.duration_ns(); t += 3'333'333) times.push_back(t);
  std::vector<Row> forward;
  for (std::int64_t t : times) forward.push_back(query(a, t));
  std::vector<std::size_t> order(times.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(12345));
  int checked = 0, invalid = 0;
  for (std::size_t i : order) {
    const Row r = query(b, times[i]);
    const Row& f = forward[i];
    ASSERT_TRUE(same_bits(r.head.orientation, f.head.orientation)) << times[i];
    ASSERT_TRUE(same_bits(r.head.angular_velocity_rad_s, f.head.angular_velocity_rad_s));
    ASSERT_TRUE(same_bits(r.head.position_m, f.head.position_m));
    ASSERT_TRUE(same_bits(r.tracker, f.tracker)) << times[i];
    ASSERT_TRUE(same_bits(r.truth, f.truth));
    ASSERT_EQ(r.objects.size(), f.objects.size());
    for (std::size_t k = 0; k < r.objects.size(); ++k) {
      ASSERT_TRUE(same_bits(r.objects[k].position_m, f.objects[k].position_m));
      ASSERT_TRUE(same_bits(r.objects[k].velocity_m_s, f.objects[k].velocity_m_s));
    }
    invalid += !r.tracker.valid;
    ++checked;
  }
  EXPECT_GT(checked, 5000);
  EXPECT_GT(invalid, 0) << "the scenario has blinks and dropouts";
  // Asking the same simulator again (after other queries) also repeats itself.
  EXPECT_TRUE(same_bits(a.tracker_at(times[100]), forward[100].tracker));
}

TEST(Determinism, LongScenarioQueriedLateFirstRepeatsItself) {
  // The saccade schedule is drawn lazily; asking for a late time first must not change it.
  const std::string json = R"({"version": 1, "display": "questpro", "duration_s": 400, "seed": 9,
      "effects": [{"type": "saccades"}, {"type": "tracker_noise", "std_deg": 0.2}]})";
  Simulator a(load_scenario_json(json, "long")), b(load_scenario_json(json, "long"));
  std::vector<std::int64_t> times;
  for (std::int64_t t = 0; t < 400'000'000'000; t += 997'000'001) times.push_back(t);
  std::vector<gaze::GazeSample> forward;
  for (std::int64_t t : times) forward.push_back(a.tracker_at(t));
  for (std::size_t i = times.size(); i-- > 0;) ASSERT_TRUE(same_bits(b.tracker_at(times[i]), forward[i])) << times[i];
}

// The schedules keep only their newest segments (bounded memory): a query from before those
// draws them again from the start, with the same bits. Two simulated hours of 20 ms fixations
// (far more than the kept segments), the vor effect's schedule too, then early times again.
TEST(Determinism, QueriesBeforeTheKeptScheduleRepeatThemselves) {
  const std::string json = R"({"version": 1, "display": "questpro", "duration_s": 7200, "seed": 4,
      "effects": [{"type": "head_sweep", "yaw_amplitude_deg": 20, "yaw_period_s": 6},
                  {"type": "saccades", "fixation_min_ms": 20, "fixation_max_ms": 20},
                  {"type": "vor"}, {"type": "tracker_noise", "std_deg": 0.2}]})";
  Simulator a(load_scenario_json(json, "long")), b(load_scenario_json(json, "long"));
  const std::vector<std::int64_t> early{1'000'000'000, 2'345'678'901, 61'000'000'000};
  std::vector<gaze::GazeSample> truth, tracker;
  std::vector<EyeTruth> eye;
  for (std::int64_t t : early) {
    truth.push_back(a.true_gaze_at(t));
    tracker.push_back(a.tracker_at(t));
    eye.push_back(a.eye_truth_at(t));
  }
  for (std::int64_t t = 0; t < 7'200'000'000'000; t += 600'000'000'000)
    b.true_gaze_at(t);  // far past the kept segments
  b.true_gaze_at(7'199'000'000'000);
  for (std::size_t i = 0; i < early.size(); ++i) {
    EXPECT_TRUE(same_bits(b.true_gaze_at(early[i]), truth[i])) << early[i];
    EXPECT_TRUE(same_bits(b.tracker_at(early[i]), tracker[i])) << early[i];
    const EyeTruth e = b.eye_truth_at(early[i]);
    EXPECT_EQ(e.in_saccade, eye[i].in_saccade) << early[i];
    EXPECT_EQ(e.last_saccade_end_ns, eye[i].last_saccade_end_ns) << early[i];
  }
}

TEST(Determinism, AnotherSeedGivesAnotherStream) {
  Scenario s1 = all_effects(), s2 = all_effects();
  s2.seed = s1.seed + 1;
  Simulator a(s1), b(s2);
  int differ = 0;
  for (std::int64_t t = 0; t < 5'000'000'000; t += 50'000'000)
    differ += !same_bits(a.tracker_at(t).direction, b.tracker_at(t).direction);
  EXPECT_GT(differ, 90);
}

}  // namespace
}  // namespace gazelod::sim
