// SPDX-License-Identifier: Apache-2.0
// The GPU cluster-selection pass's host side (cluster_select_pass.hpp): pipeline, buffers,
// descriptor sets per dispatch, uploads, the recorded frame and the read-backs.
#include "render/cluster_select_pass.hpp"

#include "render/cluster_select_frame.hpp"
#include "render/render_error.hpp"
#include "shaders/cluster_select.comp.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace gazelod::render {
namespace {

constexpr std::uint32_t kGroup = GZL_CLUSTER_SELECT_WORKGROUP;
// Dispatches start at multiples of this many clusters, so that every binding's offset is a
// multiple of 256 bytes (Vulkan's largest minStorageBufferOffsetAlignment): 8192 drawn bits
// are 1 KiB.
constexpr std::uint32_t kChunkAlign = 8192;
constexpr VkDeviceSize kStagingBytes = VkDeviceSize{16} << 20;
constexpr VkDeviceSize kSphereBytes = 16, kErrorBytes = 8, kCommandBytes = sizeof(VkDrawIndexedIndirectCommand);
static_assert(sizeof(VkDrawIndexedIndirectCommand) == 20, "the shader's DrawCommand");

// drawn_bits words a dispatch of `clusters` writes: 8 per workgroup.
std::uint32_t words_for(std::uint32_t clusters) {
  return (clusters + kGroup - 1) / kGroup * (kGroup / 32);
}

}  // namespace

ClusterSelectPass::ClusterSelectPass(const DeviceContext& ctx, const lod::ClusterSet& clusters,
                                     std::span<const ClusterDrawRange> ranges, const ClusterSelectOptions& options)
    : ctx_(ctx) {
  if (clusters.size() == 0) throw std::invalid_argument("cluster select pass: the set has no clusters");
  if (clusters.size() > std::numeric_limits<std::uint32_t>::max() - kChunkAlign)
    throw std::invalid_argument("cluster select pass: " + std::to_string(clusters.size()) +
                                " clusters (ids are 32-bit)");
  if (ranges.size() != clusters.size())
    throw std::invalid_argument("cluster select pass: " + std::to_string(ranges.size()) + " draw ranges for " +
                                std::to_string(clusters.size()) + " clusters (one each)");
  if (const std::string e = lod::validate_clusters(clusters); !e.empty())
    throw std::invalid_argument("cluster select pass: " + e);
  cluster_count_ = clusters.size();
  mesh_count_ = clusters.mesh_count();
  // Every member cleans up after itself, also when a step here throws.
  one_shot_ = std::make_unique<OneShotCommands>(ctx_);
  vk_ = std::make_unique<VulkanObjects>();
  vk_->device = ctx_.device;
  create_pipeline();
  create_buffers(clusters, options);
  write_descriptors();
  copy_to_device(*one_shot_, staging_, draw_ranges_.buffer(), 0, ranges.data(), ranges.size_bytes());
  upload(clusters);
}

ClusterSelectPass::~ClusterSelectPass() = default;

// vkDestroy* ignores null handles; the descriptor pool frees the sets.
ClusterSelectPass::VulkanObjects::~VulkanObjects() {
  vkDestroyPipeline(device, pipeline, nullptr);
  vkDestroyPipelineLayout(device, layout, nullptr);
  vkDestroyDescriptorPool(device, pool, nullptr);
  vkDestroyDescriptorSetLayout(device, set_layout, nullptr);
  vkDestroyQueryPool(device, queries, nullptr);
}

