// SPDX-License-Identifier: Apache-2.0
// Rendering the chain from the view sphere and reducing the differences (profile_render.hpp).
#include "bake/profile_render.hpp"
#include "auxiliary/angles.hpp"

#include "bake/profile_spectrum.hpp"
#include "render/camera.hpp"
#include "render/frame_renderer.hpp"
#include "render/mesh_library.hpp"
#include "render/offscreen_target.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace gazelod::bake {
namespace {

double deg_to_rad(double d) {
  return d * aux::kRadPerDeg;
}

// Eye on the view sphere at `dir` * distance, looking at the origin, +y up (+z when looking
// along y). The sphere of radius 1 then just fills the square view.
render::EyeView eye_for(const glm::dvec3& dir, double half_fov_rad) {
  const double distance = 1.0 / std::sin(half_fov_rad);
  const glm::dvec3 z = glm::normalize(dir);  // the eye looks down -z
  const glm::dvec3 up = std::abs(z.y) > 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  const glm::dvec3 x = glm::normalize(glm::cross(up, z));
  const glm::dvec3 y = glm::cross(z, x);
  render::EyeView v;
  v.pose.orientation = glm::quat_cast(glm::dmat3(x, y, z));
  v.pose.position_m = z * distance;
  v.fov = {-half_fov_rad, half_fov_rad, half_fov_rad, -half_fov_rad};
  v.near_m = distance - 1.5;
  v.far_m = distance + 1.5;
  return v;
}

std::vector<float> grey(const render::RgbaImage& img) {
  std::vector<float> g(static_cast<std::size_t>(img.width) * img.height);
  for (std::size_t i = 0; i < g.size(); ++i)
    g[i] = 0.299f * img.pixels[4 * i] + 0.587f * img.pixels[4 * i + 1] + 0.114f * img.pixels[4 * i + 2];
  return g;
}

}  // namespace

std::vector<glm::dvec3> view_directions(int viewpoints) {
  if (viewpoints != 6 && viewpoints != 18)
    throw std::invalid_argument("profile: viewpoints must be 6 or 18, got " + std::to_string(viewpoints));
  std::vector<glm::dvec3> d;
  for (int axis = 0; axis < 3; ++axis)
    for (double s : {1.0, -1.0}) {
      glm::dvec3 v(0.0);
      v[axis] = s;
      d.push_back(v);
    }
  if (viewpoints == 18)
    for (int a = 0; a < 3; ++a)  // edge midpoints: two non-zero coordinates of +-1
      for (double sa : {1.0, -1.0})
        for (double sb : {1.0, -1.0}) {
          glm::dvec3 v(0.0);
          v[a] = sa;
          v[(a + 1) % 3] = sb;
          d.push_back(glm::normalize(v));
        }
  return d;
}

Profiler::Profiler(ProfileOptions o) : options_(o) {
  (void)view_directions(o.viewpoints);
  if (o.image_px < 16 || o.image_px > 1024 || (o.image_px & (o.image_px - 1)) != 0)
    throw std::invalid_argument("profile: image_px must be a power of two in [16, 1024], got " +
                                std::to_string(o.image_px));
  if (!(o.half_fov_deg >= 0.5 && o.half_fov_deg <= 45.0))
    throw std::invalid_argument("profile: half_fov_deg must be in [0.5, 45]");
  device_ = std::make_unique<render::OffscreenDevice>(false);
}

Profiler::~Profiler() = default;

double Profiler::nyquist_cycles_per_diameter() const {
  // The image width spans diameter / cos(half fov) at the centre plane.
  return options_.image_px / 2.0 * std::cos(deg_to_rad(options_.half_fov_deg));
}

std::vector<LevelProfile> Profiler::profile(std::span<const float> xyz,
                                            const std::vector<std::vector<std::uint32_t>>& levels) {
  std::vector<LevelProfile> out(levels.size());
  if (levels.empty() || xyz.size() < 3) return out;
  // Unit bounding-sphere frame: box centre, farthest vertex (as bake.cpp measures diameter).
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], double(xyz[i + a])), hi[a] = std::max(hi[a], double(xyz[i + a]));
  const glm::dvec3 c = (lo + hi) / 2.0;
  double r = 0.0;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    r = std::max(r, glm::length(glm::dvec3(xyz[i], xyz[i + 1], xyz[i + 2]) - c));
  const double scale = r > 0.0 ? 1.0 / r : 1.0;
  std::vector<glm::vec3> unit(xyz.size() / 3);
  for (std::size_t v = 0; v < unit.size(); ++v)
    unit[v] = glm::vec3((glm::dvec3(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]) - c) * scale);

  render::MeshLibrary meshes;
  std::vector<std::uint32_t> ids;
  for (const auto& l : levels) ids.push_back(meshes.add_mesh(unit, l));
  meshes.upload(device_->context());
  const std::uint32_t px = options_.image_px;
  render::OffscreenTarget target(device_->context(), px, px);
  render::FrameRenderer renderer(device_->context(), meshes, target.target());

  const double half_fov = deg_to_rad(options_.half_fov_deg);
  const double per_width_to_per_diameter = std::cos(half_fov);
  const double nyquist = nyquist_cycles_per_diameter();
  for (auto& p : out) p.rendered_cycles_per_diameter = nyquist;
  out[0].rendered_cycles_per_diameter = 0.0;
  for (const glm::dvec3& dir : view_directions(options_.viewpoints)) {
    const render::EyeView eye = eye_for(dir, half_fov);
    auto draw = [&](std::uint32_t mesh) {
      const render::DrawItem item{glm::vec3(0.0f), 1.0f, mesh, 0};  // same tint for every level
      renderer.draw(0, eye, {&item, 1});
      return grey(renderer.read_back(0));
    };
    const std::vector<float> full = draw(ids[0]);
    for (std::size_t k = 1; k < levels.size(); ++k) {
      std::vector<float> d = draw(ids[k]);
      for (std::size_t i = 0; i < d.size(); ++i) d[i] -= full[i];
      const double f = energy_frequency_cycles_per_width(d, px);
      const double cpd = f < 0.0 ? -1.0 : std::max(f * per_width_to_per_diameter, 1e-3);
      out[k].per_view_cycles_per_diameter.push_back(cpd);
      if (cpd > 0.0) out[k].rendered_cycles_per_diameter = std::min(out[k].rendered_cycles_per_diameter, cpd);
    }
  }
  for (std::size_t k = 2; k < out.size(); ++k)  // non-increasing towards coarser levels
    out[k].rendered_cycles_per_diameter =
        std::min(out[k].rendered_cycles_per_diameter, out[k - 1].rendered_cycles_per_diameter);
  return out;
}

}  // namespace gazelod::bake
