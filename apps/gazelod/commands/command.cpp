// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/commands/command.hpp"

#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <filesystem>
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

void check_output_file(const std::string& option, const std::string& path) {
  std::error_code ec;
  if (!path.empty() && std::filesystem::is_directory(path, ec))
    throw UsageError(option + ": cannot write '" + path + "': is a directory (name the file to write)");
}

CLI::Validator non_negative_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        // Only "-" and digits: any other text is the decimal-integer check's to refuse.
        if (text.size() > 1 && text[0] == '-' && text.find_first_not_of("0123456789", 1) == std::string::npos)
          return "'" + text + "' is negative";
        return "";
      },
      "");
}

namespace {

// strict_numbers' message for an integer past 64 bits; run() then names the option's own range.
constexpr const char* kPast64Bits = "is out of range (64 bits)";

bool integer_type(const CLI::Option& opt, bool& is_unsigned) {
  // "INT", or "INT:INT in [1 - 10000000]" once a range is attached.
  const std::string type = opt.get_type_name();
  const auto is = [&](const char* t) { return type == t || type.rfind(std::string(t) + ":", 0) == 0; };
  is_unsigned = is("UINT");
  return is("INT") || is_unsigned;
}

// Integer options take decimal digits only (a leading '-' where the type is signed); floating-
// point ones take a finite number. Applied to every option of `app` and its sub-commands by
// the type CLI11 reports for it.
void strict_numbers(CLI::App& app) {
  const auto integer = [](bool is_unsigned) {
    return CLI::Validator(
        [is_unsigned](std::string& text) -> std::string {
          const std::size_t start = !text.empty() && text[0] == '-' ? 1 : 0;
          if (text.size() == start || text.find_first_not_of("0123456789", start) != std::string::npos)
            return "'" + text + "' is not a decimal integer";
          // Past 64 bits CLI11 saturates (a seed of 2^64 ran as 2^64 - 1): refused instead. A
          // signed option past 2^63 - 1 too (negative values are the unsigned check's).
          if (is_unsigned && start == 1) return "";  // "is negative" (non_negative_integer)
          errno = 0;
          if (is_unsigned)
            (void)std::strtoull(text.c_str(), nullptr, 10);
          else
            (void)std::strtoll(text.c_str(), nullptr, 10);
          if (errno == ERANGE) return "'" + text + "' " + kPast64Bits;
          return "";
        },
        "");
  };
  const CLI::Validator finite(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end == nullptr || *end != '\0' || !std::isfinite(v))
          return "'" + text + "' is not a finite number";
        return "";
      },
      "");
  // Added in front of the option's own checks (CLI11's transform inserts first; these change
  // nothing): a range check that ran first read "1e3" or "5 " as a number and said "Value 1e3
  // not in range 1 to 10000000", of a value inside the range.
  for (CLI::Option* opt : app.get_options()) {
    bool is_unsigned = false;
    if (integer_type(*opt, is_unsigned)) {
      opt->transform(integer(is_unsigned));
      if (is_unsigned) opt->transform(non_negative_integer());  // first: "-1" is negative
    }
    const std::string type = opt->get_type_name();
    if (type == "FLOAT" || type.rfind("FLOAT:", 0) == 0) opt->transform(finite);
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) strict_numbers(*sub);
}

// The width of an integer option's type: 8, 16, 32 or 64 bits, found by converting the
// smallest value past each (CLI11 names every integer type INT or UINT); 0 when a check of the
// option's refuses the probe. Replaces the option's results: only after a parse that failed.
int integer_bits(CLI::Option& opt, bool is_unsigned) {
  for (const int w : {8, 16, 32}) {
    opt.clear();
    opt.add_result(std::to_string(std::uint64_t{1} << (is_unsigned ? w : w - 1)));
    try {
      opt.run_callback();
    } catch (const CLI::ConversionError&) {
      return w;
    } catch (const CLI::Error&) {
      return 0;
    }
  }
  return 64;
}

// An integer option given a value its type cannot hold: CLI11 says "Could not convert: --levels
// = 99999999999" when it fits 64 bits but not an int, and strict_numbers "out of range (64
// bits)" past 64 bits whatever the type. Found again here, among the options given (in the
// order CLI11 converts them), as "--levels: '99999999999' is out of range (32 bits: -2147483648
// to 2147483647)"; "" when no option has such a value. Only after a parse that failed.
std::string integer_out_of_range(CLI::App& app) {
  for (CLI::Option* opt : app.get_options()) {
    bool is_unsigned = false;
    if (!integer_type(*opt, is_unsigned) || opt->count() == 0) continue;
    const CLI::results_t values = opt->results();
    const int bits = integer_bits(*opt, is_unsigned);
    if (bits == 0) continue;
    const long long lo = is_unsigned || bits == 64 ? 0 : -(1LL << (bits - 1));
    const unsigned long long hi = bits == 64
                                      ? (is_unsigned ? ~0ULL : ~0ULL >> 1)
                                      : static_cast<unsigned long long>(is_unsigned ? (1LL << bits) - 1 : -lo - 1);
    for (const std::string& text : values) {
      const std::size_t start = !text.empty() && text[0] == '-' ? 1 : 0;
      if (text.size() == start || text.find_first_not_of("0123456789", start) != std::string::npos) continue;
      errno = 0;
      bool past = false;
      if (start == 1) {
        const long long v = std::strtoll(text.c_str(), nullptr, 10);
        past = errno == ERANGE || (bits < 64 && v < lo);
      } else {
        const unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
        past = errno == ERANGE || v > hi;
      }
      if (!past) continue;
      std::string range = std::to_string(bits) + " bits: ";
      if (is_unsigned)
        range += "at most " + std::to_string(hi);
      else
        range += (bits == 64 ? std::to_string(std::numeric_limits<long long>::min()) : std::to_string(lo)) + " to " +
                 std::to_string(hi);
      return opt->get_name() + ": '" + text + "' is out of range (" + range + ")";
    }
  }
  for (CLI::App* sub : app.get_subcommands())
    if (std::string why = integer_out_of_range(*sub); !why.empty()) return why;
  return "";
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
    // An integer past its option's type: said with the type's range, as for every option.
    std::string why;
    if (dynamic_cast<const CLI::ConversionError*>(&e) != nullptr ||
        std::string(e.what()).find(kPast64Bits) != std::string::npos)
      why = integer_out_of_range(app);
    err << "gazelod" << where << ": " << (why.empty() ? std::string(e.what()) : why) << "\n";
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
