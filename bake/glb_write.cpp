// Serialise to memory with tinygltf, then write + fsync-free rename (see glb_write.hpp).
#include "bake/glb_write.hpp"

#include "bake/bake_error.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::bake {
namespace {

// Never re-encode an image: every image is already a bufferView (gltf_pack) or a kept URI.
bool no_image_write(const std::string*, const std::string*, const tinygltf::Image*, bool,
                    std::string*, void*) {
  return false;
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
  const std::string bytes = glb.str();

  const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw OutputError(path + ": cannot write (" + std::strerror(errno) + ")");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();  // checked: a full disk may only show at close
    if (!out) {
      const std::string why = std::strerror(errno);
      fs::remove(tmp, ec);
      throw OutputError(path + ": write failed (" + why + ")");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    fs::remove(tmp, ec);
    throw OutputError(path + ": cannot replace the output (" + why + ")");
  }
}

}  // namespace gazelod::bake
