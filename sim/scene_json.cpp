#include "sim/scene_json.hpp"

#include "sim/random.hpp"

#include <cmath>
#include <set>

namespace gazelod::sim {
namespace {

constexpr std::uint64_t kGeneratorStream = 0x5CE7E0000ULL;  // away from effect streams (1, 2, ...)

lod::LodLevel read_level(const nlohmann::json& j, const std::string& path, const std::string& source) {
  JsonFields f(j, path, source);
  lod::LodLevel l;
  l.triangles = static_cast<std::uint32_t>(f.integer("triangles", 0, 0, 4'000'000'000LL));
  l.vertices = static_cast<std::uint32_t>(f.integer("vertices", 0, 0, 4'000'000'000LL));
  const std::string kind = f.string("detail_kind", "removed_cycles_per_diameter");
  if (kind == "removed_cycles_per_diameter") l.detail_kind = lod::DetailKind::removed_cycles_per_diameter;
  else if (kind == "geometric_error_m") l.detail_kind = lod::DetailKind::geometric_error_m;
  else f.fail("detail_kind", "expected \"removed_cycles_per_diameter\" or \"geometric_error_m\", got \"" + kind + "\"");
  l.detail = f.number("detail", 0.0, 0.0, 1e9);
  f.finish();
  return l;
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
  if (!lods->is_array() || lods->empty()) f.fail("lods", "expected a non-empty array, got " + json_type_name(*lods));
  for (std::size_t i = 0; i < lods->size(); ++i)
    o.lods.push_back(read_level((*lods)[i], f.key_path("lods") + "[" + std::to_string(i) + "]", source));
  f.finish();
  return o;
}

void random_field(const nlohmann::json& j, const std::string& path, const std::string& source, Scenario& sc) {
  JsonFields f(j, path, source);
  (void)f.child("type");
  const auto count = static_cast<std::size_t>(f.integer("count", 200, 0, 1'000'000));
  const glm::dvec3 lo = f.vec3("min_m", glm::dvec3(-20.0, -4.0, -120.0));
  const glm::dvec3 hi = f.vec3("max_m", glm::dvec3(20.0, 4.0, -5.0));
  for (int a = 0; a < 3; ++a)
    if (!(lo[a] <= hi[a])) f.fail("max_m", "must be >= min_m on every axis");
  const double r_min = f.number("radius_min_m", 0.2, 1e-6, 1e6);
  const double r_max = f.number("radius_max_m", std::max(1.5, r_min), r_min, 1e6);
  const int levels = static_cast<int>(f.integer("lod_count", 4, 1, 16));
  const auto tris = static_cast<std::uint32_t>(f.integer("triangles", 20000, 1, 1'000'000'000));
  const double ratio = f.number("triangle_ratio", 4.0, 1.0, 100.0);
  const double speed = f.number("forward_speed_m_s", 0.0, 0.0, 1000.0);
  const std::string prefix = f.string("name_prefix", "field");
  f.finish();
  sc.head_path.velocity_m_s = glm::dvec3(0.0, 0.0, -speed);  // OpenXR forward is -Z
  const CounterRng rng{sc.seed, kGeneratorStream};
  const std::vector<lod::LodLevel> chain = make_lod_chain(tris, levels, ratio);
  for (std::size_t i = 0; i < count; ++i) {
    SceneObject o;
    o.name = prefix + std::to_string(i);
    for (int a = 0; a < 3; ++a) o.position_m[a] = rng.uniform(8 * i + static_cast<std::uint64_t>(a), lo[a], hi[a]);
    o.radius_m = rng.uniform(8 * i + 3, r_min, r_max);
    o.lods = chain;
    sc.objects.push_back(std::move(o));
  }
}

}  // namespace

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

void read_scene(const nlohmann::json& scene, const std::string& path, const std::string& source, Scenario& sc) {
  JsonFields f(scene, path, source);
  if (const nlohmann::json* objs = f.child("objects")) {
    if (!objs->is_array()) f.fail("objects", "expected an array, got " + json_type_name(*objs));
    for (std::size_t i = 0; i < objs->size(); ++i)
      sc.objects.push_back(read_object((*objs)[i], f.key_path("objects") + "[" + std::to_string(i) + "]", source,
                                       sc.objects.size()));
  }
  if (const nlohmann::json* gens = f.child("generators")) {
    if (!gens->is_array()) f.fail("generators", "expected an array, got " + json_type_name(*gens));
    for (std::size_t i = 0; i < gens->size(); ++i) {
      const std::string gp = f.key_path("generators") + "[" + std::to_string(i) + "]";
      const nlohmann::json& g = (*gens)[i];
      JsonFields gf(g, gp, source);
      const std::string type = gf.required_string("type");
      if (type == "random_field") random_field(g, gp, source, sc);
      else gf.fail("type", "unknown generator \"" + type + "\" (known: random_field)");
    }
  }
  if (const nlohmann::json* hp = f.child("head_path")) {
    JsonFields h(*hp, f.key_path("head_path"), source);
    sc.head_path.start_m = h.vec3("start_m", sc.head_path.start_m);
    sc.head_path.velocity_m_s = h.vec3("velocity_m_s", sc.head_path.velocity_m_s, -1e4, 1e4);
    h.finish();
  }
  f.finish();
  std::set<std::string> names;
  for (std::size_t i = 0; i < sc.objects.size(); ++i)
    if (!names.insert(sc.objects[i].name).second)
      f.fail("objects", "two objects are named \"" + sc.objects[i].name + "\"");
}

}  // namespace gazelod::sim
