// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/clusters/audit.hpp"

#include "auxiliary/text.hpp"

#include "apps/gazelod/run/in_view.hpp"
#include "lod/cluster/cluster_select.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace gazelod::cli {
namespace {

double ratio(double num, double den) {
  return den > 0.0 ? num / den : 0.0;
}

}  // namespace

void count_cluster_leaves(const ClusterLeafInput& in, ClusterAuditFrame& f) {
  const std::size_t n = std::min({in.drawn.size(), in.oracle.size(), in.in_view.size()});
  const auto depth = [&](std::uint32_t c) -> std::int64_t { return c < in.depth_of.size() ? in.depth_of[c] : 0; };
  for (std::size_t k = 0; k < n; ++k) {
    if (!in.in_view[k]) continue;
    ++f.leaves_in_view;
    const LeafCover& d = in.drawn[k];
    const LeafCover& o = in.oracle[k];
    if (d.self_error_m > o.self_error_m) {
      ++f.degraded;
      const std::int64_t excess = depth(d.cluster) - depth(o.cluster);
      if (excess > 0) {
        f.excess_depth += static_cast<std::uint64_t>(excess);
        f.excess_depth_max = std::max(f.excess_depth_max, static_cast<std::uint32_t>(excess));
      }
    }
    if (k < in.previous.size() && in.previous[k] != d.cluster) ++f.switches;
  }
}

ClusterAuditOracle::ClusterAuditOracle(const ClusterScene& scene) {
  std::size_t clusters = 0;
  for (const ClusterMesh& m : scene.meshes) clusters += m.primitive->hierarchy.size();
  store_.reserve(scene.meshes.size(), clusters);
  covers_.reserve(scene.meshes.size());
  for (const ClusterMesh& m : scene.meshes) {
    const lod::ClusterHierarchy& h = m.primitive->hierarchy;
    try {
      const std::uint32_t id = store_.add_mesh(h, m.pose, glm::dvec3(0.0), m.primitive->indices.size());
      first_.push_back(store_.first_cluster(id));
      local_.push_back(&h);
      covers_.emplace_back(h);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("cluster audit: " + m.label + ": " + e.what());
    }
    count_.push_back(static_cast<std::uint32_t>(h.size()));
    leaf_first_.push_back(static_cast<std::uint32_t>(drawn_cover_.size()));
    drawn_cover_.resize(drawn_cover_.size() + covers_.back().leaves().size());
    for (std::size_t c = 0; c < h.size(); ++c) {
      triangles_.push_back(h.index_count[c] / 3);
      depth_.push_back(h.depth[c]);
    }
  }
  oracle_cover_.resize(drawn_cover_.size());
  previous_cover_.assign(drawn_cover_.size(), kNoCluster);
  leaf_in_view_.assign(drawn_cover_.size(), 0);
  for (auto* v : {&oracle_drawn_, &limited_, &in_view_, &size_only_, &eccentricity_only_, &velocity_only_})
    v->assign(store_.size(), 0);
  record_flags_.assign(store_.record_count(), 0);
}

void ClusterAuditOracle::set_pose(std::size_t mesh, const lod::InstanceTransform& pose,
                                  const glm::dvec3& velocity_m_s) {
  if (mesh >= local_.size()) throw std::out_of_range("cluster audit: mesh " + std::to_string(mesh) + " out of range");
  store_.set_pose(static_cast<std::uint32_t>(mesh), *local_[mesh], pose, velocity_m_s);
}

