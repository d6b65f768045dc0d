// SPDX-License-Identifier: Apache-2.0
// shaders/cluster_select.comp as compiled (its SPIR-V words, no device needed): every float
// addition, subtraction, multiplication and division is NoContraction (`precise`: no FMA, no
// reassociation, the CPU kernel's rounding), the CPU kernel's constants are there bit for bit,
// and the blocks' member offsets and array strides are those of shaders/cluster_select_gpu.h.
// And the frame constants (render/cluster_select_frame.hpp) are select_clusters' own.
#include "auxiliary/angles.hpp"
#include "lod/acuity.hpp"
#include "lod/cluster/cluster_select_kernel.hpp"
#include "render/cluster_select_frame.hpp"
#include "render/render_error.hpp"
#include "shaders/cluster_select.comp.h"
#include "shaders/cluster_select_gpu.h"

#include <gtest/gtest.h>
#include <vulkan/vulkan.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

namespace gazelod::render {
namespace {

// The parts of a SPIR-V module these tests read.
struct Module {
  std::map<std::string, std::vector<std::uint32_t>> ids_of;            // OpName (a struct used in a
                                                                       // block and in code: two types)
  std::map<std::uint32_t, std::vector<std::uint32_t>> member_offsets;  // struct -> Offset per member
  std::map<std::uint32_t, std::uint32_t> stride_of_element;            // runtime array's element -> stride
  std::set<std::uint32_t> no_contraction, float_constant_bits;
  std::vector<std::uint32_t> float_arithmetic;  // result ids
};

Module parse(const std::uint32_t* words, std::size_t count) {
  constexpr std::uint32_t kName = 5, kTypeFloat = 22, kTypeRuntimeArray = 29, kConstant = 43, kDecorate = 71,
                          kMemberDecorate = 72;
  constexpr std::uint32_t kNoContraction = 42, kArrayStride = 6, kOffset = 35;
  const std::set<std::uint32_t> arithmetic{127, 129, 131, 133, 136,
                                           140, 141, 142, 143};  // FNegate .. MatrixTimesScalar
  Module m;
  std::set<std::uint32_t> float32;
  std::map<std::uint32_t, std::uint32_t> array_element, stride_of_array;
  for (std::size_t at = 5; at < count;) {
    const std::uint32_t n = words[at] >> 16, op = words[at] & 0xffffu;
    const std::uint32_t* w = words + at;
    if (n == 0 || at + n > count) break;
    if (op == kName) m.ids_of[reinterpret_cast<const char*>(w + 2)].push_back(w[1]);
    if (op == kTypeFloat && w[2] == 32) float32.insert(w[1]);
    if (op == kTypeRuntimeArray) array_element[w[1]] = w[2];
    if (op == kConstant && float32.contains(w[1])) m.float_constant_bits.insert(w[3]);
    if (op == kDecorate && w[2] == kNoContraction) m.no_contraction.insert(w[1]);
    if (op == kDecorate && w[2] == kArrayStride) stride_of_array[w[1]] = w[3];
    if (op == kMemberDecorate && w[3] == kOffset) {
      std::vector<std::uint32_t>& offsets = m.member_offsets[w[1]];
      offsets.resize(std::max<std::size_t>(offsets.size(), w[2] + 1));
      offsets[w[2]] = w[4];
    }
    if (arithmetic.contains(op)) m.float_arithmetic.push_back(w[2]);
    at += n;
  }
  for (const auto& [array, element] : array_element)
    if (stride_of_array.contains(array)) m.stride_of_element[element] = stride_of_array[array];
  return m;
}

// The type named `name` that carries the block layout (member offsets), and its array stride
// (0 if it is no runtime array's element).
std::uint32_t laid_out(const Module& m, const std::string& name) {
  for (std::uint32_t id : m.ids_of.count(name) ? m.ids_of.at(name) : std::vector<std::uint32_t>{})
    if (m.member_offsets.contains(id)) return id;
  ADD_FAILURE() << "no laid-out type " << name;
  return 0;
}
std::uint32_t stride_of(const Module& m, const std::string& name) {
  const std::uint32_t id = laid_out(m, name);
  return m.stride_of_element.contains(id) ? m.stride_of_element.at(id) : 0;
}

const Module& shader() {
  static const Module m = parse(cluster_select_comp_spv, std::size(cluster_select_comp_spv));
  return m;
}

TEST(ClusterSelectShader, EveryFloatOperationIsPrecise) {
  const Module& m = shader();
  ASSERT_GT(m.float_arithmetic.size(), 100u);
  for (std::uint32_t id : m.float_arithmetic) EXPECT_TRUE(m.no_contraction.contains(id)) << "result %" << id;
}

TEST(ClusterSelectShader, HasTheKernelsConstantsBitForBit) {
  using namespace lod;
  using namespace lod::detail;
  const float expected[] = {
      kNearFloorM, kDistanceLow, 1.0f - 0x1p-19f, static_cast<float>(aux::kDegPerRad),
      static_cast<float>(kVelocitySeamDps), static_cast<float>(kGIntercept) + kGSlackCpd, static_cast<float>(kGSlope),
      static_cast<float>(kAcuityMaxCpd), static_cast<float>(kEccentricitySeamDeg), static_cast<float>(kMSlope),
      static_cast<float>(kMNumerator), std::numbers::pi_v<float>, std::numbers::pi_v<float> / 4,
      1.0f / std::numbers::sqrt2_v<float>, std::numbers::ln2_v<float> / std::numbers::ln10_v<float>,
      // lod/cluster/cluster_select_math.hpp's polynomials, as written there.
      -0.333332866f, 0.199912377f, -0.140241428f, 0.0852049204f, 0.414213562f, 1.44269652f, -0.721360179f, 0.480613125f,
      -0.359524455f, 0.296119557f, -0.267963871f, 0.168186591f};
  for (float f : expected)
    EXPECT_TRUE(shader().float_constant_bits.contains(std::bit_cast<std::uint32_t>(f)))
        << f << " (0x" << std::hex << std::bit_cast<std::uint32_t>(f) << ") is not among the shader's constants";
}

TEST(ClusterSelectShader, BlocksMatchTheCHeader) {
  const Module& m = shader();
  using F = gzl_cluster_select_frame;
  const std::vector<std::uint32_t> frame{offsetof(F, eye_hi_m),
                                         offsetof(F, ecc_offset_rad),
                                         offsetof(F, eye_lo_m),
                                         offsetof(F, scale),
                                         offsetof(F, gaze_unit),
                                         offsetof(F, scale_xi_cpd),
                                         offsetof(F, gaze_omega_rad_s),
                                         offsetof(F, static_limit_cpd),
                                         offsetof(F, error_factor),
                                         offsetof(F, on_eccentricity),
                                         offsetof(F, on_velocity),
                                         offsetof(F, use_size),
                                         offsetof(F, lip_w),
                                         offsetof(F, slack_w),
                                         offsetof(F, cull),
                                         offsetof(F, reserved0),
                                         offsetof(F, view_hi_m),
                                         offsetof(F, near_m),
                                         offsetof(F, view_lo_m),
                                         offsetof(F, far_m),
                                         offsetof(F, view_row_x),
                                         offsetof(F, view_row_y),
                                         offsetof(F, view_row_z),
                                         offsetof(F, side_x),
                                         offsetof(F, side_y)};
  using M = gzl_cluster_select_mesh;
  const std::vector<std::uint32_t> mesh{offsetof(M, rel_vel_m_s),    offsetof(M, lip_v),        offsetof(M, slack_v),
                                        offsetof(M, cap_combined_m), offsetof(M, error_factor), offsetof(M, reserved)};
  using R = gzl_cluster_select_draw_range;
  const std::vector<std::uint32_t> range{offsetof(R, first_index), offsetof(R, index_count),
                                         offsetof(R, vertex_offset)};
  using D = gzl_cluster_select_dispatch;
  const std::vector<std::uint32_t> dispatch{offsetof(D, cluster_base), offsetof(D, cluster_count),
                                            offsetof(D, command_capacity), offsetof(D, reserved0)};
  using C = VkDrawIndexedIndirectCommand;
  const std::vector<std::uint32_t> command{offsetof(C, indexCount), offsetof(C, instanceCount), offsetof(C, firstIndex),
                                           offsetof(C, vertexOffset), offsetof(C, firstInstance)};
  for (const auto& [name, offsets] : std::map<std::string, std::vector<std::uint32_t>>{{"Frame", frame},
                                                                                       {"MeshFrame", mesh},
                                                                                       {"DrawRange", range},
                                                                                       {"Dispatch", dispatch},
                                                                                       {"DrawCommand", command}}) {
    const std::uint32_t id = laid_out(m, name);
    EXPECT_EQ(m.member_offsets.count(id) ? m.member_offsets.at(id) : std::vector<std::uint32_t>{}, offsets) << name;
  }
  EXPECT_EQ(stride_of(m, "MeshFrame"), sizeof(M));
  EXPECT_EQ(stride_of(m, "DrawRange"), sizeof(R));
  EXPECT_EQ(stride_of(m, "DrawCommand"), sizeof(C));
}

TEST(ClusterSelectFrame, CopiesTheCpuConstantsAndReplacesInfinities) {
  lod::Viewer v;
  v.eye_position_m = {1000.1, 1.7, -3.3};
  v.gaze_direction = {0.2, -0.3, -1.0};
  v.head_angular_velocity_rad_s = {0.1, 0.7, 0.0};
  v.xi_cpd = 20.0, v.scale = 0.7, v.tracker_error_deg = 1.5;
  const lod::detail::ClusterFrame f = lod::detail::make_cluster_frame(v);
  const gzl_cluster_select_frame g = make_cluster_select_frame(v, nullptr);
  const auto same = [](float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); };
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(same(g.eye_hi_m[k], f.eye_hi_m[k]) && same(g.eye_lo_m[k], f.eye_lo_m[k]));
    EXPECT_TRUE(same(g.gaze_unit[k], f.gaze_unit[k]) && same(g.gaze_omega_rad_s[k], f.gaze_omega_rad_s[k]));
  }
  EXPECT_TRUE(same(g.ecc_offset_rad, f.ecc_offset_rad) && same(g.scale, f.scale) &&
              same(g.scale_xi_cpd, f.scale_xi_cpd) && same(g.static_limit_cpd, f.static_limit_cpd) &&
              same(g.error_factor, f.error_factor));
  EXPECT_EQ(g.use_size, 1u);
  EXPECT_EQ(g.cull, 0u);
  v.use_size = false;
  const gzl_cluster_select_frame off = make_cluster_select_frame(v, nullptr);
  EXPECT_EQ(off.use_size, 0u);  // the CPU's a0 is +inf
  EXPECT_EQ(off.static_limit_cpd, 0.0f);

