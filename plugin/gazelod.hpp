// gazelod: the plugin an OpenXR application links. Created from the application's
// XrInstance, XrSession and base XrSpace; each frame at the predicted display time it reads
// head pose and velocity, per-eye views and gaze, and picks a level of detail per object
// (Reddy 1998 acuity model, Reddy 1995 foveal cone). Thin adapter: the math is in lod/.
//
//   auto plugin = gazelod::LodPlugin::create(instance, system, session, local_space, config);
//   for each object: plugin->add_object(desc);            (one level per object: LOD chains)
//   for each large mesh: plugin->add_cluster_mesh(desc);  (detail per region: a cluster hierarchy)
//   frame: xrWaitFrame -> plugin->begin_frame(predicted_display_time) -> draw decisions.lod
//          and the clusters with decisions.cluster_drawn -> xrEndFrame -> plugin->end_frame(ms)
// Configuration: plugin/plugin_config.hpp; the per-frame output: plugin/frame_output.hpp.
#pragma once

#include "lod/cluster_hierarchy.hpp"
#include "lod/cluster_select_store.hpp"
#include "lod/lod_chain.hpp"
#include "plugin/frame_output.hpp"
#include "plugin/gaze_source_kind.hpp"
#include "plugin/plugin_config.hpp"

#include <glm/vec3.hpp>
#include <openxr/openxr.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gazelod {

struct ObjectDesc {
  glm::dvec3 center_m{0.0};            // in the base space
  double radius_m = 0.5;               // bounding sphere
  glm::dvec3 velocity_m_s{0.0};
  std::vector<lod::LodLevel> lods;     // level 0 = full detail
  double importance = 1.0;
};

// A mesh drawn as a cut of its cluster hierarchy (gazelod bake --clusters; lod/cluster_select.hpp):
// each cluster is drawn where its own simplification error is invisible and its parent's is
// not, with Reddy's rule per cluster, so detail follows the fovea across one mesh.
struct ClusterMeshDesc {
  lod::ClusterHierarchy hierarchy;     // the mesh's own space
  std::size_t index_count = 0;         // size of the mesh's index buffer (the clusters' ranges lie in it)
  lod::InstanceTransform pose;         // mesh space -> base space (rotation, translation, uniform scale)
  glm::dvec3 velocity_m_s{0.0};        // in the base space
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
  // Registration of a cluster mesh; returns its id (0, 1, 2, ...). Its clusters are
  // FrameDecisions::cluster_drawn[cluster_first[id] ...]. Throws std::invalid_argument with
  // the reason for an inconsistent hierarchy (lod::validate_cluster_hierarchy) or pose.
  virtual std::uint32_t add_cluster_mesh(const ClusterMeshDesc& desc) = 0;
  // A cluster mesh moved (per frame, no allocation; linear in its clusters): its new pose and
  // velocity, both in the base space, as in ClusterMeshDesc. Throws std::out_of_range for an
  // unknown id, std::invalid_argument for a pose or velocity that is not finite (or a zero
  // rotation, a scale <= 0); the mesh keeps its previous pose then.
  virtual void set_cluster_mesh_motion(std::uint32_t id, const lod::InstanceTransform& pose,
                                       const glm::dvec3& velocity_m_s) = 0;
  virtual std::size_t cluster_mesh_count() const = 0;

  // Called when the session state changes (from the application's xrPollEvent loop).
  virtual void on_session_state(XrSessionState state, XrTime time) = 0;

  // At the frame's predicted display time: gaze, head, views, selection. The returned
  // spans stay valid until the next begin_frame. No allocation after the first frame.
  virtual const FrameDecisions& begin_frame(XrTime predicted_display_time) = 0;
  // How the last begin_frame decided (valid until the next one).
  virtual const FrameDiagnostics& diagnostics() const = 0;
  // The measured frame time (for the budget's cost model).
  virtual void end_frame(double measured_frame_ms) = 0;

  virtual GazeSourceKind active_source() const = 0;
  // Called once per change, with the reason ("runtime advertised eye gaze but delivered
  // none for 1.0 s", "HID tracker unplugged", ...).
  virtual void on_source_changed(SourceChanged callback) = 0;
};

}  // namespace gazelod
