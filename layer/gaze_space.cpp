// SPDX-License-Identifier: Apache-2.0
// Gaze spaces: xrCreateActionSpace on a gaze action gives a layer-owned space whose handle is a
// VIEW reference space created on the runtime (so it is unique and the runtime tears it down
// with the session). xrLocateSpace composes the head pose the runtime gives for that VIEW space
// at the requested time with the tracker's eye-in-head pose at that time (and the configured
// tracker-in-head offset and the space's poseInActionSpace); XrEyeGazeSampleTimeEXT in the
// location's chain gets the time the gaze sample is for. Located only while the action is
// active (last xrSyncActions) and a fresh sample exists; velocities are not reported.
// locate_pair is that composition for one pair of spaces (gaze_space.hpp), which
// xrLocateSpaces(KHR) uses too.
#include "layer/gaze_space.hpp"
#include "layer/entry_points.hpp"

namespace gazelod::layer {
namespace {

using Lock = std::lock_guard<std::mutex>;

constexpr XrSpaceLocationFlags kAllLocationBits =
    XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
    XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT | XR_SPACE_LOCATION_POSITION_TRACKED_BIT;

// Fills what the application chained: the sample time, and no velocity for gaze.
void fill_chain(XrSpaceLocation* location, bool gaze, std::int64_t sample_time_ns) {
  for (auto* n = static_cast<XrBaseOutStructure*>(location->next); n != nullptr; n = n->next) {
    if (n->type == XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT)
      reinterpret_cast<XrEyeGazeSampleTimeEXT*>(n)->time = static_cast<XrTime>(sample_time_ns);
    else if (gaze && n->type == XR_TYPE_SPACE_VELOCITY)
      reinterpret_cast<XrSpaceVelocity*>(n)->velocityFlags = 0;
  }
}

}  // namespace

EyeAt eye_at(EmulatedInstance& e, XrSpace space, std::int64_t t_ns) {
  EyeAt out;
  auto it = e.gaze_spaces.find(space);
  if (it == e.gaze_spaces.end()) return out;
  out.is_gaze = true;
  const GazeSpace& g = it->second;
  auto s = e.sessions.find(g.session);
  if (s == e.sessions.end() || !e.feed) return out;
  auto a = s->second.gaze_actions.find(g.action);
  if (a == s->second.gaze_actions.end() || !a->second.active) return out;
  const auto sample = e.feed->sample_at(t_ns);
  if (!sample) return out;
  const auto pose = eye_pose(*sample);
  if (!pose) return out;
  out.eye = compose(compose(e.tracker_in_head, *pose), g.pose_in_action);
  out.sample_time_ns = sample->t_ns;
  return out;
}

XrResult locate_pair(PFN_xrLocateSpace next, XrSpace space, XrSpace baseSpace, XrTime time, const EyeAt& of_space,
                     const EyeAt& of_base, XrSpaceLocation* location) {
  if (!of_space.is_gaze && !of_base.is_gaze) {
    const XrResult r = next(space, baseSpace, time, location);
    if (XR_SUCCEEDED(r) && location != nullptr) fill_chain(location, false, 0);
    return r;
  }
  if (location == nullptr || location->type != XR_TYPE_SPACE_LOCATION) return XR_ERROR_VALIDATION_FAILURE;
  // The heads (the gaze spaces' VIEW handles) located by the runtime, without the app's chain.
  XrSpaceLocation heads{XR_TYPE_SPACE_LOCATION};
  const XrResult r = next(space, baseSpace, time, &heads);
  if (XR_FAILED(r)) return r;
  const bool located = (!of_space.is_gaze || of_space.eye) && (!of_base.is_gaze || of_base.eye);
  location->locationFlags = 0;
  location->pose = XrPosef{{0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}};
  if (located && (heads.locationFlags & XR_SPACE_LOCATION_ORIENTATION_VALID_BIT) != 0) {
    Pose p = from_xr(heads.pose);                            // space's head (or space) in base's head (or base)
    if (of_space.eye) p = compose(p, *of_space.eye);         // ... the eye in its head
    if (of_base.eye) p = compose(inverse(*of_base.eye), p);  // ... in the base's eye
    location->pose = to_xr(p);
    location->locationFlags = heads.locationFlags & kAllLocationBits;
  }
  const EyeAt& gaze = of_space.is_gaze ? of_space : of_base;
  fill_chain(location, true, location->locationFlags != 0 ? gaze.sample_time_ns : 0);
  return r;  // XR_SESSION_LOSS_PENDING is a success code the application must still see
}

XrResult CreateActionSpace(XrSession session, const XrActionSpaceCreateInfo* createInfo, XrSpace* space) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrCreateActionSpace next = nullptr;
    PFN_xrCreateReferenceSpace create_view = nullptr;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = layer_state().emulated.get();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.CreateActionSpace;
      auto s = e->sessions.find(session);
      if (createInfo == nullptr || s == e->sessions.end()) return next(session, createInfo, space);
      auto a = s->second.gaze_actions.find(createInfo->action);
      const bool gaze = a != s->second.gaze_actions.end() && !a->second.destroyed;
      const XrPath sub = createInfo->subactionPath;
      // /user/eyes_ext is this layer's: any pose action created with it gets its space here (one
      // that is not a gaze action is never located), and the runtime never sees the path.
      const bool eyes = sub != XR_NULL_PATH && sub == e->paths.eyes_user;
      if (!eyes && !(gaze && sub == XR_NULL_PATH)) return next(session, createInfo, space);
      auto rec = e->actions.find(createInfo->action);
      if (rec == e->actions.end() || rec->second.handle_destroyed) return next(session, createInfo, space);
      if (createInfo->type != XR_TYPE_ACTION_SPACE_CREATE_INFO || space == nullptr) return XR_ERROR_VALIDATION_FAILURE;
      if (rec->second.type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
      if (eyes && !rec->second.eyes_subaction) return XR_ERROR_PATH_UNSUPPORTED;
      if (!is_unit_orientation(createInfo->poseInActionSpace)) return XR_ERROR_POSE_INVALID;
      create_view = e->next.CreateReferenceSpace;
    }
    XrReferenceSpaceCreateInfo view{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    view.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    view.poseInReferenceSpace.orientation.w = 1.0f;
    const XrResult r = create_view(session, &view, space);
    if (XR_FAILED(r)) return r;
    Lock lock(layer_state().mutex);
    if (EmulatedInstance* e = layer_state().emulated.get())
      e->gaze_spaces[*space] = GazeSpace{session, createInfo->action, from_xr(createInfo->poseInActionSpace)};
    return r;
  });
}

XrResult DestroySpace(XrSpace space) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrDestroySpace next = nullptr;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = layer_state().emulated.get();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.DestroySpace;
      e->gaze_spaces.erase(space);
    }
    return next(space);
  });
}

XrResult LocateSpace(XrSpace space, XrSpace baseSpace, XrTime time, XrSpaceLocation* location) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrLocateSpace next = nullptr;
    EyeAt of_space, of_base;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = layer_state().emulated.get();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.LocateSpace;
      if (!e->gaze_spaces.empty() && time > 0) {
        of_space = eye_at(*e, space, static_cast<std::int64_t>(time));
        of_base = eye_at(*e, baseSpace, static_cast<std::int64_t>(time));
      }
    }
    return locate_pair(next, space, baseSpace, time, of_space, of_base, location);
  });
}

}  // namespace gazelod::layer
