// SPDX-License-Identifier: Apache-2.0
// gazelod scenario: check a scenario file, print a scenario (the embedded default, or a file
// with its generated objects written out), and record what a scenario simulates as a gazelod
// gaze trace.
#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/run/signals.hpp"
#include "auxiliary/atomic_file.hpp"
#include "auxiliary/text.hpp"
#include "sim/record_trace.hpp"
#include "sim/scenario_family.hpp"
#include "sim/simulator.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace gazelod::cli {
namespace {

struct Options {
  std::string file;
  bool use_default = false;
  std::string out;
  bool truth = false;
  double rate_hz = 0.0;
  double duration_s = 0.0;
  std::uint64_t seed = 0;
  std::string ideal;  // family: parts of the tracker made ideal (sim::parse_ideal_tracker)
};

sim::Scenario load(const Options& o) {
  if (o.use_default == !o.file.empty()) throw UsageError("give a scenario FILE or --default (one of them)");
  try {
    return o.use_default ? sim::load_scenario_json(sim::default_scenario_json(), "<embedded default scenario>")
                         : sim::load_scenario_file(o.file);
  } catch (const sim::ScenarioError& e) {
    throw UsageError(e.what());
  }
}

int run_validate(const Options& o, Io io) {
  const sim::Scenario sc = load(o);
  io.out << (o.use_default ? std::string("<embedded default scenario>") : o.file) << ": ok: \"" << sc.name
         << "\", display " << sc.display.name << " (" << sc.display.label << "), " << sc.duration_s << " s at "
         << sc.frame_rate_hz << " Hz, seed " << sc.seed << ", " << aux::counted(sc.objects.size(), "object", "objects")
         << ", effects:";
  if (sc.effects.empty()) io.out << " none (still head, centred gaze)";
  for (const sim::EffectSpec& e : sc.effects) io.out << " " << e.type;
  io.out << "\n";
  return 0;
}

int run_print(const Options& o, Io io) {
  if (o.use_default && o.file.empty()) {
    io.out << sim::default_scenario_json() << "\n";
    return 0;
  }
  io.out << sim::scenario_to_json(load(o));
  return 0;
}

int run_record(const Options& o, Io io) {
  check_output_file("--out", o.out);
  std::error_code ec;
  if (!o.file.empty() && std::filesystem::exists(o.out, ec) && std::filesystem::equivalent(o.file, o.out, ec))
    throw UsageError("--out: '" + o.out + "' is the scenario being recorded; write the trace to another file");
  sim::Scenario sc = load(o);
  sim::Simulator simulator(std::move(sc));
  sim::RecordOptions ro;
  ro.step_hz = o.rate_hz;
  ro.true_gaze = o.truth;
  ro.duration_s = o.duration_s;
  // Progress every few seconds; Ctrl-C or SIGTERM stops it with no file written.
  StopOnSignal stop;
  auto last = std::chrono::steady_clock::now();
  ro.progress = [&](double done_s, double total_s) {
    if (stop.requested()) return false;
    const auto now = std::chrono::steady_clock::now();
    if (now - last > std::chrono::seconds(2)) {
      last = now;
      io.err << "gazelod scenario record: " << static_cast<long long>(done_s) << " of "
             << static_cast<long long>(total_s) << " s simulated\n"
             << std::flush;
    }
    return true;
  };
  sim::RecordStats st;
  try {  // written atomically: a failure leaves no file behind, partial or temporary; a second
         // signal removes the temporary too (AtomicRunFile)
    AtomicRunFile file(o.out);
    st = sim::record_trace(simulator, file.stream(), ro);
    // A trace of no samples (a tracker latency of the whole duration or more) is no recording:
    // `run --trace` refused it later, after this said "wrote 0 rows" and exited 0.
    if (st.rows == 0) {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%g", ro.duration_s > 0 ? ro.duration_s : simulator.scenario().duration_s);
      throw UsageError(std::string("no sample arrives within the recording's ") + seconds +
                       " s (the tracker's latency is as long or longer); nothing written");
    }
    file.commit();
  } catch (const aux::WriteError& e) {
    throw UsageError(std::string("--out: ") + e.what(), 1);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  } catch (const sim::RecordStopped&) {
    stop.acted_on();
    throw UsageError(std::string("stopped by ") + StopOnSignal::name(stop.requested()) + "; nothing written",
                     128 + stop.requested());
  }
  io.out << "wrote " << st.rows << " rows (" << st.invalid_rows << " invalid) to " << o.out << "\n";
  return 0;
}

// One member of the scenario family (sim/scenario_family.hpp), checked by the loader before
// it is printed or written.
int run_family(const Options& o, Io io) {
  sim::IdealTracker ideal;
  if (!sim::parse_ideal_tracker(o.ideal, ideal))
    throw UsageError(std::string("--ideal: expected ") + sim::kIdealTrackerNames + ", got '" + o.ideal + "'");
  check_output_file("--out", o.out);
  const sim::FamilyScenario f = sim::family_scenario(o.seed, o.duration_s, ideal);
  try {
    (void)sim::load_scenario_json(f.json, "family seed " + std::to_string(o.seed));
  } catch (const sim::ScenarioError& e) {
    throw UsageError(std::string("internal: the family made a scenario its loader refuses: ") + e.what(), 1);
  }
  if (o.out.empty()) {
    io.out << f.json << "\n";
  } else {
    try {
      aux::AtomicFile file(o.out);
      file.stream() << f.json << "\n";
      file.commit();
    } catch (const aux::WriteError& e) {
      throw UsageError(std::string("--out: ") + e.what(), 1);
    }
    io.out << "wrote " << o.out << "\n";
  }
  io.err << "family seed " << o.seed << ": " << f.summary << "\n";
  return 0;
}

void add_source(CLI::App* app, Options& o) {
  app->add_option("file", o.file, "scenario JSON file");
  app->add_flag("--default", o.use_default, "the embedded default scenario");
}

const Registrar registrar{
    "scenario", "Check, print or record a simulator scenario (JSON, version 1)", [](CLI::App& sub) -> Action {
      auto o = std::make_shared<Options>();
      sub.require_subcommand(1);
      CLI::App* validate = sub.add_subcommand("validate", "Load a scenario and report it or its first error");
      add_source(validate, *o);
      CLI::App* print = sub.add_subcommand("print", "Print a scenario as JSON (generated objects written out)");
      add_source(print, *o);
      CLI::App* record = sub.add_subcommand("record", "Simulate a scenario and write it as a gazelod trace");
      add_source(record, *o);
      record->add_option("--out", o->out, "trace CSV to write")->required();
      record->add_flag("--truth", o->truth, "record the true gaze instead of the tracker's samples");
      record->add_option("--rate", o->rate_hz, "how often to ask the tracker, Hz (default: the frame rate)")
          ->check(CLI::Range(1.0, 100000.0));
      record->add_option("--duration", o->duration_s, "seconds to record (default: the scenario's)")
          ->check(CLI::Range(0.001, 1e6));
      CLI::App* family = sub.add_subcommand(
          "family",
          "Print (or write) one scenario of the seeded family used to tune and evaluate (gazelod eval family)");
      family->add_option("--seed", o->seed, "which member (any non-negative integer)")->required();
      family->add_option("--out", o->out, "scenario JSON to write (default: print it)");
      family->add_option("--duration", o->duration_s, "seconds (default 20)")->check(CLI::Range(1.0, 3600.0));
      family->add_option("--ideal", o->ideal,
                         "what-if: make parts of the seed's tracker ideal: latency (0 ms), noise (0 deg), rate (1000 "
                         "Hz), comma-separated, or all");
      return [o, validate, print, family](Io io) {
        if (validate->parsed()) return run_validate(*o, io);
        if (print->parsed()) return run_print(*o, io);
        if (family->parsed()) return run_family(*o, io);
        return run_record(*o, io);
      };
    }};

}  // namespace
}  // namespace gazelod::cli