void ClusterSelectPass::create_pipeline() {
  std::array<VkDescriptorSetLayoutBinding, GZL_CLUSTER_SELECT_BINDING_COUNT> bindings{};
  for (std::uint32_t b = 0; b < bindings.size(); ++b)
    bindings[b] = {
        b,
        b == GZL_CLUSTER_SELECT_BINDING_FRAME ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
        1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo dci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  dci.bindingCount = static_cast<std::uint32_t>(bindings.size());
  dci.pBindings = bindings.data();
  vk_check(vkCreateDescriptorSetLayout(ctx_.device, &dci, nullptr, &vk_->set_layout), "vkCreateDescriptorSetLayout");
  const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gzl_cluster_select_dispatch)};
  VkPipelineLayoutCreateInfo lci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  lci.setLayoutCount = 1;
  lci.pSetLayouts = &vk_->set_layout;
  lci.pushConstantRangeCount = 1;
  lci.pPushConstantRanges = &range;
  vk_check(vkCreatePipelineLayout(ctx_.device, &lci, nullptr, &vk_->layout), "vkCreatePipelineLayout");

  VkShaderModuleCreateInfo sci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  sci.codeSize = sizeof cluster_select_comp_spv;
  sci.pCode = cluster_select_comp_spv;
  VkShaderModule module = VK_NULL_HANDLE;
  vk_check(vkCreateShaderModule(ctx_.device, &sci, nullptr, &module), "vkCreateShaderModule");
  VkComputePipelineCreateInfo pci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  pci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  pci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  pci.stage.module = module;
  pci.stage.pName = "main";
  pci.layout = vk_->layout;
  const VkResult r = vkCreateComputePipelines(ctx_.device, VK_NULL_HANDLE, 1, &pci, nullptr, &vk_->pipeline);
  vkDestroyShaderModule(ctx_.device, module, nullptr);
  vk_check(r, "vkCreateComputePipelines");

  // Timestamps, where the queue has them.
  std::uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(ctx_.physical, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(ctx_.physical, &n, families.data());
  const std::uint32_t bits = ctx_.queue_family < n ? families[ctx_.queue_family].timestampValidBits : 0;
  if (bits == 0) return;
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(ctx_.physical, &props);
  timestamp_ns_ = props.limits.timestampPeriod;
  timestamp_mask_ = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
  VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  qci.queryType = VK_QUERY_TYPE_TIMESTAMP;
  qci.queryCount = 2;
  vk_check(vkCreateQueryPool(ctx_.device, &qci, nullptr, &vk_->queries), "vkCreateQueryPool");
}

