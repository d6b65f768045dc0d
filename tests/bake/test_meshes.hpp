// SPDX-License-Identifier: Apache-2.0
// Meshes and scenes the bake tests generate themselves: an icosphere, a (wavy) grid, a soup of
// separate triangles, and a small scene with names, materials, a texture and transforms,
// written to .gltf or .glb with tinygltf.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::bake::testing {

struct TestMesh {
  std::vector<float> positions;  // xyz
  std::vector<std::uint32_t> indices;
  std::size_t triangles() const { return indices.size() / 3; }
};

// Subdivided icosahedron on a sphere of `radius_m`: 20 * 4^subdivisions triangles.
TestMesh icosphere(int subdivisions, double radius_m);
// n x n quads over [0, size]^2, z = amplitude * sin(2 pi x / size) * cos(2 pi y / size).
TestMesh grid(int n, double size_m, double amplitude_m);
// `count` separate triangles (no shared vertices) in a unit cube.
TestMesh triangle_soup(int count);

// The bytes of the scene's one image; the bake must keep them bit for bit.
std::vector<unsigned char> image_bytes();

// Scene: node 0 "Root" (translation 1,2,3; children 1, 2), node 1 "SphereNode" (mesh 0
// "Sphere" = icosphere(4, 0.5), scale 2, rotation 90 deg about z), node 2 "WavyNode" (mesh 1
// "Wavy": grid(32, 1, 0.05) split into two primitives with materials 0 and 1, matrix with
// translation 0,0,-4), node 3 "SphereCopy" (mesh 0, translation -5,0,0, extras {"tag": "keep"}).
// Material 0 "Red" has a base colour texture (texture 0 -> image 0, in a bufferView).
tinygltf::Model scene_model();
// One mesh "M" on one node "N" from `mesh` (POSITION + indices, mode TRIANGLES).
tinygltf::Model single_mesh_model(const TestMesh& mesh);

// Writes .glb when `path` ends in ".glb", else .gltf with embedded buffers. Returns `path`.
std::string write_model(const tinygltf::Model& model, const std::string& path);
// A fresh empty folder for one test (under the build tree).
std::string temp_dir(const std::string& test_name);

}  // namespace gazelod::bake::testing
