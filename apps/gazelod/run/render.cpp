// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/render.hpp"

#include "apps/gazelod/run/signals.hpp"
#include "auxiliary/atomic_file.hpp"
#include "auxiliary/angles.hpp"
#include "render/lod_key.hpp"
#include "render/camera.hpp"
#include "render/foveal_marker.hpp"
#include "render/png_io.hpp"
#include "render/render_error.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace gazelod::cli {
namespace {

render::EyeView to_eye_view(const XrView& v) {
  render::EyeView e;
  const XrQuaternionf& q = v.pose.orientation;
  e.pose.orientation = glm::dquat(q.w, q.x, q.y, q.z);
  e.pose.position_m = {v.pose.position.x, v.pose.position.y, v.pose.position.z};
  e.fov = {v.fov.angleLeft, v.fov.angleRight, v.fov.angleUp, v.fov.angleDown};
  return e;
}

// The mesh's positions posed into LOCAL space.
std::vector<glm::dvec3> posed_positions(const ClusterMesh& m) {
  const std::vector<float>& xyz = m.primitive->positions_xyz;
  std::vector<glm::dvec3> world(xyz.size() / 3);
  const glm::dquat rotation = glm::normalize(m.pose.rotation);
  for (std::size_t v = 0; v < world.size(); ++v)
    world[v] =
        m.pose.translation_m + m.pose.scale * (rotation * glm::dvec3(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
  return world;
}

// The sphere around the box of `points` (radius 1 for one point or none: any radius places it).
void bounding_sphere(std::span<const glm::dvec3> points, glm::dvec3& center_m, double& radius_m) {
  glm::dvec3 lo(0.0), hi(0.0);
  for (std::size_t v = 0; v < points.size(); ++v) {
    lo = v == 0 ? points[v] : glm::min(lo, points[v]);
    hi = v == 0 ? points[v] : glm::max(hi, points[v]);
  }
  center_m = 0.5 * (lo + hi);
  double r2 = 0.0;
  for (const glm::dvec3& p : points) r2 = std::max(r2, glm::dot(p - center_m, p - center_m));
  radius_m = r2 > 0.0 ? std::sqrt(r2) : 1.0;
}

// Positions in the unit frame of a sphere ((p - centre) / radius, what a DrawItem places).
std::vector<glm::vec3> in_unit_frame(std::span<const glm::dvec3> points, const glm::dvec3& center_m, double radius_m) {
  std::vector<glm::vec3> unit(points.size());
  for (std::size_t v = 0; v < points.size(); ++v) unit[v] = glm::vec3((points[v] - center_m) / radius_m);
  return unit;
}

// A baked level's positions posed by the object's world transform, in the unit frame of its
// bounding sphere; its triangles turned over where the transform mirrors (the renderer's front
// faces are counter-clockwise).
void unit_level(const bake::BakedObject& o, const bake::BakedLevelMesh& level, std::vector<glm::vec3>& unit,
                std::vector<std::uint32_t>& indices) {
  const std::vector<float>& xyz = level.positions_xyz;
  unit.resize(xyz.size() / 3);
  for (std::size_t v = 0; v < unit.size(); ++v) {
    const glm::dvec3 world(o.world * glm::dvec4(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2], 1.0));
    unit[v] = glm::vec3((world - o.center_m) / o.radius_m);
  }
  indices = level.indices;
  if (glm::determinant(glm::dmat3(o.world)) < 0.0)
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
}

}  // namespace

RunRenderer::RunRenderer(xr_host::XrApp& app, const std::vector<std::vector<lod::LodLevel>>& chains,
                         const ClusterScene* clusters, std::span<const bake::BakedObject* const> baked,
                         bool gpu_select) {
  std::size_t max_items = 0;
  mesh_ids_.reserve(chains.size());
  std::vector<glm::vec3> unit;
  std::vector<std::uint32_t> indices;
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const bake::BakedObject* o = i < baked.size() ? baked[i] : nullptr;
    const bool own =
        o != nullptr && o->level_meshes.size() == chains[i].size() && o->radius_m > 0.0 && std::isfinite(o->radius_m);
    std::vector<std::uint32_t> ids;
    for (std::size_t l = 0; l < chains[i].size(); ++l) {
      if (!own) {
        ids.push_back(meshes_.add_sphere(chains[i][l].triangles));
        continue;
      }
      unit_level(*o, o->level_meshes[l], unit, indices);
      ids.push_back(meshes_.add_mesh(unit, indices));
    }
    mesh_ids_.push_back(std::move(ids));
    ++max_items;
  }
  std::vector<std::uint32_t> first_mesh;  // per cluster mesh: the MeshLibrary id of its cluster 0
  if (clusters != nullptr) {
    std::vector<std::vector<glm::dvec3>> posed;
    for (const ClusterMesh& m : clusters->meshes) posed.push_back(posed_positions(m));
    // One indirect draw places every mesh: with gpu_select one frame for all, the scene's sphere.
    glm::dvec3 scene_center(0.0);
    double scene_radius = 1.0;
    if (gpu_select) {
      std::vector<glm::dvec3> all;
      for (const auto& p : posed) all.insert(all.end(), p.begin(), p.end());
      bounding_sphere(all, scene_center, scene_radius);
      gpu_center_m_ = glm::vec3(scene_center);
      gpu_radius_m_ = static_cast<float>(scene_radius);
    }
    for (std::size_t k = 0; k < clusters->meshes.size(); ++k) {
      const ClusterMesh& m = clusters->meshes[k];
      const lod::ClusterHierarchy& h = m.primitive->hierarchy;
      glm::dvec3 center(0.0);
      double radius = 1.0;
      if (gpu_select) {
        center = scene_center;
        radius = scene_radius;
      } else {
        bounding_sphere(posed[k], center, radius);
      }
      ClusterDraw d;
      d.center_m = glm::vec3(center);
      d.radius_m = static_cast<float>(radius);
      d.first_mesh = meshes_.add_cluster_mesh(in_unit_frame(posed[k], center, radius), m.primitive->indices,
                                              h.first_index, h.index_count);
      d.first_cluster = clusters->first_cluster[k];
      d.depth = h.depth;
      first_mesh.push_back(d.first_mesh);
      max_items += h.size();
      clusters_.push_back(std::move(d));
    }
  }
  marker_mesh_ = meshes_.add_sphere(80);
  render::DeviceContext ctx;
  ctx.instance = app.vk_instance();
  ctx.physical = app.vk_physical_device();
  ctx.device = app.vk_device();
  ctx.queue_family = app.vk_queue_family();
  ctx.queue = app.vk_queue();
  ctx.multi_draw_indirect = app.vk_multi_draw_indirect();
  ctx.draw_indirect_count = app.vk_draw_indirect_count();
  meshes_.upload(ctx);
  if (gpu_select && clusters != nullptr) {
    if (!ctx.draw_indirect_count)
      throw render::RenderError("--cluster-select gpu needs Vulkan 1.2's drawIndirectCount, which " +
                                app.vk_device_name() + " does not offer here");
    gpu_ = std::make_unique<GpuClusterCut>(ctx, *clusters, meshes_, first_mesh);
  }
  for (const xr_host::XrSwapchainView& sc : app.swapchains()) {
    render::RenderTarget target;
    target.images = sc.images;
    target.format = static_cast<VkFormat>(sc.format);
    target.width = static_cast<std::uint32_t>(sc.width);
    target.height = static_cast<std::uint32_t>(sc.height);
    eyes_.push_back(std::make_unique<render::FrameRenderer>(ctx, meshes_, std::move(target)));
  }
  items_.reserve(max_items + render::kFovealMarkerDots);
  if (gpu_) {  // each cluster the GPU draws in its depth's tint, as the CPU path draws it
    std::vector<std::uint8_t> depths;
    for (const ClusterDraw& d : clusters_) depths.insert(depths.end(), d.depth.begin(), d.depth.end());
    for (auto& eye : eyes_) eye->set_instance_tints(depths);
  }
}

