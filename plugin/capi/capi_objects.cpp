// SPDX-License-Identifier: Apache-2.0
// Objects through the C ABI: stable handles over the engine's dense ids (include/gazelod/gazelod.h).
#include "plugin/capi/capi_convert.hpp"
#include "plugin/capi/capi_errors.hpp"

#include <algorithm>
#include <limits>

using namespace gazelod;
using namespace gazelod::capi;

namespace {

// The engine id of a live handle, or a Refusal naming the handle.
std::uint32_t slot_of(gzl_plugin p, gzl_object h) {
  const std::string why = p->pub.rows.refuse(h, p->tag);  // rows change only under mu, held here
  if (!why.empty()) throw Refusal{GZL_ERROR_OBJECT_INVALID, "gazelod: object " + std::to_string(h) + " " + why};
  return p->slot_of_row[split_handle(h).index];
}

// Room for `more` elements, growing geometrically: reserve() alone allocates exactly what it is
// asked for, and one more element per registration made adding n objects O(n^2).
template <typename T>
void make_room(std::vector<T>& v, std::size_t more = 1) {
  if (v.size() + more > v.capacity()) v.reserve(std::max(v.size() + more, 2 * v.capacity()));
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
    const auto lock = lock_live(p);
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
    // The row: the last freed one, else a new one.
    const bool reuse = !p->free_rows.empty();
    if (!reuse && p->slot_of_row.size() >= kMaxRows)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, "gazelod: this plugin holds 2^32 - 2 objects; create a new one"};
    const auto row = reuse ? p->free_rows.back() : static_cast<std::uint32_t>(p->slot_of_row.size());
    Published& pub = p->pub;
    const bool new_block = !reuse || pub.triangles_room_by_row[row] < desc.lods.size();
    // Room first (so a failed allocation leaves nothing half registered), then the engine.
    make_room(p->row_of_slot);
    if (!reuse) {
      make_room(p->slot_of_row);
      p->free_rows.reserve(p->slot_of_row.capacity());  // so that a removal never allocates
    }
    {
      std::lock_guard out(p->out_mu);
      if (!reuse) {
        make_room(pub.rows.generation), make_room(pub.rows.live), make_room(pub.level_by_row);
        make_room(pub.decided_by_row), make_room(pub.triangles_first_by_row), make_room(pub.triangles_room_by_row);
      }
      if (new_block) make_room(pub.level_triangles, desc.lods.size());
    }
    std::uint32_t slot = 0;
    try {
      slot = p->core().add_object(desc);
    } catch (const std::invalid_argument& e) {
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, std::string("gazelod: desc->levels: ") + e.what()};
    }
    // Nothing below allocates.
    p->row_of_slot.push_back(row);
    std::uint16_t generation = 0;
    if (reuse) {
      p->free_rows.pop_back();
      p->slot_of_row[row] = slot;
      generation = static_cast<std::uint16_t>(pub.rows.generation[row] + 1);
    } else {
      p->slot_of_row.push_back(slot);
    }
    {
      std::lock_guard out(p->out_mu);
      if (!reuse) {
        pub.rows.generation.push_back(0), pub.rows.live.push_back(0), pub.level_by_row.push_back(0);
        pub.decided_by_row.push_back(0), pub.triangles_first_by_row.push_back(0),
            pub.triangles_room_by_row.push_back(0);
      }
      pub.rows.generation[row] = generation;
      pub.rows.live[row] = 1;
      pub.level_by_row[row] = 0;  // full detail until a frame decides
      pub.decided_by_row[row] = 0;
      if (new_block) {
        pub.triangles_first_by_row[row] = static_cast<std::uint32_t>(pub.level_triangles.size());
        pub.triangles_room_by_row[row] = static_cast<std::uint8_t>(desc.lods.size());
        pub.level_triangles.resize(pub.level_triangles.size() + desc.lods.size());
      }
      std::uint32_t* tri = pub.level_triangles.data() + pub.triangles_first_by_row[row];
      for (const lod::LodLevel& l : desc.lods) *tri++ = l.triangles;
    }
    *object = make_handle(p->tag, generation, row);
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_remove_object(gzl_plugin p, gzl_object h) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    const auto lock = lock_live(p);
    const std::uint32_t slot = slot_of(p, h);
    if (!p->core().object_enabled(slot)) --p->disabled;
    const std::uint32_t moved_from = p->core().remove_object(slot);  // the last slot moved into `slot`
    p->dense = false;
    if (moved_from != slot) {
      const std::uint32_t moved_row = p->row_of_slot[moved_from];
      p->row_of_slot[slot] = moved_row;
      p->slot_of_row[moved_row] = slot;
    }
    p->row_of_slot.pop_back();
    const std::uint32_t row = split_handle(h).index;
    p->slot_of_row[row] = kNoSlot;
    // A row whose generations are spent is retired: its next handle would repeat an old one.
    // free_rows has room for every row (reserved when the row was made), so this cannot throw.
    if (p->pub.rows.generation[row] != kLastGeneration) p->free_rows.push_back(row);
    std::lock_guard out(p->out_mu);
    p->pub.rows.live[row] = 0;
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_set_object_enabled(gzl_plugin p, gzl_object h, gzl_bool32 enabled) {
  return guarded(p, [&]() -> gzl_result {
    need_live(p);
    const auto lock = lock_live(p);
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
    const auto lock = lock_live(p);
    p->core().set_object_motion(slot_of(p, h), c, v);
    return GZL_SUCCESS;
  });
}

}  // extern "C"
