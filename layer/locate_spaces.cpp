// SPDX-License-Identifier: Apache-2.0
// The other commands that locate in a space, with gaze spaces (gaze_space.hpp):
// - xrLocateSpacesKHR (XR_KHR_locate_spaces) and xrLocateSpaces (OpenXR 1.1), when the runtime
//   gives them: with no gaze space among the spaces or as the base, passed down unchanged;
//   otherwise answered space by space as xrLocateSpace answers (locate_pair, through the
//   runtime's xrLocateSpace), velocities as the runtime gives them except for the elements that
//   involve a gaze space (no velocity flags).
// - xrLocateViews in a gaze space: the runtime locates the views in the gaze space's VIEW handle
//   (the head); each view pose is then put in the eye. Without a fresh sample the views are not
//   located (no orientation / position bits, identity poses). Fields of view are unchanged.
#include "layer/entry_points.hpp"
#include "layer/gaze_space.hpp"

#include <vector>

namespace gazelod::layer {
namespace {

using Lock = std::lock_guard<std::mutex>;

constexpr XrViewStateFlags kAllViewBits = XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT |
                                          XR_VIEW_STATE_ORIENTATION_TRACKED_BIT | XR_VIEW_STATE_POSITION_TRACKED_BIT;

// The XrSpaceVelocitiesKHR chained on the locations, if any.
XrSpaceVelocitiesKHR* velocities_of(XrSpaceLocationsKHR* locations) {
  for (auto* n = static_cast<XrBaseOutStructure*>(locations->next); n != nullptr; n = n->next)
    if (n->type == XR_TYPE_SPACE_VELOCITIES_KHR) return reinterpret_cast<XrSpaceVelocitiesKHR*>(n);
  return nullptr;
}

// xrLocateSpacesKHR and xrLocateSpaces: one body; `which` picks the runtime's command to pass
// down to.
XrResult locate_spaces(PFN_xrLocateSpacesKHR NextDispatch::*which, XrSession session, const XrSpacesLocateInfoKHR* info,
                       XrSpaceLocationsKHR* locations) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrLocateSpacesKHR next = nullptr;
    PFN_xrLocateSpace locate_one = nullptr;
    EyeAt of_base;
    std::vector<EyeAt> of_spaces;
    bool gaze = false;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = layer_state().emulated.get();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.*which;
      locate_one = e->next.LocateSpace;
      if (next == nullptr) return XR_ERROR_FUNCTION_UNSUPPORTED;  // never handed out then
      if (info != nullptr && info->type == XR_TYPE_SPACES_LOCATE_INFO_KHR && info->time > 0 &&
          !e->gaze_spaces.empty() && (info->spaces != nullptr || info->spaceCount == 0)) {
        const auto t = static_cast<std::int64_t>(info->time);
        of_base = eye_at(*e, info->baseSpace, t);
        gaze = of_base.is_gaze;
        of_spaces.resize(info->spaceCount);
        for (std::uint32_t i = 0; i < info->spaceCount; ++i) {
          of_spaces[i] = eye_at(*e, info->spaces[i], t);
          gaze = gaze || of_spaces[i].is_gaze;
        }
        if (gaze) {
          // The runtime checks the other spaces against the session; the gaze spaces are ours.
          if (e->sessions.count(session) == 0) return XR_ERROR_HANDLE_INVALID;
          auto other_session = [&](XrSpace s) {
            auto g = e->gaze_spaces.find(s);
            return g != e->gaze_spaces.end() && g->second.session != session;
          };
          if (other_session(info->baseSpace)) return XR_ERROR_VALIDATION_FAILURE;
          for (std::uint32_t i = 0; i < info->spaceCount; ++i)
            if (other_session(info->spaces[i])) return XR_ERROR_VALIDATION_FAILURE;
        }
      }
    }
    if (!gaze) return next(session, info, locations);
    const std::uint32_t n = info->spaceCount;
    if (locations == nullptr || locations->type != XR_TYPE_SPACE_LOCATIONS_KHR || n == 0 ||
        locations->locationCount != n || locations->locations == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    XrSpaceVelocitiesKHR* velocities = velocities_of(locations);
    if (velocities != nullptr && (velocities->velocityCount != n || velocities->velocities == nullptr))
      return XR_ERROR_VALIDATION_FAILURE;
    XrResult result = XR_SUCCESS;  // or the first other success code (XR_SESSION_LOSS_PENDING)
    for (std::uint32_t i = 0; i < n; ++i) {
      XrSpaceVelocity velocity{XR_TYPE_SPACE_VELOCITY};
      XrSpaceLocation location{XR_TYPE_SPACE_LOCATION, velocities != nullptr ? &velocity : nullptr};
      const XrResult r =
          locate_pair(locate_one, info->spaces[i], info->baseSpace, info->time, of_spaces[i], of_base, &location);
      if (XR_FAILED(r)) return r;
      if (result == XR_SUCCESS) result = r;
      locations->locations[i] = XrSpaceLocationDataKHR{location.locationFlags, location.pose};
      if (velocities != nullptr)
        velocities->velocities[i] =
            XrSpaceVelocityDataKHR{velocity.velocityFlags, velocity.linearVelocity, velocity.angularVelocity};
    }
    return result;
  });
}

}  // namespace

XrResult LocateSpacesKHR(XrSession session, const XrSpacesLocateInfoKHR* locateInfo,
                         XrSpaceLocationsKHR* spaceLocations) {
  return locate_spaces(&NextDispatch::LocateSpacesKHR, session, locateInfo, spaceLocations);
}

XrResult LocateSpaces(XrSession session, const XrSpacesLocateInfoKHR* locateInfo, XrSpaceLocationsKHR* spaceLocations) {
  return locate_spaces(&NextDispatch::LocateSpaces, session, locateInfo, spaceLocations);
}

XrResult LocateViews(XrSession session, const XrViewLocateInfo* viewLocateInfo, XrViewState* viewState,
                     uint32_t viewCapacityInput, uint32_t* viewCountOutput, XrView* views) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrLocateViews next = nullptr;
    EyeAt eye;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = layer_state().emulated.get();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.LocateViews;
      if (viewLocateInfo != nullptr && viewLocateInfo->type == XR_TYPE_VIEW_LOCATE_INFO &&
          viewLocateInfo->displayTime > 0 && !e->gaze_spaces.empty())
        eye = eye_at(*e, viewLocateInfo->space, static_cast<std::int64_t>(viewLocateInfo->displayTime));
    }
    // In a gaze space, the runtime answers in its VIEW handle: the head.
    const XrResult r = next(session, viewLocateInfo, viewState, viewCapacityInput, viewCountOutput, views);
    if (!eye.is_gaze || XR_FAILED(r)) return r;
    const bool filled = viewCapacityInput != 0 && views != nullptr && viewCountOutput != nullptr &&
                        *viewCountOutput <= viewCapacityInput;
    if (!eye.eye && viewState != nullptr) viewState->viewStateFlags &= ~kAllViewBits;
    if (!filled) return r;
    const Pose to_eye = eye.eye ? inverse(*eye.eye) : Pose{};
    for (std::uint32_t i = 0; i < *viewCountOutput; ++i)
      views[i].pose = eye.eye ? to_xr(compose(to_eye, from_xr(views[i].pose)))
                              : XrPosef{{0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}};
    return r;
  });
}

}  // namespace gazelod::layer
