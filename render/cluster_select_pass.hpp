// SPDX-License-Identifier: Apache-2.0
// GPU-driven cluster LOD: runs shaders/cluster_select.comp (select_clusters' combined rule per
// cluster, frustum culling, compacted VkDrawIndexedIndirectCommands; docs/gpu-selection.md) on
// an existing DeviceContext. The host's part:
//   ClusterSelectPass pass(ctx, store.view(), ranges);  // validates, uploads (device-local)
//   pass.run(viewer, &eye_view);                         // per frame: constants, dispatch, wait
//   renderer.draw_indirect_count(0, eye_view, {..., pass.commands_buffer(), pass.count_buffer(),
//                                               pass.command_capacity()});
// or record() into the caller's own command buffer after set_frame(). Results stay on the
// device; read_* copy them back (tests, benchmarks), timestamp queries time the dispatch.
//
// Buffers (shaders/cluster_select_gpu.h): per cluster, structure of arrays, device-local:
// self and parent spheres (16 bytes each), errors (8), mesh (4), draw range (12) -- 56 bytes
// per cluster, and the drawn bits; per frame, host-visible: the frame block and one 32-byte
// entry per mesh. A device whose maxStorageBufferRange is below a sphere array (lavapipe: 128
// MiB, 8 M clusters) gets the clusters in dispatches of up to that many, each bound at its
// offset (a multiple of 8192 clusters); the draw count and commands are shared.
#pragma once

#include "lod/cluster/cluster_select.hpp"
#include "render/camera.hpp"
#include "render/device_buffer.hpp"
#include "render/device_context.hpp"
#include "render/gpu_memory.hpp"
#include "shaders/cluster_select_gpu.h"

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace gazelod::render {

using ClusterDrawRange = gzl_cluster_select_draw_range;

struct ClusterSelectOptions {
  // Commands the buffer holds; 0: one per cluster. Capped by the device's
  // maxStorageBufferRange / 20 and maxDrawIndirectCount.
  std::uint32_t command_capacity = 0;
  // Clusters per dispatch at most (rounded down to a multiple of 8192, at least 8192); 0: as
  // many as the device's limits allow (tests use it to exercise several dispatches).
  std::uint32_t max_dispatch_clusters = 0;
};

class ClusterSelectPass {
 public:
  // `clusters` (lod::ClusterStore::view()) must pass lod::validate_clusters, with one draw range
  // per cluster (the triangles its command draws). Throws std::invalid_argument (bad set,
  // ranges, no clusters) or RenderError (Vulkan).
  ClusterSelectPass(const DeviceContext& ctx, const lod::ClusterSet& clusters, std::span<const ClusterDrawRange> ranges,
                    const ClusterSelectOptions& options = {});
  ~ClusterSelectPass();
  ClusterSelectPass(const ClusterSelectPass&) = delete;
  ClusterSelectPass& operator=(const ClusterSelectPass&) = delete;

  // Meshes moved (ClusterStore::set_pose): uploads the records and velocities again. The set
  // must have the same clusters and meshes. Throws as the constructor.
  void upload_records(const lod::ClusterSet& clusters);

  // One frame: set_frame, then record() in the pass's own command buffer, submitted and waited
  // for. viewer: lod::validate_viewer'd (std::invalid_argument otherwise); cull_view null: no
  // culling, a command for every drawn cluster; detail_scale: empty (every mesh at 1) or one
  // scale per mesh (a frame budget's steps, FrameDecisions::cluster_detail_scale;
  // lod::check_detail_scales, std::invalid_argument otherwise).
  void run(const lod::Viewer& viewer, const EyeView* cull_view, std::span<const double> detail_scale = {});
  // The frame's constants into the host-visible frame and mesh buffers: call only when no
  // submitted record() of this pass is still executing.
  void set_frame(const lod::Viewer& viewer, const EyeView* cull_view, std::span<const double> detail_scale = {});
  // Zeroes the draw count, dispatches (between two timestamps) and ends with a barrier that
  // makes the commands, count and drawn bits visible to indirect draws and transfers. The pass
  // must outlive the GPU's execution of it.
  void record(VkCommandBuffer cmd);

  // After the last run (or a waited-for record): the commands' count as the shader counted it
  // (above command_capacity: that many were dropped, drawing uses command_capacity), each
  // cluster's decision (drawn.size() == size(): 1 in the cut, in view or not), the commands
  // written, and the dispatch's GPU time in ms (timestamp queries; -1 where the queue has no
  // timestamps or nothing was recorded yet).
  std::uint32_t read_draw_count();
  void read_drawn(std::span<std::uint8_t> drawn);
  std::vector<VkDrawIndexedIndirectCommand> read_commands();
  double read_dispatch_ms() const;

  VkBuffer commands_buffer() const { return commands_.buffer(); }
  VkBuffer count_buffer() const { return count_.buffer(); }
  std::uint32_t command_capacity() const { return capacity_; }
  std::size_t size() const { return cluster_count_; }
  std::size_t dispatch_count() const { return chunks_.size(); }  // dispatches per frame

 private:
  struct Chunk {
    std::uint32_t base = 0, count = 0;
    VkDescriptorSet set = VK_NULL_HANDLE;
  };
  void create_pipeline();
  void create_buffers(const lod::ClusterSet& clusters, const ClusterSelectOptions& options);
  void write_descriptors();
  void upload(const lod::ClusterSet& clusters);  // records and per-mesh data, validated

  DeviceContext ctx_;
  std::size_t cluster_count_ = 0, mesh_count_ = 0;
  std::uint32_t capacity_ = 0, chunk_clusters_ = 0;
  std::vector<Chunk> chunks_;
  // Per mesh, for the frame constants (lod::detail::make_cluster_mesh_frame reads these).
  std::vector<double> vel_x_, vel_y_, vel_z_, finest_;
  struct VulkanObjects {  // destroyed with the pass, or by a constructor that throws
    VkDevice device = VK_NULL_HANDLE;
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkQueryPool queries = VK_NULL_HANDLE;
    ~VulkanObjects();
  };
  std::unique_ptr<VulkanObjects> vk_;
  double timestamp_ns_ = 0.0;  // per tick; 0 where the queue has no timestamps
  std::uint64_t timestamp_mask_ = 0;
  bool recorded_ = false;  // the queries were written at least once
  HostBuffer frame_, meshes_, staging_;
  DeviceBuffer self_, parent_, errors_, mesh_of_, draw_ranges_, drawn_bits_, count_, commands_;
  std::unique_ptr<OneShotCommands> one_shot_;
};

}  // namespace gazelod::render
