// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/commands/command.hpp"

#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <memory>

namespace gazelod::cli {
namespace {

struct Entry {
  std::string name;
  std::string description;
  Setup setup;
};

// Function-local static: registrars in other translation units may run before this file's
// statics are initialised.
std::vector<Entry>& registry() {
  static std::vector<Entry> entries;
  return entries;
}

}  // namespace

double parse_number(const std::string& option, const std::string& text) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  auto [p, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc{} || p != end || text.empty() || !std::isfinite(v))
    throw UsageError(option + ": '" + text + "' is not a finite number");
  return v;
}

Registrar::Registrar(std::string name, std::string description, Setup setup) {
  registry().push_back({std::move(name), std::move(description), std::move(setup)});
}

namespace {

// Integer options take decimal digits only (a leading '-' where the type is signed); floating-
// point ones take a finite number. Applied to every option of `app` and its sub-commands by
// the type CLI11 reports for it.
void strict_numbers(CLI::App& app) {
  const CLI::Validator integer(
      [](std::string& text) -> std::string {
        const std::size_t start = !text.empty() && text[0] == '-' ? 1 : 0;
        if (text.size() == start || text.find_first_not_of("0123456789", start) != std::string::npos)
          return "'" + text + "' is not a decimal integer";
        // Past 64 bits CLI11 saturates (a seed of 2^64 ran as 2^64 - 1): refused instead.
        errno = 0;
        if (start == 1)
          (void)std::strtoll(text.c_str(), nullptr, 10);
        else
          (void)std::strtoull(text.c_str(), nullptr, 10);
        if (errno == ERANGE) return "'" + text + "' is out of range (64 bits)";
        return "";
      },
      "");
  const CLI::Validator non_negative(
      [](std::string& text) -> std::string {
        if (!text.empty() && text[0] == '-') return "'" + text + "' is negative";
        return "";
      },
      "");
  const CLI::Validator finite(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end == nullptr || *end != '\0' || !std::isfinite(v))
          return "'" + text + "' is not a finite number";
        return "";
      },
      "");
  for (CLI::Option* opt : app.get_options()) {
    // "INT", or "INT:INT in [1 - 10000000]" once a range is attached.
    const std::string type = opt->get_type_name();
    const auto is = [&](const char* t) { return type == t || type.rfind(std::string(t) + ":", 0) == 0; };
    if (is("INT") || is("UINT")) opt->check(integer);
    if (is("UINT")) opt->check(non_negative);
    if (is("FLOAT")) opt->check(finite);
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) strict_numbers(*sub);
}

}  // namespace

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"gazelod: gaze-contingent perceptual level of detail for OpenXR", "gazelod"};
  app.require_subcommand(1);
  struct Bound {
    CLI::App* sub;
    Action action;
    std::string name;
  };
  std::vector<Bound> bound;
  for (const Entry& e : registry()) {
    CLI::App* sub = app.add_subcommand(e.name, e.description);
    bound.push_back({sub, e.setup(*sub), e.name});
  }

  // Numbers as a user types them, for every command at once: CLI11 alone reads "0x10" as 16,
  // wraps "-1" into an unsigned option and takes "nan" for a floating-point one.
  strict_numbers(app);

  // CLI11 parses the vector from the back.
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    out << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::ParseError& e) {
    // Help for a sub-command arrives as CallForHelp from the sub-command too.
    if (e.get_exit_code() == 0) {
      for (const Bound& b : bound)
        if (b.sub->parsed()) {
          out << b.sub->help();
          return 0;
        }
      out << app.help();
      return 0;
    }
    std::string where;
    for (const Bound& b : bound)
      if (b.sub->parsed()) where = " " + b.name;
    err << "gazelod" << where << ": " << e.what() << "\n";
    return 2;
  }

  for (Bound& b : bound) {
    if (!b.sub->parsed()) continue;
    Io io{out, err};
    try {
      return b.action(io);
    } catch (const UsageError& e) {
      err << "gazelod " << b.name << ": " << e.what() << "\n";
      return e.exit_code;
    } catch (const std::exception& e) {
      err << "gazelod " << b.name << ": error: " << e.what() << "\n";
      return 1;
    }
  }
  err << "gazelod: no command given (try --help)\n";
  return 2;
}

}  // namespace gazelod::cli