  const std::vector<std::uint32_t> first{0}, count{1};
  const std::vector<double> vx{0.5}, vy{0.0}, vz{0.0}, finest{0.01};
  lod::ClusterSet meshes;
  meshes.mesh_first_cluster = first, meshes.mesh_cluster_count = count;
  meshes.mesh_vel_x_m_s = vx, meshes.mesh_vel_y_m_s = vy, meshes.mesh_vel_z_m_s = vz,
  meshes.mesh_finest_error_m = finest;
  v.use_size = true;
  EXPECT_EQ(make_cluster_select_mesh(v, meshes, 0).cap_combined_m, std::numeric_limits<float>::max());
  v.use_size = false;
  const gzl_cluster_select_mesh capped = make_cluster_select_mesh(v, meshes, 0);
  EXPECT_TRUE(same(capped.cap_combined_m, lod::detail::make_cluster_mesh_frame(v, meshes, 0).cap_m));
  EXPECT_GT(capped.lip_v, 2.0f * capped.rel_vel_m_s[0]);

  EyeView view;
  view.pose.position_m = {1000.1, 1.7, -3.3};
  const gzl_cluster_select_frame culled = make_cluster_select_frame(v, &view);
  EXPECT_EQ(culled.cull, 1u);
  EXPECT_EQ(culled.view_row_z[2], 1.0f);  // identity orientation: view space is world space
  view.fov.angle_left = view.fov.angle_right;
  EXPECT_THROW(make_cluster_select_frame(v, &view), RenderError);
}

}  // namespace
}  // namespace gazelod::render
