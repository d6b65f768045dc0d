// SPDX-License-Identifier: Apache-2.0
// Reference and action spaces and xrLocateSpace with XrSpaceVelocity and
// XrEyeGazeSampleTimeEXT (OpenXR 1.0 chapter 7 "Spaces", XR_EXT_eye_gaze_interaction), and
// xrLocateSpacesKHR with XrSpaceVelocitiesKHR (XR_KHR_locate_spaces).
#include "sim/runtime/action_bindings.hpp"
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/space_locate.hpp"

namespace gazelod::xrrt {
namespace {

bool supported_reference(XrReferenceSpaceType t) {
  return t == XR_REFERENCE_SPACE_TYPE_VIEW || t == XR_REFERENCE_SPACE_TYPE_LOCAL || t == XR_REFERENCE_SPACE_TYPE_STAGE;
}

XrSpace add_space(std::unique_ptr<Space> space) {
  Runtime& rt = runtime();
  space->id = rt.next_id++;
  const XrSpace h = to_handle<XrSpace>(space->id);
  rt.spaces.live.emplace(space->id, std::move(space));
  return h;
}

// a's pose in b, with the location bits both allow.
void where_relative(const Located& la, const Located& lb, XrSpaceLocationDataKHR& out) {
  const bool valid = la.valid && lb.valid;
  out.pose = to_xr(valid ? compose(inverse(lb.pose), la.pose) : Pose{});
  out.locationFlags = 0;
  if (valid) out.locationFlags |= XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT;
  if (valid && la.tracked && lb.tracked)
    out.locationFlags |= XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT | XR_SPACE_LOCATION_POSITION_TRACKED_BIT;
}

// a's velocity seen from b, when both have one.
void velocity_relative(const Located& la, const Located& lb, XrSpaceVelocityDataKHR& out) {
  out = XrSpaceVelocityDataKHR{};
  if (!(la.valid && lb.valid && la.has_velocity && lb.has_velocity)) return;
  // Relative motion of a's origin seen from b, in b's axes.
  const glm::dquat to_b = glm::conjugate(lb.pose.orientation);
  const glm::dvec3 w = to_b * (la.angular_rad_s - lb.angular_rad_s);
  const glm::dvec3 lin =
      to_b * ((la.linear_m_s - lb.linear_m_s) - glm::cross(lb.angular_rad_s, la.pose.position - lb.pose.position));
  out.angularVelocity = to_xr(w);
  out.linearVelocity = to_xr(lin);
  out.velocityFlags = XR_SPACE_VELOCITY_LINEAR_VALID_BIT | XR_SPACE_VELOCITY_ANGULAR_VALID_BIT;
}

}  // namespace

XrResult EnumerateReferenceSpaces(XrSession session, uint32_t capacity, uint32_t* count, XrReferenceSpaceType* spaces) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (find_session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    return two_call(capacity, count, spaces,
                    std::vector<XrReferenceSpaceType>{XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL,
                                                      XR_REFERENCE_SPACE_TYPE_STAGE});
  });
}

XrResult CreateReferenceSpace(XrSession session, const XrReferenceSpaceCreateInfo* info, XrSpace* space) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || space == nullptr || info->type != XR_TYPE_REFERENCE_SPACE_CREATE_INFO)
      return XR_ERROR_VALIDATION_FAILURE;
    if (!supported_reference(info->referenceSpaceType)) return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    if (!is_unit_orientation(info->poseInReferenceSpace)) return XR_ERROR_POSE_INVALID;
    auto sp = std::make_unique<Space>();
    sp->session_id = s->id;
    sp->kind = SpaceKind::reference;
    sp->reference = info->referenceSpaceType;
    sp->offset = info->poseInReferenceSpace;
    *space = add_space(std::move(sp));
    return XR_SUCCESS;
  });
}

XrResult GetReferenceSpaceBoundsRect(XrSession session, XrReferenceSpaceType type, XrExtent2Df* bounds) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (find_session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (bounds == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (!supported_reference(type)) return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    if (type == XR_REFERENCE_SPACE_TYPE_STAGE) {
      *bounds = {4.0f, 4.0f};  // a 4 m x 4 m play area
      return XR_SUCCESS;
    }
    *bounds = {0.0f, 0.0f};
    return XR_SPACE_BOUNDS_UNAVAILABLE;
  });
}

