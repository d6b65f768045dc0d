// SPDX-License-Identifier: Apache-2.0
// xrLocateViews: one view per eye, placed half the IPD either side of the head pose from the
// scenario's head script, with the display's per-eye field of view.
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/space_locate.hpp"
#include "sim/runtime/system_info.hpp"

namespace gazelod::xrrt {

XrResult LocateViews(XrSession session, const XrViewLocateInfo* info, XrViewState* viewState, uint32_t capacity,
                     uint32_t* count, XrView* views) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_VIEW_LOCATE_INFO || viewState == nullptr ||
        viewState->type != XR_TYPE_VIEW_STATE || count == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    const Space* base = find_space(info->space);
    if (base == nullptr || base->session_id != s->id) return XR_ERROR_HANDLE_INVALID;
    if (info->viewConfigurationType != s->view_config) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (info->displayTime <= 0) return XR_ERROR_TIME_INVALID;
    Instance& inst = *instance_of(*s);
    const std::uint32_t n = view_count(inst);
    *count = n;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < n) return XR_ERROR_SIZE_INSUFFICIENT;
    if (views == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    for (std::uint32_t i = 0; i < n; ++i)
      if (views[i].type != XR_TYPE_VIEW) return XR_ERROR_VALIDATION_FAILURE;

    Space head_space;
    head_space.kind = SpaceKind::reference;
    head_space.reference = XR_REFERENCE_SPACE_TYPE_VIEW;
    head_space.offset.orientation.w = 1.0f;
    const Located head = locate_in_local(inst, *s, head_space, info->displayTime);
    const Located b = locate_in_local(inst, *s, *base, info->displayTime);
    viewState->viewStateFlags = 0;
    if (head.valid && b.valid)
      viewState->viewStateFlags = XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT |
                                  XR_VIEW_STATE_ORIENTATION_TRACKED_BIT | XR_VIEW_STATE_POSITION_TRACKED_BIT;
    const lod::DisplaySpec& d = inst.simulator->scenario().display;
    const Pose to_base = inverse(b.pose);
    for (std::uint32_t i = 0; i < n; ++i) {
      const double x = n == 1 ? 0.0 : (i == 0 ? -0.5 : 0.5) * kIpdM;
      const Pose eye = compose(head.pose, Pose{glm::dquat(1, 0, 0, 0), glm::dvec3(x, 0.0, 0.0)});
      views[i].pose = to_xr(compose(to_base, eye));
      const lod::FovRad& f = d.views[i].fov;
      views[i].fov = {float(f.angle_left_rad), float(f.angle_right_rad), float(f.angle_up_rad),
                      float(f.angle_down_rad)};
    }
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
