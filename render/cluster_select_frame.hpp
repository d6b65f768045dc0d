// SPDX-License-Identifier: Apache-2.0
// The per-frame inputs of shaders/cluster_select.comp (shaders/cluster_select_gpu.h) from a
// lod::Viewer and an optional culling view: select_clusters' own float constants
// (lod::detail::make_cluster_frame and make_cluster_mesh_frame, lod/cluster/cluster_select_kernel.hpp),
// copied bit for bit, plus the terms geometry_loop derives from them in float, so that the
// shader starts from exactly what the CPU kernel starts from. Where the CPU uses +inf (size off,
// a size-on mesh's distance cap) the block says so without one (use_size, FLT_MAX): a device
// may assume no infinities. No Vulkan here.
#pragma once

#include "lod/cluster/cluster_select.hpp"
#include "render/camera.hpp"
#include "shaders/cluster_select_gpu.h"

#include <cstddef>

namespace gazelod::render {

// viewer valid (lod::validate_viewer). cull_view null: cull 0 (a command for every drawn
// cluster); else its frustum (ViewCuller's planes, near and far). Throws RenderError for a
// degenerate cull view (projection_matrix's rules).
gzl_cluster_select_frame make_cluster_select_frame(const lod::Viewer& viewer, const EyeView* cull_view);

// Mesh `mesh` of `clusters` (only the mesh arrays are read: velocities, finest errors), its
// errors divided by detail_scale (>= 1, lod::check_detail_scales; a frame budget's step).
gzl_cluster_select_mesh make_cluster_select_mesh(const lod::Viewer& viewer, const lod::ClusterSet& clusters,
                                                 std::size_t mesh, double detail_scale = 1.0);

}  // namespace gazelod::render
