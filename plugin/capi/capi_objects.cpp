// SPDX-License-Identifier: Apache-2.0
// Objects through the C ABI: stable handles over the engine's dense ids (include/gazelod/gazelod.h).
#include "plugin/capi/capi_convert.hpp"
#include "plugin/capi/capi_errors.hpp"

#include <limits>

using namespace gazelod;
using namespace gazelod::capi;

namespace {

constexpr std::uint32_t kRemoved = std::numeric_limits<std::uint32_t>::max();

// The engine id of a live handle, or a Refusal naming the handle.
std::uint32_t slot_of(gzl_plugin p, gzl_object h) {
  if (h == GZL_NULL_OBJECT || h > p->slot_of_handle.size())
    throw Refusal{GZL_ERROR_OBJECT_INVALID,
                  "gazelod: object " + std::to_string(h) + " was never issued by this plugin"};
  const std::uint32_t s = p->slot_of_handle[h - 1];
  if (s == kRemoved) throw Refusal{GZL_ERROR_OBJECT_INVALID, "gazelod: object " + std::to_string(h) + " was removed"};
  return s;
}

int view_height_px(gzl_plugin p) {
  if (p->openxr) return p->xr->max_view_height_px();
  // With quad views the primary pair (views 0 and 1) is what a share of "the screen" means.
  std::uint32_t h = 0;
  for (std::uint32_t i = 0; i < p->view_count && i < 2; ++i) h = std::max(h, p->data_views[i].height_px);
  return static_cast<int>(h);
}

}  // namespace

extern "C" {

GZL_API gzl_result gzl_add_object(gzl_plugin p, const gzl_object_desc* d, gzl_object* object) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    if (object == nullptr) throw Refusal{GZL_ERROR_NULL_POINTER, "gazelod: object (the output) is NULL"};
    *object = GZL_NULL_OBJECT;
    need_struct(d, GZL_TYPE_OBJECT_DESC, "desc");
    std::lock_guard lock(p->mu);
    ObjectDesc desc;
    desc.center_m = to_vec(d->center_m, "desc->center_m");
    desc.velocity_m_s = to_vec(d->velocity_m_s, "desc->velocity_m_s");
    if (!std::isfinite(d->radius_m) || d->radius_m < 0.0)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, "gazelod: desc->radius_m must be finite and >= 0"};
    desc.radius_m = d->radius_m;
    if (!std::isfinite(d->importance) || d->importance < 0.0 || d->importance > 1.0)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, "gazelod: desc->importance must be in [0, 1] (0 means 1)"};
    desc.importance = d->importance == 0.0 ? 1.0 : d->importance;
    desc.lods = to_levels(*d, view_height_px(p));
    if (p->slot_of_handle.size() >= kRemoved - 1)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, "gazelod: this plugin has issued 2^32 - 2 handles; create a new one"};
    // Room first (so a failed allocation leaves nothing half registered), then the engine.
    p->slot_of_handle.reserve(p->slot_of_handle.size() + 1);
    p->handle_index_of_slot.reserve(p->handle_index_of_slot.size() + 1);
    {
      std::lock_guard out(p->out_mu);
      p->pub.level_by_handle.reserve(p->slot_of_handle.size() + 1);
      p->pub.state_by_handle.reserve(p->slot_of_handle.size() + 1);
      p->pub.triangles_first_by_handle.reserve(p->slot_of_handle.size() + 1);
      p->pub.level_triangles.reserve(p->pub.level_triangles.size() + desc.lods.size());
    }
    std::uint32_t slot = 0;
    try {
      slot = p->core().add_object(desc);
    } catch (const std::invalid_argument& e) {
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, std::string("gazelod: desc->levels: ") + e.what()};
    }
    const auto index = static_cast<std::uint32_t>(p->slot_of_handle.size());
    p->slot_of_handle.push_back(slot);
    p->handle_index_of_slot.push_back(index);
    {
      std::lock_guard out(p->out_mu);
      p->pub.level_by_handle.push_back(0);  // full detail until a frame decides
      p->pub.state_by_handle.push_back(kHandleIssued);
      p->pub.triangles_first_by_handle.push_back(static_cast<std::uint32_t>(p->pub.level_triangles.size()));
      for (const lod::LodLevel& l : desc.lods) p->pub.level_triangles.push_back(l.triangles);
    }
    *object = static_cast<gzl_object>(index) + 1;
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_remove_object(gzl_plugin p, gzl_object h) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    std::lock_guard lock(p->mu);
    const std::uint32_t slot = slot_of(p, h);
    if (!p->core().object_enabled(slot)) --p->disabled;
    const std::uint32_t moved_from = p->core().remove_object(slot);  // the last slot moved into `slot`
    p->dense = false;
    if (moved_from != slot) {
      const std::uint32_t moved_index = p->handle_index_of_slot[moved_from];
      p->handle_index_of_slot[slot] = moved_index;
      p->slot_of_handle[moved_index] = slot;
    }
    p->handle_index_of_slot.pop_back();
    p->slot_of_handle[h - 1] = kRemoved;
    std::lock_guard out(p->out_mu);
    p->pub.state_by_handle[h - 1] = kHandleRemoved;
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_set_object_enabled(gzl_plugin p, gzl_object h, gzl_bool32 enabled) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    std::lock_guard lock(p->mu);
    const std::uint32_t slot = slot_of(p, h);
    const bool was = p->core().object_enabled(slot), now = enabled != 0;
    if (was != now) now ? --p->disabled : ++p->disabled;
    p->core().set_object_enabled(slot, now);
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_set_object_motion(gzl_plugin p, gzl_object h, const gzl_vec3* center_m,
                                         const gzl_vec3* velocity_m_s) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    if (center_m == nullptr || velocity_m_s == nullptr)
      throw Refusal{GZL_ERROR_NULL_POINTER, "gazelod: center_m and velocity_m_s must not be NULL"};
    const glm::dvec3 c = to_vec(*center_m, "center_m"), v = to_vec(*velocity_m_s, "velocity_m_s");
    std::lock_guard lock(p->mu);
    p->core().set_object_motion(slot_of(p, h), c, v);
    return GZL_SUCCESS;
  });
}

}  // extern "C"
