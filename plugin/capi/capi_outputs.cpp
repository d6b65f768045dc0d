// SPDX-License-Identifier: Apache-2.0
// Readers of the last published frame (include/gazelod/gazelod.h): they take only the short
// publication lock, never the one a frame holds while it is decided.
#include "plugin/capi/capi_errors.hpp"

using namespace gazelod::capi;

extern "C" {

GZL_API gzl_result gzl_get_levels(gzl_plugin p, uint32_t count, const gzl_object* objects, uint8_t* levels) {
  return guarded(p, [&]() -> gzl_result {
    need_plugin(p);
    if (count == 0) return GZL_SUCCESS;
    if (objects == nullptr || levels == nullptr)
      throw Refusal{GZL_ERROR_NULL_POINTER, "gazelod: objects and levels must not be NULL when count > 0"};
    std::lock_guard lock(p->out_mu);
    for (std::uint32_t i = 0; i < count; ++i) {
      const gzl_object h = objects[i];
      const std::string why = p->pub.rows.refuse(h, p->tag);
      if (!why.empty())
        throw Refusal{GZL_ERROR_OBJECT_INVALID,
                      "gazelod: objects[" + std::to_string(i) + "] = " + std::to_string(h) + " " + why};
      levels[i] = p->pub.level_by_row[split_handle(h).index];
    }
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_get_frame_info(gzl_plugin p, gzl_frame_info* info) {
  return guarded(p, [&]() -> gzl_result {
    need_plugin(p);
    if (info == nullptr) throw Refusal{GZL_ERROR_NULL_POINTER, "gazelod: info (the output) is NULL"};
    if (info->type != GZL_TYPE_FRAME_INFO)
      throw Refusal{GZL_ERROR_STRUCT_TYPE, "gazelod: info->type must be GZL_TYPE_FRAME_INFO"};
    void* next = info->next;
    std::lock_guard lock(p->out_mu);
    *info = p->pub.info;
    info->next = next;
    // Triangles of the published levels, summed here rather than in every frame.
    const Published& pub = p->pub;
    info->triangles_drawn = info->triangles_full = 0;
    for (std::size_t r = 0; r < pub.level_by_row.size(); ++r) {
      if (!pub.rows.live[r] || !pub.decided_by_row[r] || pub.level_by_row[r] == GZL_LEVEL_DISABLED) continue;
      const std::uint32_t* tri = pub.level_triangles.data() + pub.triangles_first_by_row[r];
      info->triangles_drawn += tri[pub.level_by_row[r]];
      info->triangles_full += tri[0];
    }
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_get_foveal_cone(gzl_plugin p, uint32_t view, gzl_foveal_cone* cone) {
  return guarded(p, [&]() -> gzl_result {
    need_plugin(p);
    if (cone == nullptr) throw Refusal{GZL_ERROR_NULL_POINTER, "gazelod: cone (the output) is NULL"};
    if (cone->type != GZL_TYPE_FOVEAL_CONE)
      throw Refusal{GZL_ERROR_STRUCT_TYPE, "gazelod: cone->type must be GZL_TYPE_FOVEAL_CONE"};
    void* next = cone->next;
    std::lock_guard lock(p->out_mu);
    if (view >= p->pub.record.view_count)
      throw Refusal{GZL_ERROR_INVALID_ARGUMENT, "gazelod: view " + std::to_string(view) +
                                                    " out of range: the last frame had " +
                                                    std::to_string(p->pub.record.view_count) + " views"};
    *cone = p->pub.cones[view];
    cone->next = next;
    return GZL_SUCCESS;
  });
}

GZL_API gzl_result gzl_get_frame_record(gzl_plugin p, gzl_frame_record* record) {
  return guarded(p, [&]() -> gzl_result {
    need_plugin(p);
    if (record == nullptr) throw Refusal{GZL_ERROR_NULL_POINTER, "gazelod: record (the output) is NULL"};
    if (record->type != GZL_TYPE_FRAME_RECORD)
      throw Refusal{GZL_ERROR_STRUCT_TYPE, "gazelod: record->type must be GZL_TYPE_FRAME_RECORD"};
    void* next = record->next;
    std::lock_guard lock(p->out_mu);
    *record = p->pub.record;
    record->next = next;
    return GZL_SUCCESS;
  });
}

}  // extern "C"
