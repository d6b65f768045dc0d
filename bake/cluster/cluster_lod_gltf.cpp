// SPDX-License-Identifier: Apache-2.0
// GAZELOD_cluster_lod writer and checked reader (cluster_lod_gltf.hpp).
#include "bake/cluster/cluster_lod_gltf.hpp"

#include "bake/bake_error.hpp"
#include "bake/cluster/cluster_sphere.hpp"
#include "bake/gltf_pack.hpp"
#include "bake/mesh_extract.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace gazelod::bake {
namespace {

using Value = tinygltf::Value;

int add_accessor(tinygltf::Model& m, const void* data, std::size_t bytes, int component, int type, std::size_t count,
                 int target) {
  tinygltf::Accessor a;
  a.bufferView = append_buffer_view(m, data, bytes, target);
  a.componentType = component;
  a.type = type;
  a.count = count;
  m.accessors.push_back(std::move(a));
  return static_cast<int>(m.accessors.size() - 1);
}

std::vector<float> spheres(std::span<const float> x, std::span<const float> y, std::span<const float> z,
                           std::span<const float> r) {
  std::vector<float> out;
  out.reserve(4 * x.size());
  for (std::size_t c = 0; c < x.size(); ++c) out.insert(out.end(), {x[c], y[c], z[c], r[c]});
  return out;
}

struct Reader {
  const tinygltf::Model& m;
  std::string where;  // "<file>: /meshes/M/primitives/P/extensions/GAZELOD_cluster_lod"
  const Value& ext;

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw BakeError(where + (key.empty() ? "" : "/" + key) + ": " + what);
  }

  std::uint32_t count(const std::string& key) const {
    if (!ext.Has(key)) fail(key, "missing");
    const Value& v = ext.Get(key);
    if (!v.IsNumber() || v.GetNumberAsDouble() < 0 || v.GetNumberAsDouble() > 4294967295.0 ||
        v.GetNumberAsDouble() != std::floor(v.GetNumberAsDouble()))
      fail(key, "must be a whole number >= 0");
    return static_cast<std::uint32_t>(v.GetNumberAsDouble());
  }

  // The accessor under `key`, checked for component type, type and (n > 0) element count.
  int accessor(const std::string& key, int component, int type, std::size_t n) const {
    const std::uint32_t a = count(key);
    if (a >= m.accessors.size()) fail(key, "accessor " + std::to_string(a) + " does not exist");
    const tinygltf::Accessor& acc = m.accessors[a];
    if (acc.componentType != component || acc.type != type)
      fail(key, "accessor " + std::to_string(a) + " has componentType " + std::to_string(acc.componentType) + " type " +
                    std::to_string(acc.type) + ", expected " + std::to_string(component) + " type " +
                    std::to_string(type));
    if (n > 0 && acc.count != n)
      fail(key, "accessor " + std::to_string(a) + " has " + std::to_string(acc.count) + " elements, clusterCount is " +
                    std::to_string(n));
    return static_cast<int>(a);
  }

  template <typename T>
  std::vector<T> values(const std::string& key, int component, int type, std::size_t components, std::size_t n) const {
    const int a = accessor(key, component, type, n);
    const std::vector<unsigned char> bytes = read_accessor_bytes(m, a, components * sizeof(T), where + "/" + key);
    std::vector<T> out(bytes.size() / sizeof(T));
    if (!bytes.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
    if constexpr (std::is_floating_point_v<T>)
      for (std::size_t i = 0; i < out.size(); ++i)
        if (!std::isfinite(out[i])) fail(key, "element " + std::to_string(i / components) + " is not finite");
    return out;
  }
};

}  // namespace

void write_cluster_lod(tinygltf::Model& m, int mesh, int primitive, const lod::ClusterHierarchy& h,
                       std::span<const std::uint32_t> indices, std::size_t vertex_count) {
  const std::size_t n = h.size();
  Value::Object ext;
  ext["version"] = Value(kClusterLodVersion);
  ext["clusterCount"] = Value(static_cast<int>(n));
  int levels = 0;
  for (std::uint8_t d : h.depth) levels = std::max(levels, d + 1);
  ext["levelCount"] = Value(levels);
  if (vertex_count <= 65536) {  // 16-bit indices halve the index data when they fit
    const std::vector<std::uint16_t> short_indices(indices.begin(), indices.end());
    ext["indices"] =
        Value(add_accessor(m, short_indices.data(), 2 * short_indices.size(), TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                           TINYGLTF_TYPE_SCALAR, indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER));
  } else {
    ext["indices"] = Value(add_accessor(m, indices.data(), 4 * indices.size(), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                        TINYGLTF_TYPE_SCALAR, indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER));
  }
  std::vector<std::uint32_t> ranges;
  std::vector<float> errors;
  for (std::size_t c = 0; c < n; ++c) {
    ranges.insert(ranges.end(), {h.first_index[c], h.index_count[c]});
    errors.insert(errors.end(),
                  {h.self_error_m[c], std::isfinite(h.parent_error_m[c]) ? h.parent_error_m[c] : kStoredNoParentError});
  }
  const std::vector<float> self = spheres(h.self_center_x_m, h.self_center_y_m, h.self_center_z_m, h.self_radius_m);
  const std::vector<float> parent =
      spheres(h.parent_center_x_m, h.parent_center_y_m, h.parent_center_z_m, h.parent_radius_m);
  ext["ranges"] = Value(add_accessor(m, ranges.data(), 4 * ranges.size(), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                     TINYGLTF_TYPE_VEC2, n, 0));
  ext["selfSpheres"] =
      Value(add_accessor(m, self.data(), 4 * self.size(), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, n, 0));
  ext["parentSpheres"] =
      Value(add_accessor(m, parent.data(), 4 * parent.size(), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, n, 0));
  ext["errors"] =
      Value(add_accessor(m, errors.data(), 4 * errors.size(), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n, 0));
  ext["depths"] = Value(add_accessor(m, h.depth.data(), h.depth.size(), TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                     TINYGLTF_TYPE_SCALAR, n, 0));
  m.meshes[static_cast<std::size_t>(mesh)]
      .primitives[static_cast<std::size_t>(primitive)]
      .extensions[kClusterLodExtension] = Value(std::move(ext));
  if (std::find(m.extensionsUsed.begin(), m.extensionsUsed.end(), kClusterLodExtension) == m.extensionsUsed.end())
    m.extensionsUsed.push_back(kClusterLodExtension);
}

