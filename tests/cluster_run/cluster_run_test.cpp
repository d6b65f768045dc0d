// SPDX-License-Identifier: Apache-2.0
// `gazelod run --scene F` with F from `gazelod bake --clusters` (a generated wavy wall) on the
// simulated runtime: the wall is a cluster mesh in its glTF placement (--scene-placement
// file) and a non-uniformly scaled copy of it stays a plain object; the report has the
// cluster figures and their audit; frame.png is drawn from the clusters; every frame of a walk
// draws a cut that covers each leaf exactly once (on the group links and on the triangles);
// bad placements are usage errors.
#include "tests/run/run_test_util.hpp"

#include "apps/gazelod/clusters/cover.hpp"
#include "apps/gazelod/run/session.hpp"
#include "bake/baked_scene.hpp"
#include "render/lod_palette.hpp"
#include "render/lod_key.hpp"
#include "render/png_io.hpp"
#include "tests/bake/test_meshes.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <map>
#include <set>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace gazelod::test {
namespace {

constexpr int kWallQuads = 128;
constexpr std::uint64_t kWallTriangles = 2 * kWallQuads * kWallQuads;

// A 20 m x 20 m wall in the XY plane facing +Z, with 5 cm bumps every 0.8 m: detail the fovea
// sees at 10 m and the periphery does not.
bake::testing::TestMesh bumpy_wall() {
  bake::testing::TestMesh m = bake::testing::grid(kWallQuads, 20.0, 0.0);
  const double k = 2.0 * std::acos(-1.0) / 0.8;
  for (std::size_t v = 0; v + 2 < m.positions.size(); v += 3)
    m.positions[v + 2] = static_cast<float>(0.05 * std::sin(k * m.positions[v]) * std::cos(k * m.positions[v + 1]));
  return m;
}

// The baked wall and a walk towards it, made once for the suite.
class ClusterRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One folder per process: CTest runs each test of the suite as its own process, two at a
    // time under -j2, and a shared folder removed by one while the other reads its bake made the
    // other's setup fail (reported as skipped).
    dir_ =
        std::filesystem::path(GAZELOD_BINARY_DIR) / "test-scratch" / ("ClusterRunSuite-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    // The wall 12 m ahead of a viewer at eye height; a copy stretched along Y far to the side
    // (not a uniform scale: drawn whole).
    tinygltf::Model model = bake::testing::single_mesh_model(bumpy_wall());
    model.nodes[0].name = "Wall";
    model.nodes[0].translation = {-10.0, -8.0, -12.0};
    tinygltf::Node stretched;
    stretched.name = "Stretched", stretched.mesh = 0, stretched.scale = {1.0, 2.0, 1.0};
    stretched.translation = {40.0, -10.0, -30.0};
    model.nodes.push_back(stretched);
    model.scenes[0].nodes.push_back(1);
    const std::string in = bake::testing::write_model(model, (dir_ / "wall.glb").string());
    baked_ = (dir_ / "wall-clusters.glb").string();
    const CliResult r = run_cli({"bake", "--clusters", in, baked_});
    ASSERT_EQ(r.rc, 0) << r.err;
    scenario_ = (dir_ / "walk.json").string();
    std::ofstream(scenario_) << R"({
      "version": 1, "name": "walk to the wall", "display": "questpro", "duration_s": 5,
      "frame_rate_hz": 90, "seed": 4,
      "scene": { "objects": [], "head_path": { "start_m": [0, 1.6, 0], "velocity_m_s": [0, 0, -1.0] } },
      "effects": [
        { "type": "head_sweep", "yaw_amplitude_deg": 10, "yaw_period_s": 3 },
        { "type": "saccades", "fixation_min_ms": 150, "fixation_max_ms": 300, "amplitude_min_deg": 4,
          "amplitude_max_deg": 15, "range_deg": 20 },
        { "type": "vor" },
        { "type": "tracker_latency", "latency_ms": 12 },
        { "type": "tracker_noise", "std_deg": 0.3 }
      ]
    })";
  }
  static void TearDownTestSuite() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  void SetUp() override { use_simulated_runtime(""); }
  // The walk on the wall in its file placement, selection only, for run_session.
  static cli::RunOptions walk_options(std::int64_t frames) {
    cli::RunOptions opt;
    opt.frames = frames;
    opt.scenario_path = scenario_;
    opt.scene_path = baked_;
    opt.scene_placement = "file";
    opt.render = false;
    opt.quiet = true;
    opt.out_dir = scratch_dir();
    return opt;
  }

  static std::filesystem::path dir_;
  static std::string baked_, scenario_;
};
std::filesystem::path ClusterRun::dir_;
std::string ClusterRun::baked_, ClusterRun::scenario_;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  std::string c;
  while (std::getline(in, c, ',')) cells.push_back(c);
  return cells;
}

