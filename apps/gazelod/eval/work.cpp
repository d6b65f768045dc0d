// SPDX-License-Identifier: Apache-2.0
// The eval work folder, machine name and report writing (see eval/work.hpp).
#include "apps/gazelod/eval/work.hpp"

#include "apps/gazelod/commands/command.hpp"
#include "auxiliary/atomic_file.hpp"

#include <unistd.h>

#include <fstream>

namespace gazelod::cli {

namespace fs = std::filesystem;

WorkDir::WorkDir(const std::string& given, const std::string& prefix) : temporary_(given.empty()) {
  path_ = temporary_ ? fs::temp_directory_path() / (prefix + "-" + std::to_string(::getpid())) : fs::path(given);
  std::error_code ec;
  if (temporary_) fs::remove_all(path_, ec);
  fs::create_directories(path_, ec);
  if (ec) throw UsageError("--work: cannot create '" + path_.string() + "': " + ec.message());
}

WorkDir::~WorkDir() {
  std::error_code ec;
  if (temporary_) fs::remove_all(path_, ec);
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      const std::size_t colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  return "";
}

void write_report(const fs::path& out_dir, const std::vector<ReportFile>& files) {
  try {
    for (const ReportFile& f : files) aux::write_file_atomic((out_dir / f.name).string(), f.text);
  } catch (const aux::WriteError& e) {
    throw UsageError(std::string("--out: ") + e.what(), 1);
  }
}

}  // namespace gazelod::cli
