// SPDX-License-Identifier: Apache-2.0
// A command's --out folder: made, and held against another gazelod writing there
// (auxiliary/folder_lock.hpp), before the command writes anything into it.
#pragma once

#include "auxiliary/folder_lock.hpp"

#include <filesystem>
#include <memory>
#include <ostream>
#include <string>

namespace gazelod::cli {

struct OutFolder {
  std::unique_ptr<aux::FolderLock> lock;
  bool created = false;  // this call made the folder
};

// Makes `dir` (with its parents) and locks it. Throws UsageError "--out: ...": exit 2 when a
// file is in the way (bad usage), 1 when the folder cannot be made (no permission, a read-only
// or full file system) or another gazelod holds it. A file system that cannot lock a folder
// gives a note on `err` ("gazelod <command>: note: ..."), and the command goes on.
OutFolder hold_out_folder(const std::filesystem::path& dir, const std::string& command, std::ostream& err);

}  // namespace gazelod::cli
