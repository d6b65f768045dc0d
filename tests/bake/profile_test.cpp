// SPDX-License-Identifier: Apache-2.0
// Reddy's rendered perceptual profile (bake/profile_*): the FFT and the energy frequency on
// hand-made images, the view sphere, the profile of generated meshes (icosphere, bumpy sphere)
// and a round trip: gazelod bake --profile, load_baked_scene, render the loaded chain.
#include "bake/baked_scene.hpp"
#include "bake/gltf_load.hpp"
#include "bake/profile_render.hpp"
#include "bake/profile_spectrum.hpp"
#include "bake/simplify_chain.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "render/frame_renderer.hpp"
#include "render/mesh_library.hpp"
#include "render/offscreen_target.hpp"
#include "render/render_error.hpp"
#include "tests/bake/test_meshes.hpp"
#include "tests/skip_or_fail.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace gazelod::bake {
namespace {

TEST(ProfileSpectrum, FftMatchesADirectDft) {
  const std::size_t n = 16;
  std::vector<double> re(n), im(n);
  for (std::size_t i = 0; i < n; ++i)
    re[i] = std::sin(0.7 * double(i)) + 0.1 * double(i), im[i] = std::cos(1.3 * double(i));
  const std::vector<double> re0 = re, im0 = im;
  fft_inplace(re, im);
  for (std::size_t k = 0; k < n; ++k) {
    std::complex<double> s = 0.0;
    for (std::size_t t = 0; t < n; ++t)
      s += std::complex<double>(re0[t], im0[t]) * std::polar(1.0, -2.0 * std::numbers::pi * double(k * t) / double(n));
    EXPECT_NEAR(re[k], s.real(), 1e-9) << k;
    EXPECT_NEAR(im[k], s.imag(), 1e-9) << k;
  }
  std::vector<double> bad(12), bad_im(12);
  EXPECT_THROW(fft_inplace(bad, bad_im), std::invalid_argument);
}

// A bar w pixels wide (full height) is half a cycle of 1 / (2 w) cycles/pixel (Reddy's feature
// measure); on 256 pixels that is 128 / w cycles per width.
// (w < 2 size / 3 so the bar stays inside its rows.)
std::vector<float> bar(std::uint32_t size, std::uint32_t w, float value) {
  std::vector<float> img(std::size_t(size) * size, 0.0f);
  for (std::uint32_t y = 0; y < size; ++y)
    for (std::uint32_t x = size / 3; x < size / 3 + w; ++x) img[std::size_t(y) * size + x] = value;
  return img;
}

TEST(ProfileSpectrum, BarOfWidthWGivesAboutHalfACyclePerW) {
  for (std::uint32_t w : {4u, 8u, 16u}) {
    const double f = energy_frequency_cycles_per_width(bar(256, w, 50.0f), 256);
    const double reddy = 256.0 / (2.0 * w);
    EXPECT_NEAR(f / reddy, 1.0, 0.25) << "w = " << w << ": " << f;
  }
  // Wider features are lower frequencies.
  EXPECT_GT(energy_frequency_cycles_per_width(bar(256, 4, 50.0f), 256),
            energy_frequency_cycles_per_width(bar(256, 16, 50.0f), 256));
}

TEST(ProfileSpectrum, NoDifferenceOrOnlyNoiseGivesNegative) {
  EXPECT_LT(energy_frequency_cycles_per_width(std::vector<float>(64 * 64, 0.0f), 64), 0.0);
  EXPECT_LT(energy_frequency_cycles_per_width(bar(64, 8, float(kNoiseFloor) * 0.9f), 64), 0.0);
  EXPECT_GT(energy_frequency_cycles_per_width(bar(64, 8, float(kNoiseFloor) * 1.1f), 64), 0.0);
  EXPECT_THROW(energy_frequency_cycles_per_width(std::vector<float>(48 * 48), 48), std::invalid_argument);
  std::vector<float> nan(16 * 16, 0.0f);
  nan[5] = NAN;
  EXPECT_THROW(energy_frequency_cycles_per_width(nan, 16), std::invalid_argument);
}

TEST(ProfileViews, CubeFacesAndEdgesAreDistinctUnitVectors) {
  for (int n : {6, 18}) {
    const auto d = view_directions(n);
    ASSERT_EQ(d.size(), std::size_t(n));
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < d.size(); ++i) {
      EXPECT_NEAR(glm::length(d[i]), 1.0, 1e-12);
      sum += d[i];
      for (std::size_t j = 0; j < i; ++j) EXPECT_GT(glm::length(d[i] - d[j]), 0.5);
    }
    EXPECT_NEAR(glm::length(sum), 0.0, 1e-12);  // symmetric: antipodal pairs
  }
  EXPECT_THROW(view_directions(7), std::invalid_argument);
}

