// SPDX-License-Identifier: Apache-2.0
// xrEndFrame with composition layers in a gaze space (a gaze-locked reticle, say). The runtime
// knows the gaze space's handle only as a VIEW space, so it would draw such a layer head-locked.
// The layer submits, in its place, a copy whose space is still that VIEW handle and whose pose(s)
// are the eye-in-head pose at frameEndInfo->displayTime composed with the layer's: quad,
// cylinder, equirect and equirect2 `pose`, cube `orientation` (a cube map has no position),
// each projection view's `pose`. The other layers keep their pointers; only the header array and
// the changed layers are copied. Layer types the layer does not know go down as they are.
//
// Every layer still reaches the runtime, so its checks (swapchains, rectangles, the layer
// limit, the session) answer as they would without this layer: a pose that is not a unit
// quaternion goes down as the application gave it (the runtime refuses it; composing would have
// normalised it), and without a fresh sample at displayTime (a blink, a lost tracker, the
// action inactive) the layer is placed by the eye it was last placed by (a reticle stays where
// the eye last was), or as given before it ever was.
#include "layer/entry_points.hpp"
#include "layer/gaze_space.hpp"

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace gazelod::layer {
namespace {

using Lock = std::lock_guard<std::mutex>;

// One changed layer. Each member starts with XrCompositionLayerBaseHeader's fields, so `base`
// names whichever was written (their common initial sequence).
union LayerCopy {
  XrCompositionLayerBaseHeader base;
  XrCompositionLayerProjection projection;
  XrCompositionLayerQuad quad;
  XrCompositionLayerCylinderKHR cylinder;
  XrCompositionLayerCubeKHR cube;
  XrCompositionLayerEquirectKHR equirect;
  XrCompositionLayerEquirect2KHR equirect2;
};

// What the copies point to, alive until the runtime's xrEndFrame returns (deques: stable).
struct Copies {
  std::deque<LayerCopy> layers;
  std::deque<std::vector<XrCompositionLayerProjectionView>> views;
};

// More than this many layers, or projection views, the layer does not read: the runtime
// refuses such a frame (its maxLayerCount is 16 or so) without reading the arrays, and an
// application's count past its array must not make the layer read past it first.
constexpr std::uint32_t kMaxLayersRead = 256;
constexpr std::uint32_t kMaxProjectionViews = 16;

bool placed_here(XrStructureType type) {
  switch (type) {
    case XR_TYPE_COMPOSITION_LAYER_PROJECTION:
    case XR_TYPE_COMPOSITION_LAYER_QUAD:
    case XR_TYPE_COMPOSITION_LAYER_CYLINDER_KHR:
    case XR_TYPE_COMPOSITION_LAYER_CUBE_KHR:
    case XR_TYPE_COMPOSITION_LAYER_EQUIRECT_KHR:
    case XR_TYPE_COMPOSITION_LAYER_EQUIRECT2_KHR:
      return true;
    default:
      return false;
  }
}

template <class T>
const T& as(const XrCompositionLayerBaseHeader* layer) {
  return *reinterpret_cast<const T*>(layer);
}

// `in_eye` (a pose in the gaze space) in the head.
XrPosef in_head(const Pose& eye, const XrPosef& in_eye) {
  return to_xr(compose(eye, from_xr(in_eye)));
}

// Whether every pose `layer` gives is a unit quaternion (else it goes down unchanged), and
// its projection views are few enough to copy (the view configurations have 1, 2 or 4).
bool placeable(const XrCompositionLayerBaseHeader* layer) {
  switch (layer->type) {
    case XR_TYPE_COMPOSITION_LAYER_QUAD:
      return is_unit_orientation(as<XrCompositionLayerQuad>(layer).pose);
    case XR_TYPE_COMPOSITION_LAYER_CYLINDER_KHR:
      return is_unit_orientation(as<XrCompositionLayerCylinderKHR>(layer).pose);
    case XR_TYPE_COMPOSITION_LAYER_EQUIRECT_KHR:
      return is_unit_orientation(as<XrCompositionLayerEquirectKHR>(layer).pose);
    case XR_TYPE_COMPOSITION_LAYER_EQUIRECT2_KHR:
      return is_unit_orientation(as<XrCompositionLayerEquirect2KHR>(layer).pose);
    case XR_TYPE_COMPOSITION_LAYER_CUBE_KHR:
      return is_unit_orientation(XrPosef{as<XrCompositionLayerCubeKHR>(layer).orientation, {0.0f, 0.0f, 0.0f}});
    case XR_TYPE_COMPOSITION_LAYER_PROJECTION: {
      const auto& p = as<XrCompositionLayerProjection>(layer);
      if (p.views == nullptr || p.viewCount > kMaxProjectionViews) return false;
      for (std::uint32_t v = 0; v < p.viewCount; ++v)
        if (!is_unit_orientation(p.views[v].pose)) return false;
      return true;
    }
    default:
      return false;
  }
}

// A copy of `layer` (of a type placed_here) with its pose(s) in the head.
const XrCompositionLayerBaseHeader* head_copy(const XrCompositionLayerBaseHeader* layer, const Pose& eye,
                                              Copies& copies) {
  LayerCopy& c = copies.layers.emplace_back();
  switch (layer->type) {
    case XR_TYPE_COMPOSITION_LAYER_QUAD:
      c.quad = as<XrCompositionLayerQuad>(layer);
      c.quad.pose = in_head(eye, c.quad.pose);
      break;
    case XR_TYPE_COMPOSITION_LAYER_CYLINDER_KHR:
      c.cylinder = as<XrCompositionLayerCylinderKHR>(layer);
      c.cylinder.pose = in_head(eye, c.cylinder.pose);
      break;
    case XR_TYPE_COMPOSITION_LAYER_EQUIRECT_KHR:
      c.equirect = as<XrCompositionLayerEquirectKHR>(layer);
      c.equirect.pose = in_head(eye, c.equirect.pose);
      break;
    case XR_TYPE_COMPOSITION_LAYER_EQUIRECT2_KHR:
      c.equirect2 = as<XrCompositionLayerEquirect2KHR>(layer);
      c.equirect2.pose = in_head(eye, c.equirect2.pose);
      break;
    case XR_TYPE_COMPOSITION_LAYER_CUBE_KHR:
      c.cube = as<XrCompositionLayerCubeKHR>(layer);
      c.cube.orientation = in_head(eye, XrPosef{c.cube.orientation, {0.0f, 0.0f, 0.0f}}).orientation;
      break;
    case XR_TYPE_COMPOSITION_LAYER_PROJECTION:
      c.projection = as<XrCompositionLayerProjection>(layer);
      if (c.projection.views != nullptr && c.projection.viewCount > 0) {
        auto& views = copies.views.emplace_back(c.projection.views, c.projection.views + c.projection.viewCount);
        for (XrCompositionLayerProjectionView& v : views) v.pose = in_head(eye, v.pose);
        c.projection.views = views.data();
      }
      break;
    default:
      copies.layers.pop_back();
      return layer;
  }
  return &c.base;
}

}  // namespace

XrResult EndFrame(XrSession session, const XrFrameEndInfo* frameEndInfo) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrEndFrame next = nullptr;
    std::vector<std::optional<Pose>> eyes;  // per layer: the eye to place it by, if in a gaze space
    bool gaze = false;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = layer_state().emulated.get();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.EndFrame;
      const XrFrameEndInfo* info = frameEndInfo;
      if (info != nullptr && info->type == XR_TYPE_FRAME_END_INFO && info->displayTime > 0 && info->layers != nullptr &&
          info->layerCount <= kMaxLayersRead && !e->gaze_spaces.empty()) {
        eyes.resize(info->layerCount);
        for (std::uint32_t i = 0; i < info->layerCount; ++i) {
          const XrCompositionLayerBaseHeader* layer = info->layers[i];
          if (layer == nullptr || !placed_here(layer->type)) continue;
          auto g = e->gaze_spaces.find(layer->space);
          // Another session's gaze space: the runtime's to refuse.
          if (g == e->gaze_spaces.end() || g->second.session != session || !placeable(layer)) continue;
          const EyeAt at = eye_at(*e, layer->space, static_cast<std::int64_t>(info->displayTime));
          if (at.eye) g->second.last_layer_eye = at.eye;
          eyes[i] = g->second.last_layer_eye;
          gaze = gaze || eyes[i].has_value();
        }
      }
    }
    if (!gaze) return next(session, frameEndInfo);
    Copies copies;
    std::vector<const XrCompositionLayerBaseHeader*> layers(frameEndInfo->layers,
                                                            frameEndInfo->layers + frameEndInfo->layerCount);
    for (std::uint32_t i = 0; i < frameEndInfo->layerCount; ++i)
      if (eyes[i]) layers[i] = head_copy(layers[i], *eyes[i], copies);
    XrFrameEndInfo down = *frameEndInfo;
    down.layers = layers.data();
    return next(session, &down);
  });
}

}  // namespace gazelod::layer
