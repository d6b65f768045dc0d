// gazelod: the plugin an OpenXR application links. Created from the application's
// XrInstance, XrSession and base XrSpace; each frame at the predicted display time it reads
// head pose and velocity, per-eye views and gaze, and picks a level of detail per object
// (Reddy 1998 acuity model, Reddy 1995 foveal cone). Thin adapter: the math is in lod/.
//
//   auto plugin = gazelod::LodPlugin::create(instance, system, session, local_space, config);
//   for each object: plugin->add_object(desc);
//   frame: xrWaitFrame -> plugin->begin_frame(predicted_display_time) -> draw decisions
//          -> xrEndFrame -> plugin->end_frame(measured_ms)
#pragma once

#include "gaze/gaze_source.hpp"
#include "lod/lod_chain.hpp"
#include "plugin/frame_budget.hpp"

#include <glm/vec3.hpp>
#include <openxr/openxr.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace gazelod {

enum class GazeSourceKind : std::uint8_t { openxr, external, head_fixed };
const char* to_string(GazeSourceKind kind);

struct Criteria {
  bool size = true;
  bool eccentricity = true;
  bool velocity = true;
};

struct PluginConfig {
  // Try the runtime's XR_EXT_eye_gaze_interaction first (the instance must have enabled it).
  bool use_openxr_eye_gaze = true;
  // Set when the application attaches action sets of its own: it must then include
  // action_set() in its xrAttachSessionActionSets and xrSyncActions calls and call
  // action_sets_attached(). Otherwise the plugin attaches and syncs its own set.
  bool application_attaches_action_sets = false;
  // A further source tried when the runtime gives no gaze (a HID tracker, a trace replay).
  std::shared_ptr<gaze::GazeSource> external_source;
  // Display preset name overriding what the runtime reports ("" = from xrLocateViews and
  // the swapchain size).
  std::string hmd_override;
  Criteria criteria;
  // A runtime that advertises eye gaze but has delivered nothing this long after the
  // session became focused is not trusted any more (seconds).
  double gaze_silence_timeout_s = 1.0;
  // Angular error assumed for each source; inflates the foveal cone (degrees).
  double openxr_gaze_error_deg = 1.5;
  double external_gaze_error_deg = 2.0;
  // Without eye tracking gaze is head-fixed (straight ahead) and the cone is widened to
  // cover where the eyes usually are relative to the head (degrees).
  double head_fixed_cone_deg = 20.0;
  // Also select with the criteria sets size+eccentricity and size+velocity each frame, so a
  // report can split the reduction between the criteria (two more selections per frame).
  bool compute_breakdown = false;
  // Frame budget (ms, 0 = none): after the perceptual selection, Mason's incremental solver
  // coarsens levels so the predicted frame time (a cost model fit online from end_frame's
  // measured times) stays under the budget. Never finer than the perceptual choice.
  double budget_ms = 0.0;
  FrameBudgetOptions budget;
};

struct ObjectDesc {
  glm::dvec3 center_m{0.0};            // in the base space
  double radius_m = 0.5;               // bounding sphere
  glm::dvec3 velocity_m_s{0.0};
  std::vector<lod::LodLevel> lods;     // level 0 = full detail
  double importance = 1.0;
};

// Per-object outcome of one frame, indexed by object id.
struct FrameDecisions {
  std::span<const std::uint8_t> lod;             // chosen level (after the budget, if any)
  std::span<const std::uint8_t> lod_perceptual;  // the perceptual choice before the budget
  std::span<const std::uint8_t> limited_by;      // lod::Criterion value (see lod/select.hpp)
  std::span<const std::uint8_t> lod_size_only;   // what each criterion alone allows
  std::span<const std::uint8_t> lod_eccentricity_only;
  std::span<const std::uint8_t> lod_velocity_only;
  std::span<const std::uint8_t> lod_size_eccentricity;  // empty unless compute_breakdown
  std::span<const std::uint8_t> lod_size_velocity;      // empty unless compute_breakdown
  GazeSourceKind gaze_source = GazeSourceKind::head_fixed;
  bool gaze_valid = false;
  glm::dvec3 gaze_direction_world{0.0, 0.0, -1.0};
  glm::dvec3 gaze_direction_head{0.0, 0.0, -1.0};  // as the source gave it (head space)
  glm::dvec3 eye_position_world{0.0};
  glm::dvec3 head_angular_velocity_rad_s{0.0};   // base space
  double cone_inflation_deg = 0.0;
  double xi_cpd = 0.0;                             // display limit used this frame
  bool head_valid = false;
  // With a frame budget: the frame time the cost model predicts for `lod`, and whether even
  // the coarsest levels were predicted over the budget.
  double predicted_ms = 0.0;
  bool budget_infeasible = false;
};

class LodPlugin {
 public:
  using SourceChanged = std::function<void(GazeSourceKind now, const std::string& why)>;

  // Throws std::runtime_error with the failing OpenXR call's name and result.
  static std::unique_ptr<LodPlugin> create(XrInstance instance, XrSystemId system,
                                           XrSession session, XrSpace base_space,
                                           PluginConfig config);
  virtual ~LodPlugin() = default;

  // See PluginConfig::application_attaches_action_sets.
  virtual XrActionSet action_set() const = 0;
  virtual void action_sets_attached() = 0;

  // Registration (not per frame). Returns the object's id (0, 1, 2, ...).
  virtual std::uint32_t add_object(const ObjectDesc& desc) = 0;
  // Per-frame updates of moving objects; no allocation.
  virtual void set_object_motion(std::uint32_t id, const glm::dvec3& center_m,
                                 const glm::dvec3& velocity_m_s) = 0;
  virtual std::size_t object_count() const = 0;

  // Called when the session state changes (from the application's xrPollEvent loop).
  virtual void on_session_state(XrSessionState state, XrTime time) = 0;

  // At the frame's predicted display time: gaze, head, views, selection. The returned
  // spans stay valid until the next begin_frame. No allocation after the first frame.
  virtual const FrameDecisions& begin_frame(XrTime predicted_display_time) = 0;
  // The measured frame time (for the budget's cost model).
  virtual void end_frame(double measured_frame_ms) = 0;

  virtual GazeSourceKind active_source() const = 0;
  // Called once per change, with the reason ("runtime advertised eye gaze but delivered
  // none for 1.0 s", "HID tracker unplugged", ...).
  virtual void on_source_changed(SourceChanged callback) = 0;
};

}  // namespace gazelod