std::optional<ClusterLod> read_cluster_lod(const tinygltf::Model& m, int mesh, int primitive, const std::string& file) {
  const tinygltf::Primitive& p =
      m.meshes.at(static_cast<std::size_t>(mesh)).primitives.at(static_cast<std::size_t>(primitive));
  const auto it = p.extensions.find(kClusterLodExtension);
  if (it == p.extensions.end()) return std::nullopt;
  const Reader r{m,
                 file + ": /meshes/" + std::to_string(mesh) + "/primitives/" + std::to_string(primitive) +
                     "/extensions/" + kClusterLodExtension,
                 it->second};
  if (!r.ext.IsObject()) r.fail("", "must be an object");
  if (r.count("version") != kClusterLodVersion)
    r.fail("version",
           "is " + std::to_string(r.count("version")) + ", this reader knows " + std::to_string(kClusterLodVersion));
  const auto pos = p.attributes.find("POSITION");
  if (pos == p.attributes.end() || pos->second < 0 || static_cast<std::size_t>(pos->second) >= m.accessors.size())
    r.fail("", "the primitive has no POSITION accessor");
  ClusterLod out;
  out.vertex_count = static_cast<std::uint32_t>(m.accessors[static_cast<std::size_t>(pos->second)].count);
  const std::size_t n = r.count("clusterCount");
  out.levels = r.count("levelCount");
  if (n == 0) r.fail("clusterCount", "must be >= 1");
  // 16- or 32-bit, as the writer chose by vertex count.
  const std::uint32_t ia = r.count("indices");
  const bool short_indices =
      ia < m.accessors.size() && m.accessors[ia].componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  r.accessor("indices", short_indices ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
             TINYGLTF_TYPE_SCALAR, 0);
  out.indices = read_index_accessor(m, static_cast<int>(ia), out.vertex_count, r.where + "/indices");
  const auto ranges = r.values<std::uint32_t>("ranges", TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_VEC2, 2, n);
  const auto self = r.values<float>("selfSpheres", TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, 4, n);
  const auto parent = r.values<float>("parentSpheres", TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, 4, n);
  const auto errors = r.values<float>("errors", TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, 2, n);
  const auto depths =
      r.values<std::uint8_t>("depths", TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_SCALAR, 1, n);

  lod::ClusterHierarchy& h = out.hierarchy;
  for (std::size_t c = 0; c < n; ++c) {
    const std::string e = "element " + std::to_string(c);
    const std::uint64_t first = ranges[2 * c], count = ranges[2 * c + 1];
    if (count == 0 || count % 3 != 0 || first + count > out.indices.size())
      r.fail("ranges", e + ": first " + std::to_string(first) + ", count " + std::to_string(count) +
                           " is not whole triangles within the " + std::to_string(out.indices.size()) + " indices");
    const Sphere s{self[4 * c], self[4 * c + 1], self[4 * c + 2], self[4 * c + 3]};
    const Sphere q{parent[4 * c], parent[4 * c + 1], parent[4 * c + 2], parent[4 * c + 3]};
    if (s.radius_m < 0.0f) r.fail("selfSpheres", e + ": radius < 0");
    if (!sphere_contains(q, s)) r.fail("parentSpheres", e + ": does not contain the self sphere");
    const float self_error = errors[2 * c];
    const float parent_error = errors[2 * c + 1] >= kStoredNoParentError ? lod::kNoParentError : errors[2 * c + 1];
    if (!(self_error >= 0.0f && self_error <= parent_error))
      r.fail("errors", e + ": need 0 <= self error <= parent error, got " + std::to_string(self_error) + ", " +
                           std::to_string(errors[2 * c + 1]));
    if (depths[c] >= out.levels)
      r.fail("depths", e + ": " + std::to_string(depths[c]) + " >= levelCount " + std::to_string(out.levels));
    h.first_index.push_back(static_cast<std::uint32_t>(first));
    h.index_count.push_back(static_cast<std::uint32_t>(count));
    h.self_center_x_m.push_back(s.x), h.self_center_y_m.push_back(s.y), h.self_center_z_m.push_back(s.z);
    h.self_radius_m.push_back(s.radius_m), h.self_error_m.push_back(self_error);
    h.parent_center_x_m.push_back(q.x), h.parent_center_y_m.push_back(q.y), h.parent_center_z_m.push_back(q.z);
    h.parent_radius_m.push_back(q.radius_m), h.parent_error_m.push_back(parent_error);
    h.depth.push_back(depths[c]);
  }
  return out;
}

}  // namespace gazelod::bake