void ClusterSelectPass::create_buffers(const lod::ClusterSet& clusters, const ClusterSelectOptions& options) {
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(ctx_.physical, &props);
  const VkDeviceSize max_range = props.limits.maxStorageBufferRange;
  // The largest per-cluster element (a sphere) bounds a dispatch's clusters, as does the
  // workgroup count limit.
  const VkDeviceSize by_range = max_range / kSphereBytes;
  const VkDeviceSize by_groups = VkDeviceSize{props.limits.maxComputeWorkGroupCount[0]} * kGroup;
  const VkDeviceSize asked = options.max_dispatch_clusters > 0 ? options.max_dispatch_clusters : by_range;
  chunk_clusters_ = static_cast<std::uint32_t>(
      std::max<VkDeviceSize>(std::min({by_range, by_groups, asked}) / kChunkAlign * kChunkAlign, kChunkAlign));
  const auto n = static_cast<std::uint32_t>(cluster_count_);
  for (std::uint32_t base = 0; base < n; base += std::min(chunk_clusters_, n - base))
    chunks_.push_back({base, std::min(chunk_clusters_, n - base), VK_NULL_HANDLE});

  const VkDeviceSize want = options.command_capacity > 0 ? options.command_capacity : n;
  capacity_ = static_cast<std::uint32_t>(std::max<VkDeviceSize>(
      1, std::min({want, max_range / kCommandBytes, VkDeviceSize{props.limits.maxDrawIndirectCount}})));

  constexpr VkBufferUsageFlags kIn = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  constexpr VkBufferUsageFlags kOut = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
  self_ = DeviceBuffer(ctx_, n * kSphereBytes, kIn);
  parent_ = DeviceBuffer(ctx_, n * kSphereBytes, kIn);
  errors_ = DeviceBuffer(ctx_, n * kErrorBytes, kIn);
  mesh_of_ = DeviceBuffer(ctx_, VkDeviceSize{n} * sizeof(std::uint32_t), kIn);
  draw_ranges_ = DeviceBuffer(ctx_, VkDeviceSize{n} * sizeof(ClusterDrawRange), kIn);
  const Chunk& last = chunks_.back();
  drawn_bits_ = DeviceBuffer(ctx_, VkDeviceSize{last.base / 32 + words_for(last.count)} * 4, kOut);
  count_ = DeviceBuffer(ctx_, sizeof(std::uint32_t), kOut);
  commands_ = DeviceBuffer(ctx_, VkDeviceSize{capacity_} * kCommandBytes, kOut);
  frame_ = HostBuffer(ctx_, sizeof(gzl_cluster_select_frame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  meshes_ =
      HostBuffer(ctx_, clusters.mesh_count() * sizeof(gzl_cluster_select_mesh), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  staging_ = HostBuffer(ctx_, kStagingBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

void ClusterSelectPass::write_descriptors() {
  const auto sets = static_cast<std::uint32_t>(chunks_.size());
  const std::array<VkDescriptorPoolSize, 2> sizes{
      {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, sets}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 9 * sets}}};
  VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pci.maxSets = sets;
  pci.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  pci.pPoolSizes = sizes.data();
  vk_check(vkCreateDescriptorPool(ctx_.device, &pci, nullptr, &vk_->pool), "vkCreateDescriptorPool");
  for (Chunk& c : chunks_) {
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = vk_->pool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &vk_->set_layout;
    vk_check(vkAllocateDescriptorSets(ctx_.device, &ai, &c.set), "vkAllocateDescriptorSets");
    const VkDeviceSize b = c.base, k = c.count;
    // Per binding (shaders/cluster_select_gpu.h): the buffer, and the chunk's slice of it.
    const std::array<VkDescriptorBufferInfo, GZL_CLUSTER_SELECT_BINDING_COUNT> info{{
        {frame_.buffer(), 0, VK_WHOLE_SIZE},
        {meshes_.buffer(), 0, VK_WHOLE_SIZE},
        {self_.buffer(), b * kSphereBytes, k * kSphereBytes},
        {parent_.buffer(), b * kSphereBytes, k * kSphereBytes},
        {errors_.buffer(), b * kErrorBytes, k * kErrorBytes},
        {mesh_of_.buffer(), b * 4, k * 4},
        {draw_ranges_.buffer(), b * sizeof(ClusterDrawRange), k * sizeof(ClusterDrawRange)},
        {drawn_bits_.buffer(), b / 32 * 4, VkDeviceSize{words_for(c.count)} * 4},
        {count_.buffer(), 0, VK_WHOLE_SIZE},
        {commands_.buffer(), 0, VK_WHOLE_SIZE},
    }};
    std::array<VkWriteDescriptorSet, GZL_CLUSTER_SELECT_BINDING_COUNT> writes{};
    for (std::uint32_t i = 0; i < writes.size(); ++i) {
      writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      writes[i].dstSet = c.set;
      writes[i].dstBinding = i;
      writes[i].descriptorCount = 1;
      writes[i].descriptorType =
          i == GZL_CLUSTER_SELECT_BINDING_FRAME ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      writes[i].pBufferInfo = &info[i];
    }
    vkUpdateDescriptorSets(ctx_.device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
  }
}

void ClusterSelectPass::upload_records(const lod::ClusterSet& clusters) {
  if (clusters.size() != cluster_count_ || clusters.mesh_count() != mesh_count_)
    throw std::invalid_argument("cluster select pass: the set has " + std::to_string(clusters.size()) +
                                " clusters and " + std::to_string(clusters.mesh_count()) + " meshes, the pass " +
                                std::to_string(cluster_count_) + " and " + std::to_string(mesh_count_));
  if (const std::string e = lod::validate_clusters(clusters); !e.empty())
    throw std::invalid_argument("cluster select pass: " + e);
  upload(clusters);
}

void ClusterSelectPass::upload(const lod::ClusterSet& c) {
  const std::size_t n = c.size();
  const auto spheres = [&](std::span<const float> x, std::span<const float> y, std::span<const float> z,
                           std::span<const float> r, const DeviceBuffer& to) {
    std::vector<float> v(4 * n);
    for (std::size_t i = 0; i < n; ++i) v[4 * i] = x[i], v[4 * i + 1] = y[i], v[4 * i + 2] = z[i], v[4 * i + 3] = r[i];
    copy_to_device(*one_shot_, staging_, to.buffer(), 0, v.data(), v.size() * sizeof(float));
  };
  spheres(c.self_center_x_m, c.self_center_y_m, c.self_center_z_m, c.self_radius_m, self_);
  spheres(c.parent_center_x_m, c.parent_center_y_m, c.parent_center_z_m, c.parent_radius_m, parent_);
  std::vector<float> errors(2 * n);
  for (std::size_t i = 0; i < n; ++i) errors[2 * i] = c.self_error_m[i], errors[2 * i + 1] = c.parent_error_m[i];
  copy_to_device(*one_shot_, staging_, errors_.buffer(), 0, errors.data(), errors.size() * sizeof(float));
  std::vector<std::uint32_t> mesh_of(n);
  for (std::size_t m = 0; m < c.mesh_count(); ++m)
    std::fill_n(mesh_of.begin() + c.mesh_first_cluster[m], c.mesh_cluster_count[m], static_cast<std::uint32_t>(m));
  copy_to_device(*one_shot_, staging_, mesh_of_.buffer(), 0, mesh_of.data(), n * sizeof(std::uint32_t));
  vel_x_.assign(c.mesh_vel_x_m_s.begin(), c.mesh_vel_x_m_s.end());
  vel_y_.assign(c.mesh_vel_y_m_s.begin(), c.mesh_vel_y_m_s.end());
  vel_z_.assign(c.mesh_vel_z_m_s.begin(), c.mesh_vel_z_m_s.end());
  finest_.assign(c.mesh_finest_error_m.begin(), c.mesh_finest_error_m.end());
}

void ClusterSelectPass::set_frame(const lod::Viewer& viewer, const EyeView* cull_view,
                                  std::span<const double> detail_scale) {
  if (const std::string e = lod::validate_viewer(viewer); !e.empty())
    throw std::invalid_argument("cluster select pass: viewer: " + e);
  if (const std::string e = lod::check_detail_scales(detail_scale, mesh_count_); !e.empty())
    throw std::invalid_argument("cluster select pass: detail scales: " + e);
  const gzl_cluster_select_frame frame = make_cluster_select_frame(viewer, cull_view);
  std::memcpy(frame_.data(), &frame, sizeof frame);
  // The mesh arrays alone are what the mesh constants read.
  lod::ClusterSet meshes;
  meshes.mesh_vel_x_m_s = vel_x_;
  meshes.mesh_vel_y_m_s = vel_y_;
  meshes.mesh_vel_z_m_s = vel_z_;
  meshes.mesh_finest_error_m = finest_;
  auto* out = static_cast<gzl_cluster_select_mesh*>(meshes_.data());
  for (std::size_t m = 0; m < mesh_count_; ++m)
    out[m] = make_cluster_select_mesh(viewer, meshes, m, detail_scale.empty() ? 1.0 : detail_scale[m]);
}

void ClusterSelectPass::record(VkCommandBuffer cmd) {
  if (vk_->queries) vkCmdResetQueryPool(cmd, vk_->queries, 0, 2);
  vkCmdFillBuffer(cmd, count_.buffer(), 0, sizeof(std::uint32_t), 0);
  // The zeroed count before the shader's atomics; earlier draws and copies of the outputs
  // (a previous frame) before the shader overwrites them.
  VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  before.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  before.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &before, 0, nullptr, 0, nullptr);
  // Bottom of pipe: latched once the fill is done, so the interval is the dispatches'.
  if (vk_->queries) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, vk_->queries, 0);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, vk_->pipeline);
  for (const Chunk& c : chunks_) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, vk_->layout, 0, 1, &c.set, 0, nullptr);
    const gzl_cluster_select_dispatch pc{c.base, c.count, capacity_, 0};
    vkCmdPushConstants(cmd, vk_->layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof pc, &pc);
    vkCmdDispatch(cmd, (c.count + kGroup - 1) / kGroup, 1, 1);
  }
  if (vk_->queries) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, vk_->queries, 1);
  recorded_ = true;
  VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  after.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &after, 0, nullptr,
                       0, nullptr);
}

