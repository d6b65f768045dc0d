// SPDX-License-Identifier: Apache-2.0
// Generators and writers for test_meshes.hpp.
#include "tests/bake/test_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace gazelod::bake::testing {
namespace {

int add_view(tinygltf::Model& m, const void* data, std::size_t size, int target) {
  if (m.buffers.empty()) m.buffers.emplace_back();
  auto& b = m.buffers[0].data;
  b.resize((b.size() + 3) & ~std::size_t{3});
  const std::size_t off = b.size();
  b.resize(off + size);
  std::memcpy(b.data() + off, data, size);
  tinygltf::BufferView v;
  v.buffer = 0, v.byteOffset = off, v.byteLength = size, v.target = target;
  m.bufferViews.push_back(v);
  return int(m.bufferViews.size() - 1);
}

int add_positions(tinygltf::Model& m, const std::vector<float>& p) {
  tinygltf::Accessor a;
  a.bufferView = add_view(m, p.data(), p.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER);
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT, a.type = TINYGLTF_TYPE_VEC3;
  a.count = p.size() / 3;
  a.minValues = {1e30, 1e30, 1e30}, a.maxValues = {-1e30, -1e30, -1e30};
  for (std::size_t i = 0; i < p.size(); ++i)
    a.minValues[i % 3] = std::min(a.minValues[i % 3], double(p[i])),
                    a.maxValues[i % 3] = std::max(a.maxValues[i % 3], double(p[i]));
  m.accessors.push_back(a);
  return int(m.accessors.size() - 1);
}

int add_indices(tinygltf::Model& m, const std::vector<std::uint32_t>& idx) {
  tinygltf::Accessor a;
  a.bufferView = add_view(m, idx.data(), idx.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, a.type = TINYGLTF_TYPE_SCALAR;
  a.count = idx.size();
  m.accessors.push_back(a);
  return int(m.accessors.size() - 1);
}

tinygltf::Primitive primitive(tinygltf::Model& m, const TestMesh& t, int material) {
  tinygltf::Primitive p;
  p.attributes["POSITION"] = add_positions(m, t.positions);
  std::vector<float> normals(t.positions.size());  // outward for the sphere; data, not checked
  for (std::size_t i = 0; i + 2 < normals.size(); i += 3) {
    const double l = std::hypot(t.positions[i], t.positions[i + 1], t.positions[i + 2]);
    for (int c = 0; c < 3; ++c) normals[i + c] = l > 0 ? float(t.positions[i + c] / l) : 0.f;
  }
  tinygltf::Accessor n = m.accessors[p.attributes["POSITION"]];
  n.bufferView = add_view(m, normals.data(), normals.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER);
  n.minValues.clear(), n.maxValues.clear();
  m.accessors.push_back(n);
  p.attributes["NORMAL"] = int(m.accessors.size() - 1);
  p.indices = add_indices(m, t.indices);
  p.material = material;
  p.mode = TINYGLTF_MODE_TRIANGLES;
  return p;
}

bool no_image_write(const std::string*, const std::string*, const tinygltf::Image*, bool, std::string*, void*) {
  return false;
}

}  // namespace

TestMesh icosphere(int subdivisions, double radius_m) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<double> v = {-1, t,  0,  1, t, 0,  -1, -t, 0,  1, -t, 0, 0,  -1, t,  0,  1, t,
                           0,  -1, -t, 0, 1, -t, t,  0,  -1, t, 0,  1, -t, 0,  -1, -t, 0, 1};
  std::vector<std::uint32_t> f = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                  4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                  6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      if (auto it = mid.find(key); it != mid.end()) return it->second;
      for (int c = 0; c < 3; ++c) v.push_back((v[3 * a + c] + v[3 * b + c]) / 2);
      return mid[key] = std::uint32_t(v.size() / 3 - 1);
    };
    std::vector<std::uint32_t> g;
    for (std::size_t i = 0; i < f.size(); i += 3) {
      const std::uint32_t a = f[i], b = f[i + 1], c = f[i + 2];
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      g.insert(g.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    f.swap(g);
  }
  TestMesh m;
  for (std::size_t i = 0; i < v.size(); i += 3) {
    const double l = std::hypot(v[i], v[i + 1], v[i + 2]);
    for (int c = 0; c < 3; ++c) m.positions.push_back(float(v[i + c] / l * radius_m));
  }
  m.indices = f;
  return m;
}