TEST_F(ClusterRun, NoRenderRunReportsClusterFiguresAndTheirAudit) {
  const auto out = scratch_dir();
  const CliResult r = run_cli({"run", "--no-render", "--frames", "60", "--scene", baked_, "--scene-placement", "file",
                               "--scenario", scenario_, "--out", out.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.err.find("'Stretched' drawn whole, not as clusters: its world transform scales non-uniformly"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("cluster triangles "), std::string::npos) << "progress lines: " << r.err;
  EXPECT_NE(r.out.find("clusters        1 mesh, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cluster audit   visible degradations "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cluster audit   every frame's cut covers each leaf exactly once"), std::string::npos) << r.out;

  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  // The plain copy: one object at its one level (the full mesh) every frame.
  EXPECT_EQ(summary.at("triangles_full").get<std::uint64_t>(), 60 * kWallTriangles);
  const auto& c = summary.at("clusters");
  EXPECT_EQ(c.at("meshes").get<int>(), 1);
  const auto full = c.at("triangles_full").get<std::uint64_t>();
  const auto drawn = c.at("triangles_drawn").get<std::uint64_t>();
  EXPECT_EQ(full, 60 * kWallTriangles);
  EXPECT_GT(drawn, 0u);
  EXPECT_LT(drawn, full) << "most of the wall lies away from the gaze";
  const auto& audit = c.at("audit");
  ASSERT_TRUE(audit.at("available").get<bool>()) << audit.dump();
  const double share = audit.at("visible_degradations").at("share").get<double>();
  EXPECT_TRUE(std::isfinite(share));
  EXPECT_GE(share, 0.0);
  EXPECT_LE(share, 1.0);
  EXPECT_GT(audit.at("visible_degradations").at("leaf_frames").get<std::int64_t>(), 0);
  const double ratio = audit.at("triangles_in_view").at("drawn_over_oracle").get<double>();
  EXPECT_TRUE(std::isfinite(ratio));
  EXPECT_GT(ratio, 0.0);
  EXPECT_EQ(audit.at("miscovered_leaf_frames").get<std::int64_t>(), 0);
  // The oracle's cut under each criterion alone: reported, some triangles, none above full.
  const auto& alone = audit.at("triangles_in_view").at("oracle_by_criterion_alone");
  for (const char* k : {"size", "eccentricity", "velocity"}) {
    EXPECT_GT(alone.at(k).get<std::uint64_t>(), 0u) << k;
    EXPECT_LE(alone.at(k).get<std::uint64_t>(), full) << k;
  }
  EXPECT_NE(r.out.find("cluster audit   oracle triangles in view, each criterion alone: size "), std::string::npos)
      << r.out;
  const std::string svg = read_text(out / "audit.svg");
  for (const char* panel : {"in-view cluster leaves", "leaf switches per frame", "cluster triangles in view"})
    EXPECT_NE(svg.find(panel), std::string::npos) << "audit.svg has the cluster panel " << panel;

  // frames.csv: a column of cluster triangles, never above full detail, below it once the
  // switch policy has let the periphery go.
  std::ifstream csv(out / "frames.csv");
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const auto header = split(line);
  const auto it = std::find(header.begin(), header.end(), "cluster_triangles_drawn");
  ASSERT_NE(it, header.end()) << line;
  const auto col = static_cast<std::size_t>(it - header.begin());
  int rows = 0, below = 0;
  while (std::getline(csv, line)) {
    const auto cells = split(line);
    ASSERT_GT(cells.size(), col);
    const std::uint64_t n = std::stoull(cells[col]);
    EXPECT_LE(n, kWallTriangles);
    below += n < kWallTriangles;
    ++rows;
  }
  EXPECT_EQ(rows, 60);
  EXPECT_GT(below, 0);

  // The default placement puts the same scene in front of the viewer: still a cluster mesh.
  const auto front = out / "in-front";
  const CliResult f = run_cli({"run", "--no-render", "--frames", "10", "--scene", baked_, "--scenario", scenario_,
                               "--out", front.string(), "--quiet"});
  ASSERT_EQ(f.rc, 0) << f.err;
  EXPECT_EQ(nlohmann::json::parse(read_text(front / "summary.json")).at("clusters").at("meshes").get<int>(), 1);
}

TEST_F(ClusterRun, RenderedFrameShowsTheClusters) {
  const auto out = scratch_dir();
  const CliResult r = run_cli({"run", "--frames", "4", "--scene", baked_, "--scene-placement", "file", "--scenario",
                               scenario_, "--out", out.string(), "--quiet"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("frame.png"), std::string::npos) << r.out;
  const render::RgbaImage img = render::without_lod_key(render::read_png(out / "frame.png"));
  ASSERT_GT(img.width, 0u);
  // The wall fills much of the view ahead: many pixels are not background.
  std::size_t wall = 0;
  for (std::uint32_t y = 0; y < img.height; y += 4)
    for (std::uint32_t x = 0; x < img.width; x += 4)
      wall += glm::length(img.rgb(x, y) - render::background_colour()) > 0.05f;
  EXPECT_GT(wall, (img.width / 4) * (img.height / 4) / 10) << "the wall covers under a tenth of the frame";
}

// The palette level whose shaded tint explains an sRGB pixel of frame.png, or -1 (background,
// foveal marker, an edge pixel). `gazelod run` renders into an sRGB swapchain, so a pixel is
// srgb(linear(tint) * light) with the headlight's light in [0.35, 1]: each level is fitted over
// that range and kept when it explains the pixel within a few 8-bit steps.
int shaded_level(const glm::vec3& pixel) {
  struct Shade {
    glm::vec3 srgb;
    int level;
  };
  static const std::vector<Shade> shades = [] {
    const auto encode = [](float linear) {
      return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    };
    std::vector<Shade> all;
    for (std::uint32_t level = 0; level < render::kLodPaletteSize; ++level) {
      const glm::vec3 tint = render::lod_colour(level);
      for (int step = 0; step <= 130; ++step) {
        const float light = 0.35f + 0.005f * static_cast<float>(step);
        all.push_back({{encode(render::srgb_to_linear(tint.r) * light), encode(render::srgb_to_linear(tint.g) * light),
                        encode(render::srgb_to_linear(tint.b) * light)},
                       static_cast<int>(level)});
      }
    }
    return all;
  }();
  if (glm::length(pixel - render::background_colour()) < 0.02f) return -1;
  int best = -1;
  float best_error = 3.0f / 255.0f * std::sqrt(3.0f);
  for (const Shade& shade : shades)
    if (const float error = glm::length(shade.srgb - pixel); error < best_error) best_error = error, best = shade.level;
  return best;
}

// frame.png end to end: the captured frame's cut (--cluster-decisions) holds clusters of several
// depths; in the image every tinted pixel has the tint of a depth that frame drew, and at least
// two depths' tints are seen.
TEST_F(ClusterRun, FramePngTintsEachDrawnDepth) {
  const auto out = scratch_dir();
  constexpr int kFrames = 45, kCaptured = 44;  // past the switch policy's hold: the periphery coarsened
  const std::string cut = (out / "cut.csv").string();
  const CliResult r = run_cli({"run", "--frames", std::to_string(kFrames), "--capture-frame", std::to_string(kCaptured),
                               "--cluster-decisions", cut, "--scene", baked_, "--scene-placement", "file", "--scenario",
                               scenario_, "--out", out.string(), "--quiet"});
  ASSERT_EQ(r.rc, 0) << r.err;
  // The captured frame's drawn depths: frame,t_ns,mesh,cluster,depth,triangles,limited_by,held.
  std::ifstream csv(cut);
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  std::map<std::uint32_t, std::uint64_t> triangles_by_tint;
  while (std::getline(csv, line)) {
    const auto cells = split(line);
    ASSERT_GE(cells.size(), 6u) << line;
    if (std::stoi(cells[0]) != kCaptured) continue;
    const auto depth = static_cast<std::uint32_t>(std::stoul(cells[4]));
    triangles_by_tint[std::min<std::uint32_t>(depth, render::kLodPaletteSize - 1)] += std::stoull(cells[5]);
  }
  for (const auto& [tint, n] : triangles_by_tint)
    std::printf("depth tint %u: %llu triangles drawn\n", tint, static_cast<unsigned long long>(n));
  ASSERT_GE(triangles_by_tint.size(), 2u) << "the captured frame's cut has one depth: nothing to tell apart";
  std::set<int> allowed{0};  // the stretched copy, a plain object at its one level, where it is in view
  for (const auto& [tint, n] : triangles_by_tint) allowed.insert(static_cast<int>(tint));

  const render::RgbaImage img = render::without_lod_key(render::read_png(out / "frame.png"));
  ASSERT_GT(img.width, 0u);
  std::map<int, std::size_t> pixels_by_tint;
  std::size_t sampled = 0;
  for (std::uint32_t y = 0; y < img.height; y += 6)
    for (std::uint32_t x = 0; x < img.width; x += 6, ++sampled) ++pixels_by_tint[shaded_level(img.rgb(x, y))];
  std::size_t tinted = 0, undrawn = 0, seen = 0;
  std::ostringstream counts;
  for (const auto& [level, n] : pixels_by_tint) {
    counts << " tint " << level << ": " << n;
    if (level < 0) continue;
    tinted += n;
    if (!allowed.count(level)) undrawn += n;
    seen += n >= sampled / 200;  // half a percent of the frame
  }
  std::printf("frame %d: %zu sampled pixels,%s (-1: background or marker)\n", kCaptured, sampled, counts.str().c_str());
  ASSERT_GT(tinted, sampled / 10) << "the wall covers under a tenth of the frame;" << counts.str();
  EXPECT_LE(undrawn, tinted / 200) << "pixels in the tint of a depth the frame did not draw;" << counts.str();
  EXPECT_GE(seen, 2u) << "one depth's tint fills the frame;" << counts.str();
}

// Undirected edges on exactly one triangle of `drawn`'s clusters, sorted: simplification keeps
// the source's vertex indices and locks group borders, so a crack leaves an edge single away
// from the source's own rim.
std::vector<std::uint64_t> single_edges(const bake::BakedClusterPrimitive& p, std::span<const std::uint8_t> drawn) {
  std::vector<std::uint64_t> keys;
  for (std::size_t c = 0; c < drawn.size(); ++c) {
    if (!drawn[c]) continue;
    const std::uint32_t* t = p.indices.data() + p.hierarchy.first_index[c];
    for (std::uint32_t k = 0; k < p.hierarchy.index_count[c]; k += 3)
      for (std::uint32_t e = 0; e < 3; ++e) {
        const std::uint64_t a = t[k + e], b = t[k + (e + 1) % 3];
        keys.push_back(std::min(a, b) << 32 | std::max(a, b));
      }
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::uint64_t> single;
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i;
    while (j < keys.size() && keys[j] == keys[i]) ++j;
    if (j - i == 1) single.push_back(keys[i]);
    i = j;
  }
  return single;
}

TEST_F(ClusterRun, EveryFrameOfAWalkCoversEachLeafExactlyOnce) {
  const bake::BakedScene scene = bake::load_baked(baked_);
  ASSERT_EQ(scene.cluster_meshes.size(), 1u);
  const bake::BakedClusterPrimitive& wall = scene.cluster_meshes[0].primitives.at(0);
  const std::size_t n = wall.hierarchy.size();
  std::vector<std::uint8_t> leaves(n, 0);
  for (std::size_t c = 0; c < n; ++c) leaves[c] = wall.hierarchy.depth[c] == 0;
  const std::vector<std::uint64_t> border = single_edges(wall, leaves);
  ASSERT_FALSE(border.empty());
  // The wall's own rim meets nothing, so the bake simplifies it along itself: a cut may leave
  // single any edge between two rim vertices, and no other (that would be a crack).
  std::set<std::uint32_t> rim;
  for (std::uint64_t e : border) rim.insert({static_cast<std::uint32_t>(e >> 32), static_cast<std::uint32_t>(e)});
  const auto inside = [&](const std::vector<std::uint64_t>& single) {
    return std::count_if(single.begin(), single.end(), [&](std::uint64_t e) {
      return !rim.contains(static_cast<std::uint32_t>(e >> 32)) || !rim.contains(static_cast<std::uint32_t>(e));
    });
  };
  cli::ClusterCover cover(wall.hierarchy);
  std::vector<cli::LeafCover> covers(cover.leaves().size());

  cli::RunOptions opt = walk_options(90);
  int frames = 0, coarser = 0;
  opt.frame_observer = [&](const FrameDecisions& d, const FrameDiagnostics& diag) {
    SCOPED_TRACE("frame " + std::to_string(frames));
    ++frames;
    ASSERT_EQ(d.cluster_first.size(), 1u);
    ASSERT_EQ(d.cluster_drawn.size(), n);
    ASSERT_EQ(diag.cluster_drawn_perceptual.size(), n);
    for (const auto cut : {d.cluster_drawn, diag.cluster_drawn_perceptual}) {
      EXPECT_EQ(cover.evaluate(cut, covers), 0u) << "leaves not covered exactly once";
      EXPECT_EQ(inside(single_edges(wall, cut)), 0) << "a crack";
    }
    coarser += !std::equal(d.cluster_drawn.begin(), d.cluster_drawn.end(), leaves.begin());
  };
  std::ostringstream out, err;
  ASSERT_EQ(cli::run_session(opt, cli::Io{out, err}), 0) << err.str();
  EXPECT_EQ(frames, 90);
  EXPECT_GT(coarser, 0) << "the walk never drew anything but the finest cut: the check proved nothing";
}

// --cluster-decisions: one row per drawn cluster per frame, exactly the cut the plugin returned
// (seen through the frame observer), with the hierarchy's depth and triangle counts, and the
// frame's rows summing to frames.csv's cluster triangles.
TEST_F(ClusterRun, ClusterDecisionsListEveryFramesCut) {
  const bake::BakedScene scene = bake::load_baked(baked_);
  const lod::ClusterHierarchy& h = scene.cluster_meshes.at(0).primitives.at(0).hierarchy;
  std::vector<std::set<std::uint32_t>> cuts;
  cli::RunOptions opt = walk_options(30);
  opt.cluster_decisions_path = (opt.out_dir / "cut.csv").string();
  opt.frame_observer = [&](const FrameDecisions& d, const FrameDiagnostics&) {
    std::set<std::uint32_t> cut;
    for (std::uint32_t c = 0; c < d.cluster_drawn.size(); ++c)
      if (d.cluster_drawn[c]) cut.insert(c);
    cuts.push_back(std::move(cut));
  };
  std::ostringstream out, err;
  ASSERT_EQ(cli::run_session(opt, cli::Io{out, err}), 0) << err.str();
  ASSERT_EQ(cuts.size(), 30u);
  EXPECT_NE(out.str().find("cut.csv"), std::string::npos) << out.str();

  std::ifstream csv(opt.cluster_decisions_path);
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line, "frame,t_ns,mesh,cluster,depth,triangles,limited_by,held");
  std::vector<std::set<std::uint32_t>> listed(cuts.size());
  std::vector<std::uint64_t> triangles(cuts.size(), 0);
  std::set<std::string> reasons;
  while (std::getline(csv, line)) {
    const auto cells = split(line + ",");  // a trailing empty cell survives getline
    ASSERT_GE(cells.size(), 7u) << line;
    const std::size_t frame = std::stoul(cells[0]);
    ASSERT_LT(frame, cuts.size()) << line;
    EXPECT_EQ(cells[2], "Wall primitive 0") << line;
    const std::uint32_t c = static_cast<std::uint32_t>(std::stoul(cells[3]));
    ASSERT_LT(c, h.size()) << line;
    EXPECT_TRUE(listed[frame].insert(c).second) << "listed twice: " << line;
    EXPECT_EQ(std::stoul(cells[4]), h.depth[c]) << line;
    EXPECT_EQ(std::stoull(cells[5]), h.index_count[c] / 3) << line;
    triangles[frame] += std::stoull(cells[5]);
    reasons.insert(cells[6]);
    if (h.depth[c] == 0) {
      EXPECT_EQ(cells[6], "none") << "a source cluster has no error to let go: " << line;
    }
  }
  for (std::size_t f = 0; f < cuts.size(); ++f) EXPECT_EQ(listed[f], cuts[f]) << "frame " << f;
  EXPECT_GT(reasons.size(), 1u) << "the coarser clusters name what let them go";

  std::ifstream frames(opt.out_dir / "frames.csv");
  ASSERT_TRUE(std::getline(frames, line));
  const auto header = split(line);
  const auto col =
      static_cast<std::size_t>(std::find(header.begin(), header.end(), "cluster_triangles_drawn") - header.begin());
  ASSERT_LT(col, header.size());
  for (std::size_t f = 0; f < cuts.size(); ++f) {
    ASSERT_TRUE(std::getline(frames, line));
    EXPECT_EQ(std::stoull(split(line).at(col)), triangles[f]) << "frame " << f;
  }

  // Without cluster meshes there is nothing to list: a usage error, before any frame.
  const auto plain = scratch_dir();
  const CliResult r = run_cli({"run", "--no-render", "--frames", "5", "--cluster-decisions",
                               (plain / "cut.csv").string(), "--out", plain.string()});
  EXPECT_EQ(r.rc, 2) << r.err;
  EXPECT_NE(r.err.find("--cluster-decisions: the scene has no cluster meshes"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(plain / "cut.csv"));
}

// object_motion moves a cluster mesh: the wall recedes at 1 km/s, its cut coarsens against the
// same walk with the wall still (to the hierarchy's top, 2 km away), the audit's oracle follows it (every leaf covered
// once, few degradations), and the rendered frame draws it where it went.
TEST_F(ClusterRun, ObjectMotionMovesTheClusterMesh) {
  std::string moving = read_text(scenario_);
  const std::string effects = "\"effects\": [";
  ASSERT_NE(moving.find(effects), std::string::npos);
  moving.replace(moving.find(effects), effects.size(),
                 effects + R"({ "type": "object_motion", "object": "Wall", "velocity_m_s": [0, 0, -1000] },)");
  const auto dir = scratch_dir();
  const std::string moving_path = (dir / "receding.json").string();
  std::ofstream(moving_path) << moving;
  const auto last_triangles = [&](const std::filesystem::path& out) {
    std::ifstream csv(out / "frames.csv");
    std::string line, last;
    std::getline(csv, line);
    const auto header = split(line);
    const auto col =
        static_cast<std::size_t>(std::find(header.begin(), header.end(), "cluster_triangles_drawn") - header.begin());
    while (std::getline(csv, line)) last = line;
    return std::stoull(split(last).at(col));
  };
  // Size and eccentricity only: the distance's effect alone.
  CliResult r =
      run_cli({"run", "--no-render", "--frames", "180", "--scene", baked_, "--scene-placement", "file", "--scenario",
               scenario_, "--criteria", "size,eccentricity", "--out", (dir / "still").string(), "--quiet"});
  ASSERT_EQ(r.rc, 0) << r.err;
  r = run_cli({"run", "--no-render", "--frames", "180", "--scene", baked_, "--scene-placement", "file", "--scenario",
               moving_path, "--criteria", "size,eccentricity", "--out", (dir / "moving").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(r.err.find("does not move"), std::string::npos) << r.err;
  EXPECT_LT(last_triangles(dir / "moving"), last_triangles(dir / "still") / 10)
      << "after 2 s the wall is 2 km away, not 10 m: its cut is much coarser";
  const auto audit = nlohmann::json::parse(read_text(dir / "moving" / "summary.json")).at("clusters").at("audit");
  ASSERT_TRUE(audit.at("available").get<bool>());
  EXPECT_EQ(audit.at("miscovered_leaf_frames").get<std::int64_t>(), 0);
  EXPECT_LT(audit.at("visible_degradations").at("share").get<double>(), 0.005)
      << "the oracle moves the wall as the plugin does";

  // Rendered: the wall, 12 m ahead at the start, covers far less of the frame once it has
  // receded (frame 150 against frame 0 of the same run).
  const auto covered = [&](const std::filesystem::path& png) {
    const render::RgbaImage img = render::without_lod_key(render::read_png(png));
    std::size_t n = 0;
    for (std::uint32_t y = 0; y < img.height; y += 4)
      for (std::uint32_t x = 0; x < img.width; x += 4)
        n += glm::length(img.rgb(x, y) - render::background_colour()) > 0.05f;
    return n;
  };
  for (const char* frame : {"0", "150"}) {
    r = run_cli({"run", "--frames", "151", "--capture-frame", frame, "--scene", baked_, "--scene-placement", "file",
                 "--scenario", moving_path, "--out", (dir / (std::string("frame") + frame)).string(), "--quiet",
                 "--no-audit"});
    ASSERT_EQ(r.rc, 0) << r.err;
  }
  EXPECT_LT(covered(dir / "frame150" / "frame.png"), covered(dir / "frame0" / "frame.png") / 2)
      << "the drawn wall recedes with its mesh";
}

TEST_F(ClusterRun, BadPlacementIsAUsageError) {
  const auto out = scratch_dir() / "run";
  CliResult r = run_cli(
      {"run", "--no-render", "--frames", "5", "--scene", baked_, "--scene-placement", "bogus", "--out", out.string()});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find("--scene-placement: 'bogus' (use in-front or file)"), std::string::npos) << r.err;
  r = run_cli({"run", "--no-render", "--frames", "5", "--scene-placement", "file", "--out", out.string()});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find("--scene-placement: needs --scene"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "summary.json"));
}

// A scene whose every object is a cluster mesh: no per-object lines or audit panels that
// would all read 0, the cluster ones instead.
TEST(ClusterOnlyRun, ReportsHaveNoEmptyPerObjectLinesOrPanels) {
  use_simulated_runtime("");
  const auto dir = scratch_dir();
  const std::string terrain = (dir / "terrain.glb").string(), baked = (dir / "terrain-clusters.glb").string();
  ASSERT_EQ(run_cli({"scene", "generate", "terrain", terrain, "--triangles", "4000"}).rc, 0);
  const CliResult b = run_cli({"bake", "--clusters", terrain, baked});
  ASSERT_EQ(b.rc, 0) << b.err;
  const CliResult r = run_cli(
      {"run", "--no-render", "--quiet", "--frames", "30", "--scene", baked, "--scene-placement", "file", "--scenario",
       std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/terrain-walk.json", "--out", (dir / "out").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("objects         every object is a cluster mesh (no per-object LOD)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("clusters        1 mesh, "), std::string::npos) << r.out;
  for (const char* gone : {"LOD histogram", "reduction owed", "triangles       0 drawn", "audit           visible"})
    EXPECT_EQ(r.out.find(gone), std::string::npos) << gone << "\n" << r.out;
  EXPECT_NE(r.out.find("cluster audit   visible degradations"), std::string::npos) << r.out;
  const std::string svg = read_text(dir / "out" / "audit.svg");
  EXPECT_EQ(svg.find("in-view objects"), std::string::npos) << "no empty per-object panel";
  EXPECT_NE(svg.find("in-view cluster leaves"), std::string::npos);
}

}  // namespace
}  // namespace gazelod::test
