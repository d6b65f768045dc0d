// SPDX-License-Identifier: Apache-2.0
// The per-cluster half of the kernel (see cluster_select_kernel.hpp): each cluster's decision
// from its two records' outcomes (drawn when the self record is invisible and the parent's is
// not), the limiting criterion and the record bits, on float blocks (combine_records) or on
// packed flags per distinct record (pack_record_flags, combine_record_flags). Written in the
// conventions of cluster_select_kernel.cpp so that GCC vectorises each loop.
#include "lod/cluster/cluster_select_kernel.hpp"

#include "lod/criterion.hpp"
#include "lod/select_kernel.hpp"  // GAZELOD_IVDEP

#include <algorithm>
#include <cstdint>

namespace gazelod::lod::detail {

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GAZELOD_NO_CLONES)
__attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
void pack_record_flags(std::size_t count, const RecordBlock& in, std::uint32_t* __restrict flags) {
  GAZELOD_IVDEP
  for (std::size_t j = 0; j < count; ++j) {
    const float bits = in.combined[j] + 2.0f * in.size[j] + 4.0f * in.eccentricity[j] + 8.0f * in.velocity[j] +
                       16.0f * in.positive[j] + 32.0f * in.invalid[j];
    flags[j] = static_cast<std::uint32_t>(static_cast<std::int32_t>(bits));
  }
}

