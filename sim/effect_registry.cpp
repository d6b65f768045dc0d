// SPDX-License-Identifier: Apache-2.0
// Effect names to makers. An explicit table rather than self-registering statics, which a
// static library would drop at link time.
#include "sim/effect.hpp"

#include "auxiliary/time.hpp"
#include "sim/effects/effects.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

namespace gazelod::sim {
namespace {

using Maker = std::unique_ptr<Effect> (*)(EffectInit&);
struct Entry {
  std::string_view name;
  Maker make;
};

constexpr std::array<Entry, 14> kEffects{{
    {"head_sweep", effects::make_head_sweep},
    {"head_turn", effects::make_head_turn},
    {"head_track", effects::make_head_track},
    {"gaze_track", effects::make_gaze_track},
    {"saccades", effects::make_saccades},
    {"vor", effects::make_vor},
    {"smooth_pursuit", effects::make_smooth_pursuit},
    {"tracker_noise", effects::make_tracker_noise},
    {"tracker_latency", effects::make_tracker_latency},
    {"tracker_rate", effects::make_tracker_rate},
    {"dropouts", effects::make_dropouts},
    {"blinks", effects::make_blinks},
    {"calibration_offset", effects::make_calibration_offset},
    {"object_motion", effects::make_object_motion},
}};

constexpr std::array<std::string_view, kEffects.size()> kNames = [] {
  std::array<std::string_view, kEffects.size()> n{};
  for (std::size_t i = 0; i < kEffects.size(); ++i) n[i] = kEffects[i].name;
  return n;
}();

}  // namespace

std::span<const std::string_view> effect_names() {
  return kNames;
}

TimeWindow read_window(JsonFields& params) {
  TimeWindow w;
  w.start_ns = aux::ns_from_seconds(params.number("start_s", 0.0, 0.0, 1e6));
  if (params.has("end_s")) {
    const double end_s = params.number("end_s", 0.0, 0.0, 1e6);
    w.end_ns = aux::ns_from_seconds(end_s);
    if (w.end_ns <= w.start_ns) params.fail("end_s", "must be after start_s");
  }
  return w;
}

std::unique_ptr<Effect> make_effect(const EffectSpec& spec, const Scenario& scenario, std::size_t index,
                                    const std::string& source) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(spec.params_json);
  } catch (const nlohmann::json::exception& e) {
    throw_at(source, spec.json_path, std::string("invalid JSON: ") + e.what());
  }
  JsonFields params(j, spec.json_path, source);
  (void)params.child("type");
  for (const Entry& e : kEffects) {
    if (e.name != spec.type) continue;
    EffectInit init{scenario, params, aux::CounterRng{scenario.seed, index + 1}, source};
    std::unique_ptr<Effect> effect = e.make(init);
    params.finish();
    return effect;
  }
  std::string known;
  for (const Entry& e : kEffects) known += (known.empty() ? "" : ", ") + std::string(e.name);
  throw_at(source, spec.json_path + ".type", "unknown effect \"" + spec.type + "\" (known: " + known + ")");
}

namespace effects {
std::size_t object_index(const Scenario& scenario, JsonFields& params, const std::string& key,
                         const std::string& name) {
  for (std::size_t i = 0; i < scenario.objects.size(); ++i)
    if (scenario.objects[i].name == name) return i;
  params.fail(key, "no scene object named \"" + name + "\"");
}

TraceParam trace_param(EffectInit& init) {
  TraceParam t;
  t.name = init.params.required_string("file");
  const std::string fmt_name = init.params.string("format", "gazelod");
  const std::optional<gaze::TraceFormat> fmt = gaze::parse_trace_format(fmt_name);
  if (!fmt) init.params.fail("format", "unknown trace format \"" + fmt_name + "\"");
  t.format = *fmt;
  t.path = trace_file_path(t.name, init.source);
  return t;
}

std::string trace_file_path(const std::string& file, const std::string& scenario_source) {
  // Relative to the scenario file, as sim/scenarios/README.md says; as given (from the working
  // folder) only where the scenario's folder has no such file, or the scenario is no file.
  const std::filesystem::path p(file), src(scenario_source);
  std::error_code ec;
  const bool beside = !p.is_absolute() && std::filesystem::is_regular_file(src, ec) &&
                      std::filesystem::exists(src.parent_path() / p, ec);
  return beside ? (src.parent_path() / p).string() : file;
}

std::vector<std::unique_ptr<Effect>> make_gaze_effects_before(const EffectInit& init) {
  // make_effect gives effect i the random stream i + 1, so the stream is the effect's place.
  std::vector<std::unique_ptr<Effect>> out;
  if (init.rng.stream == 0 || init.rng.stream > init.scenario.effects.size()) return out;
  const auto index = static_cast<std::size_t>(init.rng.stream - 1);
  for (std::size_t i = 0; i < index; ++i) {
    std::unique_ptr<Effect> e = make_effect(init.scenario.effects[i], init.scenario, i, init.source);
    if (e->stages() & kStageGaze) out.push_back(std::move(e));
  }
  return out;
}
}  // namespace effects

}  // namespace gazelod::sim
