// SPDX-License-Identifier: Apache-2.0
// `gazelod run --decisions FILE`: the drawn level of every object in every frame, as CSV
//   frame,t_ns,<object name>,...     (names quoted per RFC 4180 where needed)
//   0,11111111,2,3,...               (t_ns: predicted display time, ns from the scenario's start)
// written through aux::AtomicFile (the project's one atomic writer): rows go to a temporary in
// FILE's folder, renamed to FILE by commit(); without commit() (an error, an exception) the
// temporary is removed and FILE is left as it was.
#pragma once

#include "apps/gazelod/run/signals.hpp"
#include "auxiliary/atomic_file.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace gazelod::cli {

// One CSV field as RFC 4180 wants it: quoted (quotes doubled) when it holds a comma, a quote,
// CR or LF; as is otherwise.
std::string csv_field(std::string_view text);

class DecisionsFile {
 public:
  // Throws std::runtime_error "--decisions: cannot write 'FILE': <the system's reason>".
  DecisionsFile(const std::filesystem::path& file, std::span<const std::string> object_names);

  // Throws std::runtime_error naming the option and the file when a write fails.
  void write(std::int64_t frame, std::int64_t t_ns, std::span<const std::uint8_t> levels);
  void commit();
  std::filesystem::path path() const { return file_.path(); }

 private:
  [[noreturn]] void fail(const std::string& what) const;
  AtomicRunFile file_;  // its temporary removed by a second signal too
  std::string row_;
};

}  // namespace gazelod::cli
