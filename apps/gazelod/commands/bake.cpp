// SPDX-License-Identifier: Apache-2.0
// gazelod bake IN.gltf|IN.glb -o OUT.glb [--levels N | --ratios r1,r2,...] [--target-error E]
// [--lock-borders] [--profile 6|18]:
// an MSFT_lod chain per mesh node (bake/bake.hpp). Progress on stderr, the summary on stdout.
// gazelod bake --clusters IN OUT.glb (or -o OUT.glb) [--lock-borders] [--fold-retries N] [--keep-seams]
// [--threads N]: a cluster
// hierarchy per mesh primitive instead, stored as GAZELOD_cluster_lod (bake/cluster/cluster_bake.hpp,
// docs/bake.md).
// --profile renders every level from 6 or 18 viewpoints (Reddy's perceptual profile, Vulkan on
// lavapipe, bake/profile_render.hpp) and stores extras.gazelod_lod.rendered_cycles_per_diameter;
// off by default so a plain bake stays fast.
#include "bake/bake.hpp"
#include "bake/bake_error.hpp"
#include "bake/cluster/cluster_bake.hpp"
#include "bake/summary.hpp"
#include "render/render_error.hpp"
#include "apps/gazelod/commands/command.hpp"

#include <filesystem>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <memory>
#include <ostream>
#include <string>

