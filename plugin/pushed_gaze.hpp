// SPDX-License-Identifier: Apache-2.0
// Gaze samples the application pushes (data mode, or OpenXR mode with GZL_GAZE_INPUT_PUSHED),
// as a GazeSource, and the head orientations given with the frames, to turn a sample into
// head space and to know the head at the sample's time.
#pragma once

#include "auxiliary/time.hpp"
#include "gaze/gaze_sample.hpp"
#include "gaze/gaze_source.hpp"

#include <glm/gtc/quaternion.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace gazelod::plugin {

// The head's orientation over the last frames (head to base space), interpolated between them.
class HeadHistory {
 public:
  void push(std::int64_t t_ns, const glm::dquat& orientation);
  // Slerp between the two frames around t; the nearest frame's at either end; nullopt when empty.
  std::optional<glm::dquat> at(std::int64_t t_ns) const;

 private:
  static constexpr std::size_t kFrames = 64;
  std::array<std::int64_t, kFrames> t_ns_{};
  std::array<glm::dquat, kFrames> q_{};
  std::size_t count_ = 0, next_ = 0;
};

struct PushedSample {
  gaze::GazeSample sample;  // direction in head space, or in the base space with in_world
  bool in_world = false;
  bool has_head_orientation = false;
  glm::dquat head_orientation{1.0, 0.0, 0.0, 0.0};
};

// [[nodiscard]]: a refused sample is the caller's to report (docs/error-policy.md).
enum class [[nodiscard]] PushResult{ok, out_of_order, in_future, invalid};

class PushedGazeSource final : public gaze::GazeSource {
 public:
  // max_age_ns: a frame uses the newest sample at most this old; lead_ns: how far past the last
  // frame's display time a sample may be stamped before it counts as from another clock.
  PushedGazeSource(const HeadHistory& heads, std::int64_t max_age_ns, std::int64_t lead_ns = aux::ns_from_seconds(1.0))
      : heads_(heads),
        max_age_ns_(max_age_ns),
        lead_ns_(lead_ns),
        stale_status_("no sample pushed in the last " + std::to_string(aux::whole_ms_from_ns(max_age_ns)) + " ms") {}

  // Checks and stores a sample; on refusal `why` says what is wrong ("gazelod: ..."), nothing
  // is stored. Allocates nothing on success.
  PushResult push(const PushedSample& s, std::string& why);
  // The display time of the frame being decided (the future check's clock). At the first
  // frame, samples pushed before it that the check would have refused are dropped (and the
  // status says so): kept, their time would make every later sample out of order.
  void frame_time(std::int64_t t_ns);

  std::string name() const override { return "pushed"; }
  // The newest sample stamped at or before t_ns and at most max_age old, in head space.
  std::optional<gaze::GazeSample> sample_at(std::int64_t t_ns) override;
  std::string status() const override { return status_; }
  // The head at the time of the sample sample_at returned last: the one pushed with it, else
  // interpolated from the frames' head poses.
  std::optional<glm::dquat> head_at_last_sample() const { return last_head_; }

 private:
  static constexpr std::size_t kSamples = 1024;  // 1 s at 1 kHz
  const HeadHistory& heads_;
  std::int64_t max_age_ns_, lead_ns_;
  std::array<PushedSample, kSamples> ring_{};
  std::size_t count_ = 0, next_ = 0;
  bool have_last_t_ = false;
  std::int64_t last_t_ns_ = 0;
  bool have_frame_ = false;
  std::int64_t frame_t_ns_ = 0;
  std::optional<glm::dquat> last_head_;
  std::string status_ = "no sample pushed yet";
  std::string stale_status_;  // "no sample pushed in the last N ms", made once: frames do not allocate
  std::string none_status_ = "no sample pushed yet";
};

}  // namespace gazelod::plugin