ClusterAuditFrame ClusterAuditOracle::audit(const lod::Viewer& truth, const glm::dvec3& eye_m, const glm::dquat& head,
                                            const lod::FovRad& fov, std::span<const std::uint8_t> drawn,
                                            bool suppressed, double frame_s, std::string* error) {
  ClusterAuditFrame f;
  if (drawn.size() != store_.size()) {
    if (error)
      *error = "the drawn cut has " + std::to_string(drawn.size()) + " clusters, the oracle " +
               std::to_string(store_.size());
    return f;
  }
  const lod::ClusterSet set = store_.view();
  lod::ClusterDecisions out;
  out.drawn = oracle_drawn_;
  out.limited_by = limited_;
  out.drawn_size_only = size_only_;
  out.drawn_eccentricity_only = eccentricity_only_;
  out.drawn_velocity_only = velocity_only_;
  out.record_flags = record_flags_;
  if (std::string err = lod::select_clusters(truth, set, out); !err.empty()) {
    if (error) *error = err;
    return f;
  }
  for (std::size_t c = 0; c < set.size(); ++c)
    in_view_[c] = sphere_in_view({set.self_center_x_m[c], set.self_center_y_m[c], set.self_center_z_m[c]},
                                 set.self_radius_m[c], eye_m, head, fov)
                      ? 1
                      : 0;
  f.available = true;
  f.suppressed = suppressed;
  for (std::size_t m = 0; m < covers_.size(); ++m) {
    const std::size_t first = first_[m], count = count_[m], lf = leaf_first_[m];
    const std::span<const std::uint32_t> leaves = covers_[m].leaves();
    const std::span<LeafCover> dc = std::span(drawn_cover_).subspan(lf, leaves.size());
    const std::span<LeafCover> oc = std::span(oracle_cover_).subspan(lf, leaves.size());
    f.miscovered += static_cast<std::int64_t>(covers_[m].evaluate(drawn.subspan(first, count), dc));
    covers_[m].evaluate(std::span<const std::uint8_t>(oracle_drawn_).subspan(first, count), oc);
    for (std::size_t k = 0; k < leaves.size(); ++k) leaf_in_view_[lf + k] = in_view_[first + leaves[k]];
    ClusterLeafInput in;
    in.drawn = dc;
    in.oracle = oc;
    if (!first_frame_) in.previous = std::span<const std::uint32_t>(previous_cover_).subspan(lf, leaves.size());
    in.in_view = std::span<const std::uint8_t>(leaf_in_view_).subspan(lf, leaves.size());
    in.depth_of = std::span<const std::uint8_t>(depth_).subspan(first, count);
    count_cluster_leaves(in, f);
    for (std::size_t c = first; c < first + count; ++c) {
      if (!in_view_[c]) continue;
      if (drawn[c]) f.drawn_triangles += triangles_[c];
      if (oracle_drawn_[c]) f.oracle_triangles += triangles_[c];
      if (size_only_[c]) f.oracle_size_only_triangles += triangles_[c];
      if (eccentricity_only_[c]) f.oracle_eccentricity_only_triangles += triangles_[c];
      if (velocity_only_[c]) f.oracle_velocity_only_triangles += triangles_[c];
    }
    for (std::size_t k = 0; k < leaves.size(); ++k) previous_cover_[lf + k] = dc[k].cluster;
  }
  f.leaf_s = static_cast<double>(f.leaves_in_view) * std::max(0.0, frame_s);
  first_frame_ = false;
  return f;
}

ClusterAuditSummary summarize_cluster_audit(std::span<const ClusterAuditFrame> frames) {
  ClusterAuditSummary s;
  std::uint64_t excess = 0;
  for (const ClusterAuditFrame& f : frames) {
    if (!f.available) continue;
    s.available = true;
    ++s.frames;
    s.drawn_triangles += f.drawn_triangles;
    s.oracle_triangles += f.oracle_triangles;
    s.oracle_size_only_triangles += f.oracle_size_only_triangles;
    s.oracle_eccentricity_only_triangles += f.oracle_eccentricity_only_triangles;
    s.oracle_velocity_only_triangles += f.oracle_velocity_only_triangles;
    s.miscovered += f.miscovered;
    if (f.suppressed) {
      s.leaf_frames_suppressed += f.leaves_in_view;
      s.degraded_suppressed += f.degraded;
      s.switches_suppressed += f.switches;
      s.leaf_s_suppressed += f.leaf_s;
    } else {
      s.leaf_frames += f.leaves_in_view;
      s.degraded += f.degraded;
      excess += f.excess_depth;
      s.excess_depth_max = std::max(s.excess_depth_max, f.excess_depth_max);
      s.switches_fixation += f.switches;
      s.leaf_s_fixation += f.leaf_s;
    }
  }
  s.degraded_share = ratio(static_cast<double>(s.degraded), static_cast<double>(s.leaf_frames));
  s.excess_depth_mean = ratio(static_cast<double>(excess), static_cast<double>(s.degraded));
  s.triangle_ratio = ratio(static_cast<double>(s.drawn_triangles), static_cast<double>(s.oracle_triangles));
  s.switches_per_leaf_s_fixation = ratio(static_cast<double>(s.switches_fixation), s.leaf_s_fixation);
  s.switches_per_leaf_s_suppressed = ratio(static_cast<double>(s.switches_suppressed), s.leaf_s_suppressed);
  return s;
}

