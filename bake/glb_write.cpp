// SPDX-License-Identifier: Apache-2.0
// Serialise to memory with tinygltf, then write it as every output is written
// (auxiliary/atomic_file.hpp: a temporary beside it, fsync, rename; see glb_write.hpp).
#include "bake/glb_write.hpp"

#include "auxiliary/atomic_file.hpp"
#include "bake/bake_error.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <sstream>

namespace gazelod::bake {
namespace {

// Never re-encode an image: every image is already a bufferView (gltf_pack) or a kept URI.
bool no_image_write(const std::string*, const std::string*, const tinygltf::Image*, bool, std::string*, void*) {
  return false;
}

std::uint32_t le32(const char* p) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(p[k]);
  return v;
}
void put_le32(std::string& s, std::size_t at, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) s[at + static_cast<std::size_t>(k)] = static_cast<char>((v >> (8 * k)) & 0xffu);
}

// tinygltf writes an object with nothing to say (a node or scene of no properties: `{}` in the
// input) as null, which glTF forbids. The GLB's JSON chunk gets `{}` back where a top-level
// array of objects holds null; the rest of the file is unchanged (re-serialised only then).
std::string fill_empty_objects(std::string glb, const std::string& path) {
  if (glb.size() < 20 || glb.compare(16, 4, "JSON") != 0)
    throw OutputError(path + ": tinygltf wrote no GLB JSON chunk");
  const std::size_t json_length = le32(glb.data() + 12);
  if (20 + json_length > glb.size()) throw OutputError(path + ": tinygltf wrote a short GLB");
  nlohmann::json doc =
      nlohmann::json::parse(glb.begin() + 20, glb.begin() + 20 + static_cast<std::ptrdiff_t>(json_length));
  bool changed = false;
  for (const char* key : {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
                          "meshes", "nodes", "samplers", "scenes", "skins", "textures"}) {
    const auto it = doc.find(key);
    if (it == doc.end() || !it->is_array()) continue;
    for (nlohmann::json& element : *it)
      if (element.is_null()) element = nlohmann::json::object(), changed = true;
  }
  if (!changed) return glb;
  std::string json = aux::json_text(doc);
  json.resize((json.size() + 3) & ~std::size_t{3}, ' ');  // GLB chunks are 4-byte aligned
  std::string out = glb.substr(0, 20) + json + glb.substr(20 + json_length);
  put_le32(out, 8, static_cast<std::uint32_t>(out.size()));
  put_le32(out, 12, static_cast<std::uint32_t>(json.size()));
  return out;
}

}  // namespace

void write_glb_atomic(const tinygltf::Model& model, const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw OutputError(path + ": output is a directory");
  const fs::path dir = fs::path(path).parent_path();
  if (!dir.empty() && !fs::is_directory(dir, ec))
    throw OutputError(path + ": output folder '" + dir.string() + "' does not exist");

  tinygltf::TinyGLTF writer;
  writer.SetImageWriter(no_image_write, nullptr);
  std::ostringstream glb;
  if (!writer.WriteGltfSceneToStream(&model, glb, false, true))
    throw OutputError(path + ": tinygltf could not serialise the model");
  const std::string bytes = fill_empty_objects(glb.str(), path);

  try {
    aux::write_file_atomic(path, bytes);
  } catch (const aux::WriteError& e) {
    throw OutputError(path + ": " + e.reason());
  }
}

}  // namespace gazelod::bake