TestMesh grid(int n, double size_m, double amplitude_m) {
  TestMesh m;
  const double k = 2.0 * std::numbers::pi / size_m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = size_m * i / n, y = size_m * j / n;
      m.positions.insert(m.positions.end(),
                         {float(x), float(y), float(amplitude_m * std::sin(k * x) * std::cos(k * y))});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + (n + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  return m;
}

TestMesh triangle_soup(int count) {
  TestMesh m;
  std::uint32_t seed = 12345;
  auto rnd = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / float(1 << 24); };
  for (int t = 0; t < count; ++t) {
    const float x = rnd(), y = rnd(), z = rnd();
    m.positions.insert(m.positions.end(), {x, y, z, x + 0.01f, y, z, x, y + 0.01f, z});
    const auto b = std::uint32_t(3 * t);
    m.indices.insert(m.indices.end(), {b, b + 1, b + 2});
  }
  return m;
}

std::vector<unsigned char> image_bytes() {
  std::vector<unsigned char> b = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  for (int i = 0; i < 61; ++i) b.push_back(static_cast<unsigned char>(i * 37 + 11));
  return b;
}

tinygltf::Model scene_model() {
  tinygltf::Model m;
  m.asset.version = "2.0";
  const std::vector<unsigned char> img = image_bytes();
  tinygltf::Image image;
  image.name = "checker";
  image.mimeType = "image/png";
  image.bufferView = add_view(m, img.data(), img.size(), 0);
  m.images.push_back(image);
  tinygltf::Texture tex;
  tex.source = 0;
  m.textures.push_back(tex);
  tinygltf::Material red, blue;
  red.name = "Red";
  red.pbrMetallicRoughness.baseColorFactor = {1, 0, 0, 1};
  red.pbrMetallicRoughness.baseColorTexture.index = 0;
  blue.name = "Blue";
  blue.pbrMetallicRoughness.baseColorFactor = {0, 0, 1, 1};
  m.materials = {red, blue};

  tinygltf::Mesh sphere;
  sphere.name = "Sphere";
  sphere.primitives.push_back(primitive(m, icosphere(4, 0.5), 0));
  TestMesh g = grid(32, 1.0, 0.05), a, b;
  a.positions = b.positions = g.positions;
  const std::size_t half = g.indices.size() / 6 * 3;
  a.indices.assign(g.indices.begin(), g.indices.begin() + long(half));
  b.indices.assign(g.indices.begin() + long(half), g.indices.end());
  tinygltf::Mesh wavy;
  wavy.name = "Wavy";
  wavy.primitives.push_back(primitive(m, a, 0));
  wavy.primitives.push_back(primitive(m, b, 1));
  m.meshes = {sphere, wavy};

  tinygltf::Node root, sn, wn, copy;
  root.name = "Root", root.translation = {1, 2, 3}, root.children = {1, 2};
  sn.name = "SphereNode", sn.mesh = 0, sn.scale = {2, 2, 2};
  sn.rotation = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};
  wn.name = "WavyNode", wn.mesh = 1;
  wn.matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -4, 1};
  copy.name = "SphereCopy", copy.mesh = 0, copy.translation = {-5, 0, 0};
  copy.extras = tinygltf::Value(tinygltf::Value::Object{{"tag", tinygltf::Value(std::string("keep"))}});
  m.nodes = {root, sn, wn, copy};
  tinygltf::Scene scene;
  scene.name = "Main", scene.nodes = {0, 3};
  m.scenes = {scene};
  m.defaultScene = 0;
  return m;
}

tinygltf::Model single_mesh_model(const TestMesh& t) {
  tinygltf::Model m;
  m.asset.version = "2.0";
  tinygltf::Mesh mesh;
  mesh.name = "M";
  tinygltf::Primitive p;
  p.attributes["POSITION"] = add_positions(m, t.positions);
  p.indices = add_indices(m, t.indices);
  p.mode = TINYGLTF_MODE_TRIANGLES;
  mesh.primitives.push_back(p);
  m.meshes.push_back(mesh);
  tinygltf::Node n;
  n.name = "N", n.mesh = 0;
  m.nodes.push_back(n);
  tinygltf::Scene s;
  s.nodes = {0};
  m.scenes.push_back(s);
  m.defaultScene = 0;
  return m;
}

std::string write_model(const tinygltf::Model& model, const std::string& path) {
  tinygltf::TinyGLTF w;
  w.SetImageWriter(no_image_write, nullptr);
  const bool glb = path.size() >= 4 && path.substr(path.size() - 4) == ".glb";
  if (!w.WriteGltfSceneToFile(&model, path, true, true, !glb, glb))
    throw std::runtime_error("test could not write " + path);
  return path;
}

std::string temp_dir(const std::string& test_name) {
  namespace fs = std::filesystem;
  const fs::path d = fs::path(GAZELOD_BINARY_DIR) / "tests" / "bake" / "tmp" / test_name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

}  // namespace gazelod::bake::testing
