// SPDX-License-Identifier: Apache-2.0
// out_folder.hpp: one way for run, compare and eval family to take their --out.
#include "apps/gazelod/commands/out_folder.hpp"

#include "apps/gazelod/commands/command.hpp"

#include <system_error>

namespace gazelod::cli {

OutFolder hold_out_folder(const std::filesystem::path& dir, const std::string& command, std::ostream& err) {
  OutFolder out;
  std::error_code ec;
  out.created = std::filesystem::create_directories(dir, ec);
  if (!ec && !std::filesystem::is_directory(dir))
    throw UsageError("--out: cannot create the folder '" + dir.string() + "': a file is in the way");
  if (ec) throw UsageError("--out: cannot create the folder '" + dir.string() + "': " + ec.message(), 1);
  try {
    out.lock = std::make_unique<aux::FolderLock>(dir.string());
  } catch (const aux::FolderLockError& e) {
    // The folder stays even when this call made it: the process that holds it may be about to
    // write into it.
    throw UsageError(std::string("--out: ") + e.what(), 1);
  }
  if (!out.lock->locked()) err << "gazelod " << command << ": note: --out " << out.lock->why_not_locked() << "\n";
  return out;
}

}  // namespace gazelod::cli