RunRenderer::~RunRenderer() = default;

render::FrameRenderer& RunRenderer::renderer(std::size_t eye) const {
  if (eye >= eyes_.size())
    throw render::RenderError("run renderer: eye " + std::to_string(eye) + " out of range (" +
                              std::to_string(eyes_.size()) + " swapchains)");
  return *eyes_[eye];
}

void RunRenderer::render_eye(std::size_t eye, std::uint32_t image_index, const XrView& view,
                             std::span<const glm::dvec3> positions_m, std::span<const double> radii_m,
                             const FrameDecisions& decisions, const FrameDiagnostics& diagnostics,
                             std::span<const glm::dvec3> cluster_shift_m) {
  render::FrameRenderer& r = renderer(eye);
  const std::size_t n = std::min({positions_m.size(), radii_m.size(), mesh_ids_.size(), decisions.lod.size()});
  items_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& ids = mesh_ids_[i];
    if (ids.empty()) continue;  // an object without levels has nothing to draw
    const std::size_t level = std::min<std::size_t>(decisions.lod[i], ids.size() - 1);
    items_.push_back(
        {glm::vec3(positions_m[i]), static_cast<float>(radii_m[i]), ids[level], static_cast<std::uint32_t>(level)});
  }
  const render::EyeView eye_view = to_eye_view(view);
  // The GPU's cut when it selected (the plugin accepted this frame's viewer); else the CPU's.
  const bool gpu = gpu_ && gpu_->select(diagnostics.viewer, eye_view, decisions.cluster_detail_scale);
  if (gpu && eye == 0) gpu_->compare(decisions.cluster_drawn);
  for (std::size_t k = 0; k < clusters_.size() && !gpu; ++k) {
    const ClusterDraw& m = clusters_[k];
    if (m.first_cluster >= decisions.cluster_drawn.size()) continue;  // not registered: nothing drawn
    const std::span<const std::uint8_t> drawn = decisions.cluster_drawn.subspan(
        m.first_cluster, std::min(m.depth.size(), decisions.cluster_drawn.size() - m.first_cluster));
    const glm::vec3 center = k < cluster_shift_m.size() ? m.center_m + glm::vec3(cluster_shift_m[k]) : m.center_m;
    for (std::size_t c = 0; c < drawn.size(); ++c)
      if (drawn[c] != 0)
        items_.push_back({center, m.radius_m, m.first_mesh + static_cast<std::uint32_t>(c), m.depth[c]});
  }
  if (foveal_circle_) {
    // Around this eye's own position, so the circle sits on the gaze in each eye's image.
    const std::size_t first = items_.size();
    items_.resize(first + render::kFovealMarkerDots);
    const std::size_t written = render::foveal_circle(eye_view.pose.position_m, diagnostics.foveal_cone.axis,
                                                      diagnostics.foveal_cone.half_angle_rad * aux::kDegPerRad,
                                                      marker_mesh_, std::span(items_).subspan(first));
    items_.resize(first + written);
  }
  if (!gpu) {
    r.draw(image_index, eye_view, items_);
    return;
  }
  render::IndirectCut cut = gpu_->cut(gpu_center_m_, gpu_radius_m_, 0);
  cut.per_instance_tint = true;
  r.draw(image_index, eye_view, items_, std::span<const render::IndirectCut>(&cut, 1));
}

void RunRenderer::save_png(std::size_t eye, std::uint32_t image_index, const std::filesystem::path& file,
                           std::uint32_t levels) {
  // Atomically, like the run's other files: a full disk leaves no cut frame.png.
  const std::vector<unsigned char> png =
      render::encode_png(render::with_lod_key(renderer(eye).read_back(image_index), levels));
  write_run_file(file.string(), std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

std::uint64_t RunRenderer::triangles_drawn(std::size_t eye) const {
  return renderer(eye).triangles_last_frame();
}

}  // namespace gazelod::cli
