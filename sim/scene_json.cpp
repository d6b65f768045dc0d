// SPDX-License-Identifier: Apache-2.0
#include "sim/scene_json.hpp"

#include "auxiliary/json_path.hpp"
#include "auxiliary/random.hpp"
#include "lod/object_set.hpp"

#include <cmath>
#include <string_view>
#include <unordered_set>

namespace gazelod::sim {
namespace {

constexpr std::uint64_t kGeneratorStream = 0x5CE7E0000ULL;  // away from effect streams (1, 2, ...)

std::string count_text(std::size_t n) {
  return std::to_string(n);
}

lod::LodLevel read_level(const nlohmann::json& j, const std::string& path, const std::string& source) {
  JsonFields f(j, path, source);
  lod::LodLevel l;
  l.triangles = static_cast<std::uint32_t>(f.integer("triangles", 0, 0, 4'000'000'000LL));
  l.vertices = static_cast<std::uint32_t>(f.integer("vertices", 0, 0, 4'000'000'000LL));
  const std::string kind = f.string("detail_kind", "removed_cycles_per_diameter");
  if (kind == "removed_cycles_per_diameter")
    l.detail_kind = lod::DetailKind::removed_cycles_per_diameter;
  else if (kind == "geometric_error_m")
    l.detail_kind = lod::DetailKind::geometric_error_m;
  else
    f.fail("detail_kind", "expected \"removed_cycles_per_diameter\" or \"geometric_error_m\", got \"" + kind + "\"");
  l.detail = f.number("detail", 0.0, 0.0, 1e9);
  f.finish();
  return l;
}

// The chain check the plugin makes when an object is registered (lod::validate_chain), with
// the JSON path of the bad level.
void check_chain(const std::vector<lod::LodLevel>& levels, const std::string& lods_path, const std::string& source) {
  const std::optional<lod::ChainProblem> p = lod::find_chain_problem(levels);
  if (!p) return;
  if (p->level >= levels.size()) throw_at(source, lods_path, p->message);
  throw_at(source, aux::json_element_path(lods_path, p->level), p->message);
}

// Adds `objects` objects of `levels_each` levels and `name_length`-byte names to the tally,
// or fails at `key` of `f` naming the limit that would be passed.
void count_objects(ScenarioTally& t, std::size_t objects, std::size_t levels_each, std::size_t name_length,
                   const JsonFields& f, const std::string& key, const std::string& what) {
  if (objects > kMaxObjects - t.objects)
    f.fail(key, "must be <= " + count_text(kMaxObjects - t.objects) + " " + what + " (a scenario has at most " +
                    count_text(kMaxObjects) + " objects in all, " + count_text(t.objects) + " before), got " +
                    count_text(objects));
  if (levels_each > 0 && objects > (kMaxLevels - t.levels) / levels_each)
    f.fail(key, "must keep the LOD levels in all <= " + count_text(kMaxLevels) + " (" + count_text(t.levels) +
                    " before), got " + count_text(objects) + " x " + count_text(levels_each) + " = " +
                    count_text(objects * levels_each) + " levels");
  const std::size_t each = scenario_object_bytes(name_length, levels_each);
  if (objects > (kMaxScenarioMemoryBytes - t.memory_bytes) / each)
    f.fail(key, "must keep the scenario's estimated memory <= " + bytes_text(kMaxScenarioMemoryBytes) + " (" +
                    bytes_text(t.memory_bytes) + " before, " + bytes_text(each) + " per object), got " +
                    bytes_text(objects * each));
  t.objects += objects;
  t.levels += objects * levels_each;
  t.memory_bytes += objects * each;
}

// Counts an explicit object from its JSON (before any is read): its levels and name.
void count_object(const nlohmann::json& j, const std::string& path, const std::string& source, std::size_t index,
                  ScenarioTally& tally) {
  JsonFields f(j, path, source);
  const auto lods = j.find("lods");
  const std::size_t n = lods != j.end() && lods->is_array() ? lods->size() : 0;
  if (n > lod::kMaxChainLevels)
    f.fail("lods", "a chain needs 1 to " + count_text(lod::kMaxChainLevels) + " levels, got " + count_text(n));
  const auto name = j.find("name");
  const std::size_t name_length =
      name != j.end() && name->is_string() ? name->get_ref<const std::string&>().size() : 6 + count_text(index).size();
  count_objects(tally, 1, n, name_length, f, "", "objects");
}

SceneObject read_object(const nlohmann::json& j, const std::string& path, const std::string& source,
                        std::size_t index) {
  JsonFields f(j, path, source);
  SceneObject o;
  o.name = f.string("name", "object" + std::to_string(index));
  if (o.name.empty()) f.fail("name", "must not be empty");
  o.position_m = f.vec3("position_m", glm::dvec3(0.0));
  o.velocity_m_s = f.vec3("velocity_m_s", glm::dvec3(0.0), -1e4, 1e4);
  o.radius_m = f.number("radius_m", 0.5, 1e-6, 1e6);
  o.importance = f.number("importance", 1.0, 0.0, 1e6);
  const nlohmann::json* lods = f.child("lods");
  if (!lods) f.fail("lods", "missing (a list of levels, level 0 = full detail)");
  if (!lods->is_array() || lods->empty())
    f.fail("lods", "expected a non-empty array, got " + aux::json_type_name(*lods));
  o.lods.reserve(lods->size());
  for (std::size_t i = 0; i < lods->size(); ++i)
    o.lods.push_back(read_level((*lods)[i], aux::json_element_path(f.key_path("lods"), i), source));
  f.finish();
  check_chain(o.lods, f.key_path("lods"), source);
  return o;
}

struct RandomField {
  std::size_t count = 200;
  glm::dvec3 lo{-20.0, -4.0, -120.0}, hi{20.0, 4.0, -5.0};
  double r_min = 0.2, r_max = 1.5;
  int levels = 4;
  std::uint32_t triangles = 20000;
  double ratio = 4.0;
  double speed = 0.0;
  std::string prefix = "field";
};

// Reads and checks a random_field's parameters and counts what it will make; makes nothing.
RandomField read_random_field(const nlohmann::json& j, const std::string& path, const std::string& source,
                              ScenarioTally& tally) {
  JsonFields f(j, path, source);
  RandomField g;
  (void)f.child("type");
  g.count = static_cast<std::size_t>(f.integer("count", 200, 0, 1'000'000));
  g.lo = f.vec3("min_m", g.lo);
  g.hi = f.vec3("max_m", g.hi);
  for (int a = 0; a < 3; ++a)
    if (!(g.lo[a] <= g.hi[a])) f.fail("max_m", "must be >= min_m on every axis");
  g.r_min = f.number("radius_min_m", 0.2, 1e-6, 1e6);
  g.r_max = f.number("radius_max_m", std::max(1.5, g.r_min), g.r_min, 1e6);
  g.levels = static_cast<int>(f.integer("lod_count", 4, 1, 16));
  g.triangles = static_cast<std::uint32_t>(f.integer("triangles", 20000, 1, 1'000'000'000));
  g.ratio = f.number("triangle_ratio", 4.0, 1.0, 100.0);
  g.speed = f.number("forward_speed_m_s", 0.0, 0.0, 1000.0);
  g.prefix = f.string("name_prefix", "field");
  f.finish();
  const std::size_t digits = g.count > 1 ? count_text(g.count - 1).size() : 1;
  count_objects(tally, g.count, static_cast<std::size_t>(g.levels), g.prefix.size() + digits, f, "count", "objects");
  check_chain(make_lod_chain(g.triangles, g.levels, g.ratio), path, source);
  return g;
}

void make_random_field(const RandomField& g, Scenario& sc) {
  sc.head_path.velocity_m_s = glm::dvec3(0.0, 0.0, -g.speed);  // OpenXR forward is -Z
  const aux::CounterRng rng{sc.seed, kGeneratorStream};
  const std::vector<lod::LodLevel> chain = make_lod_chain(g.triangles, g.levels, g.ratio);
  for (std::size_t i = 0; i < g.count; ++i) {
    SceneObject o;
    o.name = g.prefix + std::to_string(i);
    for (int a = 0; a < 3; ++a) o.position_m[a] = rng.uniform(8 * i + static_cast<std::uint64_t>(a), g.lo[a], g.hi[a]);
    o.radius_m = rng.uniform(8 * i + 3, g.r_min, g.r_max);
    o.lods = chain;
    sc.objects.push_back(std::move(o));
  }
}

}  // namespace

std::size_t scenario_object_bytes(std::size_t name_length, std::size_t levels) {
  constexpr std::size_t kShortString = 15;  // libstdc++'s in-place capacity
  return sizeof(SceneObject) + sizeof(ObjectState) + (name_length > kShortString ? name_length + 1 : 0) +
         levels * sizeof(lod::LodLevel);
}

std::string bytes_text(std::size_t bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  double v = static_cast<double>(bytes);
  int u = 0;
  while (v >= 1024.0 && u < 4) v /= 1024.0, ++u;
  if (u == 0) return std::to_string(bytes) + " bytes";
  std::string s = format_number(std::round(v * 10.0) / 10.0);
  s.append(" ").append(units[u]);
  return s;
}

std::vector<lod::LodLevel> make_lod_chain(std::uint32_t full_triangles, int levels, double ratio) {
  std::vector<lod::LodLevel> chain;
  double t = full_triangles;
  for (int l = 0; l < levels; ++l, t /= ratio) {
    lod::LodLevel lv;
    lv.triangles = static_cast<std::uint32_t>(std::max(1.0, std::round(t)));
    lv.vertices = lv.triangles / 2 + 2;  // closed triangle mesh: V ~ T / 2
    lv.detail_kind = lod::DetailKind::removed_cycles_per_diameter;
    lv.detail = l == 0 ? 0.0 : std::sqrt(static_cast<double>(lv.triangles)) / 2.0;
    chain.push_back(lv);
  }
  return chain;
}

void read_scene(const nlohmann::json& scene, const std::string& path, const std::string& source, Scenario& sc,
                ScenarioTally& tally) {
  JsonFields f(scene, path, source);
  // First everything is counted against the scenario's limits, then objects are made.
  const nlohmann::json* objs = f.child("objects");
  if (objs) {
    if (!objs->is_array()) f.fail("objects", "expected an array, got " + aux::json_type_name(*objs));
    if (objs->size() > kMaxObjects - tally.objects)
      f.fail("objects", "must hold at most " + count_text(kMaxObjects - tally.objects) +
                            " objects (a scenario has at most " + count_text(kMaxObjects) + " in all), got " +
                            count_text(objs->size()));
    for (std::size_t i = 0; i < objs->size(); ++i)
      count_object((*objs)[i], aux::json_element_path(f.key_path("objects"), i), source, i, tally);
  }
  std::vector<RandomField> fields;
  if (const nlohmann::json* gens = f.child("generators")) {
    if (!gens->is_array()) f.fail("generators", "expected an array, got " + aux::json_type_name(*gens));
    for (std::size_t i = 0; i < gens->size(); ++i) {
      const std::string gp = aux::json_element_path(f.key_path("generators"), i);
      const nlohmann::json& g = (*gens)[i];
      JsonFields gf(g, gp, source);
      const std::string type = gf.required_string("type");
      if (type == "random_field")
        fields.push_back(read_random_field(g, gp, source, tally));
      else
        gf.fail("type", "unknown generator \"" + type + "\" (known: random_field)");
    }
  }
  if (const nlohmann::json* hp = f.child("head_path")) {
    JsonFields h(*hp, f.key_path("head_path"), source);
    sc.head_path.start_m = h.vec3("start_m", sc.head_path.start_m);
    sc.head_path.velocity_m_s = h.vec3("velocity_m_s", sc.head_path.velocity_m_s, -1e4, 1e4);
    h.finish();
  }
  f.finish();

  sc.objects.reserve(sc.objects.size() + tally.objects);  // exact: one allocation
  if (objs)
    for (std::size_t i = 0; i < objs->size(); ++i)
      sc.objects.push_back(
          read_object((*objs)[i], aux::json_element_path(f.key_path("objects"), i), source, sc.objects.size()));
  // A generator's forward speed sets the head path unless scene.head_path gives a velocity
  // (as before: the generator wrote it, then head_path read it with that as its default).
  const glm::dvec3 head_velocity = sc.head_path.velocity_m_s;
  const bool velocity_given =
      scene.contains("head_path") && scene["head_path"].is_object() && scene["head_path"].contains("velocity_m_s");
  for (const RandomField& g : fields) make_random_field(g, sc);
  if (velocity_given) sc.head_path.velocity_m_s = head_velocity;
  std::unordered_set<std::string_view> names;
  names.reserve(sc.objects.size());
  for (std::size_t i = 0; i < sc.objects.size(); ++i)
    if (!names.insert(sc.objects[i].name).second)
      f.fail("objects", "two objects are named \"" + sc.objects[i].name + "\"");
}

}  // namespace gazelod::sim
