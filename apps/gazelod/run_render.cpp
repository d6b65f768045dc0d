#include "apps/gazelod/run_render.hpp"

#include "gaze/atomic_file.hpp"
#include "lod/angles.hpp"
#include "render/camera.hpp"
#include "render/foveal_marker.hpp"
#include "render/png_io.hpp"
#include "render/render_error.hpp"

#include <algorithm>
#include <string>

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

}  // namespace

RunRenderer::RunRenderer(xr_host::XrApp& app, const std::vector<std::vector<lod::LodLevel>>& chains) {
  std::size_t max_items = 0;
  mesh_ids_.reserve(chains.size());
  for (const auto& chain : chains) {
    std::vector<std::uint32_t> ids;
    for (const lod::LodLevel& level : chain) ids.push_back(meshes_.add_sphere(level.triangles));
    mesh_ids_.push_back(std::move(ids));
    ++max_items;
  }
  marker_mesh_ = meshes_.add_sphere(80);
  render::DeviceContext ctx;
  ctx.instance = app.vk_instance();
  ctx.physical = app.vk_physical_device();
  ctx.device = app.vk_device();
  ctx.queue_family = app.vk_queue_family();
  ctx.queue = app.vk_queue();
  meshes_.upload(ctx);
  for (const xr_host::XrSwapchainView& sc : app.swapchains()) {
    render::RenderTarget target;
    target.images = sc.images;
    target.format = static_cast<VkFormat>(sc.format);
    target.width = static_cast<std::uint32_t>(sc.width);
    target.height = static_cast<std::uint32_t>(sc.height);
    eyes_.push_back(std::make_unique<render::FrameRenderer>(ctx, meshes_, std::move(target)));
  }
  items_.reserve(max_items + render::kFovealMarkerDots);
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
                             const FrameDecisions& decisions, const FrameDiagnostics& diagnostics) {
  render::FrameRenderer& r = renderer(eye);
  const std::size_t n = std::min({positions_m.size(), radii_m.size(), mesh_ids_.size(), decisions.lod.size()});
  items_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& ids = mesh_ids_[i];
    if (ids.empty()) continue;  // an object without levels has nothing to draw
    const std::size_t level = std::min<std::size_t>(decisions.lod[i], ids.size() - 1);
    items_.push_back({glm::vec3(positions_m[i]), static_cast<float>(radii_m[i]), ids[level],
                      static_cast<std::uint32_t>(level)});
  }
  const render::EyeView eye_view = to_eye_view(view);
  if (foveal_circle_) {
    // Around this eye's own position, so the circle sits on the gaze in each eye's image.
    const std::size_t first = items_.size();
    items_.resize(first + render::kFovealMarkerDots);
    const std::size_t written = render::foveal_circle(
        eye_view.pose.position_m, diagnostics.foveal_cone.axis,
        diagnostics.foveal_cone.half_angle_rad * lod::kDegPerRad, marker_mesh_,
        std::span(items_).subspan(first));
    items_.resize(first + written);
  }
  r.draw(image_index, eye_view, items_);
}

void RunRenderer::save_png(std::size_t eye, std::uint32_t image_index, const std::filesystem::path& file) {
  // Atomically, like the run's other files: a full disk leaves no cut frame.png.
  const std::vector<unsigned char> png = render::encode_png(renderer(eye).read_back(image_index));
  gaze::write_file_atomic(file.string(), std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

std::uint64_t RunRenderer::triangles_drawn(std::size_t eye) const { return renderer(eye).triangles_last_frame(); }

}  // namespace gazelod::cli
