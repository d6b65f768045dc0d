// SPDX-License-Identifier: Apache-2.0
// `gazelod run --cluster-decisions FILE`: the cut drawn in every frame, one row per drawn
// cluster, so that a researcher can see where the detail went on a large mesh (the
// per-object levels are --decisions' wide table; a cut has too many clusters for columns).
//
// Format (CSV, RFC 4180, header first):
//   frame,t_ns,mesh,cluster,depth,triangles,limited_by,held
// mesh: the cluster mesh's label ("Terrain primitive 0"); cluster: its index within the mesh's
// hierarchy; depth: 0 for a source cluster, one more per simplification; triangles: its own;
// limited_by: the criterion that let its own error go (lod::Criterion's names: none, size,
// eccentricity, velocity, combined); held: why a coarser cut waits for it (lod::HoldReason's
// names), empty without the switch policy. Written to a temporary file beside FILE and renamed
// over it by commit(): FILE is complete or untouched.
#pragma once

#include "apps/gazelod/clusters/scene.hpp"
#include "apps/gazelod/run/signals.hpp"
#include "auxiliary/atomic_file.hpp"
#include "plugin/frame_output.hpp"

#include <cstdint>
#include <string>

namespace gazelod::cli {

class ClusterDecisionsFile {
 public:
  // `scene` must outlive the file. Throws std::runtime_error naming the option and the file.
  ClusterDecisionsFile(const std::string& file, const ClusterScene& scene);

  // One frame's cut (the scene's layout: FrameDecisions::cluster_drawn). Throws
  // std::runtime_error when the layout differs from the scene's or a write fails.
  void write(std::int64_t frame, std::int64_t t_ns, const FrameDecisions& d);
  void commit();
  const std::string& path() const { return file_.path(); }
  std::uint64_t rows() const { return rows_; }

 private:
  [[noreturn]] void fail(const std::string& what) const;
  const ClusterScene& scene_;
  AtomicRunFile file_;  // its temporary removed by a second signal too
  std::string row_;
  std::uint64_t rows_ = 0;
};

}  // namespace gazelod::cli
