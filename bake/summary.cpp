// SPDX-License-Identifier: Apache-2.0
// Fixed-width text table for format_summary (summary.hpp).
#include "bake/summary.hpp"

#include "auxiliary/text.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace gazelod::bake {

std::string format_summary(const BakeReport& r) {
  std::ostringstream s;
  char line[256];
  std::snprintf(line, sizeof line, "%-28s %5s %9s %9s %10s %11s %12s %8s %9s\n", "mesh", "level", "triangles",
                "vertices", "error_rel", "error_m", "cycles/diam", "method", "time_ms");
  s << line;
  for (const MeshReport& m : r.meshes) {
    std::string name = std::to_string(m.mesh) + (m.name.empty() ? "" : " " + m.name);
    if (name.size() > 28) name = name.substr(0, 25) + "...";
    for (std::size_t k = 0; k < m.levels.size(); ++k) {
      const LevelReport& l = m.levels[k];
      std::snprintf(line, sizeof line, "%-28s %5zu %9u %9u %10.3g %11.4g %12.4g %8s %9s\n", k == 0 ? name.c_str() : "",
                    k, l.triangles, l.vertices, l.error_relative, l.error_m, l.detail_cycles_per_diameter,
                    k == 0 ? "input" : (l.sloppy ? "sloppy" : "simplify"),
                    k == 0 ? std::to_string(std::lround(m.seconds * 1000.0)).c_str() : "");
      s << line;
    }
    // The mesh's index as the table names it (a nameless mesh gave "note:  stops at ...").
    if (!m.note.empty())
      s << "  note: mesh " << m.mesh << (m.name.empty() ? "" : " " + m.name) << " " << m.note << "\n";
  }
  // Warnings before the total: a run ends with its result.
  for (const std::string& w : r.warnings) s << "warning: " << w << "\n";
  const double tps = r.seconds > 0.0 ? double(r.input_triangles) / r.seconds : 0.0;
  std::snprintf(
      line, sizeof line, "total: %s, %s with MSFT_lod, %llu input triangles, %.3f s (%.3g input triangles/s)\n",
      aux::counted(r.meshes.size(), "mesh", "meshes").c_str(), aux::counted(r.lod_nodes, "node", "nodes").c_str(),
      static_cast<unsigned long long>(r.input_triangles), r.seconds, tps);
  s << line;
  return s.str();
}

}  // namespace gazelod::bake
