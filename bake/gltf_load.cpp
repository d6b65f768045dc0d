// SPDX-License-Identifier: Apache-2.0
// load_gltf: read the bytes, check a GLB's declared length against the file, then tinygltf.
#include "bake/gltf_load.hpp"

#include "bake/bake_error.hpp"
#include "bake/node_world.hpp"

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace gazelod::bake {
namespace {

// Limits that keep the recursive walks (tinygltf's JSON parser, the node walks of bake and
// run) off the end of the stack, far above what real files use.
constexpr std::size_t kMaxNodeDepth = 1024;
constexpr int kMaxJsonDepth = 256;

// tinygltf image callback: keep the encoded bytes as they are (Image::as_is).
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  if (size < 0 || (size > 0 && !bytes)) return false;
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

std::vector<unsigned char> read_all(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw BakeError(path + ": is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw BakeError(path + ": cannot open for reading (" + std::strerror(errno) + ")");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw BakeError(path + ": read error");
  if (bytes.empty()) throw BakeError(path + ": file is empty");
  return bytes;
}

// A glTF's external files are read through these instead of tinygltf's defaults, which expand
// `~` and environment variables in a uri and open whatever the path names.
struct UriPolicy {
  std::filesystem::path folder;  // canonical
  GltfLoadOptions options;
  std::vector<std::filesystem::path>* read = nullptr;  // every file read, resolved
};

bool uri_exists(const std::string&, void*) {
  return true;
}  // the reader says why it cannot
std::string uri_as_given(const std::string& path, void*) {
  return path;
}
bool no_writes(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;
}

// 4 GiB: what a glTF buffer's byteLength (uint32 in practice) can address.
constexpr std::uintmax_t kMaxExternalBytes = std::uintmax_t{1} << 32;

bool read_uri(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const UriPolicy& policy = *static_cast<const UriPolicy*>(user);
  auto fail = [&](const std::string& why) {
    if (err) *err += "external file '" + path + "': " + why + "\n";
    return false;
  };
  std::error_code ec;
  const std::filesystem::path real = std::filesystem::weakly_canonical(path, ec);
  if (ec) return fail("cannot resolve (" + ec.message() + ")");
  if (!policy.options.allow_outside_folder) {
    const auto rel = real.lexically_relative(policy.folder);
    if (rel.empty() || *rel.begin() == "..")
      return fail("outside the glTF's folder " + policy.folder.string() +
                  " (refused: copy it beside the glTF, or pass --allow-outside-uris)");
  }
  const auto status = std::filesystem::status(real, ec);
  if (ec || !std::filesystem::exists(status)) return fail("no such file");
  if (!std::filesystem::is_regular_file(status)) return fail("not a regular file (a directory, FIFO or device)");
  const std::uintmax_t size = std::filesystem::file_size(real, ec);
  if (ec) return fail("cannot read its size (" + ec.message() + ")");
  if (size > kMaxExternalBytes) return fail("larger than 4 GiB");
  std::ifstream in(real, std::ios::binary);
  if (!in) return fail(std::string("cannot open (") + std::strerror(errno) + ")");
  if (policy.read != nullptr) policy.read->push_back(real);
  out->resize(static_cast<std::size_t>(size));
  if (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size)))
    return fail("read error");
  return true;
}

// The scene graph both `bake` and `run --scene` rely on, checked once here: every index in
// range, no cycle, every transform finite and invertible. bake wrote such files with exit 0
// and run refused them (or, without these checks, would have drawn NaNs).
void check_scene_graph(const std::string& path, const tinygltf::Model& m) {
  const auto fail = [&](const std::string& where, const std::string& why) {
    throw BakeError(path + ": " + where + ": " + why);
  };
  const std::size_t nodes = m.nodes.size();
  for (std::size_t i = 0; i < nodes; ++i) {
    const tinygltf::Node& n = m.nodes[i];
    const std::string at = "/nodes/" + std::to_string(i);
    if (n.mesh >= 0 && static_cast<std::size_t>(n.mesh) >= m.meshes.size())
      fail(at + "/mesh",
           "no mesh " + std::to_string(n.mesh) + " (the file has " + std::to_string(m.meshes.size()) + ")");
    for (std::size_t k = 0; k < n.children.size(); ++k)
      if (n.children[k] < 0 || static_cast<std::size_t>(n.children[k]) >= nodes)
        fail(at + "/children/" + std::to_string(k), "no node " + std::to_string(n.children[k]));
    for (const std::vector<double>* v : {&n.matrix, &n.translation, &n.rotation, &n.scale})
      for (double x : *v)
        if (!std::isfinite(x)) fail(at, "a transform component is not finite");
    if (n.rotation.size() == 4 &&
        std::hypot(std::hypot(n.rotation[0], n.rotation[1]), std::hypot(n.rotation[2], n.rotation[3])) < 1e-6)
      fail(at + "/rotation", "a zero quaternion is no rotation (glTF requires a unit one)");
    const double det = glm::determinant(node_local_matrix(n));
    if (!std::isfinite(det)) fail(at, "scale or matrix too large: the transform's determinant overflows a double");
    if (std::abs(det) < 1e-300)
      fail(at, n.matrix.size() == 16 ? "matrix is singular (zero or collapsing scale): nothing could be drawn from it"
                                     : "scale or rotation collapses the node (a zero scale or rotation)");
  }
  // glTF 2.0: a node has at most one parent and a scene lists only roots. A node shared by two
  // parents (or listed twice by one) makes every walk over the graph visit it once per path:
  // 32 nodes each listing the next twice meant 2^32 visits.
  std::vector<int> parent(nodes, -1);
  for (std::size_t i = 0; i < nodes; ++i)
    for (std::size_t k = 0; k < m.nodes[i].children.size(); ++k) {
      const auto c = static_cast<std::size_t>(m.nodes[i].children[k]);
      if (parent[c] >= 0)
        fail("/nodes/" + std::to_string(i) + "/children/" + std::to_string(k),
             "node " + std::to_string(c) + " is already a child of node " + std::to_string(parent[c]) +
                 " (glTF 2.0: a node has at most one parent)");
      parent[c] = static_cast<int>(i);
    }
  // A cycle: a node reached again while it is on the current path (depth-first, iterative so a
  // deep chain cannot overflow the stack).
  std::vector<std::uint8_t> state(nodes, 0);  // 0 unseen, 1 on the path, 2 done
  for (std::size_t start = 0; start < nodes; ++start) {
    if (state[start] != 0) continue;
    std::vector<std::pair<std::size_t, std::size_t>> stack{{start, 0}};
    state[start] = 1;
    while (!stack.empty()) {
      auto& [node, next] = stack.back();
      const auto& children = m.nodes[node].children;
      if (next == children.size()) {
        state[node] = 2;
        stack.pop_back();
        continue;
      }
      const auto child = static_cast<std::size_t>(children[next++]);
      if (state[child] == 1)
        fail("/nodes/" + std::to_string(node) + "/children",
             "node graph has a cycle through node " + std::to_string(child));
      if (state[child] == 0) {
        state[child] = 1;
        stack.push_back({child, 0});
      }
    }
  }
  // Depth below the root, up the parent links (one each, no cycle): the walks after this one
  // recurse, so it is bounded (a chain of 20 000 nodes overflowed them; real scenes are tens
  // deep).
  std::vector<std::size_t> depth(nodes, 0);  // 0: not known yet; a root is 1
  std::vector<std::size_t> up;
  for (std::size_t i = 0; i < nodes; ++i) {
    std::size_t n = i;
    up.clear();
    while (depth[n] == 0 && parent[n] >= 0) {
      up.push_back(n);
      n = static_cast<std::size_t>(parent[n]);
    }
    if (depth[n] == 0) depth[n] = 1;  // a root
    for (auto it = up.rbegin(); it != up.rend(); ++it) {
      depth[*it] = depth[static_cast<std::size_t>(parent[*it])] + 1;
      if (depth[*it] > kMaxNodeDepth)
        fail("/nodes/" + std::to_string(*it),
             "node graph deeper than " + std::to_string(kMaxNodeDepth) + " levels (gazelod's limit)");
    }
  }
  for (std::size_t s = 0; s < m.scenes.size(); ++s)
    for (std::size_t k = 0; k < m.scenes[s].nodes.size(); ++k) {
      const int r = m.scenes[s].nodes[k];
      const std::string at = "/scenes/" + std::to_string(s) + "/nodes/" + std::to_string(k);
      if (r < 0 || static_cast<std::size_t>(r) >= nodes) fail(at, "no node " + std::to_string(r));
      if (parent[static_cast<std::size_t>(r)] >= 0)
        fail(at, "node " + std::to_string(r) + " is a child of node " +
                     std::to_string(parent[static_cast<std::size_t>(r)]) + ", not a root (glTF 2.0)");
    }
  if (m.defaultScene >= 0 && static_cast<std::size_t>(m.defaultScene) >= m.scenes.size())
    fail("/scene",
         "no scene " + std::to_string(m.defaultScene) + " (the file has " + std::to_string(m.scenes.size()) + ")");
}

std::uint32_t le32(const unsigned char* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

// Geometry compressed by an extension the file requires cannot be read without decoding it
// (tinygltf does not; it fails on the accessors, "accessor[0] invalid bufferView", or reads
// nothing): named up front instead.
void refuse_compressed_geometry(const std::string& path, const std::vector<unsigned char>& bytes, bool glb) {
  std::size_t begin = 0, end = bytes.size();
  if (glb) {
    if (bytes.size() < 20) return;
    begin = 20, end = std::min<std::size_t>(bytes.size(), 20 + std::size_t{le32(bytes.data() + 12)});
  }
  // tinygltf parses JSON recursively: 30 000 nested arrays in "extras" overflowed its stack.
  int depth = 0;
  const nlohmann::json::parser_callback_t deepest = [&](int d, nlohmann::json::parse_event_t, nlohmann::json&) {
    depth = std::max(depth, d);
    return true;
  };
  const nlohmann::json doc = nlohmann::json::parse(bytes.begin() + static_cast<std::ptrdiff_t>(begin),
                                                   bytes.begin() + static_cast<std::ptrdiff_t>(end), deepest, false);
  if (depth > kMaxJsonDepth)
    throw BakeError(path + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                    " levels of arrays and objects (gazelod's limit; glTF itself needs about 8)");
  if (!doc.is_object()) return;  // tinygltf says what is wrong with it
  // tinygltf reads a glTF 1.0 file (objects keyed by id where 2.0 has arrays) as a 2.0 one
  // with nothing in it, and the bake then said "nothing to bake".
  if (const auto asset = doc.find("asset"); asset != doc.end() && asset->is_object())
    if (const auto v = asset->find("version"); v != asset->end() && v->is_string()) {
      const std::string version = v->get<std::string>();
      if (version.rfind("2.", 0) != 0)
        throw BakeError(path + ": /asset/version: \"" + version +
                        "\": gazelod reads glTF 2.0 only; convert the file to glTF 2.0 first");
    }
  const auto required = doc.find("extensionsRequired");
  if (required == doc.end() || !required->is_array()) return;
  for (const nlohmann::json& e : *required)
    for (const char* compressed : {"KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_meshopt_compression"})
      if (e.is_string() && e.get<std::string>() == compressed)
        throw BakeError(path + ": /extensionsRequired: " + compressed +
                        " (compressed geometry), which gazelod does not decode; decompress the file first");
}

}  // namespace

LoadedGltf load_gltf(const std::string& path, GltfLoadOptions options) {
  const std::vector<unsigned char> bytes = read_all(path);
  const bool glb = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (glb) {
    if (bytes.size() < 20)
      throw BakeError(path + ": truncated GLB: " + std::to_string(bytes.size()) + " bytes, the header alone needs 20");
    if (const std::uint32_t version = le32(bytes.data() + 4); version != 2)
      throw BakeError(path + ": GLB container version " + std::to_string(version) +
                      " (byte 4): gazelod reads glTF 2.0 (GLB version 2) only; convert the file first");
    const std::uint32_t declared = le32(bytes.data() + 8);
    if (declared > bytes.size())
      throw BakeError(path + ": truncated GLB: header (byte 8) declares " + std::to_string(declared) +
                      " bytes, file has " + std::to_string(bytes.size()));
  }
  if (bytes.size() > UINT32_MAX) throw BakeError(path + ": larger than 4 GiB");

  refuse_compressed_geometry(path, bytes, glb);

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_bytes, nullptr);
  LoadedGltf out;
  std::string err, warn;
  std::string base_dir = std::filesystem::path(path).parent_path().string();
  if (base_dir.empty()) base_dir = ".";
  std::error_code ec;
  UriPolicy policy{std::filesystem::weakly_canonical(base_dir, ec), options, &out.external_files};
  if (ec) throw BakeError(path + ": cannot resolve its folder (" + ec.message() + ")");
  tinygltf::FsCallbacks fs{&uri_exists, &uri_as_given, &read_uri, &no_writes, &policy};
  loader.SetFsCallbacks(fs);
  const auto n = static_cast<unsigned int>(bytes.size());
  const bool ok = glb ? loader.LoadBinaryFromMemory(&out.model, &err, &warn, bytes.data(), n, base_dir)
                      : loader.LoadASCIIFromString(&out.model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                   n, base_dir);
  if (!ok || !err.empty())
    throw BakeError(path + ": " + (glb ? "invalid GLB: " : "invalid glTF: ") +
                    (err.empty() ? std::string("tinygltf rejected the file") : trim(err)));
  // tinygltf reads a mesh whose "primitives" is not an array as a mesh without primitives;
  // glTF requires at least one (and a bake would write an invalid mesh back).
  check_scene_graph(path, out.model);
  for (std::size_t i = 0; i < out.model.meshes.size(); ++i)
    if (out.model.meshes[i].primitives.empty())
      throw BakeError(path + ": /meshes/" + std::to_string(i) +
                      "/primitives: a mesh needs at least one primitive (missing, empty or not an "
                      "array)");
  std::istringstream w(warn);
  for (std::string line; std::getline(w, line);)
    if (!line.empty()) out.warnings.push_back(path + ": " + line);
  return out;
}

void refuse_output_over_input(const std::string& in, const LoadedGltf& loaded, const std::string& out) {
  std::error_code ec;
  const std::filesystem::path target = std::filesystem::weakly_canonical(out, ec);
  if (ec) return;  // the write says what is wrong with the path
  for (const std::filesystem::path& f : loaded.external_files) {
    std::error_code same_ec;
    if (f == target || std::filesystem::equivalent(f, target, same_ec))
      throw BakeError(out + ": is " + f.string() + ", which " + in +
                      " reads (a buffer or image): the bake would write over its own input; write it elsewhere");
  }
}

}  // namespace gazelod::bake
