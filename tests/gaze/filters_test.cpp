// One Euro fixation smoothing, prediction, head angular velocity.
#include "gaze/angles.hpp"
#include "gaze/gaze_predictor.hpp"
#include "gaze/head_velocity.hpp"
#include "gaze/one_euro.hpp"
#include "tests/gaze/synth.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <random>

namespace gazelod::gaze {
namespace {

constexpr std::int64_t kMs = 1'000'000;

double rms_error_deg(const std::vector<GazeSample>& s, const glm::dvec3& truth, std::size_t from) {
  double sum = 0;
  for (std::size_t i = from; i < s.size(); ++i) {
    const double e = angle_between_rad(s[i].direction, truth) * kDegPerRad;
    sum += e * e;
  }
  return std::sqrt(sum / static_cast<double>(s.size() - from));
}

TEST(OneEuro, SmoothsFixationNoise) {
  testing::Synth s;
  s.yaw_deg = 5.0;
  s.fixate(2.0);
  FixationSmoother f;
  std::vector<GazeSample> smooth;
  for (const auto& g : s.out) smooth.push_back(f.filter(g));
  const glm::dvec3 truth = direction_from_yaw_pitch_deg(5.0, 0.0);
  const double raw = rms_error_deg(s.out, truth, 50), sm = rms_error_deg(smooth, truth, 50);
  EXPECT_NEAR(raw, 0.1 * std::sqrt(2.0), 0.02);  // the synthetic noise itself
  EXPECT_LT(sm, 0.5 * raw);
  // Same times and flags as the raw samples.
  EXPECT_EQ(smooth[100].t_ns, s.out[100].t_ns);
  EXPECT_EQ(smooth[100].valid, s.out[100].valid);
}

TEST(OneEuro, LeavesSaccadesRaw) {
  testing::Synth s;
  s.fixate(0.5);
  const std::size_t start = s.out.size();
  s.saccade(10.0, 30.0);
  const std::size_t end = s.out.size();
  s.fixate(0.5);
  const auto labels = classify_ivt(s.out);
  FixationSmoother f;
  int raw_saccade_samples = 0;
  for (std::size_t i = 0; i < s.out.size(); ++i) {
    const GazeSample out = f.filter(s.out[i], labels[i].label);
    if (labels[i].label == GazeLabel::saccade) {
      EXPECT_EQ(out.direction, s.out[i].direction) << i;
      ++raw_saccade_samples;
    }
    // No lag after landing: within 40 ms of the saccade's end the output is near the target.
    if (i >= end + 10) {
      EXPECT_LT(angle_between_rad(out.direction, direction_from_yaw_pitch_deg(s.yaw_deg, s.pitch_deg)) *
                    kDegPerRad, 0.5) << i;
    }
  }
  EXPECT_GE(raw_saccade_samples, static_cast<int>(end - start));
  // An invalid sample passes through untouched.
  GazeSample bad = s.out[0];
  bad.valid = false;
  EXPECT_EQ(f.filter(bad).direction, bad.direction);
}

TEST(Predictor, ExtrapolatesPursuitWithinHorizon) {
  // Smooth pursuit at 20 deg/s to the right, no noise.
  GazePredictor p;
  for (int i = 0; i <= 10; ++i) {
    GazeSample g;
    g.t_ns = i * 4 * kMs;
    g.direction = direction_from_yaw_pitch_deg(0.02 * 4 * i, 0.0);
    g.valid = true;
    p.push(g);
  }
  EXPECT_NEAR(p.speed_deg_s(), 20.0, 0.01);
  const auto a = p.predict(40 * kMs + 20 * kMs);
  ASSERT_TRUE(a.has_value());
  EXPECT_FALSE(a->clamped);
  EXPECT_NEAR(std::atan2(a->sample.direction.x, -a->sample.direction.z) * kDegPerRad, 0.8 + 0.4, 1e-3);
  // Beyond 50 ms the prediction stops moving, the uncertainty keeps growing (to its cap).
  const auto b = p.predict(40 * kMs + 50 * kMs), c = p.predict(40 * kMs + 200 * kMs);
  EXPECT_TRUE(c->clamped);
  EXPECT_NEAR(angle_between_rad(b->sample.direction, c->sample.direction), 0.0, 1e-12);
  double last = 0.0;
  for (int h_ms = 0; h_ms <= 500; h_ms += 10) {
    const double u = p.predict(40 * kMs + h_ms * kMs)->uncertainty_deg;
    EXPECT_GE(u, last);
    EXPECT_LE(u, PredictorOptions{}.max_uncertainty_deg);
    last = u;
  }
  // At h = 0: the accuracy; at 20 ms: accuracy + (10 + 0.25 * 20) * 0.02 = 0.8 deg.
  EXPECT_NEAR(p.predict(40 * kMs)->uncertainty_deg, 0.5, 1e-9);
  EXPECT_NEAR(a->uncertainty_deg, 0.5 + (10.0 + 5.0) * 0.02, 1e-6);
}

TEST(Predictor, HoldsDuringSaccadeAndNeedsData) {
  GazePredictor p;
  EXPECT_FALSE(p.predict(0).has_value());
  for (int i = 0; i <= 5; ++i) {
    GazeSample g;
    g.t_ns = i * 4 * kMs;
    g.direction = direction_from_yaw_pitch_deg(1.0 * i, 0.0);  // 250 deg/s
    g.valid = true;
    p.push(g);
  }
  const auto q = p.predict(20 * kMs + 20 * kMs);
  EXPECT_TRUE(q->in_saccade);
  EXPECT_NEAR(std::atan2(q->sample.direction.x, -q->sample.direction.z) * kDegPerRad, 5.0, 1e-9);
  EXPECT_GT(q->uncertainty_deg, 250.0 * 0.02);  // could be anywhere it can reach
}

glm::dquat about_y(double deg) {
  const double h = deg / kDegPerRad / 2.0;
  return {std::cos(h), 0.0, std::sin(h), 0.0};
}

TEST(HeadVelocity, RobustToSignFlipsAndUnevenSpacing) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> dt(2, 17);
  HeadVelocityEstimator est;
  std::int64_t t = 0;
  for (int i = 0; i < 200; ++i) {
    HeadSample h;
    h.t_ns = t;
    h.valid = true;
    h.orientation = about_y(90.0 * static_cast<double>(t) * 1e-9);  // 90 deg/s
    if (i % 2) h.orientation = -h.orientation;                        // same rotation
    est.push(h);
    if (i > 1) {
      const auto w = est.velocity_rad_s();
      ASSERT_TRUE(w.has_value());
      EXPECT_NEAR(w->y * kDegPerRad, 90.0, 1e-6) << i;
      EXPECT_NEAR(w->x, 0.0, 1e-9);
    }
    t += dt(rng) * kMs;
  }
  EXPECT_NEAR(est.speed_deg_s(), 90.0, 1e-6);
}

TEST(HeadVelocity, TinyRotationsAndDegenerateInput) {
  HeadSample a, b;
  a.valid = b.valid = true;
  b.t_ns = 1 * kMs;
  b.orientation = about_y(1e-7);  // 1e-7 deg in 1 ms = 1e-4 deg/s
  const auto w = angular_velocity_rad_s(a, b);
  ASSERT_TRUE(w.has_value());
  EXPECT_NEAR(w->y * kDegPerRad, 1e-4, 1e-12);
  b.orientation = a.orientation;
  EXPECT_EQ(*angular_velocity_rad_s(a, b), glm::dvec3(0.0));
  b.t_ns = 0;
  EXPECT_FALSE(angular_velocity_rad_s(a, b).has_value());
  // Rotation vector of a 170 deg turn given as -q: still the 170 deg short way.
  const glm::dvec3 r = rotation_vector_between(glm::dquat(1, 0, 0, 0), -about_y(170.0));
  EXPECT_NEAR(r.y * kDegPerRad, 170.0, 1e-9);
  HeadVelocityEstimator est;
  HeadSample bad;
  bad.valid = true;
  bad.orientation = glm::dquat(0, 0, 0, 0);
  est.push(bad);
  EXPECT_FALSE(est.velocity_rad_s().has_value());
  EXPECT_EQ(est.speed_deg_s(), 0.0);
}

}  // namespace
}  // namespace gazelod::gaze