nlohmann::json cluster_audit_json(const ClusterAuditSummary& s) {
  if (!s.available) return {{"available", false}};
  const auto rate = [](std::int64_t n, double leaf_s, double per) {
    return nlohmann::json{{"switches", n}, {"leaf_seconds", leaf_s}, {"per_leaf_second", per}};
  };
  return {
      {"available", true},
      {"oracle",
       "lod::select_clusters at the simulator's true gaze and head, tracker error 0, the run's xi "
       "and criteria, no switch policy"},
      {"frames", s.frames},
      {"visible_degradations",
       {{"leaf_frames", s.leaf_frames},
        {"degraded", s.degraded},
        {"share", s.degraded_share},
        {"excess_depth_mean", s.excess_depth_mean},
        {"excess_depth_max", s.excess_depth_max}}},
      {"suppressed_degradations", {{"leaf_frames", s.leaf_frames_suppressed}, {"degraded", s.degraded_suppressed}}},
      {"triangles_in_view",
       {{"drawn", s.drawn_triangles},
        {"oracle", s.oracle_triangles},
        {"drawn_over_oracle", s.triangle_ratio},
        {"oracle_by_criterion_alone",
         {{"size", s.oracle_size_only_triangles},
          {"eccentricity", s.oracle_eccentricity_only_triangles},
          {"velocity", s.oracle_velocity_only_triangles}}}}},
      {"switches",
       {{"outside_suppression", rate(s.switches_fixation, s.leaf_s_fixation, s.switches_per_leaf_s_fixation)},
        {"inside_suppression", rate(s.switches_suppressed, s.leaf_s_suppressed, s.switches_per_leaf_s_suppressed)}}},
      {"miscovered_leaf_frames", s.miscovered}};
}

void print_cluster_audit(const ClusterAuditSummary& s, std::ostream& out) {
  if (!s.available) {
    out << "cluster audit   unavailable (see audit)\n";
    return;
  }
  char line[320];
  std::snprintf(line, sizeof line,
                "cluster audit   visible degradations %.2f%% of %lld in-view leaf-frames outside suppression "
                "(excess mean %.2f levels, max %u)\n",
                100.0 * s.degraded_share, static_cast<long long>(s.leaf_frames), s.excess_depth_mean,
                s.excess_depth_max);
  out << line;
  std::snprintf(line, sizeof line, "cluster audit   triangles in view drawn / oracle %.3f (%llu / %llu)\n",
                s.triangle_ratio, static_cast<unsigned long long>(s.drawn_triangles),
                static_cast<unsigned long long>(s.oracle_triangles));
  out << line;
  std::snprintf(line, sizeof line,
                "cluster audit   oracle triangles in view, each criterion alone: size %llu, eccentricity %llu, "
                "velocity %llu\n",
                static_cast<unsigned long long>(s.oracle_size_only_triangles),
                static_cast<unsigned long long>(s.oracle_eccentricity_only_triangles),
                static_cast<unsigned long long>(s.oracle_velocity_only_triangles));
  out << line;
  std::snprintf(line, sizeof line,
                "cluster audit   cluster switches per leaf-second %.3f outside suppression, %.3f inside\n",
                s.switches_per_leaf_s_fixation, s.switches_per_leaf_s_suppressed);
  out << line;
  if (s.miscovered == 0)
    out << "cluster audit   every frame's cut covers each leaf exactly once\n";
  else
    out << "cluster audit   " << s.miscovered << " leaf-frames NOT covered exactly once (cracks or overlaps)\n";
}

void write_cluster_csv_header(std::ostream& csv) {
  csv << ",cluster_triangles_drawn,cluster_triangles_perceptual,cluster_audit_leaves_in_view,"
         "cluster_audit_degraded,cluster_audit_drawn_triangles,cluster_audit_oracle_triangles,"
         "cluster_audit_switches,cluster_audit_miscovered";
}

