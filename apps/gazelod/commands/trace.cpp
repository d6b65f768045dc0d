// SPDX-License-Identifier: Apache-2.0
// gazelod trace stats FILE / gazelod trace convert IN OUT: gaze traces in gazelod's format or
// an imported layout (GazeBaseVR, Pupil Core, Pupil Cloud), detected from the header unless
// --format says. Malformed files exit non-zero naming file:line:column; --lenient skips bad
// lines and reports every one of them. On a Pupil Cloud trace, stats also says how our
// classifiers agree with Pupil Cloud's own fixations and blinks (gaze/gaze_agreement.hpp).
#include "auxiliary/atomic_file.hpp"
#include "gaze/trace_open.hpp"
#include "gaze/trace_stats.hpp"
#include "gaze/trace_writer.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/run/signals.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <iomanip>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <string>

namespace gazelod::cli {
namespace {

struct Options {
  std::string file, out_file, format = "auto", time_unit = "ns";
  bool json = false, lenient = false;
};

gaze::TraceFormat format_of(const Options& o) {
  const auto f = gaze::parse_trace_format(o.format);
  if (!f)
    throw UsageError("--format: expected auto, gazelod, gazebasevr, pupil, pupil_cloud or sranipal, got '" + o.format +
                     "'");
  return *f;
}

// Lenient mode never drops silently: the count and the first lines go to stderr.
void report_skipped(const gaze::SkipReport& s, std::ostream& err) {
  if (s.skipped == 0) return;
  err << "warning: skipped " << s.skipped << " bad line(s):\n";
  for (const auto& issue : s.first) err << "  " << issue.to_string() << "\n";
  if (s.skipped > s.first.size()) err << "  ... and " << s.skipped - s.first.size() << " more\n";
}

// The agreement block (Pupil Cloud traces): one classifier, fixations and blinks.
nlohmann::json agreement_json(const std::optional<gaze::EventAgreement>& a) {
  if (!a) return nullptr;
  return {{"agreement", a->agreement},
          {"kappa", a->kappa ? nlohmann::json(*a->kappa) : nlohmann::json(nullptr)},
          {"both", a->samples.both},
          {"ours_only", a->samples.ours_only},
          {"reference_only", a->samples.reference_only},
          {"neither", a->samples.neither},
          {"ours_events", a->ours_events},
          {"reference_events", a->reference_events},
          {"reference_overlapped", a->reference_overlapped},
          {"ours_overlapped", a->ours_overlapped}};
}

constexpr const char* kIvtName = "I-VT (trace stats' classifier)";
constexpr const char* kIvdtName = "I-VDT (gaze_conditioner, the plugin's; pursuit is not fixation)";

nlohmann::json agreement_json(const gaze::ReferenceAgreement& a) {
  auto classifier = [](const gaze::ClassifierAgreement& c, const char* name) {
    return nlohmann::json{
        {"classifier", name}, {"fixation", agreement_json(c.fixation)}, {"blink", agreement_json(c.blink)}};
  };
  return {{"reference", "pupil_cloud fixation id / blink id, per sample"},
          {"blinks_file", a.blinks_file.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.blinks_file)},
          {"blinks_in_file", a.blinks_in_file},
          {"samples_in_blinks", a.samples_in_blinks},
          {"ivt", classifier(a.ivt, kIvtName)},
          {"ivdt", classifier(a.ivdt, kIvdtName)}};
}

void print_category(std::ostream& out, std::string_view what, const std::optional<gaze::EventAgreement>& a) {
  const std::string label = "    " + std::string(what) + std::string(what.size() < 10 ? 10 - what.size() : 1, ' ');
  if (!a) {
    out << label << "(no Pupil " << what << " id column)\n";
    return;
  }
  out << label << "agreement " << a->agreement * 100.0 << " %, kappa ";
  if (a->kappa)
    out << *a->kappa;
  else
    out << "n/a";
  out << " (samples: both " << a->samples.both << ", ours only " << a->samples.ours_only << ", Pupil only "
      << a->samples.reference_only << ", neither " << a->samples.neither << ")\n"
      << std::string(label.size(), ' ') << "events: ours " << a->ours_events << ", Pupil " << a->reference_events
      << ", Pupil's overlapped by ours " << a->reference_overlapped << ", ours overlapped by Pupil's "
      << a->ours_overlapped << "\n";
}

void print_agreement(std::ostream& out, const gaze::ReferenceAgreement& a) {
  out << "agreement with Pupil Cloud's fixation id / blink id, per sample\n";
  if (a.blinks_file.empty())
    out << "  blinks file: none beside the trace; the samples with a blink id (" << a.samples_in_blinks
        << ") made invalid, so blink agreement checks that import\n";
  else
    out << "  blinks file: " << a.blinks_file << ", " << a.blinks_in_file << " blinks, " << a.samples_in_blinks
        << " samples made invalid (so blink agreement checks that import)\n";
  for (const auto& [c, name] : {std::pair{&a.ivt, kIvtName}, std::pair{&a.ivdt, kIvdtName}}) {
    out << "  " << name << "\n";
    print_category(out, "fixation", c->fixation);
    print_category(out, "blink", c->blink);
  }
}

int run_stats(const Options& o, Io io) {
  gaze::TraceStats st;
  std::unique_ptr<gaze::RecordStream> stream;
  try {
    stream = gaze::open_trace(o.file, format_of(o), {.lenient = o.lenient});
    st = gaze::compute_trace_stats(*stream);
  } catch (const gaze::TraceError& e) {
    throw UsageError(e.what());
  }
  report_skipped(stream->skipped(), io.err);
  const auto opened = gaze::opened_trace_format(*stream);
  const std::string format(opened ? gaze::trace_format_name(*opened) : std::string_view(o.format));
  if (o.json) {
    nlohmann::json j;
    j["file"] = o.file;
    j["format"] = format;
    j["samples"] = st.samples;
    j["duration_s"] = st.duration_s;
    j["rate_hz"] = st.rate_hz;
    j["invalid_fraction"] = st.invalid_fraction;
    j["classified_in"] = !st.classified_in_world ? "head" : st.classified_in_head > 0 ? "head_then_world" : "world";
    j["saccades"] = st.saccades;
    j["fixations"] = st.fixations;
    j["mean_saccade_amplitude_deg"] = st.mean_saccade_amplitude_deg;
    j["max_saccade_peak_velocity_deg_s"] = st.max_saccade_peak_velocity_deg_s;
    j["samples_with_head"] = st.with_head;
    j["skipped_lines"] = stream->skipped().skipped;
    nlohmann::json skipped = nlohmann::json::array();
    for (const auto& issue : stream->skipped().first)
      skipped.push_back({{"line", issue.line}, {"column", issue.column}, {"message", issue.message}});
    j["skipped"] = skipped;
    if (st.agreement) j["agreement"] = agreement_json(*st.agreement);
    io.out << aux::json_text(j, 2) << "\n";
    return 0;
  }
  io.out << std::fixed << std::setprecision(3) << "file              " << o.file << " (" << format << ")\n"
         << "samples           " << st.samples << "\n"
         << "duration          " << st.duration_s << " s\n"
         << "rate              " << st.rate_hz << " Hz\n"
         << "invalid           " << st.invalid_fraction * 100.0 << " %\n"
         << "saccades          " << st.saccades << " (mean amplitude " << st.mean_saccade_amplitude_deg
         << " deg; classified "
         << (!st.classified_in_world     ? "in the head: no head poses"
             : st.classified_in_head > 0 ? "in the head, then in the world from the first head pose"
                                         : "in the world: the trace has head poses")
         << ")\n"
         << "fixations         " << st.fixations << "\n"
         << "with head pose    " << st.with_head << "\n"
         << "skipped lines     " << stream->skipped().skipped << "\n";
  if (st.agreement) print_agreement(io.out, *st.agreement);
  return 0;
}

int run_convert(const Options& o, Io io) {
  namespace fs = std::filesystem;
  if (o.time_unit != "ns" && o.time_unit != "s")
    throw UsageError("--time: expected ns or s, got '" + o.time_unit + "'");
  std::error_code ec;
  if (fs::exists(o.out_file, ec) && fs::equivalent(o.file, o.out_file, ec))
    throw UsageError("OUT must not be the input file");
  check_output_file("OUT", o.out_file);
  // Written atomically (auxiliary/atomic_file.hpp): a failure, in the input or the output, leaves
  // neither a truncated OUT nor a temporary file. Ctrl-C or SIGTERM (a pipe that does not end,
  // a long file) stops it the same way: a conversion cut short is not the trace, so OUT is not
  // written, and a second signal removes the temporary before the process ends.
  StopOnSignal stop;
  std::size_t n = 0;
  const auto stop_if_asked = [&] {
    if (const int sig = stop.requested()) {
      stop.acted_on();
      throw UsageError(std::string("stopped by ") + StopOnSignal::name(sig) + " after " + std::to_string(n) +
                           " samples; " + o.out_file + " not written",
                       128 + sig);
    }
  };
  std::unique_ptr<gaze::RecordStream> stream;
  try {
    stream = gaze::open_trace(o.file, format_of(o), {.lenient = o.lenient});
    TemporaryOnSignal temporary;  // released after the writer has removed or renamed its file
    gaze::TraceFileWriter writer(o.out_file, {.time_in_ns = o.time_unit == "ns", .write_head = stream->has_head()});
    temporary.hold(writer.temp_path());
    gaze::TraceRecord r;
    while (stream->next(r)) {
      stop_if_asked();
      writer.write(r);
      ++n;
    }
    // A signal that interrupted a read from a pipe ends the input early: never committed.
    stop_if_asked();
    writer.commit();
  } catch (const gaze::TraceError& e) {
    stop_if_asked();  // the read the signal interrupted failed: the stop, not the input, says why
    throw UsageError(e.what());
  } catch (const aux::WriteError& e) {
    throw UsageError(e.what(), 1);
  }
  report_skipped(stream->skipped(), io.err);
  io.out << "wrote " << n << " samples to " << o.out_file << "\n";
  return 0;
}

const Registrar registrar{
    "trace", "Gaze traces: statistics and conversion to gazelod's format (docs/gaze.md)", [](CLI::App& sub) -> Action {
      auto o = std::make_shared<Options>();
      sub.require_subcommand(1);
      const std::string fmt_help =
          "input layout: auto (default: from the header), gazelod, gazebasevr, pupil, pupil_cloud, sranipal";
      CLI::App* stats = sub.add_subcommand("stats", "samples, duration, rate, invalid fraction, saccades, fixations");
      stats->add_option("FILE", o->file, "trace file")->required();
      stats->add_option("--format", o->format, fmt_help);
      stats->add_flag("--json", o->json, "print one JSON object");
      stats->add_flag("--lenient", o->lenient, "skip bad lines (each is reported on stderr)");
      CLI::App* convert = sub.add_subcommand("convert", "convert a trace to gazelod's CSV format");
      convert->add_option("IN", o->file, "input trace")->required();
      convert->add_option("OUT", o->out_file, "output file (gazelod format)")->required();
      convert->add_option("--format", o->format, fmt_help);
      convert->add_option("--time", o->time_unit, "time column: ns (t_ns, default) or s (t_s)");
      convert->add_flag("--lenient", o->lenient, "skip bad lines (each is reported on stderr)");
      return [o, stats](Io io) { return stats->parsed() ? run_stats(*o, io) : run_convert(*o, io); };
    }};

}  // namespace
}  // namespace gazelod::cli