namespace {

template <bool kPerCriterion, bool kRecords>
[[gnu::always_inline]] inline void combine_loop(std::size_t count, const RecordBlock& self, const RecordBlock& parent,
                                                const ClusterOutput& out) {
  // Pointers copied out of `out` first: a byte store may alias them, so GCC would reload them
  // per iteration (and not vectorise).
  std::uint8_t* __restrict drawn = out.drawn;
  std::uint8_t* __restrict why_out = out.limited_by;
  std::uint8_t* __restrict only_s = out.size_only;
  std::uint8_t* __restrict only_e = out.eccentricity_only;
  std::uint8_t* __restrict only_v = out.velocity_only;
  std::uint8_t* __restrict bits_out = out.record_invisible;
  GAZELOD_IVDEP
  for (std::size_t j = 0; j < count; ++j) {
    // A product, not std::max: max of two array elements becomes a load from a selected
    // address, which GCC does not vectorise.
    const float valid = (1.0f - self.invalid[j]) * (1.0f - parent.invalid[j]);
    const float sc = self.combined[j], pc = parent.combined[j];
    const float chosen = sc * self.positive[j];
    const float draw = sc * (1.0f - pc) * valid;
    float why = limiting_criterion(chosen, self.size[j], self.eccentricity[j], self.velocity[j]);
    why = draw > 0.5f ? why : float(Criterion::none);  // only a drawn cluster has a reason
    why = valid > 0.5f ? why : float(Criterion::invalid_input);
    drawn[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(draw));
    why_out[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(why));
    if constexpr (kPerCriterion) {
      const float ds = self.size[j] * (1.0f - parent.size[j]) * valid;
      const float de = self.eccentricity[j] * (1.0f - parent.eccentricity[j]) * valid;
      const float dv = self.velocity[j] * (1.0f - parent.velocity[j]) * valid;
      only_s[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(ds));
      only_e[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(de));
      only_v[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(dv));
    }
    if constexpr (kRecords) {
      const float bits = (sc + 2.0f * pc) * valid;
      bits_out[j] = static_cast<std::uint8_t>(static_cast<std::int32_t>(bits));
    }
  }
}

// The outputs as restrict parameters (see combine_loop: a byte store may alias them).
template <bool kPerCriterion, bool kRecords>
[[gnu::always_inline]] inline void combine_flags_loop(std::size_t count, const std::uint32_t* __restrict flags,
                                                      const std::uint32_t* __restrict self_index,
                                                      const std::uint32_t* __restrict parent_index, std::uint32_t lo,
                                                      std::uint32_t hi, std::uint8_t* __restrict drawn,
                                                      std::uint8_t* __restrict why_out, std::uint8_t* __restrict only_s,
                                                      std::uint8_t* __restrict only_e, std::uint8_t* __restrict only_v,
                                                      std::uint8_t* __restrict bits_out) {
  constexpr auto kNone = static_cast<std::uint32_t>(Criterion::none);
  constexpr auto kInvalid = static_cast<std::uint32_t>(Criterion::invalid_input);
  GAZELOD_IVDEP
  for (std::size_t j = 0; j < count; ++j) {
    // combine_loop's arithmetic on the packed bits (the same limiting_criterion, on 0/1 words).
    // Offsets from the mesh's first record, as int32 (what a vector gather takes).
    const auto self_at = static_cast<std::int32_t>(std::min(std::max(self_index[j], lo), hi) - lo);
    const auto parent_at = static_cast<std::int32_t>(std::min(std::max(parent_index[j], lo), hi) - lo);
    const std::uint32_t sb = flags[self_at];
    const std::uint32_t pb = flags[parent_at];
    const std::uint32_t valid = (((sb | pb) >> 5) & 1u) ^ 1u;
    const std::uint32_t sc = sb & 1u, pc = pb & 1u;
    const std::uint32_t draw = sc & (pc ^ 1u) & valid;
    const std::uint32_t chosen = sc & (sb >> 4) & 1u;  // invisible and positive
    std::uint32_t why = limiting_criterion<std::uint32_t>(chosen, (sb >> 1) & 1u, (sb >> 2) & 1u, (sb >> 3) & 1u);
    why = draw != 0u ? why : kNone;
    why = valid != 0u ? why : kInvalid;
    const std::uint32_t only = sb & ~pb & (0u - valid);  // per criterion: self invisible, parent not
    drawn[j] = static_cast<std::uint8_t>(draw);
    why_out[j] = static_cast<std::uint8_t>(why);
    if constexpr (kPerCriterion) {
      only_s[j] = static_cast<std::uint8_t>((only >> 1) & 1u);
      only_e[j] = static_cast<std::uint8_t>((only >> 2) & 1u);
      only_v[j] = static_cast<std::uint8_t>((only >> 3) & 1u);
    }
    // Without the per-criterion cuts, a self record under an invisible parent is set (the
    // nesting), as the per-cluster path does.
    const std::uint32_t sc_set = kPerCriterion ? sc : sc | pc;
    if constexpr (kRecords) bits_out[j] = static_cast<std::uint8_t>((sc_set | (pc << 1)) & (0u - valid));
  }
}

}  // namespace

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GAZELOD_NO_CLONES)
__attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
void combine_record_flags(std::size_t count, const std::uint32_t* flags, const std::uint32_t* self_index,
                          const std::uint32_t* parent_index, std::uint32_t lo, std::uint32_t hi,
                          const ClusterOutput& out) {
  const auto run = [&]<bool kPerCriterion, bool kRecords>() {
    combine_flags_loop<kPerCriterion, kRecords>(count, flags + lo, self_index, parent_index, lo, hi, out.drawn,
                                                out.limited_by, out.size_only, out.eccentricity_only, out.velocity_only,
                                                out.record_invisible);
  };
  const bool per_criterion = out.size_only != nullptr, records = out.record_invisible != nullptr;
  if (per_criterion)
    records ? run.operator()<true, true>() : run.operator()<true, false>();
  else
    records ? run.operator()<false, true>() : run.operator()<false, false>();
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GAZELOD_NO_CLONES)
__attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif
void combine_records(std::size_t count, const RecordBlock& self, const RecordBlock& parent,
                     const ClusterOutput& out) {
  const bool per_criterion = out.size_only != nullptr, records = out.record_invisible != nullptr;
  if (per_criterion) {
    if (records)
      combine_loop<true, true>(count, self, parent, out);
    else
      combine_loop<true, false>(count, self, parent, out);
  } else {
    if (records)
      combine_loop<false, true>(count, self, parent, out);
    else
      combine_loop<false, false>(count, self, parent, out);
  }
}

}  // namespace gazelod::lod::detail
