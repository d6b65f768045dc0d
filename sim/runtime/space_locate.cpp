// SPDX-License-Identifier: Apache-2.0
// Space poses in LOCAL (see space_locate.hpp).
#include "sim/runtime/space_locate.hpp"
#include "sim/runtime/interaction_profiles.hpp"
#include "sim/runtime/sim_clock.hpp"
#include "xr/eye_gaze_paths.hpp"

#include <algorithm>
#include <optional>

namespace gazelod::xrrt {
namespace {

constexpr int kMaxLocateDepth = 4;  // automation poses set relative to other action spaces

std::int64_t scenario_time(XrTime t) {
  return std::max<std::int64_t>(0, SimClock::scenario_ns(t));
}

Located head_attached(Instance& inst, const Pose& offset, XrTime time) {
  const sim::HeadState h = inst.simulator->head_at(scenario_time(time));
  const Pose head{h.orientation, h.position_m};
  Located l;
  l.valid = l.tracked = true;
  l.pose = compose(head, offset);
  l.has_velocity = true;
  l.angular_rad_s = h.angular_velocity_rad_s;
  // A point fixed to the head moves with the head's rotation too: v = v_head + w x r.
  l.linear_m_s = h.linear_velocity_m_s + glm::cross(h.angular_velocity_rad_s, l.pose.position - head.position);
  return l;
}

Located from_automation(Instance& inst, Session& session, const InputDevice::Location& loc, const Pose& offset,
                        XrTime time, int depth) {
  Located l;
  const Space* ref = runtime().spaces.find(loc.space_id);
  if (ref == nullptr || depth >= kMaxLocateDepth) return l;
  Located base = locate_in_local(inst, session, *ref, time, depth + 1);
  if (!base.valid) return l;
  l.valid = true;
  l.tracked = base.tracked;
  l.pose = compose(compose(base.pose, from_xr(loc.pose)), offset);
  return l;
}

// An active controller whose pose no test has set (XR_EXT_conformance_automation) is tracked at
// a fixed resting place in LOCAL, a hand's width either side, below and in front of the eyes:
// the conformance suite waits for an activated controller to become locatable, and a
// simulated device has no reason to be lost.
Located default_controller(std::string_view top_level, const Pose& offset) {
  const double side_m = top_level == "/user/hand/left" ? -0.2 : top_level == "/user/hand/right" ? 0.2 : 0.0;
  Located l;
  l.valid = l.tracked = true;
  l.pose = compose(Pose{glm::dquat(1, 0, 0, 0), glm::dvec3(side_m, -0.3, -0.4)}, offset);
  l.has_velocity = true;  // at rest
  return l;
}

Located locate_gaze(Instance& inst, Session& session, const InputDevice* eyes, XrPath gaze_path, const Pose& offset,
                    XrTime time, int depth) {
  Located l;
  l.is_gaze = true;
  if (eyes != nullptr) {
    if (auto it = eyes->locations.find(gaze_path); it != eyes->locations.end()) {
      Located set = from_automation(inst, session, it->second, offset, time, depth);
      set.is_gaze = true;
      set.gaze_sample_time = time;
      return set;
    }
  }
  const sim::RuntimeOptions& opt = inst.simulator->scenario().runtime;
  if (opt.gaze_delivery == sim::GazeDelivery::never_delivers) return l;
  const gaze::GazeSample g = inst.simulator->tracker_at(scenario_time(time));
  switch (opt.gaze_delivery) {
    case sim::GazeDelivery::sample_time_zero:
      l.gaze_sample_time = 0;
      break;
    case sim::GazeDelivery::sample_time_is_request_time:
      l.gaze_sample_time = time;
      break;
    default:
      l.gaze_sample_time = g.t_ns + kTimeBaseNs;
      break;
  }
  // A blink, a dropout: position and orientation both untracked.
  const std::optional<Pose> eye_in_head = g.valid ? gaze_ray_pose(g.direction, g.origin_m) : std::nullopt;
  if (!eye_in_head) return l;
  const sim::HeadState h = inst.simulator->head_at(scenario_time(time));
  l.valid = l.tracked = true;
  l.pose = compose(compose(Pose{h.orientation, h.position_m}, *eye_in_head), offset);
  return l;
}

}  // namespace

Located locate_in_local(Instance& inst, Session& session, const Space& space, XrTime time, int depth) {
  const Pose offset = from_xr(space.offset);
  if (space.kind == SpaceKind::reference) {
    switch (space.reference) {
      case XR_REFERENCE_SPACE_TYPE_VIEW:
        return head_attached(inst, offset, time);
      case XR_REFERENCE_SPACE_TYPE_STAGE:
      case XR_REFERENCE_SPACE_TYPE_LOCAL: {
        Located l;
        l.valid = l.tracked = true;
        const Pose origin{glm::dquat(1, 0, 0, 0), space.reference == XR_REFERENCE_SPACE_TYPE_STAGE
                                                      ? glm::dvec3(0.0, -kStageFloorBelowLocalM, 0.0)
                                                      : glm::dvec3(0.0)};
        l.pose = compose(origin, offset);
        l.has_velocity = true;  // both are fixed in the world
        return l;
      }
      default:
        return {};
    }
  }
  // Action space: follows one bound source of its action (active at the last xrSyncActions),
  // located while that source's device is switched on.
  XrPath source = space.followed_source;
  const Action* action = runtime().actions.find(space.action_id);
  if (action != nullptr) {
    auto st = session.action_states.find(action->id);
    if (st == session.action_states.end()) return {};
    const std::string* sub = inst.paths.find(space.subaction);
    const bool still_bound = source != XR_NULL_PATH && st->second.current.count(source) != 0;
    if (source == XR_NULL_PATH) {
      for (const auto& [candidate, value] : st->second.current) {
        const std::string* src = inst.paths.find(candidate);
        if (src == nullptr || (sub != nullptr && top_level_of(*src) != *sub)) continue;
        source = space.followed_source = candidate;
        break;
      }
    } else if (!still_bound) {
      return {};  // the followed source is not active: the space is not located
    }
  }
  const std::string* src = inst.paths.find(source);
  if (source == XR_NULL_PATH || src == nullptr) return {};
  const InputDevice* device = nullptr;
  for (const auto& [top, d] : session.devices)
    if (const std::string* t = inst.paths.find(top); t != nullptr && top_level_of(*src) == *t) device = &d;
  if (*src == xr::kGazePosePath) return locate_gaze(inst, session, device, source, offset, time, depth);
  if (device == nullptr || !device->switched_on()) return {};
  if (auto it = device->locations.find(source); it != device->locations.end())
    return from_automation(inst, session, it->second, offset, time, depth);
  return default_controller(top_level_of(*src), offset);
}

}  // namespace gazelod::xrrt