namespace gazelod::cli {
namespace {

struct Options {
  std::string input, output, output_argument, ratios, target_error;
  int levels = -1;  // unset
  int profile = 0;
  int threads = -1;       // unset
  int fold_retries = -1;  // unset
  bool lock_borders = false;
  bool keep_seams = false;
  bool clusters = false;
  bool allow_outside_uris = false;
};

// -o OUT or the second argument, not two different ones.
std::string output_path(const Options& o) {
  if (!o.output.empty() && !o.output_argument.empty() && o.output != o.output_argument)
    throw UsageError("--output: give the output once (-o OUT or a second argument), got '" + o.output + "' and '" +
                     o.output_argument + "'");
  const std::string out = o.output.empty() ? o.output_argument : o.output;
  if (out.empty()) throw UsageError("--output: missing: give -o OUT.glb (or OUT.glb after the input)");
  // The same file by another name (./a.glb, a link) too: the bake would replace its own input.
  std::error_code ec;
  if (std::filesystem::equivalent(o.input, out, ec) ||
      std::filesystem::path(o.input).lexically_normal() == std::filesystem::path(out).lexically_normal())
    throw UsageError("--output: '" + out + "' is the input file; write the bake to another file");
  check_output_file("--output", out);  // a folder: refused before the bake (it failed after it, exit 1)
  return out;
}

int run_clusters(const Options& o, const std::string& out, Io io) {
  for (const auto& [set, name] : {std::pair{o.levels != -1, "--levels"},
                                  {!o.ratios.empty(), "--ratios"},
                                  {!o.target_error.empty(), "--target-error"},
                                  {o.profile != 0, "--profile"}})
    if (set) throw UsageError(std::string("--clusters: cannot be combined with ") + name);
  bake::ClusterBakeOptions opts;
  opts.build.lock_open_borders = o.lock_borders;
  opts.build.stuck_across_seams = !o.keep_seams;
  if (o.fold_retries >= 0) opts.build.fold_retries = static_cast<unsigned>(o.fold_retries);
  if (o.threads >= 0) opts.build.threads = static_cast<unsigned>(o.threads);
  opts.progress = [&io](const std::string& line) { io.err << line << '\n' << std::flush; };
  opts.load.allow_outside_folder = o.allow_outside_uris;
  try {
    io.out << bake::format_cluster_summary(bake::bake_clusters_file(o.input, out, opts));
  } catch (const bake::OutputError& e) {
    throw UsageError(e.what(), 1);  // the input was fine: "other failure"
  } catch (const bake::BakeError& e) {
    throw UsageError(e.what(), 2);  // bad input file
  }
  return 0;
}

std::vector<double> parse_ratios(const std::string& text) {
  std::vector<double> r;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    r.push_back(parse_number("--ratios", text.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return r;
}

// Rendered against geometric figure per level, when the bake profiled.
void print_profile(const bake::BakeReport& report, std::ostream& out) {
  out << "perceptual profile (removed cycles per diameter): mesh level geometric rendered\n";
  char line[160];
  for (const bake::MeshReport& m : report.meshes) {
    for (std::size_t k = 1; k < m.levels.size(); ++k) {
      std::snprintf(line, sizeof line, "  %4d %5zu %12.3f %10.3f\n", m.mesh, k, m.levels[k].detail_cycles_per_diameter,
                    m.levels[k].rendered_cycles_per_diameter);
      out << line;
    }
    std::snprintf(line, sizeof line, "  mesh %d profile: %.3f s\n", m.mesh, m.profile_seconds);
    out << line;
  }
}

int run_bake(const Options& o, Io io) {
  const std::string out = output_path(o);
  if (o.clusters) return run_clusters(o, out, io);
  if (o.threads >= 0) throw UsageError("--threads: only with --clusters (a chain is baked on one thread)");
  if (o.keep_seams)
    throw UsageError(
        "--keep-seams: only with --clusters (a chain's levels always keep attribute seams; "
        "its sloppy fallback ignores them)");
  if (o.fold_retries >= 0)
    throw UsageError(
        "--fold-retries: only with --clusters (a chain's levels are simplified from the source, "
        "where retrying with the folds' surroundings locked did not help)");
  if (o.profile != 0 && o.profile != 6 && o.profile != 18)
    throw UsageError("--profile: must be 6 or 18 viewpoints, got " + std::to_string(o.profile));
  if (o.levels != -1 && !o.ratios.empty()) throw UsageError("--levels: give either --levels or --ratios, not both");
  bake::BakeOptions opts;
  if (o.levels != -1) {
    if (o.levels < 2 || o.levels > 16)
      throw UsageError("--levels: must be in [2, 16], got " + std::to_string(o.levels));
    opts.chain.ratios = bake::ratios_for_levels(o.levels);
  } else if (!o.ratios.empty()) {
    opts.chain.ratios = parse_ratios(o.ratios);
  }
  if (!o.target_error.empty()) opts.chain.target_error_rel = parse_number("--target-error", o.target_error);
  if (std::string e = bake::validate_chain_options(opts.chain); !e.empty())
    throw UsageError((o.target_error.empty() ? "--ratios: " : "--ratios/--target-error: ") + e);
  opts.chain.lock_borders = o.lock_borders;
  opts.profile_viewpoints = o.profile;
  opts.load.allow_outside_folder = o.allow_outside_uris;
  opts.progress = [&io](const std::string& line) { io.err << line << '\n' << std::flush; };
  try {
    const bake::BakeReport report = bake::bake_file(o.input, out, opts);
    io.out << bake::format_summary(report);
    if (o.profile != 0) print_profile(report, io.out);
  } catch (const bake::OutputError& e) {
    throw UsageError(e.what(), 1);  // the input was fine: "other failure"
  } catch (const bake::BakeError& e) {
    throw UsageError(e.what(), 2);          // bad input file
  } catch (const render::RenderError& e) {  // --profile without Vulkan (NoVulkanDevice) or a render failure
    throw UsageError(std::string("--profile: ") + e.what(), 1);
  }
  return 0;
}

const Registrar reg(
    "bake", "Bake glTF LOD chains (MSFT_lod) or cluster hierarchies (--clusters) with meshoptimizer",
    [](CLI::App& app) -> Action {
      auto o = std::make_shared<Options>();
      app.add_option("input", o->input, "input .gltf or .glb")->required();
      app.add_option("output", o->output_argument, "output .glb (or -o)");
      app.add_option("-o,--output", o->output, "output .glb (written atomically)");
      app.add_flag("--allow-outside-uris", o->allow_outside_uris,
                   "read buffer and image uris outside the glTF's folder too (absolute paths, ../)");
      app.add_flag("--clusters", o->clusters,
                   "a cluster hierarchy per mesh primitive (GAZELOD_cluster_lod) instead of "
                   "MSFT_lod chains");
      app.add_option("--levels", o->levels, "levels in all, each with 1/4 of the previous triangles (default 4)");
      app.add_option("--ratios", o->ratios, "triangle ratios of the coarser levels, e.g. 0.5,0.2,0.05");
      app.add_option("--target-error", o->target_error,
                     "cap on meshoptimizer's error estimate per level, relative to the mesh extent (default 1 = no "
                     "limit; the stored error_m is measured and can be larger)");
      app.add_flag("--lock-borders", o->lock_borders,
                   "keep open borders in place (chains: no cracks between a mesh's primitives; "
                   "--clusters: also borders that meet no other primitive, which are simplified by default)");
      app.add_option("--fold-retries", o->fold_retries,
                     "--clusters: simplify a group that meshoptimizer 0.18 folded over (folds wider than its "
                     "error estimate) again, up to N times, with the folds' surroundings locked (default 2; 0: keep "
                     "the first result, its folds counted in its error)")
          ->check(CLI::Range(0, static_cast<int>(bake::kMaxFoldRetries)));
      app.add_flag("--keep-seams", o->keep_seams,
                   "--clusters: never simplify across attribute seams (positions vertices share with "
                   "different normals or UVs); by default a group that does not simplify with them kept "
                   "is simplified across them, each new corner taking the copy from its side");
      app.add_option("--threads", o->threads,
                     "--clusters: threads for the hierarchy build (default 0: one per core); the "
                     "hierarchy is the same for any count")
          ->check(CLI::Range(0, 1024));
      app.add_option("--profile", o->profile,
                     "render each level from 6 or 18 viewpoints and store Reddy's rendered "
                     "figure (Vulkan; off by default)");
      return [o](Io io) { return run_bake(*o, io); };
    });

}  // namespace
}  // namespace gazelod::cli
