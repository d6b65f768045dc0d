// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/decisions_file.hpp"

#include <charconv>
#include <stdexcept>

namespace gazelod::cli {

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string r = "\"";
  for (char c : text) {
    if (c == '"') r += '"';
    r += c;
  }
  r += '"';
  return r;
}

// A function-try-block: the option's name goes on a WriteError from the file's creation.
DecisionsFile::DecisionsFile(const std::filesystem::path& file, std::span<const std::string> object_names) try
    : file_(file.string()) {
  row_ = "frame,t_ns";
  for (const std::string& name : object_names) {
    row_ += ',';
    row_ += csv_field(name);
  }
  row_ += '\n';
  file_.stream().write(row_.data(), static_cast<std::streamsize>(row_.size()));
  if (!file_.stream()) fail("error while writing the header");
  row_.clear();
  row_.reserve(48 + 4 * object_names.size());  // frame, t_ns and up to 3 digits a level: no growth per row
} catch (const aux::WriteError& e) {
  throw std::runtime_error(std::string("--decisions: ") + e.what());
}

void DecisionsFile::fail(const std::string& what) const {
  throw std::runtime_error("--decisions " + file_.path() + ": " + what + " (the file is not left behind)");
}

void DecisionsFile::write(std::int64_t frame, std::int64_t t_ns, std::span<const std::uint8_t> levels) {
  char buf[24];
  row_.clear();
  const auto add = [&](std::int64_t v) {
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    row_.append(buf, r.ptr);
  };
  add(frame);
  row_ += ',';
  add(t_ns);
  for (std::uint8_t l : levels) {
    row_ += ',';
    add(l);
  }
  row_ += '\n';
  file_.stream().write(row_.data(), static_cast<std::streamsize>(row_.size()));
  if (!file_.stream()) fail("error while writing frame " + std::to_string(frame));
}

void DecisionsFile::commit() {
  try {
    file_.commit();
  } catch (const aux::WriteError& e) {
    throw std::runtime_error(std::string("--decisions: ") + e.what());
  }
}

}  // namespace gazelod::cli
