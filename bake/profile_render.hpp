// SPDX-License-Identifier: Apache-2.0
// Reddy's perceptual profile of an LOD chain (Reddy 1998 sections 3.2-3.3, Figure 1): render the
// full model and every level offscreen (Vulkan, lavapipe) from 6 or 18 viewpoints on the view
// sphere, all looking at the centre; per level and viewpoint, the frequency of the difference
// image against the full model (profile_spectrum.hpp), in cycles per object diameter.
// Per level the figure is the MINIMUM over viewpoints: lod::select_lods may use a level when
// its figure lies above the acuity limit, so the lowest (most visible) frequency any viewpoint
// shows is the conservative choice. Viewpoints where the level looks identical are skipped; a
// level identical from every viewpoint removes nothing the render resolves and gets the
// render's Nyquist limit. Figures are made non-increasing along the chain (running minimum),
// as the geometric errors are made non-decreasing.
#pragma once

#include "render/device_context.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace gazelod::bake {

struct ProfileOptions {
  int viewpoints = 6;            // 6 (cube faces) or 18 (faces + edges), Reddy 1998 Figure 1
  std::uint32_t image_px = 256;  // square; power of two in [16, 1024]
  double half_fov_deg = 5.0;     // narrow perspective whose view just encloses the bounding sphere
};

// Unit directions from the centre to the viewpoints: the 6 cube faces, then the 12 edges.
// Throws std::invalid_argument unless `viewpoints` is 6 or 18.
std::vector<glm::dvec3> view_directions(int viewpoints);

struct LevelProfile {
  double rendered_cycles_per_diameter = 0.0;         // the level's figure (0 at level 0)
  std::vector<double> per_view_cycles_per_diameter;  // < 0 where the view shows no difference
};

class Profiler {
 public:
  // Creates its own OffscreenDevice (no validation layer, for speed). Throws
  // std::invalid_argument for bad options, render::NoVulkanDevice without Vulkan.
  explicit Profiler(ProfileOptions options = {});
  ~Profiler();
  Profiler(const Profiler&) = delete;
  Profiler& operator=(const Profiler&) = delete;

  // positions_xyz: the mesh's vertices (3 floats each, finite); levels[0] the full mesh's
  // triangle list, levels[k] level k's, all indexing positions_xyz. One result per level.
  // Throws render::RenderError (bad indices included).
  std::vector<LevelProfile> profile(std::span<const float> positions_xyz,
                                    const std::vector<std::vector<std::uint32_t>>& levels);

  // Figure given to a level that differs from no viewpoint: the render's Nyquist frequency.
  double nyquist_cycles_per_diameter() const;
  const ProfileOptions& options() const { return options_; }

 private:
  ProfileOptions options_;
  std::unique_ptr<render::OffscreenDevice> device_;
};

}  // namespace gazelod::bake
