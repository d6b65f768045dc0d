// SPDX-License-Identifier: Apache-2.0
// What a gzl_plugin handle is (include/gazelod/gazelod.h): the engine in one of its two fronts,
// the stable object handles over the engine's dense ids, the last published frame, and the
// locks that make every call safe from any thread. Internal to libgazelod.
#pragma once

#include "auxiliary/time.hpp"
#include "gazelod/gazelod.h"
#include "plugin/capi/capi_handles.hpp"
#include "plugin/lod_core.hpp"
#include "plugin/lod_plugin.hpp"
#include "plugin/pushed_gaze.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace gazelod::capi {

// Data mode's front: the application gives head poses and views and pushes gaze samples.
struct DataFront {
  explicit DataFront(const PluginConfig& config)
      : core(config), pushed(heads, aux::ns_from_seconds(config.max_pushed_sample_age_s)) {
    core.set_primary(&pushed, GazeSourceKind::pushed, "");
    core.set_orientation_at([this](std::int64_t t_ns) -> std::optional<glm::dquat> {
      if (auto q = pushed.head_at_last_sample()) return q;
      return heads.at(t_ns);
    });
  }
  plugin::LodCore core;
  plugin::HeadHistory heads;
  plugin::PushedGazeSource pushed;
  plugin::HeadTracker head;  // velocities from successive poses where none are given
  bool have_frame = false;
  std::int64_t last_t_ns = 0;
};

struct Published {
  HandleRows rows;                           // by handle row (capi_handles.hpp)
  std::vector<std::uint8_t> level_by_row;    // the published level (0 until a frame decides)
  std::vector<std::uint8_t> decided_by_row;  // 1 when the published frame decided the row's object
  // Each row's triangles per level, in a block of level_triangles (written at registration, and
  // reused by the row's next object when its levels fit), so a frame publishes only its levels
  // and gzl_get_frame_info sums triangles when asked.
  std::vector<std::uint32_t> triangles_first_by_row;
  std::vector<std::uint8_t> triangles_room_by_row;  // levels the row's block holds
  std::vector<std::uint32_t> level_triangles;
  gzl_frame_info info{};
  std::array<gzl_foveal_cone, GZL_MAX_VIEWS> cones{};
  gzl_frame_record record{};
};

}  // namespace gazelod::capi

struct gzl_plugin_T {
  // Every call but the output readers holds this for its whole length (a frame too).
  std::mutex mu;
  // The published frame; held only to copy in or out, never across a frame's decision.
  std::mutex out_mu;
  // The last error message (copied out under its own lock).
  std::mutex err_mu;
  std::string last_error;
  std::string gaze_status;  // under err_mu too: the last source change's reason

  bool openxr = false;
  gzl_gaze_input gaze_input = GZL_GAZE_INPUT_NONE;  // OpenXR mode's
  // Set under mu by gzl_shutdown; read without it for an early refusal, and again under it
  // (lock_live) by every call that changes the plugin.
  std::atomic<bool> shut_down{false};
  std::unique_ptr<gazelod::LodPlugin> xr;          // OpenXR mode
  std::unique_ptr<gazelod::capi::DataFront> data;  // data mode
  std::uint32_t view_count = 0;
  std::array<gzl_view, GZL_MAX_VIEWS> data_views{};
  gazelod::PluginConfig config;

  // Object handles over the engine's dense ids (capi_handles.hpp): each row's engine id
  // (kNoSlot while free), each id's row, and the free rows, reused last-freed first.
  std::uint16_t tag = gazelod::capi::next_plugin_tag();
  std::vector<std::uint32_t> slot_of_row;
  std::vector<std::uint32_t> row_of_slot;
  std::vector<std::uint32_t> free_rows;
  // While no object was ever removed, row == engine id, and with none disabled a
  // frame's levels are published with one copy.
  bool dense = true;
  std::uint32_t disabled = 0;
  std::uint64_t frames = 0;

  gazelod::capi::Published pub;

  gazelod::plugin::LodCore& core() { return openxr ? xr->core() : data->core; }
};