void ClusterSelectPass::run(const lod::Viewer& viewer, const EyeView* cull_view, std::span<const double> detail_scale) {
  set_frame(viewer, cull_view, detail_scale);
  record(one_shot_->begin());
  one_shot_->submit_and_wait();
}

std::uint32_t ClusterSelectPass::read_draw_count() {
  std::uint32_t count = 0;
  copy_from_device(*one_shot_, staging_, count_.buffer(), 0, &count, sizeof count);
  return count;
}

void ClusterSelectPass::read_drawn(std::span<std::uint8_t> drawn) {
  if (drawn.size() != cluster_count_)
    throw std::invalid_argument("cluster select pass: read_drawn into " + std::to_string(drawn.size()) +
                                " bytes, the pass has " + std::to_string(cluster_count_) + " clusters");
  std::vector<std::uint32_t> words(drawn_bits_.size() / 4);
  copy_from_device(*one_shot_, staging_, drawn_bits_.buffer(), 0, words.data(), drawn_bits_.size());
  for (std::size_t i = 0; i < drawn.size(); ++i) drawn[i] = static_cast<std::uint8_t>((words[i / 32] >> (i % 32)) & 1u);
}

std::vector<VkDrawIndexedIndirectCommand> ClusterSelectPass::read_commands() {
  std::vector<VkDrawIndexedIndirectCommand> out(std::min(read_draw_count(), capacity_));
  copy_from_device(*one_shot_, staging_, commands_.buffer(), 0, out.data(), out.size() * kCommandBytes);
  return out;
}

double ClusterSelectPass::read_dispatch_ms() const {
  if (!vk_->queries || !recorded_) return -1.0;
  std::array<std::uint64_t, 2> ticks{};
  vk_check(vkGetQueryPoolResults(ctx_.device, vk_->queries, 0, 2, sizeof ticks, ticks.data(), sizeof(std::uint64_t),
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
           "vkGetQueryPoolResults");
  return static_cast<double>((ticks[1] - ticks[0]) & timestamp_mask_) * timestamp_ns_ * 1e-6;
}

}  // namespace gazelod::render