// An icosphere with radial bumps: r = 1 + a * sin(k x) sin(k y) sin(k z).
testing::TestMesh bumpy(int subdivisions, double amplitude) {
  testing::TestMesh m = testing::icosphere(subdivisions, 1.0);
  for (std::size_t i = 0; i + 2 < m.positions.size(); i += 3) {
    const glm::dvec3 p(m.positions[i], m.positions[i + 1], m.positions[i + 2]);
    const double s = 1.0 + amplitude * std::sin(6 * p.x) * std::sin(6 * p.y) * std::sin(6 * p.z);
    for (int a = 0; a < 3; ++a) m.positions[i + a] = float(p[a] * s);
  }
  return m;
}

class ProfileRender : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      profiler_ = std::make_unique<Profiler>(ProfileOptions{6});
    } catch (const render::NoVulkanDevice& e) {
      GAZELOD_SKIP_OR_FAIL("no Vulkan device: " << e.what());
    }
  }
  // Levels: full, an identical copy, then the simplifier's levels at `ratios`.
  std::vector<LevelProfile> run(const testing::TestMesh& m, std::vector<double> ratios) {
    ChainOptions o;
    o.ratios = ratios;
    const PrimitiveChain c = simplify_chain(m.positions, m.indices, o);
    std::vector<std::vector<std::uint32_t>> levels{m.indices, m.indices};
    for (std::size_t k = 1; k < c.levels.size(); ++k) levels.push_back(c.levels[k].indices);
    return profiler_->profile(m.positions, levels);
  }
  std::unique_ptr<Profiler> profiler_;
};

void expect_profile_properties(const std::vector<LevelProfile>& p, double nyquist) {
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[0].rendered_cycles_per_diameter, 0.0);
  // The identical copy differs from no viewpoint: it removes nothing the render resolves.
  EXPECT_EQ(p[1].rendered_cycles_per_diameter, nyquist);
  for (double v : p[1].per_view_cycles_per_diameter) EXPECT_LT(v, 0.0);
  for (std::size_t k = 1; k < p.size(); ++k) {
    EXPECT_TRUE(std::isfinite(p[k].rendered_cycles_per_diameter)) << k;
    EXPECT_GT(p[k].rendered_cycles_per_diameter, 0.0) << k;
    EXPECT_LE(p[k].rendered_cycles_per_diameter, nyquist) << k;
    EXPECT_EQ(p[k].per_view_cycles_per_diameter.size(), 6u);
  }
  // The much coarser level removes lower frequencies than the mildly simplified one.
  EXPECT_LT(p[3].rendered_cycles_per_diameter, p[2].rendered_cycles_per_diameter);
  EXPECT_LT(p[2].rendered_cycles_per_diameter, nyquist);
}

TEST_F(ProfileRender, IcosphereLevels) {
  const auto p = run(testing::icosphere(4, 1.0), {0.3, 0.02});
  expect_profile_properties(p, profiler_->nyquist_cycles_per_diameter());
}

TEST_F(ProfileRender, BumpySphereLevels) {
  const auto p = run(bumpy(4, 0.15), {0.3, 0.02});
  expect_profile_properties(p, profiler_->nyquist_cycles_per_diameter());
}

// The 6 cube-face viewpoints are among the 18, and a level's figure is the minimum over its
// viewpoints: 18 viewpoints can only find the same or a lower (more visible) frequency.
TEST_F(ProfileRender, EighteenViewpointsAreAtMostSix) {
  const testing::TestMesh m = bumpy(3, 0.15);
  ChainOptions o;
  o.ratios = {0.25, 0.05};
  const PrimitiveChain c = simplify_chain(m.positions, m.indices, o);
  std::vector<std::vector<std::uint32_t>> levels{m.indices};
  for (std::size_t k = 1; k < c.levels.size(); ++k) levels.push_back(c.levels[k].indices);
  const auto p6 = profiler_->profile(m.positions, levels);
  Profiler p18(ProfileOptions{18});
  const auto q = p18.profile(m.positions, levels);
  ASSERT_EQ(q.size(), p6.size());
  for (std::size_t k = 1; k < q.size(); ++k) {
    EXPECT_EQ(q[k].per_view_cycles_per_diameter.size(), 18u);
    for (std::size_t v = 0; v < 6; ++v)  // the same cameras render the same images
      EXPECT_EQ(q[k].per_view_cycles_per_diameter[v], p6[k].per_view_cycles_per_diameter[v]) << k << " " << v;
    EXPECT_LE(q[k].rendered_cycles_per_diameter, p6[k].rendered_cycles_per_diameter) << k;
  }
}

TEST_F(ProfileRender, BadIndicesAreARenderError) {
  const testing::TestMesh m = testing::icosphere(1, 1.0);
  std::vector<std::uint32_t> bad = m.indices;
  bad[4] = 100000;
  EXPECT_THROW(profiler_->profile(m.positions, {m.indices, bad}), render::RenderError);
}

