// SPDX-License-Identifier: Apache-2.0
// ObjectStore's registration: a random run of adds and removes (chains of 1 to 6 levels) checked
// after every step against a plain model of what each dense id must hold, with the level weights
// kept within twice the live ones (removal leaves holes and packs them out now and then).
#include "lod/object_set.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace gazelod::lod {
namespace {

std::vector<LodLevel> chain(std::size_t n) {
  std::vector<LodLevel> c(n);
  for (std::size_t k = 0; k < n; ++k)
    c[k] = {static_cast<std::uint32_t>(4000 >> k), 0, DetailKind::geometric_error_m,
            k == 0 ? 0.0 : 0.001 * static_cast<double>(k)};
  return c;
}

struct Expected {
  double radius_m;
  std::vector<float> weights;
};

TEST(ObjectStore, AddsAndRemovesKeepEveryChainAndBoundedLevels) {
  ObjectStore st;
  std::vector<Expected> model;  // by dense id, as the store must hold them
  std::mt19937 rng(7);
  std::size_t packs = 0, previous_size = 0;
  for (int step = 0; step < 6000; ++step) {
    const bool add = model.empty() || (step < 3000 ? rng() % 3 != 0 : rng() % 3 == 0);
    if (add) {
      const double r = 0.01 + 0.001 * step;
      const std::uint32_t id = st.add({0, 0, -3}, r, {}, chain(1 + rng() % 6));
      ASSERT_EQ(id, model.size());
      const ObjectSet v = st.view();
      Expected e{r, {}};
      for (std::uint32_t k = 0; k < v.lod_count[id]; ++k) e.weights.push_back(v.level_weight[v.lod_first[id] + k]);
      model.push_back(e);
    } else {
      const std::uint32_t id = static_cast<std::uint32_t>(rng() % model.size());
      st.remove(id);
      model[id] = model.back();  // the last object moves into the removed one's place
      model.pop_back();
    }
    const ObjectSet v = st.view();
    ASSERT_EQ(st.size(), model.size());
    std::size_t live_levels = 0;
    for (std::size_t i = 0; i < model.size(); ++i) {
      ASSERT_EQ(v.radius_m[i], model[i].radius_m) << "step " << step << ", id " << i;
      ASSERT_EQ(v.lod_count[i], model[i].weights.size());
      for (std::size_t k = 0; k < model[i].weights.size(); ++k)
        ASSERT_EQ(v.level_weight[v.lod_first[i] + k], model[i].weights[k]) << "step " << step << ", id " << i;
      live_levels += model[i].weights.size();
    }
    ASSERT_LE(v.level_weight.size(), 2 * live_levels + 6) << "step " << step;
    ASSERT_EQ(validate_objects(v), "");
    if (v.level_weight.size() < previous_size) ++packs;
    previous_size = v.level_weight.size();
  }
  EXPECT_GT(packs, 3u);  // the holes were packed out, more than once
}

}  // namespace
}  // namespace gazelod::lod
