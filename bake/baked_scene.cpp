// SPDX-License-Identifier: Apache-2.0
// load_baked_scene: scene traversal with world matrices, chain reading, bounding spheres.
#include "bake/baked_scene.hpp"

#include "bake/bake_error.hpp"
#include "bake/cluster/cluster_lod_gltf.hpp"
#include "bake/gltf_load.hpp"
#include "bake/mesh_extract.hpp"
#include "bake/node_world.hpp"
#include "lod/object_set.hpp"

#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gazelod::bake {
namespace {

using tinygltf::Value;

struct Reader {
  const std::string& path;
  const tinygltf::Model& m;
  const std::vector<BakedClusterMesh>& clusters;
  const std::vector<int>& cluster_mesh_of;  // per mesh: index into `clusters`, or -1
  bool level_geometry = false;

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw BakeError(path + ": " + where + ": " + what);
  }

  const Value& member(const Value& obj, const std::string& key, const std::string& where) const {
    if (!obj.IsObject() || !obj.Has(key)) fail(where + "/" + key, "missing");
    return obj.Get(key);
  }

  double number(const Value& obj, const std::string& key, const std::string& where) const {
    const Value& v = member(obj, key, where);
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble())) fail(where + "/" + key, "must be a finite number");
    return v.GetNumberAsDouble();
  }

  lod::LodLevel level(int node, int expect_level) const {
    const std::string where = "/nodes/" + std::to_string(node) + "/extras/gazelod_lod";
    const tinygltf::Node& n = m.nodes[static_cast<std::size_t>(node)];
    if ((!n.extras.IsObject() || !n.extras.Has("gazelod_lod")) && expect_level == 0 &&
        cluster_mesh_of[static_cast<std::size_t>(n.mesh)] >= 0)
      return full_mesh_level(clusters[static_cast<std::size_t>(cluster_mesh_of[static_cast<std::size_t>(n.mesh)])]);
    if (!n.extras.IsObject() || !n.extras.Has("gazelod_lod"))
      fail(where, "missing: --scene takes what gazelod bake writes (gazelod bake IN OUT.glb, or bake --clusters)");
    const Value& e = n.extras.Get("gazelod_lod");
    if (!e.IsObject()) fail(where, "must be an object");
    if (number(e, "level", where) != expect_level) fail(where + "/level", "expected " + std::to_string(expect_level));
    const double tri = number(e, "triangles", where);
    double det = number(e, "detail_cycles_per_diameter", where);
    // A rendered profile (bake --profile, Reddy's method) is preferred to the geometric estimate.
    if (e.Has("rendered_cycles_per_diameter")) {
      det = number(e, "rendered_cycles_per_diameter", where);
      if (det < 0.0) fail(where + "/rendered_cycles_per_diameter", "must be >= 0");
    }
    if (!(tri >= 1.0 && tri <= 4294967295.0) || tri != std::floor(tri))
      fail(where + "/triangles", "must be a whole number >= 1");
    if (det < 0.0) fail(where + "/detail_cycles_per_diameter", "must be >= 0");
    lod::LodLevel l;
    l.triangles = static_cast<std::uint32_t>(tri);
    const double verts = e.Has("vertices") ? number(e, "vertices", where) : 0.0;
    l.vertices = verts >= 0.0 && verts <= 4294967295.0 ? static_cast<std::uint32_t>(verts) : 0;
    l.detail_kind = lod::DetailKind::removed_cycles_per_diameter;
    l.detail = expect_level == 0 ? 0.0 : det;
    return l;
  }

  // A --clusters bake has no chain: one level, the source triangles of every hierarchy.
  static lod::LodLevel full_mesh_level(const BakedClusterMesh& c) {
    lod::LodLevel l;
    for (const BakedClusterPrimitive& p : c.primitives) {
      for (std::size_t k = 0; k < p.hierarchy.size(); ++k)
        if (p.hierarchy.depth[k] == 0) l.triangles += p.hierarchy.index_count[k] / 3;
      l.vertices += p.vertex_count;
    }
    l.detail_kind = lod::DetailKind::removed_cycles_per_diameter;
    return l;
  }

  // The mesh's triangle primitives as one list (vertices of later primitives after earlier ones).
  BakedLevelMesh level_mesh(int mesh) const {
    BakedLevelMesh out;
    for (std::size_t p = 0; p < m.meshes[static_cast<std::size_t>(mesh)].primitives.size(); ++p) {
      // Points and lines (bake --clusters carries them over) have no levels: not drawn here.
      if (!draws_triangles(m.meshes[static_cast<std::size_t>(mesh)].primitives[p])) continue;
      PrimitiveGeometry g;
      try {
        g = extract_primitive(m, mesh, static_cast<int>(p));
      } catch (const BakeError& e) {
        throw BakeError(path + ": " + e.what());
      }
      const std::size_t base = out.positions_xyz.size() / 3;
      if (base + g.positions_xyz.size() / 3 > 0xffffffffu)
        fail(primitive_label(m, mesh, static_cast<int>(p)), "the mesh has more than 2^32 - 1 vertices");
      out.positions_xyz.insert(out.positions_xyz.end(), g.positions_xyz.begin(), g.positions_xyz.end());
      for (std::uint32_t i : g.indices) out.indices.push_back(static_cast<std::uint32_t>(base + i));
    }
    return out;
  }

  // World-space sphere around the box centre of the transformed full-detail positions.
  void sphere(int node, const glm::dmat4& world, BakedObject& o) const {
    const tinygltf::Mesh& mesh = m.meshes[static_cast<std::size_t>(m.nodes[static_cast<std::size_t>(node)].mesh)];
    std::vector<glm::dvec3> pts;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const auto it = mesh.primitives[p].attributes.find("POSITION");
      const std::string where = "/nodes/" + std::to_string(node) + " mesh primitive " + std::to_string(p);
      if (it == mesh.primitives[p].attributes.end()) fail(where, "has no POSITION");
      const std::vector<float> xyz = read_positions(m, it->second, path + ": " + where);
      for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
        pts.push_back(glm::dvec3(world * glm::dvec4(xyz[i], xyz[i + 1], xyz[i + 2], 1.0)));
        // The node's transform (its scale, matrix or translation, or a parent's) can put a
        // vertex past any meaningful distance, or make it inf or NaN (1e200 squared): the
        // sphere would then be NaN, so the node is named here.
        const glm::dvec3& q = pts.back();
        for (int c = 0; c < 3; ++c)
          if (!std::isfinite(q[c]) || std::fabs(q[c]) > kMaxPositionM) {
            std::ostringstream msg;
            msg << "vertex " << i / 3 << " of its mesh's primitive " << p << " lands at " << q[c]
                << " m in the world (at most " << kMaxPositionM
                << " m): check the scale, rotation, translation or matrix of this node and its parents";
            fail("/nodes/" + std::to_string(node), msg.str());
          }
      }
    }
    if (pts.empty()) return;
    glm::dvec3 lo = pts[0], hi = pts[0];
    for (const auto& q : pts) lo = glm::min(lo, q), hi = glm::max(hi, q);
    o.center_m = (lo + hi) * 0.5;
    double r2 = 0.0;
    for (const auto& q : pts) r2 = std::max(r2, glm::dot(q - o.center_m, q - o.center_m));
    o.radius_m = std::sqrt(r2);
  }

  void object(int node, const glm::dmat4& world, std::vector<BakedObject>& out) const {
    const tinygltf::Node& n = m.nodes[static_cast<std::size_t>(node)];
    BakedObject o;
    o.node = node;
    o.mesh = n.mesh;
    o.name = n.name.empty() ? "node " + std::to_string(node) : n.name;
    o.lods.push_back(level(node, 0));
    std::vector<int> meshes{n.mesh};
    const auto ext = n.extensions.find("MSFT_lod");
    if (ext != n.extensions.end()) {
      const std::string where = "/nodes/" + std::to_string(node) + "/extensions/MSFT_lod/ids";
      const Value& ids = member(ext->second, "ids", "/nodes/" + std::to_string(node) + "/extensions/MSFT_lod");
      if (!ids.IsArray()) fail(where, "must be an array");
      for (std::size_t k = 0; k < ids.ArrayLen(); ++k) {
        const Value& id = ids.Get(static_cast<int>(k));
        const std::string w = where + "/" + std::to_string(k);
        if (!id.IsInt() || id.GetNumberAsInt() < 0 || static_cast<std::size_t>(id.GetNumberAsInt()) >= m.nodes.size())
          fail(w, "not a node index");
        if (m.nodes[static_cast<std::size_t>(id.GetNumberAsInt())].mesh < 0) fail(w, "node has no mesh");
        o.lods.push_back(level(id.GetNumberAsInt(), static_cast<int>(k + 1)));
        meshes.push_back(m.nodes[static_cast<std::size_t>(id.GetNumberAsInt())].mesh);
      }
    }
    if (std::string e = lod::validate_chain(o.lods); !e.empty())
      fail("/nodes/" + std::to_string(node), "LOD chain: " + e);
    if (level_geometry)
      for (std::size_t l = 0; l < meshes.size(); ++l) {
        const int mesh = meshes[l];
        if (static_cast<std::size_t>(mesh) >= m.meshes.size()) fail("/meshes", "no mesh " + std::to_string(mesh));
        o.level_meshes.push_back(level_mesh(mesh));
        // A baked chain's level must be the level drawn (a primitive turned to points or lines
        // is no longer drawn, and the report's triangles would be wrong). A cluster mesh's one
        // level counts its hierarchy's triangles, without the degenerate ones the bake dropped.
        const std::size_t drawn = o.level_meshes.back().indices.size() / 3;
        if (cluster_mesh_of[static_cast<std::size_t>(mesh)] < 0 && drawn != o.lods[l].triangles)
          throw BakeError(path + ": " + mesh_label(m, mesh) + ": level " + std::to_string(l) + " draws " +
                          std::to_string(drawn) + " triangles, its chain says " + std::to_string(o.lods[l].triangles));
      }
    sphere(node, world, o);
    o.world = world;
    out.push_back(std::move(o));
  }

  void visit(int node, const glm::dmat4& parent, std::vector<bool>& on_path, std::vector<BakedObject>& out) const {
    if (node < 0 || static_cast<std::size_t>(node) >= m.nodes.size())
      fail("/nodes", "reference to missing node " + std::to_string(node));
    if (on_path[static_cast<std::size_t>(node)]) fail("/nodes/" + std::to_string(node), "node graph has a cycle");
    on_path[static_cast<std::size_t>(node)] = true;
    const tinygltf::Node& n = m.nodes[static_cast<std::size_t>(node)];
    const glm::dmat4 world = parent * node_local_matrix(n);
    if (n.mesh >= 0) {
      if (static_cast<std::size_t>(n.mesh) >= m.meshes.size())
        fail("/nodes/" + std::to_string(node) + "/mesh", "no such mesh");
      // A mesh of points or lines only, which bake --clusters carries over unbaked: no object.
      const auto& prims = m.meshes[static_cast<std::size_t>(n.mesh)].primitives;
      if (std::any_of(prims.begin(), prims.end(), [](const tinygltf::Primitive& p) { return draws_triangles(p); }))
        object(node, world, out);
    }
    for (int c : n.children) visit(c, world, on_path, out);
    on_path[static_cast<std::size_t>(node)] = false;
  }
};

}  // namespace