TEST(ProfileOptionsCheck, RejectsBadViewpointsAndSizes) {
  EXPECT_THROW(Profiler(ProfileOptions{5}), std::invalid_argument);
  EXPECT_THROW(Profiler(ProfileOptions{6, 100}), std::invalid_argument);
}

// Bake with --profile through the CLI, read the figures back, load the chain and render it.
TEST(ProfileRoundTrip, BakeProfileLoadRender) {
  std::unique_ptr<render::OffscreenDevice> device;
  try {
    device = std::make_unique<render::OffscreenDevice>();
  } catch (const render::NoVulkanDevice& e) {
    GAZELOD_SKIP_OR_FAIL("no Vulkan device: " << e.what());
  }
  const std::string dir = testing::temp_dir("profile_rt");
  const std::string in = testing::write_model(testing::single_mesh_model(bumpy(4, 0.1)), dir + "/in.glb");
  std::ostringstream out, err;
  const int rc = cli::run({"bake", in, "-o", dir + "/out.glb", "--levels", "4", "--profile", "6"}, out, err);
  ASSERT_EQ(rc, 0) << err.str();
  EXPECT_NE(out.str().find("perceptual profile"), std::string::npos) << out.str();

  const LoadedGltf g = load_gltf(dir + "/out.glb");
  std::vector<double> rendered;
  for (const tinygltf::Node& n : g.model.nodes) {
    const tinygltf::Value& lod = n.extras.Get("gazelod_lod");
    ASSERT_TRUE(lod.Has("rendered_cycles_per_diameter")) << n.name;
    rendered.push_back(lod.Get("rendered_cycles_per_diameter").GetNumberAsDouble());
  }
  ASSERT_EQ(rendered.size(), 4u);  // N, then N_lod1..3 appended in order
  EXPECT_EQ(rendered[0], 0.0);
  for (std::size_t k = 1; k < rendered.size(); ++k) {
    EXPECT_GT(rendered[k], 0.0);
    EXPECT_TRUE(std::isfinite(rendered[k]));
    if (k > 1) {
      EXPECT_LE(rendered[k], rendered[k - 1]);
    }
  }
  EXPECT_LT(rendered[3], rendered[1]);

  const auto objects = load_baked_scene(dir + "/out.glb");
  ASSERT_EQ(objects.size(), 1u);
  ASSERT_EQ(objects[0].lods.size(), 4u);
  render::MeshLibrary meshes;
  std::vector<std::uint32_t> ids;
  for (const auto& l : objects[0].lods) ids.push_back(meshes.add_sphere(l.triangles));
  meshes.upload(device->context());
  render::OffscreenTarget target(device->context(), 64, 64);
  render::FrameRenderer renderer(device->context(), meshes, target.target());
  render::EyeView eye;
  eye.pose.position_m = objects[0].center_m + glm::dvec3(0, 0, 4.0 * objects[0].radius_m);
  for (std::uint32_t k = 0; k < ids.size(); ++k) {
    const render::DrawItem item{glm::vec3(objects[0].center_m), float(objects[0].radius_m), ids[k], k};
    renderer.draw(0, eye, {&item, 1});
    const render::RgbaImage img = renderer.read_back(0);
    EXPECT_NE(img.rgb(32, 32), img.rgb(0, 0)) << "level " << k << ": object not drawn at the centre";
  }
  for (const std::string& m : device->validation_messages()) ADD_FAILURE() << "validation: " << m;
}

TEST(ProfileRoundTrip, PlainBakeStoresNoRenderedFigure) {
  const std::string dir = testing::temp_dir("profile_off");
  const std::string in = testing::write_model(testing::single_mesh_model(testing::icosphere(2, 1.0)), dir + "/in.glb");
  std::ostringstream out, err;
  ASSERT_EQ(cli::run({"bake", in, "-o", dir + "/out.glb"}, out, err), 0) << err.str();
  const LoadedGltf g = load_gltf(dir + "/out.glb");
  ASSERT_FALSE(g.model.nodes.empty());
  for (const tinygltf::Node& n : g.model.nodes) {
    EXPECT_TRUE(n.extras.Get("gazelod_lod").Has("detail_cycles_per_diameter")) << n.name;
    EXPECT_FALSE(n.extras.Get("gazelod_lod").Has("rendered_cycles_per_diameter")) << n.name;
  }
}

TEST(ProfileRoundTrip, CliRejectsBadViewpointCount) {
  const std::string dir = testing::temp_dir("profile_bad");
  const std::string in = testing::write_model(testing::single_mesh_model(testing::icosphere(2, 1.0)), dir + "/in.glb");
  std::ostringstream out, err;
  EXPECT_NE(cli::run({"bake", in, "-o", dir + "/out.glb", "--profile", "7"}, out, err), 0);
  EXPECT_NE(err.str().find("--profile"), std::string::npos) << err.str();
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.glb"));
}

}  // namespace
}  // namespace gazelod::bake
