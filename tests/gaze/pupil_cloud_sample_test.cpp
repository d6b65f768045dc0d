// SPDX-License-Identifier: Apache-2.0
// The real Pupil Invisible export in ../shared/data/gaze (not part of the repository; skipped
// without it): it imports whole, its axes agree with its own scene pixels, and trace stats
// reports the agreement with Pupil Cloud's fixations and blinks.
#include "apps/gazelod/commands/command.hpp"
#include "gaze/trace_open.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::gaze {
namespace {

namespace fs = std::filesystem;

fs::path sample_gaze() {
  return fs::path(GAZELOD_SOURCE_DIR) / ".." / "shared" / "data" / "gaze" / "pupil_cloud_invisible_gaze.csv";
}

// Pearson correlation; 0 when either side is constant.
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ma += a[i] / n;
    mb += b[i] / n;
  }
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

TEST(PupilCloudSample, AxesFollowTheScenePixelsAndStatsReportAgreement) {
  const fs::path gaze = sample_gaze();
  if (!fs::is_regular_file(gaze)) GAZELOD_SKIP_OR_FAIL("no " << gaze << " (../shared/data/gaze, evaluation data)");

  // The export's own gaze x/y [px] (columns 4 and 5): x grows to the right, y downwards.
  std::ifstream in(gaze);
  std::string line;
  std::getline(in, line);
  ASSERT_EQ(line.rfind("section id,recording id,timestamp [ns],gaze x [px],gaze y [px]", 0), 0u);
  std::vector<double> px, py, dx, dy;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell;
    for (int i = 0; i < 5 && std::getline(ss, cell, ','); ++i) {
      if (i == 3) px.push_back(std::stod(cell));
      if (i == 4) py.push_back(std::stod(cell));
    }
  }
  auto s = open_trace(gaze.string(), TraceFormat::automatic);
  ASSERT_EQ(opened_trace_format(*s), TraceFormat::pupil_cloud);
  TraceRecord r;
  while (s->next(r)) {
    dx.push_back(r.gaze.direction.x);
    dy.push_back(r.gaze.direction.y);
  }
  ASSERT_EQ(dx.size(), px.size());
  EXPECT_GT(correlation(px, dx), 0.99);   // right in the image = +x
  EXPECT_LT(correlation(py, dy), -0.99);  // down in the image = -y

  std::ostringstream out, err;
  ASSERT_EQ(cli::run({"trace", "stats", gaze.string(), "--json"}, out, err), 0) << err.str();
  const auto j = nlohmann::json::parse(out.str());
  EXPECT_EQ(j["samples"].get<int>(), 8567);
  const auto& a = j["agreement"];
  EXPECT_EQ(a["blinks_in_file"].get<int>(), 38);
  EXPECT_EQ(a["samples_in_blinks"].get<int>(), 2376);  // exactly the samples with a blink id
  for (const char* c : {"ivt", "ivdt"}) {
    SCOPED_TRACE(c);
    EXPECT_EQ(a[c]["fixation"]["reference_events"].get<int>(), 63);
    const double kappa = a[c]["fixation"]["kappa"].get<double>();
    EXPECT_GT(kappa, 0.0);  // better than chance
    EXPECT_LE(kappa, 1.0);
    EXPECT_EQ(a[c]["blink"]["reference_only"].get<int>(), 0);
  }
}

}  // namespace
}  // namespace gazelod::gaze
