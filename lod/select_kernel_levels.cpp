// SPDX-License-Identifier: Apache-2.0
// Filling the rows (before phase 1), and phase 2 of the selection (see select_kernel.hpp):
// per object, the count of rows with w_k^2 above each criterion's threshold A^2 p^2, and
// which criterion limits the combined choice; comparisons and counts in float (exact small
// integers), so that GCC vectorises the loop 16 objects wide without mask conversions.
#include "lod/select_kernel.hpp"

#include "lod/criterion.hpp"
#include "lod/acuity.hpp"

#include <cstdint>
#include <limits>

namespace gazelod::lod::detail {
namespace {

// Counts of rows with w_k^2 > threshold, in float: 16 objects per AVX-512 vector. Rounding
// both sides to float is monotone, so float(a) > float(b) implies a > b: a float comparison
// may keep a finer level where the two lie within float rounding (6e-8 relative) of each
// other, never a coarser one. kRows comparisons are unrolled with the counts in registers
// (a runtime row loop would round-trip them through memory per row); then the limiting
// criterion, and the bytes.
template <std::size_t kRows>
[[gnu::always_inline]] inline void count_levels(const KernelFrame& f, std::size_t count, const KernelBlock& b,
                                                const LevelOutput& out) {
  const float on_s = f.use_size ? 1.0f : 0.0f, on_e = f.use_eccentricity ? 1.0f : 0.0f,
              on_v = f.use_velocity ? 1.0f : 0.0f;
  std::uint8_t* lod = out.lod;
  std::uint8_t* limited = out.limited_by;
  std::uint8_t* only_s = out.size_only;
  std::uint8_t* only_e = out.eccentricity_only;
  std::uint8_t* only_v = out.velocity_only;
  GAZELOD_IVDEP
  for (std::size_t j = 0; j < count; ++j) {
    const float ts = static_cast<float>(b.t_size[j]), te = static_cast<float>(b.t_ecc[j]),
                tv = static_cast<float>(b.t_vel[j]), tc = static_cast<float>(b.t_comb[j]);
    // Comparisons are false for NaN thresholds (A = 0 with p = inf): no level, as w * 0 > 0.
    float ns = 0.0f, ne = 0.0f, nv = 0.0f, nc = 0.0f;
    for (std::size_t k = 0; k < kRows; ++k) {
      const float w2 = b.weight[k][j];
      ns += w2 > ts ? 1.0f : 0.0f;
      ne += w2 > te ? 1.0f : 0.0f;
      nv += w2 > tv ? 1.0f : 0.0f;
      nc += w2 > tc ? 1.0f : 0.0f;
    }
    ns *= on_s, ne *= on_e, nv *= on_v;
    // A switched-off count is 0, so it can only equal nc when nc is 0 (already "none").
    float why = limiting_criterion(nc, ns, ne, nv);
    why = b.invalid[j] > 0.5 ? float(Criterion::invalid_input) : why;
    // Exact small integers: float -> int32 -> uint8.
    lod[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(nc));
    limited[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(why));
    only_s[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(ns));
    only_e[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(ne));
    only_v[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(nv));
  }
}

// Rows (squared weights) from back-to-back chains of kLen levels: a compile-time stride, so
// the loads vectorise (or at least unroll) instead of a gather per weight.
template <std::size_t kLen>
[[gnu::always_inline]] inline void fill_rows(const float* w, std::size_t count, KernelBlock& blk) {
  static_assert(kLen >= 2 && kLen <= kRowLevels + 1);
  // A float product is rounded once from the exact one, as double-then-float would be.
  for (std::size_t j = 0; j < count; ++j)
    for (std::size_t k = 1; k < kLen; ++k) {
      const float wk = w[j * kLen + k];
      blk.weight[k - 1][j] = wk * wk;
    }
  for (std::size_t j = 0; j < count; ++j) blk.w1_sq[j] = size_off_w1_sq(w[j * kLen + 1]);
}

}  // namespace

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GAZELOD_NO_CLONES)
__attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
std::size_t
select_kernel_rows_regular(const ChainInput& in, std::size_t begin, std::size_t count, KernelBlock& blk) {
  if (count == 0) return 0;
  const std::uint32_t* first = in.lod_first + begin;
  const std::uint8_t* levels = in.lod_count + begin;
  const std::uint32_t len = levels[0], first0 = first[0];
  if (len == 0 || len > kRowLevels + 1 || std::uint64_t{first0} + std::uint64_t{len} * count > in.n_weights) return 0;
  // Back to back, all of length len: one pass per array, OR-reduced (vectorises).
  std::uint32_t off = 0;
  for (std::size_t j = 0; j < count; ++j) off |= (first[j] - first0) ^ (static_cast<std::uint32_t>(j) * len);
  std::uint32_t diff = 0;
  for (std::size_t j = 0; j < count; ++j) diff |= levels[j] ^ len;
  if ((off | diff) != 0) return 0;

  const std::uint8_t* kind = reinterpret_cast<const std::uint8_t*>(in.detail_kind) + begin;
  // removed_cycles_per_diameter is 0; any other byte counts as geometric error (as in
  // select.cpp's object-by-object path). A conversion, not a compare: it vectorises.
  static_assert(static_cast<int>(DetailKind::removed_cycles_per_diameter) == 0);
  for (std::size_t j = 0; j < count; ++j) blk.kind_error[j] = static_cast<double>(kind[j]);
  const float* w = in.level_weight + first0;
  switch (len) {
    case 2:
      fill_rows<2>(w, count, blk);
      break;
    case 3:
      fill_rows<3>(w, count, blk);
      break;
    case 4:
      fill_rows<4>(w, count, blk);
      break;
    case 5:
      fill_rows<5>(w, count, blk);
      break;
    case 6:
      fill_rows<6>(w, count, blk);
      break;
    case 7:
      fill_rows<7>(w, count, blk);
      break;
    case 8:
      fill_rows<8>(w, count, blk);
      break;
    default:  // one level: no coarser one, row 0 all zero
      for (std::size_t j = 0; j < count; ++j) blk.weight[0][j] = 0.0f, blk.w1_sq[j] = 0.0;
      return 1;
  }
  return len - 1;
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GAZELOD_NO_CLONES)
__attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
void select_kernel_levels(const KernelFrame& frame, std::size_t count, std::size_t rows,
                          const KernelBlock& blk, const LevelOutput& out) {
  static_assert(kRowLevels == 7, "the switch below lists rows 1..kRowLevels");
  switch (rows) {
#define GAZELOD_ROWS(R)                      \
  case R:                                    \
    count_levels<R>(frame, count, blk, out); \
    break;
    GAZELOD_ROWS(1)
    GAZELOD_ROWS(2) GAZELOD_ROWS(3) GAZELOD_ROWS(4) GAZELOD_ROWS(5) GAZELOD_ROWS(6) GAZELOD_ROWS(7)
#undef GAZELOD_ROWS
        default : break;  // rows outside 1..kRowLevels: a caller bug; nothing is counted
  }
}

}  // namespace gazelod::lod::detail
