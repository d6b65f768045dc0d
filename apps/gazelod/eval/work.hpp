// SPDX-License-Identifier: Apache-2.0
// What the eval subcommands share: the work folder (a given one, or a temporary one removed on
// the way out) and the machine's name for the reports.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gazelod::cli {

class WorkDir {
 public:
  // given "": a fresh temp_directory_path()/"<prefix>-<pid>". Throws UsageError when it cannot
  // be created.
  WorkDir(const std::string& given, const std::string& prefix);
  ~WorkDir();
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  bool temporary_;
  std::filesystem::path path_;
};

// /proc/cpuinfo's first "model name", or "".
std::string cpu_model();

// Writes a report's files into out_dir, each whole or not at all (write_file_atomic); a failure
// becomes a UsageError naming --out.
struct ReportFile {
  std::string name;
  std::string text;
};
void write_report(const std::filesystem::path& out_dir, const std::vector<ReportFile>& files);

}  // namespace gazelod::cli
