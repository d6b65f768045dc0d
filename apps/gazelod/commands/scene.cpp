// SPDX-License-Identifier: Apache-2.0
// gazelod scene generate terrain|city OUT.glb [--triangles N] [--seed S] [--tiles N]: large
// test scenes as glTF (bake/terrain_mesh.hpp, bake/city_mesh.hpp, bake/generated_scene.hpp),
// written atomically, for `gazelod bake` (--clusters) and `gazelod eval clusters`.
#include "apps/gazelod/commands/command.hpp"
#include "bake/bake_error.hpp"
#include "bake/city_mesh.hpp"
#include "bake/terrain_mesh.hpp"

#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace gazelod::cli {
namespace {

struct Options {
  std::string kind, out;
  std::uint64_t triangles = 1'000'000;
  std::uint64_t seed = 1;
  int tiles = 1;
};

int run_generate(const Options& o, CLI::App& sub, Io io) {
  if (o.out.size() < 5 || o.out.substr(o.out.size() - 4) != ".glb")
    throw UsageError("OUT: must name a .glb file, got '" + o.out + "'");
  check_output_file("OUT", o.out);
  if (o.kind == "city" && sub.count("--tiles") > 0)
    throw UsageError("--tiles: only for terrain (a city is one mesh per block)");
  const auto started = std::chrono::steady_clock::now();
  std::vector<bake::GeneratedMesh> meshes;
  std::string what;
  try {
    if (o.kind == "terrain") {
      bake::TerrainOptions t;
      t.triangles = o.triangles, t.seed = o.seed, t.tiles = o.tiles;
      meshes = bake::terrain_meshes(t);
      const std::uint32_t n = bake::terrain_quads_per_side(t);
      char s[200];
      std::snprintf(s, sizeof s, "terrain %g x %g m, %u x %u quads (%.3f m), relief %g m, seed %llu", t.size_m,
                    t.size_m, n, n, t.size_m / n, t.relief_m, static_cast<unsigned long long>(t.seed));
      what = s;
    } else {
      bake::CityOptions c;
      c.triangles = o.triangles, c.seed = o.seed;
      meshes = bake::city_meshes(c);
      what = "city of " + std::to_string(meshes.size() - 1) + " blocks, seed " + std::to_string(c.seed);
    }
    bake::write_generated_glb(meshes, o.out);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  } catch (const bake::BakeError& e) {  // the output: folder missing, not writable, disk full
    throw UsageError(e.what(), 1);
  }
  const bake::GeneratedStats s = bake::generated_stats(meshes);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  char line[400];
  std::snprintf(line, sizeof line,
                "wrote %s: %s; %llu triangles, %llu vertices in %zu mesh%s; bounds x %.1f..%.1f, y %.1f..%.1f, "
                "z %.1f..%.1f m; %.2f s\n",
                o.out.c_str(), what.c_str(), static_cast<unsigned long long>(s.triangles),
                static_cast<unsigned long long>(s.vertices), s.meshes, s.meshes == 1 ? "" : "es", s.min_m[0],
                s.max_m[0], s.min_m[1], s.max_m[1], s.min_m[2], s.max_m[2], seconds);
  io.out << line;
  return 0;
}

const Registrar registrar{
    "scene", "Generate large test scenes as glTF (terrain, city)", [](CLI::App& sub) -> Action {
      auto o = std::make_shared<Options>();
      sub.require_subcommand(1);
      CLI::App* generate = sub.add_subcommand(
          "generate", "Write a generated scene as .glb: terrain (a fractal height field) or city (box buildings)");
      generate->add_option("kind", o->kind, "terrain or city")->required()->check(CLI::IsMember({"terrain", "city"}));
      generate->add_option("out", o->out, "output .glb (written atomically)")->required();
      generate->add_option("--triangles", o->triangles, "at least this many triangles (default 1000000)")
          ->check(CLI::Range(std::uint64_t{2}, bake::kMaxGeneratedTriangles));
      generate->add_option("--seed", o->seed, "random seed (default 1): the same seed, the same file");
      generate->add_option("--tiles", o->tiles, "terrain only: split into N x N meshes (default 1)")
          ->check(CLI::Range(1, 64));
      return [o, generate](Io io) { return run_generate(*o, *generate, io); };
    }};

}  // namespace
}  // namespace gazelod::cli