void write_cluster_csv_cells(std::ostream& csv, std::uint64_t triangles_drawn, std::uint64_t triangles_perceptual,
                             const ClusterAuditFrame& a) {
  csv << ',' << triangles_drawn << ',' << triangles_perceptual;
  if (a.available)
    csv << ',' << a.leaves_in_view << ',' << a.degraded << ',' << a.drawn_triangles << ',' << a.oracle_triangles << ','
        << a.switches << ',' << a.miscovered;
  else
    csv << ",,,,,,";
}

namespace {

double mean_of(double sum, std::uint64_t n) {
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

nlohmann::json cluster_gpu_json(const ClusterGpuSummary& g) {
  if (!g.used) return {{"used", false}};
  return {{"used", true},
          {"dispatches_per_selection", g.dispatches_per_select},
          {"selections", g.selections},
          {"selections_refused", g.selections_refused},
          {"commands_per_selection", mean_of(static_cast<double>(g.commands), g.selections)},
          {"dispatch_ms_mean", g.dispatches_timed > 0 ? nlohmann::json(mean_of(g.dispatch_ms_sum, g.dispatches_timed))
                                                      : nlohmann::json(nullptr)},
          {"dispatch_ms_max", g.dispatches_timed > 0 ? nlohmann::json(g.dispatch_ms_max) : nlohmann::json(nullptr)},
          {"frames_compared", g.frames_compared},
          {"decisions_compared", g.decisions_compared},
          {"differences_from_cpu", g.differences}};
}

}  // namespace

nlohmann::json cluster_run_json(const ClusterRunSummary& s) {
  if (s.meshes == 0) return {{"meshes", 0}};
  return {{"meshes", s.meshes},
          {"clusters", s.clusters},
          {"leaves", s.leaves},
          {"triangles_drawn", s.triangles_drawn},
          {"triangles_perceptual", s.triangles_perceptual},
          {"triangles_full", s.triangles_full},
          {"drawn_over_full", ratio(static_cast<double>(s.triangles_drawn), static_cast<double>(s.triangles_full))},
          {"audit", cluster_audit_json(s.audit)},
          {"gpu_select", cluster_gpu_json(s.gpu)}};
}

void print_cluster_run(const ClusterRunSummary& s, std::int64_t frames, std::ostream& out) {
  if (s.meshes == 0) return;
  const double n = static_cast<double>(std::max<std::int64_t>(frames, 1));
  char line[320];
  std::snprintf(line, sizeof line,
                "clusters        %s, %zu clusters (%zu leaves): %.0f triangles drawn per frame of %.0f at "
                "full detail (%.1f%%, per eye; %.0f before the switch policy)\n",
                aux::counted(s.meshes, "mesh", "meshes").c_str(), s.clusters, s.leaves,
                static_cast<double>(s.triangles_drawn) / n, static_cast<double>(s.triangles_full) / n,
                100.0 * ratio(static_cast<double>(s.triangles_drawn), static_cast<double>(s.triangles_full)),
                static_cast<double>(s.triangles_perceptual) / n);
  out << line;
  const ClusterGpuSummary& g = s.gpu;
  if (!g.used) return;
  std::snprintf(line, sizeof line,
                "cluster GPU     selected on the GPU %llu times (%llu refused viewers), %.0f draw commands each; "
                "against the plugin's cut: %llu differences in %llu decisions over %llu frames\n",
                static_cast<unsigned long long>(g.selections), static_cast<unsigned long long>(g.selections_refused),
                mean_of(static_cast<double>(g.commands), g.selections), static_cast<unsigned long long>(g.differences),
                static_cast<unsigned long long>(g.decisions_compared),
                static_cast<unsigned long long>(g.frames_compared));
  out << line;
  if (g.dispatches_timed > 0) {
    std::snprintf(line, sizeof line, "cluster GPU     dispatch %.3f ms mean, %.3f ms max (timestamp queries)\n",
                  mean_of(g.dispatch_ms_sum, g.dispatches_timed), g.dispatch_ms_max);
    out << line;
  }
}

}  // namespace gazelod::cli
