// Phase 2 of the selection (see select_kernel.hpp): per object, the squared threshold
// A^2 p^2 of each criterion, the count of rows with w_k^2 > A^2 p^2, and which criterion
// limits the combined choice. Doubles throughout (counts are small exact
// integers) so that GCC vectorises every loop without mask conversions.
#include "lod/select_kernel.hpp"

#include "lod/acuity.hpp"

#include <cstdint>
#include <limits>

namespace gazelod::lod::detail {
namespace {

// Size switched off (seed 000 section 6): the object counts as no smaller than the size at
// which level 1 sits exactly at the static limit a0, i.e. p >= w_1 / a0. The factor puts the
// floor a few ulps above, so rounding never lets level 1 pass at A = a0 by size-off alone.
constexpr double kSizeOffMargin = 1.0 + 4e-15;

// One pass over the block: thresholds, then kRows compile-time-unrolled comparisons with the
// counts in registers (a runtime row loop would round-trip them through memory per row),
// then the limiting criterion.
template <bool kUseSize, std::size_t kRows>
[[gnu::always_inline]] inline void count_levels(const KernelFrame& f, std::size_t count,
                                                KernelBlock& b) {
  const double a0 = f.acuity_static_cpd, s = f.scale, xi = f.xi_cpd;
  const double a0_2 = a0 * a0;
  const double floor_per_w = kSizeOffMargin / a0;  // a0 > 0 for a valid Viewer
  const double floor2_per_w2 = floor_per_w * floor_per_w;
  const double on_s = f.use_size ? 1.0 : 0.0, on_e = f.use_eccentricity ? 1.0 : 0.0,
               on_v = f.use_velocity ? 1.0 : 0.0;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < count; ++j) {
    // Squared thresholds; e and c are compared against w^2 / M^2 (see select_kernel.hpp).
    const double p2 = b.kind_error[j] > 0.5 ? b.p2_error[j] : b.p2_cycles[j];
    const double p2_floor = b.weight[0][j] * floor2_per_w2;
    const double p2_off = p2 > p2_floor ? p2 : p2_floor;
    const double g = b.g_cpd[j], inv_m = b.inv_m[j], xi_m = xi * inv_m;
    const double av = s * (g < xi ? g : xi);
    const double ae = s * (kAcuityMaxCpd < xi_m ? kAcuityMaxCpd : xi_m);
    const double ac = s * (g < xi_m ? g : xi_m);
    // Invalid object (p2_cycles < 0): thresholds +inf, so no level; marked below.
    const bool bad = b.p2_cycles[j] < 0.0;
    const double ts = bad ? kInf : a0_2 * p2;
    const double te = bad ? kInf : ae * ae * p2_off;
    const double tv = bad ? kInf : av * av * p2_off;
    const double tc = bad ? kInf : ac * ac * (kUseSize ? p2 : p2_off);
    const double im2 = inv_m * inv_m;
    // Comparisons are false for NaN thresholds (A = 0 with p = inf): no level, as w * 0 > 0.
    double ns = 0.0, ne = 0.0, nv = 0.0, nc = 0.0;
    for (std::size_t k = 0; k < kRows; ++k) {
      const double w2 = b.weight[k][j], w2m = w2 * im2;
      ns += w2 > ts ? 1.0 : 0.0;
      ne += w2m > te ? 1.0 : 0.0;
      nv += w2 > tv ? 1.0 : 0.0;
      nc += w2m > tc ? 1.0 : 0.0;
    }
    ns *= on_s, ne *= on_e, nv *= on_v;
    b.n_size[j] = ns, b.n_ecc[j] = ne, b.n_vel[j] = nv, b.n_comb[j] = nc;
    // Criterion values (select.hpp): none 0, size 1, eccentricity 2, velocity 3, combined 4.
    // A switched-off count is 0, so it can only equal nc when nc is 0 (already "none").
    // Innermost choice first: one two-way blend per step (a nested ?: chain is a phi GCC
    // 12 cannot if-convert).
    double why = nc == nv ? 3.0 : 4.0;
    why = nc == ne ? 2.0 : why;
    why = nc == ns ? 1.0 : why;
    why = nc == 0.0 ? 0.0 : why;
    b.why[j] = bad ? 5.0 : why;  // Criterion::invalid_input
  }
}

// Counts to bytes: doubles -> int32 -> uint8 (exact: counts are at most kRowLevels).
[[gnu::always_inline]] inline void write_bytes(const KernelBlock& b, std::size_t count,
                                               const LevelOutput& out) {
  std::uint8_t* lod = out.lod;
  std::uint8_t* why = out.limited_by;
  std::uint8_t* ls = out.size_only;
  std::uint8_t* le = out.eccentricity_only;
  std::uint8_t* lv = out.velocity_only;
#pragma GCC ivdep
  for (std::size_t j = 0; j < count; ++j) {
    lod[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(b.n_comb[j]));
    why[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(b.why[j]));
    ls[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(b.n_size[j]));
    le[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(b.n_ecc[j]));
    lv[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(b.n_vel[j]));
  }
}

// Rows (squared weights) from back-to-back chains of kLen levels: a compile-time stride, so
// the loads vectorise (or at least unroll) instead of a gather per weight.
template <std::size_t kLen>
[[gnu::always_inline]] inline void fill_rows(const double* w, std::size_t count, KernelBlock& blk) {
  static_assert(kLen >= 2 && kLen <= kRowLevels + 1);
  for (std::size_t j = 0; j < count; ++j)
    for (std::size_t k = 1; k < kLen; ++k) {
      const double wk = w[j * kLen + k];
      blk.weight[k - 1][j] = wk * wk;
    }
}

}  // namespace

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GAZELOD_NO_CLONES)
__attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
std::size_t select_kernel_rows_regular(const ChainInput& in, std::size_t begin, std::size_t count,
                                       KernelBlock& blk) {
  if (count == 0) return 0;
  const std::uint32_t* first = in.lod_first + begin;
  const std::uint8_t* levels = in.lod_count + begin;
  const std::uint32_t len = levels[0], first0 = first[0];
  if (len == 0 || len > kRowLevels + 1 ||
      std::uint64_t{first0} + std::uint64_t{len} * count > in.n_weights)
    return 0;
  // Back to back, all of length len: one pass per array, OR-reduced (vectorises).
  std::uint32_t off = 0;
  for (std::size_t j = 0; j < count; ++j)
    off |= (first[j] - first0) ^ (static_cast<std::uint32_t>(j) * len);
  std::uint32_t diff = 0;
  for (std::size_t j = 0; j < count; ++j) diff |= levels[j] ^ len;
  if ((off | diff) != 0) return 0;

  const std::uint8_t* kind = reinterpret_cast<const std::uint8_t*>(in.detail_kind) + begin;
  // removed_cycles_per_diameter is 0; any other byte counts as geometric error (as in
  // select.cpp's object-by-object path). A conversion, not a compare: it vectorises.
  static_assert(static_cast<int>(DetailKind::removed_cycles_per_diameter) == 0);
  for (std::size_t j = 0; j < count; ++j) blk.kind_error[j] = static_cast<double>(kind[j]);
  const double* w = in.level_weight + first0;
  switch (len) {
    case 2: fill_rows<2>(w, count, blk); break;
    case 3: fill_rows<3>(w, count, blk); break;
    case 4: fill_rows<4>(w, count, blk); break;
    case 5: fill_rows<5>(w, count, blk); break;
    case 6: fill_rows<6>(w, count, blk); break;
    case 7: fill_rows<7>(w, count, blk); break;
    case 8: fill_rows<8>(w, count, blk); break;
    default:  // one level: no coarser one, row 0 all zero
      for (std::size_t j = 0; j < count; ++j) blk.weight[0][j] = 0.0;
      return 1;
  }
  return len - 1;
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GAZELOD_NO_CLONES)
__attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
void select_kernel_levels(const KernelFrame& frame, std::size_t count, std::size_t rows,
                          KernelBlock& blk, const LevelOutput& out) {
  static_assert(kRowLevels == 7, "the switch below lists rows 1..kRowLevels");
  const bool use_s = frame.use_size;
  switch (rows) {
#define GAZELOD_ROWS(R)                                                        \
  case R:                                                                      \
    if (use_s) count_levels<true, R>(frame, count, blk);                       \
    else count_levels<false, R>(frame, count, blk);                            \
    break;
    GAZELOD_ROWS(1) GAZELOD_ROWS(2) GAZELOD_ROWS(3) GAZELOD_ROWS(4) GAZELOD_ROWS(5)
    GAZELOD_ROWS(6) GAZELOD_ROWS(7)
#undef GAZELOD_ROWS
    default: break;  // rows outside 1..kRowLevels: a caller bug; nothing is counted
  }
  write_bytes(blk, count, out);
}

}  // namespace gazelod::lod::detail