XrResult CreateActionSpace(XrSession session, const XrActionSpaceCreateInfo* info, XrSpace* space) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || space == nullptr || info->type != XR_TYPE_ACTION_SPACE_CREATE_INFO)
      return XR_ERROR_VALIDATION_FAILURE;
    const Action* a = find_action(info->action);
    if (a == nullptr || a->instance_id != s->instance_id) return XR_ERROR_HANDLE_INVALID;
    if (a->type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (XrResult r = check_subaction(*instance_of(*s), *a, info->subactionPath); r != XR_SUCCESS) return r;
    if (!is_unit_orientation(info->poseInActionSpace)) return XR_ERROR_POSE_INVALID;
    auto sp = std::make_unique<Space>();
    sp->session_id = s->id;
    sp->kind = SpaceKind::action;
    sp->action_id = a->id;
    sp->subaction = info->subactionPath;
    sp->offset = info->poseInActionSpace;
    *space = add_space(std::move(sp));
    return XR_SUCCESS;
  });
}

XrResult DestroySpace(XrSpace space) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (find_space(space) == nullptr) return XR_ERROR_HANDLE_INVALID;
    runtime().spaces.live.erase(handle_id(space));
    return XR_SUCCESS;
  });
}

XrResult LocateSpace(XrSpace space, XrSpace baseSpace, XrTime time, XrSpaceLocation* location) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    const Space* a = find_space(space);
    const Space* b = find_space(baseSpace);
    if (a == nullptr || b == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (a->session_id != b->session_id) return XR_ERROR_VALIDATION_FAILURE;
    if (location == nullptr || location->type != XR_TYPE_SPACE_LOCATION) return XR_ERROR_VALIDATION_FAILURE;
    if (time <= 0) return XR_ERROR_TIME_INVALID;
    Session& s = *runtime().sessions.find(a->session_id);
    Instance& inst = *instance_of(s);
    const Located la = locate_in_local(inst, s, *a, time);
    const Located lb = locate_in_local(inst, s, *b, time);
    XrSpaceLocationDataKHR where{};
    where_relative(la, lb, where);
    location->pose = where.pose;
    location->locationFlags = where.locationFlags;
    for (auto* n = static_cast<XrBaseOutStructure*>(location->next); n != nullptr; n = n->next) {
      if (n->type == XR_TYPE_SPACE_VELOCITY) {
        auto* v = reinterpret_cast<XrSpaceVelocity*>(n);
        XrSpaceVelocityDataKHR d{};
        velocity_relative(la, lb, d);
        v->velocityFlags = d.velocityFlags;
        v->linearVelocity = d.linearVelocity;
        v->angularVelocity = d.angularVelocity;
      } else if (n->type == XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT && inst.ext_eye_gaze) {
        reinterpret_cast<XrEyeGazeSampleTimeEXT*>(n)->time = la.is_gaze ? la.gaze_sample_time : 0;
      }
    }
    return XR_SUCCESS;
  });
}

// Each space located as xrLocateSpace locates it against the base.
XrResult LocateSpacesKHR(XrSession session, const XrSpacesLocateInfoKHR* info, XrSpaceLocationsKHR* locations) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_SPACES_LOCATE_INFO_KHR || locations == nullptr ||
        locations->type != XR_TYPE_SPACE_LOCATIONS_KHR)
      return XR_ERROR_VALIDATION_FAILURE;
    const std::uint32_t n = info->spaceCount;
    if (n == 0 || info->spaces == nullptr || locations->locationCount != n || locations->locations == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    XrSpaceVelocitiesKHR* velocities = nullptr;
    for (auto* c = static_cast<XrBaseOutStructure*>(locations->next); c != nullptr; c = c->next)
      if (c->type == XR_TYPE_SPACE_VELOCITIES_KHR) velocities = reinterpret_cast<XrSpaceVelocitiesKHR*>(c);
    if (velocities != nullptr && (velocities->velocityCount != n || velocities->velocities == nullptr))
      return XR_ERROR_VALIDATION_FAILURE;
    const Space* b = find_space(info->baseSpace);
    if (b == nullptr) return XR_ERROR_HANDLE_INVALID;
    std::vector<const Space*> spaces(n);
    for (std::uint32_t i = 0; i < n; ++i)
      if ((spaces[i] = find_space(info->spaces[i])) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (b->session_id != s->id) return XR_ERROR_VALIDATION_FAILURE;
    for (const Space* a : spaces)
      if (a->session_id != s->id) return XR_ERROR_VALIDATION_FAILURE;
    if (info->time <= 0) return XR_ERROR_TIME_INVALID;
    Instance& inst = *instance_of(*s);
    const Located lb = locate_in_local(inst, *s, *b, info->time);
    for (std::uint32_t i = 0; i < n; ++i) {
      const Located la = locate_in_local(inst, *s, *spaces[i], info->time);
      where_relative(la, lb, locations->locations[i]);
      if (velocities != nullptr) velocity_relative(la, lb, velocities->velocities[i]);
    }
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