const BakedClusterMesh* BakedScene::clusters_of(const BakedObject& object) const {
  for (const BakedClusterMesh& c : cluster_meshes)
    if (c.mesh == object.mesh) return &c;
  return nullptr;
}

BakedScene load_baked(const std::string& path, BakedLoad what) {
  LoadedGltf g = load_gltf(path);
  BakedScene scene;
  std::vector<int> cluster_mesh_of(g.model.meshes.size(), -1);
  for (std::size_t mi = 0; mi < g.model.meshes.size(); ++mi) {
    BakedClusterMesh c;
    c.mesh = static_cast<int>(mi);
    c.name = g.model.meshes[mi].name;
    for (std::size_t p = 0; p < g.model.meshes[mi].primitives.size(); ++p)
      if (auto lod = read_cluster_lod(g.model, c.mesh, static_cast<int>(p), path)) {
        // read_cluster_lod found POSITION; the cluster indices point into these vertices.
        const std::string where = path + ": /meshes/" + std::to_string(mi) + "/primitives/" + std::to_string(p);
        std::vector<float> xyz =
            read_positions(g.model, g.model.meshes[mi].primitives[p].attributes.at("POSITION"), where);
        if (xyz.size() != 3 * std::size_t{lod->vertex_count})
          throw BakeError(where + ": POSITION has " + std::to_string(xyz.size() / 3) + " vertices, expected " +
                          std::to_string(lod->vertex_count));
        c.primitives.push_back({static_cast<int>(p), lod->vertex_count, lod->levels, std::move(lod->hierarchy),
                                std::move(lod->indices), std::move(xyz)});
      }
    if (c.primitives.empty()) continue;
    cluster_mesh_of[mi] = static_cast<int>(scene.cluster_meshes.size());
    scene.cluster_meshes.push_back(std::move(c));
  }
  const Reader r{path, g.model, scene.cluster_meshes, cluster_mesh_of, what == BakedLoad::with_level_geometry};
  std::vector<bool> on_path(g.model.nodes.size(), false);
  const auto& scenes = g.model.scenes;
  for (std::size_t s = 0; s < scenes.size(); ++s) {
    if (g.model.defaultScene >= 0 && static_cast<int>(s) != g.model.defaultScene) continue;
    for (int root : scenes[s].nodes) r.visit(root, glm::dmat4(1.0), on_path, scene.objects);
  }
  if (scene.objects.empty()) throw BakeError(path + ": /scenes: no node with a mesh in the scene");
  return scene;
}

std::vector<BakedObject> load_baked_scene(const std::string& path) {
  return load_baked(path).objects;
}

}  // namespace gazelod::bake
