// SPDX-License-Identifier: Apache-2.0
#include "bake/cluster/seam_copies.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace gazelod::bake {
namespace {

// Copies whose source triangles face within about 11 degrees of the best are told apart by
// distance instead (both sides of a UV seam on a smooth surface face alike).
constexpr float kSameFacingCos = 0.98f;
// A position with more copies than this (a flat-shaded fan's apex) is given one of those the
// group's own triangles use, so that the work per corner stays bounded; others pick from all.
constexpr std::uint32_t kAllCopiesUpTo = 64;

struct Vec {
  float x, y, z;
};
Vec at(std::span<const float> pos, std::uint32_t v) {
  return {pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]};
}
Vec sub(Vec a, Vec b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Vec cross(Vec a, Vec b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
float dot(Vec a, Vec b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Vec face_normal(std::span<const float> pos, const std::uint32_t* t) {  // twice the area long
  const Vec a = at(pos, t[0]);
  return cross(sub(at(pos, t[1]), a), sub(at(pos, t[2]), a));
}
Vec centroid(std::span<const float> pos, const std::uint32_t* t) {
  const Vec a = at(pos, t[0]), b = at(pos, t[1]), c = at(pos, t[2]);
  return {(a.x + b.x + c.x) / 3.0f, (a.y + b.y + c.y) / 3.0f, (a.z + b.z + c.z) / 3.0f};
}

}  // namespace

SeamCopies::SeamCopies(std::span<const float> pos, std::span<const std::uint32_t> weld,
                       std::span<const std::uint32_t> source)
    : pos_(pos), weld_(weld) {
  const std::size_t n = weld.size();
  // Which vertices the source's kept triangles use, and each one's slot among its position's copies.
  constexpr std::uint32_t kUnused = UINT32_MAX;
  std::vector<std::uint32_t>& slot = slot_;
  slot.assign(n, kUnused);
  first_.assign(n + 1, 0);
  auto kept = [&](std::size_t t) {
    const std::uint32_t* v = &source[3 * t];
    return weld[v[0]] != weld[v[1]] && weld[v[1]] != weld[v[2]] && weld[v[2]] != weld[v[0]];
  };
  const std::size_t triangles = source.size() / 3;
  for (std::size_t t = 0; t < triangles; ++t)
    if (kept(t))
      for (int k = 0; k < 3; ++k)
        if (std::uint32_t v = source[3 * t + k]; slot[v] == kUnused) slot[v] = 0, ++first_[weld[v] + 1];
  for (std::size_t w = 0; w < n; ++w) {
    if (first_[w + 1] > 1) ++seam_positions_;
    first_[w + 1] += first_[w];
  }
  copies_.resize(first_[n]);
  std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
  for (std::uint32_t v = 0; v < n; ++v)
    if (slot[v] != kUnused) slot[v] = fill[weld[v]]++, copies_[slot[v]] = v;
  normal_sum_.assign(3 * copies_.size(), 0.0f);
  centroid_sum_.assign(3 * copies_.size(), 0.0f);
  triangles_of_.assign(copies_.size(), 0);
  for (std::size_t t = 0; t < triangles; ++t) {
    if (!kept(t)) continue;
    const std::uint32_t* v = &source[3 * t];
    const Vec nrm = face_normal(pos, v), c = centroid(pos, v);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t e = slot[v[k]];
      if (first_[weld[v[k]] + 1] - first_[weld[v[k]]] < 2) continue;  // one copy: nothing to choose
      normal_sum_[3 * e] += nrm.x, normal_sum_[3 * e + 1] += nrm.y, normal_sum_[3 * e + 2] += nrm.z;
      centroid_sum_[3 * e] += c.x, centroid_sum_[3 * e + 1] += c.y, centroid_sum_[3 * e + 2] += c.z;
      ++triangles_of_[e];
    }
  }
}

void SeamCopies::collect(std::span<const std::uint32_t> group, std::vector<std::uint64_t>& pairs) const {
  pairs.clear();
  for (std::uint32_t v : group)
    if (slot_[v] != UINT32_MAX) pairs.push_back(std::uint64_t{weld_[v]} << 32 | slot_[v]);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

void SeamCopies::choose(std::span<std::uint32_t> triangles, std::span<const std::uint64_t> pairs) const {
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    std::uint32_t* v = &triangles[t];
    const Vec nrm = face_normal(pos_, v), c = centroid(pos_, v);
    const float len = std::sqrt(dot(nrm, nrm));
    // Cosine between this triangle's normal and copy s's (1 when either is degenerate, which
    // leaves the choice to distance).
    auto facing = [&](std::uint32_t s) {
      const Vec m{normal_sum_[3 * s], normal_sum_[3 * s + 1], normal_sum_[3 * s + 2]};
      const float m_len = std::sqrt(dot(m, m));
      return len > 0.0f && m_len > 0.0f ? dot(nrm, m) / (len * m_len) : 1.0f;
    };
    // The best of a list of copy slots (at least two).
    auto best = [&](auto first, auto last, auto slot) {
      float best_cos = -1.0f;
      for (auto it = first; it != last; ++it) best_cos = std::max(best_cos, facing(slot(*it)));
      float best_d2 = INFINITY;
      std::uint32_t chosen = slot(*first);
      for (auto it = first; it != last; ++it) {
        const std::uint32_t s = slot(*it);
        if (facing(s) < best_cos - (1.0f - kSameFacingCos)) continue;
        const float inv = 1.0f / static_cast<float>(std::max<std::uint32_t>(triangles_of_[s], 1));
        const Vec d =
            sub(c, Vec{centroid_sum_[3 * s] * inv, centroid_sum_[3 * s + 1] * inv, centroid_sum_[3 * s + 2] * inv});
        if (const float d2 = dot(d, d); d2 < best_d2) best_d2 = d2, chosen = s;
      }
      return copies_[chosen];
    };
    std::uint32_t chosen[3];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t w = weld_[v[k]], b = first_[w], e = first_[w + 1];
      chosen[k] = b < e ? copies_[b] : v[k];
      if (e - b < 2) continue;
      if (e - b <= kAllCopiesUpTo) {
        // The slots b..e-1 spelled out (std::views::iota here did not compile with clang 14 and
        // libstdc++ 12, which broke the fuzz build).
        std::array<std::uint32_t, kAllCopiesUpTo> all;
        for (std::uint32_t s = b; s < e; ++s) all[s - b] = s;
        chosen[k] = best(all.begin(), all.begin() + (e - b), [](std::uint32_t s) { return s; });
        continue;
      }
      const auto lo = std::lower_bound(pairs.begin(), pairs.end(), std::uint64_t{w} << 32);
      const auto hi = std::lower_bound(lo, pairs.end(), (std::uint64_t{w} + 1) << 32);
      if (lo != hi) chosen[k] = best(lo, hi, [](std::uint64_t pair) { return static_cast<std::uint32_t>(pair); });
    }
    v[0] = chosen[0], v[1] = chosen[1], v[2] = chosen[2];
  }
}

}  // namespace gazelod::bake
