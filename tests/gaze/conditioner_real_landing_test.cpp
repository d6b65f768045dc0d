// SPDX-License-Identifier: Apache-2.0
// The landing test (ConditionerConfig::saccade_ends_at_landing) on a real recording: the Pupil
// Invisible export in ../shared/data/gaze (200 Hz; not part of the repository; skipped without
// it, required under CI=true). Pupil Cloud labels each sample with its own fixation id, from
// its own detector: the first sample of each of its fixations is an independent estimate of
// where a saccade landed. Where our conditioner ends a saccade next to such a landing, the
// landing test should end it sooner after that landing than the velocity fit alone does, and
// should not end a saccade in flight (a saccade read again soon after the end it took). The
// saccade cone read a latency late must hold those landings too.
#include "gaze/gaze_conditioner.hpp"
#include "auxiliary/angles.hpp"
#include "gaze/import_pupil_cloud.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace gazelod::gaze {
namespace {

namespace fs = std::filesystem;

fs::path recording() {
  return fs::path(GAZELOD_SOURCE_DIR) / ".." / "shared" / "data" / "gaze" / "pupil_cloud_invisible_gaze.csv";
}

struct Sample {
  GazeSample gaze;
  std::uint32_t fixation_id = 0;
};

std::vector<Sample> read_all(const fs::path& file) {
  // The blinks file beside it marks its blink samples invalid (as `gazelod trace` reads it).
  PupilCloudBlinks blinks;
  if (const auto path = pupil_cloud_blinks_path(file.string())) {
    std::ifstream b(*path);
    blinks = read_pupil_cloud_blinks(b, *path);
  }
  std::ifstream in(file);
  PupilCloudReader reader(in, file.string(), {}, blinks);
  std::vector<Sample> out;
  TraceRecord r;
  while (reader.next(r)) out.push_back({r.gaze, reader.last_ids().fixation_id});
  return out;
}

struct Reading {
  std::vector<std::int64_t> ends;  // sample times at which a saccade reading ended
  int moved_on = 0;                // ends after which the gaze went on by more than 2 deg
};

// The mean direction of the valid samples in [from, to) ns; false if none.
bool mean_between(const std::vector<Sample>& samples, std::int64_t from, std::int64_t to, glm::dvec3& out) {
  glm::dvec3 sum(0.0);
  for (const Sample& s : samples)
    if (s.gaze.valid && s.gaze.t_ns >= from && s.gaze.t_ns < to) sum += s.gaze.direction;
  const double n = glm::length(sum);
  if (!(n > 0.0)) return false;
  out = sum / n;
  return true;
}

// Each sample pushed and read at its own time (no latency), the head still (a head-worn
// tracker without head pose: the eye in the world is the eye in the head).
Reading read(const std::vector<Sample>& samples, const ConditionerConfig& config) {
  GazeConditioner c(config);
  const glm::dquat still{1.0, 0.0, 0.0, 0.0};
  Reading out;
  bool in_saccade = false;
  for (const Sample& s : samples) {
    c.push(s.gaze, still);
    const bool now = c.at(s.gaze.t_ns, still).motion == EyeMotion::saccade;
    if (!now && in_saccade) out.ends.push_back(s.gaze.t_ns);
    in_saccade = now;
  }
  // A saccade ended in flight goes on: the samples 35-50 ms after the end lie far from those
  // of its first 15 ms (a landing's do not, but for noise and drift).
  for (const std::int64_t t : out.ends) {
    glm::dvec3 at_end, later;
    if (mean_between(samples, t, t + 15'000'000, at_end) &&
        mean_between(samples, t + 35'000'000, t + 50'000'000, later))
      out.moved_on += aux::angle_between_rad(at_end, later) * aux::kDegPerRad > 2.0 ? 1 : 0;
  }
  return out;
}

TEST(ConditionerRealLanding, EndsSoonerAfterPupilCloudsFixationStartsOnARealRecording) {
  const fs::path file = recording();
  if (!fs::is_regular_file(file)) GAZELOD_SKIP_OR_FAIL("no " << file << " (../shared/data/gaze, evaluation data)");
  const std::vector<Sample> samples = read_all(file);
  ASSERT_EQ(samples.size(), 8567u);
  // Pupil Cloud's landings: the first sample of each of its fixations.
  std::vector<std::int64_t> landings;
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (samples[i].fixation_id != 0 && samples[i].fixation_id != samples[i - 1].fixation_id)
      landings.push_back(samples[i].gaze.t_ns);
  ASSERT_GE(landings.size(), 50u);

  ConditionerConfig old;
  old.saccade_ends_at_landing = false;
  const Reading a = read(samples, ConditionerConfig{});
  const Reading b = read(samples, old);
  // Each of Pupil's landings that both readings end a saccade near (within 100 ms after it,
  // or 20 ms before: our end is a sample of the landing's own run): how long after it.
  std::vector<double> lag_now, lag_old;
  const auto end_near = [](const std::vector<std::int64_t>& ends, std::int64_t t) -> const std::int64_t* {
    const auto it = std::lower_bound(ends.begin(), ends.end(), t - 20'000'000);
    return it != ends.end() && *it <= t + 100'000'000 ? &*it : nullptr;
  };
  for (const std::int64_t t : landings) {
    const std::int64_t* x = end_near(a.ends, t);
    const std::int64_t* y = end_near(b.ends, t);
    if (x == nullptr || y == nullptr) continue;
    lag_now.push_back(static_cast<double>(*x - t) * 1e-6);
    lag_old.push_back(static_cast<double>(*y - t) * 1e-6);
  }
  ASSERT_GE(lag_now.size(), 20u) << "saccades both readings end next to one of Pupil's landings";
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  const double m_now = median(lag_now), m_old = median(lag_old);
  std::printf(
      "landings %zu, matched %zu, ends now %zu old %zu, median lag now %.1f ms old %.1f ms, moved on now %d old %d\n",
      landings.size(), lag_now.size(), a.ends.size(), b.ends.size(), m_now, m_old, a.moved_on, b.moved_on);
  // Measured (2026-12-07): a median 20 ms after Pupil's landing, against 28 ms with the
  // velocity fit alone; 20 of 68 ends followed by more than 2 deg of movement either way (a
  // head-worn tracker without head pose: the eye's reflex and pursuits move it in the head).
  // A landing test whose slope limit came from its own few samples ended 23 of 70 so, and one
  // with neither a slope nor a 15 ms condition 32 of 81.
  EXPECT_LT(m_now, m_old - 5.0);
  EXPECT_LE(a.moved_on, b.moved_on + 2);
}

// The saccade's cone a latency late (ConditionerConfig::saccade_ahead_of_travelled) on the same
// recording: samples shown latency_s after their time, read once per 90 Hz display frame. In
// each frame read as a saccade once vision is back (more than 50 ms after the next of Pupil's
// landings), the cone should hold where the eye landed: the mean of the landing's first 30 ms.
// Real saccades curve and overshoot, which the simulated ones do not; this is the cap's check
// against them.
struct ConeCheck {
  int frames = 0;         // saccade frames shown after vision is back at a landing
  int held = 0;           // ... whose cone holds it (the uncertainty plus 1.5 deg)
  int held_tight = 0;     // ... within the uncertainty alone
  double cone_sum = 0.0;  // sum of every saccade frame's uncertainty, deg
  int saccade_frames = 0;
};

ConeCheck check_cone(const std::vector<Sample>& samples, const std::vector<std::int64_t>& landings,
                     const ConditionerConfig& config, double latency_s) {
  GazeConditioner c(config);
  const glm::dquat still{1.0, 0.0, 0.0, 0.0};
  const std::int64_t latency_ns = static_cast<std::int64_t>(latency_s * 1e9);
  const std::int64_t frame_ns = 11'111'111;
  ConeCheck out;
  std::size_t next = 0;
  for (std::int64_t shown = samples.front().gaze.t_ns + latency_ns; shown <= samples.back().gaze.t_ns + latency_ns;
       shown += frame_ns) {
    while (next < samples.size() && samples[next].gaze.t_ns + latency_ns <= shown) c.push(samples[next++].gaze, still);
    const ConditionedGaze g = c.at(shown, still);
    if (g.motion != EyeMotion::saccade || !g.valid) continue;
    ++out.saccade_frames;
    out.cone_sum += g.uncertainty_deg;
    // The landing of this saccade: Pupil's first fixation start after the newest sample (the eye
    // was in flight there), if it comes within 150 ms of it. (A frame whose newest sample lies
    // already past Pupil's landing, or in a saccade Pupil does not end within 150 ms, is not
    // counted; one followed within 150 ms by a fixation after a fixation Pupil missed would be
    // matched to that later one.)
    const auto it = std::lower_bound(landings.begin(), landings.end(), g.sample_t_ns);
    if (it == landings.end() || *it > g.sample_t_ns + 150'000'000) continue;
    if (shown <= *it + 50'000'000) continue;  // vision still suppressed
    glm::dvec3 landed;
    if (!mean_between(samples, *it, *it + 30'000'000, landed)) continue;
    ++out.frames;
    const double miss_deg = aux::angle_between_rad(g.direction_world, landed) * aux::kDegPerRad;
    out.held += miss_deg <= g.uncertainty_deg + 1.5 ? 1 : 0;
    out.held_tight += miss_deg <= g.uncertainty_deg ? 1 : 0;
  }
  return out;
}

TEST(ConditionerRealLanding, TheCappedSaccadeConeStillHoldsRealLandings) {
  const fs::path file = recording();
  if (!fs::is_regular_file(file)) GAZELOD_SKIP_OR_FAIL("no " << file << " (../shared/data/gaze, evaluation data)");
  const std::vector<Sample> samples = read_all(file);
  ASSERT_FALSE(samples.empty());
  std::vector<std::int64_t> landings;
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (samples[i].fixation_id != 0 && samples[i].fixation_id != samples[i - 1].fixation_id)
      landings.push_back(samples[i].gaze.t_ns);
  ConditionerConfig uncapped;
  uncapped.saccade_ahead_of_travelled = 0.0;
  for (const double latency : {0.02, 0.05, 0.07, 0.09}) {
    const ConeCheck capped = check_cone(samples, landings, ConditionerConfig{}, latency);
    const ConeCheck far = check_cone(samples, landings, uncapped, latency);
    std::printf(
        "latency %.0f ms: saccade frames %d, after vision is back %d: held capped %d (%d tight) uncapped %d (%d "
        "tight); "
        "mean cone capped %.2f uncapped %.2f deg\n",
        latency * 1e3, capped.saccade_frames, capped.frames, capped.held, capped.held_tight, far.held, far.held_tight,
        capped.cone_sum / std::max(1, capped.saccade_frames), far.cone_sum / std::max(1, far.saccade_frames));
    // Measured (2026-12-07), 308 saccade frames at every latency: after vision is back, 0, 8,
    // 33 and 48 frames at 20, 50, 70 and 90 ms; both cones held 0, 8, 33 and 47 of them (within
    // the uncertainty alone: capped 0, 8, 32, 42; uncapped 0, 8, 33, 46); the mean cone 3.13
    // against 3.22, 4.30 against 6.60, 4.59 against 8.95 and 4.76 against 11.32 deg.
    const std::string what = std::to_string(latency) + " s";
    ASSERT_EQ(capped.saccade_frames, far.saccade_frames) << what << ": the same frames (only the cone differs)";
    if (latency >= 0.07) {
      ASSERT_GE(capped.frames, 20) << what << ": frames shown after vision is back";
    }
    EXPECT_GE(capped.held, far.held) << what;
    EXPECT_GE(20 * capped.held, 19 * capped.frames) << what;
    // Within the cone alone the cap misses a few more (42 against 46 of 48 at 90 ms): bounded
    // here, so that a tighter cap shows. (At 20 ms no saccade frame is shown after vision is
    // back, the reading having ended by then: that case checks only that both read the same
    // saccade frames.)
    EXPECT_GE(10 * capped.held_tight, 8 * capped.frames) << what;
    if (latency >= 0.05) {
      EXPECT_LT(capped.cone_sum, 0.7 * far.cone_sum) << what;
    }
  }
}

}  // namespace
}  // namespace gazelod::gaze
