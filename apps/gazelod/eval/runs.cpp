// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/runs.hpp"

#include "apps/gazelod/commands/command.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <vector>

namespace gazelod::cli {
namespace {

double num(const nlohmann::json& j, const char* a, const char* b, const std::string& source) {
  const nlohmann::json* v = &j;
  for (const char* key : {a, b}) {
    if (key == nullptr) break;
    if (!v->is_object() || !v->contains(key)) throw UsageError(source + ": missing " + key, 1);
    v = &v->at(key);
  }
  if (!v->is_number()) throw UsageError(source + ": " + a + (b ? std::string(".") + b : "") + ": not a number", 1);
  return v->get<double>();
}

}  // namespace

EvalRun eval_run(const ReddyScenario& scenario, const std::string& criteria, bool render,
                 const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const auto scenario_path = dir / "scenario.json";
  {
    std::ofstream f(scenario_path);
    f << reddy_scenario_json(scenario);
    if (!f) throw UsageError("cannot write " + scenario_path.string(), 1);
  }
  std::vector<std::string> args{"run",    "--scenario", scenario_path.string(), "--criteria",
                                criteria, "--out",      dir.string(),           "--quiet"};
  if (!render) args.push_back("--no-render");
  std::ostringstream out, err;
  const int rc = run(args, out, err);
  if (rc != 0) throw UsageError("gazelod run on " + scenario_path.string() + " failed: " + err.str(), rc);

  const auto path = dir / "summary.json";
  std::ifstream in(path);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(path.string() + ": " + e.what(), 1);
  }
  const std::string src = path.string();
  EvalRun r;
  const double frames = num(j, "frames", nullptr, src);
  if (!(frames > 0)) throw UsageError(src + ": no frames", 1);
  r.mean_frame_ms = num(j, "frame_time_ms", "mean", src);
  r.frame_rate_hz = r.mean_frame_ms > 0.0 ? 1000.0 / r.mean_frame_ms : 0.0;
  // Objects in the view frustum only: what Reddy 1998's renderer drew and averaged over.
  const auto& v = j.at("in_view");
  r.objects_in_view = num(v, "objects_per_frame", nullptr, src);
  r.triangles_per_frame = num(v, "drawn", "triangles", src) / frames;
  r.full_triangles_per_frame = num(v, "none", "triangles", src) / frames;
  r.lod_drawn = 1.0 + num(v, "drawn", "average_lod", src);
  r.lod_size = 1.0 + num(v, "size", "average_lod", src);
  r.lod_size_ecc = 1.0 + num(v, "size+eccentricity", "average_lod", src);
  r.lod_size_vel = 1.0 + num(v, "size+velocity", "average_lod", src);
  r.lod_map = 1.0 + num(v, "lod_map", "average_lod", src);
  r.triangles_size = num(v, "size", "triangles", src) / frames;
  r.triangles_size_ecc = num(v, "size+eccentricity", "triangles", src) / frames;
  r.triangles_size_vel = num(v, "size+velocity", "triangles", src) / frames;
  r.triangles_map = num(v, "lod_map", "triangles", src) / frames;
  // Shares of the triangle reduction (as run/report.hpp defines them), in view.
  const double reduction = r.full_triangles_per_frame - r.triangles_per_frame;
  if (reduction > 0.0) {
    r.share_size = (r.full_triangles_per_frame - r.triangles_size) / reduction;
    r.share_eccentricity = (r.triangles_size_vel - r.triangles_per_frame) / reduction;
    r.share_velocity = (r.triangles_size_ecc - r.triangles_per_frame) / reduction;
  }
  return r;
}

EvalRun mean_of(const std::vector<EvalRun>& runs) {
  EvalRun m;
  if (runs.empty()) return m;
  m = EvalRun{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  const double n = static_cast<double>(runs.size());
  for (const EvalRun& r : runs) {
    m.mean_frame_ms += r.mean_frame_ms / n;
    m.frame_rate_hz += r.frame_rate_hz / n;  // the paper averages the trials' frame rates
    m.triangles_per_frame += r.triangles_per_frame / n;
    m.objects_in_view += r.objects_in_view / n;
    m.full_triangles_per_frame += r.full_triangles_per_frame / n;
    m.lod_drawn += r.lod_drawn / n;
    m.lod_size += r.lod_size / n;
    m.lod_size_ecc += r.lod_size_ecc / n;
    m.lod_size_vel += r.lod_size_vel / n;
    m.lod_map += r.lod_map / n;
    m.triangles_size += r.triangles_size / n;
    m.triangles_size_ecc += r.triangles_size_ecc / n;
    m.triangles_size_vel += r.triangles_size_vel / n;
    m.triangles_map += r.triangles_map / n;
    m.share_size += r.share_size / n;
    m.share_eccentricity += r.share_eccentricity / n;
    m.share_velocity += r.share_velocity / n;
  }
  return m;
}

}  // namespace gazelod::cli
