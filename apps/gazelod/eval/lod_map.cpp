// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/lod_map.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace gazelod::lod {

double lod_map_size_score(double angular_radius_deg, const LodMapParams& p) {
  if (!(angular_radius_deg > 0.0) || !(p.size_full_deg > 0.0)) return 0.0;  // NaN too
  return std::min(1.0, angular_radius_deg / p.size_full_deg);
}

double lod_map_eccentricity_score(double eccentricity_deg) {
  if (std::isnan(eccentricity_deg)) return 0.0;
  const double e = std::max(0.0, eccentricity_deg);
  return 1.0 / (1.0 + 0.29 * e);  // denominator >= 1; infinity gives 0
}

double lod_map_motion_score(double speed_deg_s, const LodMapParams& p) {
  if (!(speed_deg_s > 0.0) || !std::isfinite(speed_deg_s)) return 0.0;
  if (!(p.motion_peak_deg_s > 0.0) || !(p.motion_max_deg_s > p.motion_peak_deg_s)) return 0.0;
  if (speed_deg_s <= p.motion_peak_deg_s) return speed_deg_s / p.motion_peak_deg_s;
  const double fall = (p.motion_max_deg_s - speed_deg_s) / (p.motion_max_deg_s - p.motion_peak_deg_s);
  return std::clamp(fall, 0.0, 1.0);
}

double lod_map_detail(const LodMapInput& in, bool use_colour, bool colour_salient, const LodMapParams& p) {
  const LodMapWeights& w = p.weights;
  const double wc = use_colour ? std::max(0.0, w.colour) : 0.0;
  const double ws = std::max(0.0, w.size), we = std::max(0.0, w.eccentricity), wm = std::max(0.0, w.motion);
  const double total = ws + wc + we + wm;
  if (!(total > 0.0) || !std::isfinite(total)) return 1.0;  // no usable weights: keep detail
  const double sum = ws * lod_map_size_score(in.angular_radius_deg, p) + wc * (colour_salient ? 1.0 : 0.0) +
                     we * lod_map_eccentricity_score(in.eccentricity_deg) +
                     wm * lod_map_motion_score(in.speed_deg_s, p);
  return std::clamp(sum / total, 0.0, 1.0);
}

std::uint8_t lod_map_level(double detail, std::uint8_t levels) {
  if (levels <= 1 || std::isnan(detail)) return 0;
  const double d = std::clamp(detail, 0.0, 1.0);
  const double level = std::round((1.0 - d) * static_cast<double>(levels - 1));
  return static_cast<std::uint8_t>(std::clamp(level, 0.0, static_cast<double>(levels - 1)));
}

std::string lod_map_select(std::span<const LodMapInput> objects, std::span<const std::uint8_t> level_counts,
                           const LodMapParams& p, std::span<std::uint8_t> out_levels) {
  if (level_counts.size() != objects.size() || out_levels.size() != objects.size())
    return "lod_map_select: " + std::to_string(objects.size()) + " objects but " + std::to_string(level_counts.size()) +
           " level counts and " + std::to_string(out_levels.size()) + " outputs";
  if (!(p.colour_salient_fraction >= 0.0 && p.colour_salient_fraction <= 1.0))
    return "lod_map_select: colour_salient_fraction must be in [0, 1]";
  std::map<int, std::size_t> group_size;
  for (const LodMapInput& o : objects)
    if (o.colour_group >= 0) ++group_size[o.colour_group];
  const bool use_colour = !group_size.empty();
  const double n = static_cast<double>(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    bool salient = false;
    if (use_colour && objects[i].colour_group >= 0)
      salient = static_cast<double>(group_size[objects[i].colour_group]) < p.colour_salient_fraction * n;
    out_levels[i] = lod_map_level(lod_map_detail(objects[i], use_colour, salient, p), level_counts[i]);
  }
  return "";
}

}  // namespace gazelod::lod
