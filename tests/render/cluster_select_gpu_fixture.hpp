// SPDX-License-Identifier: Apache-2.0
// What the GPU cluster-selection tests share: a lavapipe device per test (the case skips, with
// the reason, where there is none; fails under CI=true) whose validation-layer messages fail the
// test, and the CPU's cut under the combined rule (select_clusters, distinct records).
#pragma once

#include "lod/cluster/cluster_select.hpp"
#include "render/device_context.hpp"
#include "render/render_error.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace gazelod::render::test {

class ClusterSelectGpu : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string missing;
    try {
      device_ = std::make_unique<OffscreenDevice>();
      if (!device_->context().draw_indirect_count) missing = "the device lacks drawIndirectCount";
    } catch (const NoVulkanDevice& e) {
      missing = std::string("no Vulkan device: ") + e.what();
    }
    if (!missing.empty()) GAZELOD_SKIP_OR_FAIL(missing);
    RecordProperty("validation_layer", device_->validation_enabled() ? "on" : "off");
  }
  // Whatever the validation layer said fails the test.
  void TearDown() override {
    const std::vector<std::string> said = device_ ? device_->validation_messages() : std::vector<std::string>{};
    for (const std::string& m : said) ADD_FAILURE() << "validation: " << m;
  }
  const DeviceContext& ctx() const { return device_->context(); }

  std::unique_ptr<OffscreenDevice> device_;
};

inline std::vector<std::uint8_t> cpu_cut(const lod::Viewer& viewer, const lod::ClusterSet& clusters) {
  std::vector<std::uint8_t> drawn(clusters.size()), why(clusters.size());
  std::vector<std::uint32_t> flags(clusters.record_count());
  lod::ClusterDecisions out;
  out.drawn = drawn;
  out.limited_by = why;
  out.record_flags = flags;
  EXPECT_EQ(lod::select_clusters(viewer, clusters, out), "");
  return drawn;
}

}  // namespace gazelod::render::test
