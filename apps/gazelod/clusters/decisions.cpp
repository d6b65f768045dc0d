// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/clusters/decisions.hpp"

#include "apps/gazelod/run/decisions_file.hpp"
#include "apps/gazelod/run/report.hpp"
#include "lod/criterion.hpp"
#include "lod/switch_policy.hpp"

#include <charconv>
#include <stdexcept>

namespace gazelod::cli {
// A function-try-block: the option's name goes on a WriteError from the file's creation.
ClusterDecisionsFile::ClusterDecisionsFile(const std::string& file, const ClusterScene& scene) try
    : scene_(scene), file_(file) {
  file_.stream() << "frame,t_ns,mesh,cluster,depth,triangles,limited_by,held\n";
  if (!file_.stream()) fail("error while writing the header");
  row_.reserve(256);
} catch (const aux::WriteError& e) {
  throw std::runtime_error(std::string("--cluster-decisions: ") + e.what());
}

void ClusterDecisionsFile::fail(const std::string& what) const {
  throw std::runtime_error("--cluster-decisions " + file_.path() + ": " + what);
}

void ClusterDecisionsFile::write(std::int64_t frame, std::int64_t t_ns, const FrameDecisions& d) {
  if (!same_cluster_layout(scene_, d.cluster_first) || d.cluster_drawn.size() != scene_.cluster_count() ||
      d.cluster_limited_by.size() != scene_.cluster_count() ||
      (!d.cluster_held.empty() && d.cluster_held.size() != scene_.cluster_count()))
    fail("frame " + std::to_string(frame) + ": the plugin's cluster layout is not the scene's");
  char buf[24];
  const auto add = [&](std::uint64_t v) {
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    row_.append(buf, r.ptr);
  };
  // frame and t_ns are the same on every row of the frame: formatted once.
  std::string prefix;
  {
    const auto r1 = std::to_chars(buf, buf + sizeof buf, frame);
    prefix.append(buf, r1.ptr);
    prefix += ',';
    const auto r2 = std::to_chars(buf, buf + sizeof buf, t_ns);
    prefix.append(buf, r2.ptr);
    prefix += ',';
  }
  std::ostream& out = file_.stream();
  for (std::size_t m = 0; m < scene_.meshes.size(); ++m) {
    const ClusterMesh& mesh = scene_.meshes[m];
    const std::string label = csv_field(mesh.label);
    const std::uint32_t first = scene_.first_cluster[m];
    const std::size_t count = mesh.primitive->hierarchy.depth.size();
    for (std::size_t c = 0; c < count; ++c) {
      const std::size_t i = first + c;
      if (d.cluster_drawn[i] == 0) continue;
      row_ = prefix;
      row_ += label;
      row_ += ',';
      add(c);
      row_ += ',';
      add(mesh.primitive->hierarchy.depth[c]);
      row_ += ',';
      add(scene_.cluster_triangles[i]);
      row_ += ',';
      row_ += lod::to_string(static_cast<lod::Criterion>(d.cluster_limited_by[i]));
      row_ += ',';
      if (!d.cluster_held.empty()) row_ += lod::to_string(static_cast<lod::HoldReason>(d.cluster_held[i]));
      row_ += '\n';
      out.write(row_.data(), static_cast<std::streamsize>(row_.size()));
      ++rows_;
    }
  }
  if (!out) fail("error while writing frame " + std::to_string(frame) + " (the file is not left behind)");
}

void ClusterDecisionsFile::commit() {
  try {
    file_.commit();
  } catch (const aux::WriteError& e) {
    throw std::runtime_error(std::string("--cluster-decisions: ") + e.what());
  }
}

}  // namespace gazelod::cli
