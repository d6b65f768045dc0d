// SPDX-License-Identifier: Apache-2.0
// gazelod eval gltfpack (see eval/gltfpack.hpp).
#include "apps/gazelod/eval/gltfpack.hpp"

#include "apps/gazelod/eval/work.hpp"
#include "bake/bake.hpp"
#include "bake/bake_error.hpp"
#include "bake/baked_scene.hpp"
#include "bake/gltf_load.hpp"
#include "bake/surface_deviation.hpp"
#include "auxiliary/json_text.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

extern char** environ;

namespace gazelod::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct GltfpackFlags {
  std::string model, out = "gazelod-eval-gltfpack", work, gltfpack = "gltfpack";
  std::vector<double> ratios{0.25, 0.0625, 0.015625};
};

struct Row {
  std::string tool;  // "gazelod bake", "gltfpack", "gltfpack -sa"
  double ratio = 1.0;
  std::size_t triangles = 0;
  bake::SurfaceDeviation to_result, from_result;  // source -> result surface, result -> source
  double seconds = 0.0;                           // the tool's run (the bake: all levels at once)
  std::string note;
};

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Runs argv (PATH searched) with stdout and stderr into `log`; the exit status, or -1 when it
// could not start (errno kept).
int spawn(const std::vector<std::string>& argv, const std::string& log) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&files, 1, 2);
  pid_t pid = 0;
  const int started = posix_spawnp(&pid, args[0], &files, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (started != 0) return errno = started, -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

std::string tail_of(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

std::string num(double x, const char* format = "%.4g") {
  if (std::isinf(x)) return "inf";
  char s[64];
  std::snprintf(s, sizeof s, format, x);
  return s;
}

nlohmann::json deviation_json(const bake::SurfaceDeviation& d) {
  const auto finite = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
  return {
      {"max_m", finite(d.max_m)}, {"p99_m", finite(d.p99_m)}, {"mean_m", finite(d.mean_m)}, {"vertices", d.vertices}};
}

int run_eval_gltfpack(const GltfpackFlags& flags, Io io) {
  if (!fs::is_regular_file(flags.model)) throw UsageError("MODEL: '" + flags.model + "' is not a file");
  for (std::size_t i = 0; i < flags.ratios.size(); ++i)
    if (!(flags.ratios[i] > 0.0 && flags.ratios[i] < 1.0) || (i > 0 && !(flags.ratios[i] < flags.ratios[i - 1])))
      throw UsageError("--ratios: each in (0, 1), strictly decreasing; got " + num(flags.ratios[i]));
  const fs::path out = flags.out;
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw UsageError("--out: cannot create '" + out.string() + "': " + ec.message());
  const WorkDir work(flags.work, "gazelod-eval-gltfpack");
  const fs::path& w = work.path();
  const auto started = Clock::now();
  const auto progress = [&](const std::string& line) {
    io.err << "gazelod eval gltfpack [" << std::lround(seconds_since(started)) << " s]: " << line << "\n" << std::flush;
  };

  // gltfpack there at all (its -v prints the version).
  const std::string version_log = (w / "gltfpack-version.txt").string();
  if (spawn({flags.gltfpack, "-v"}, version_log) < 0)
    throw UsageError("--gltfpack: cannot run '" + flags.gltfpack +
                         "' (Debian package gltfpack; bash scripts/install-deps.sh installs it)",
                     1);
  const std::string version = tail_of(version_log);

  const bake::TriangleSoup source = bake::world_triangles(bake::load_gltf(flags.model).model);
  if (source.triangles() == 0) throw UsageError("MODEL: '" + flags.model + "' has no triangles a scene shows");
  const double extent = bake::soup_extent_m(source);
  progress(flags.model + ": " + std::to_string(source.triangles()) + " triangles, extent " + num(extent) + " m");
  std::vector<Row> rows;
  const auto measure = [&](Row r, const bake::TriangleSoup& result) {
    r.triangles = result.triangles();
    r.to_result = bake::surface_deviation(source, result);
    r.from_result = bake::surface_deviation(result, source);
    progress(r.tool + " at " + num(r.ratio) + ": " + std::to_string(r.triangles) + " triangles, largest distance " +
             num(r.to_result.max_m) + " m (" + num(100.0 * r.to_result.max_m / extent, "%.3f") + " % of the extent)" +
             (r.note.empty() ? "" : "; " + r.note));
    rows.push_back(r);
  };

  // gazelod bake: one run, every level of `ratios`.
  const auto bake_chain = [&](const std::string& tool, const std::vector<double>& ratios, const std::string& file) {
    bake::BakeOptions bo;
    bo.chain.ratios = ratios;
    progress(tool + ": gazelod bake " + flags.model + " -> " + file + " ...");
    const auto tb = Clock::now();
    try {
      bake::bake_file(flags.model, file, bo);
    } catch (const bake::BakeError& e) {
      throw UsageError(std::string("gazelod bake: ") + e.what());
    }
    const double bake_s = seconds_since(tb);
    const bake::BakedScene scene = bake::load_baked(file, bake::BakedLoad::with_level_geometry);
    for (std::size_t k = 1; k <= ratios.size(); ++k) {
      bake::TriangleSoup level;
      for (const bake::BakedObject& o : scene.objects)
        if (!o.level_meshes.empty()) {
          const bake::BakedLevelMesh& m = o.level_meshes[std::min(k, o.level_meshes.size() - 1)];
          bake::append_placed(level, m.positions_xyz, m.indices, o.world);
        }
      measure(
          {tool, ratios[k - 1], 0, {}, {}, bake_s, k == 1 && ratios.size() > 1 ? "time: all levels in one run" : ""},
          level);
    }
  };
  bake_chain("gazelod bake", flags.ratios, (w / "chains.glb").string());

  for (const bool aggressive : {false, true})
    for (const double r : flags.ratios) {
      const std::string name = std::string("gltfpack") + (aggressive ? " -sa" : "");
      const std::string file = (w / ("gltfpack-" + num(r, "%g") + (aggressive ? "-sa" : "") + ".glb")).string();
      std::vector<std::string> argv{flags.gltfpack, "-i", flags.model, "-o", file, "-si", num(r, "%.9g"), "-noq"};
      if (aggressive) argv.push_back("-sa");
      const auto t = Clock::now();
      const int rc = spawn(argv, file + ".log");
      const double s = seconds_since(t);
      if (rc != 0)
        throw UsageError(
            name + " -si " + num(r) + " failed (exit " + std::to_string(rc) + "): " + tail_of(file + ".log"), 1);
      try {
        measure({name, r, 0, {}, {}, s, ""}, bake::world_triangles(bake::load_gltf(file).model));
      } catch (const bake::BakeError& e) {
        throw UsageError(name + " wrote a file gazelod cannot read: " + std::string(e.what()), 1);
      }
    }

  // The chain again at the triangle shares gltfpack reached (it stops at its error cap, or
  // short of the ratio even with -sa): errors at equal triangle counts.
  std::vector<double> reached;
  for (const Row& r : rows)
    if (r.tool != "gazelod bake") reached.push_back(double(r.triangles) / double(source.triangles()));
  std::sort(reached.begin(), reached.end(), std::greater<>());
  reached.erase(std::unique(reached.begin(), reached.end(), [](double a, double b) { return std::abs(a - b) < 1e-4; }),
                reached.end());
  reached.erase(std::remove_if(reached.begin(), reached.end(), [](double r) { return !(r > 0.0 && r < 1.0); }),
                reached.end());
  // One bake per share: in one chain, levels this close would stop each other (a level must get
  // below the one before it).
  for (std::size_t i = 0; i < reached.size(); ++i)
    bake_chain("gazelod bake at gltfpack's share", {reached[i]},
               (w / ("chains-matched-" + std::to_string(i) + ".glb")).string());

  std::ostringstream md;
  md << "<!-- written by: gazelod eval gltfpack " << flags.model << " -->\n\n"
     << "Source: `" << flags.model << "`, " << source.triangles() << " triangles, extent " << num(extent) << " m; "
     << version << "; machine: " << cpu_model() << ". Distances: from every source vertex to the result's "
     << "surface (and back), in % of the extent.\n\n"
     << "| tool | ratio | triangles | x source | largest | 99th pct | mean | back: largest | seconds |\n"
     << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const auto pct = [&](double m) { return num(100.0 * m / extent, "%.3g"); };
  for (const Row& r : rows)
    md << "| " << r.tool << " | " << num(r.ratio) << " | " << r.triangles << " | "
       << num(double(r.triangles) / double(source.triangles()), "%.4f") << " | " << pct(r.to_result.max_m) << " | "
       << pct(r.to_result.p99_m) << " | " << pct(r.to_result.mean_m) << " | " << pct(r.from_result.max_m) << " | "
       << num(r.seconds, "%.3f") << (r.note.empty() ? "" : " (" + r.note + ")") << " |\n";
  nlohmann::json j{{"model", flags.model},   {"source_triangles", source.triangles()},
                   {"extent_m", extent},     {"gltfpack", version},
                   {"machine", cpu_model()}, {"rows", nlohmann::json::array()}};
  for (const Row& r : rows)
    j["rows"].push_back({{"tool", r.tool},
                         {"ratio", r.ratio},
                         {"triangles", r.triangles},
                         {"source_to_result", deviation_json(r.to_result)},
                         {"result_to_source", deviation_json(r.from_result)},
                         {"seconds", r.seconds}});
  write_report(out, {{"gltfpack.md", md.str()}, {"gltfpack.json", aux::json_text(j, 2) + "\n"}});
  io.out << md.str() << "\nfiles: gltfpack.md, gltfpack.json in " << out.string() << "\n";
  return 0;
}

}  // namespace

EvalSubcommand add_eval_gltfpack(CLI::App& eval) {
  auto flags = std::make_shared<GltfpackFlags>();
  CLI::App* app = eval.add_subcommand(
      "gltfpack", "gazelod bake's LOD chain beside meshoptimizer's gltfpack on one model, measured alike");
  app->add_option("model", flags->model, "The glTF (.gltf/.glb) to simplify")->required();
  app->add_option("--out", flags->out, "Folder for gltfpack.md and gltfpack.json");
  app->add_option("--work", flags->work, "Folder for the simplified files (default: a temporary one, removed)");
  app->add_option("--ratios", flags->ratios, "Triangle ratios, decreasing (default 0.25 0.0625 0.015625)");
  app->add_option("--gltfpack", flags->gltfpack, "The gltfpack program (default: gltfpack on PATH)");
  return {app, [flags](Io io) { return run_eval_gltfpack(*flags, io); }};
}

}  // namespace gazelod::cli
