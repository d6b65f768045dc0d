// SPDX-License-Identifier: Apache-2.0
// Every file of the fuzz corpus (fuzz/corpus/<target>/: the seeds and each input a fuzzing
// campaign found crashing, kept as regressions) through the same entry function the libFuzzer
// target runs, here in the normal build. An entry aborts on a broken invariant and lets any
// unexpected exception escape, so a regression fails (or kills) this test.
#include "fuzz/fuzz_entry.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace gazelod::fuzz {
namespace {

namespace fs = std::filesystem;
using Entry = int (*)(const std::uint8_t*, std::size_t);

std::vector<fs::path> corpus_files(const std::string& target) {
  const fs::path dir = fs::path(GAZELOD_SOURCE_DIR) / "fuzz" / "corpus" / target;
  std::vector<fs::path> files;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::uint8_t> read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void replay(const std::string& target, Entry entry) {
  const auto files = corpus_files(target);
  ASSERT_GE(files.size(), 3u) << "fuzz/corpus/" << target << " should hold a seed corpus";
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    const auto bytes = read_bytes(f);
    EXPECT_EQ(entry(bytes.data(), bytes.size()), 0);
  }
  // The empty input and a lone byte are the first things a fuzzer tries.
  EXPECT_EQ(entry(nullptr, 0), 0);
  const std::uint8_t one = 0x10;
  EXPECT_EQ(entry(&one, 1), 0);
}

TEST(FuzzCorpus, TraceReader) {
  replay("trace_reader", &trace_reader);
}
TEST(FuzzCorpus, Scenario) {
  replay("scenario", &scenario);
}
TEST(FuzzCorpus, HidReports) {
  replay("hid_reports", &hid_reports);
}
TEST(FuzzCorpus, BudgetInstance) {
  replay("budget_instance", &budget_instance);
}
TEST(FuzzCorpus, Gltf) {
  replay("gltf", &gltf);
}
TEST(FuzzCorpus, Capi) {
  replay("capi", &capi);
}

}  // namespace
}  // namespace gazelod::fuzz
