// SPDX-License-Identifier: Apache-2.0
// Buffer merging and image embedding (see gltf_pack.hpp).
#include "bake/gltf_pack.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace gazelod::bake {
namespace {

std::size_t align4(std::size_t n) {
  return (n + 3) & ~std::size_t{3};
}

std::string mime_from_uri(const std::string& uri) {
  std::string ext = uri.substr(uri.find_last_of('.') == std::string::npos ? uri.size() : uri.find_last_of('.') + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "png") return "image/png";
  if (ext == "jpg" || ext == "jpeg") return "image/jpeg";
  if (ext == "ktx2") return "image/ktx2";
  if (ext == "webp") return "image/webp";
  return "application/octet-stream";
}

}  // namespace

int append_buffer_view(tinygltf::Model& model, const void* bytes, std::size_t size, int target) {
  if (model.buffers.empty()) model.buffers.emplace_back();
  std::vector<unsigned char>& data = model.buffers[0].data;
  data.resize(align4(data.size()), 0);
  const std::size_t offset = data.size();
  data.resize(offset + size);
  if (size) std::memcpy(data.data() + offset, bytes, size);
  tinygltf::BufferView bv;
  bv.buffer = 0;
  bv.byteOffset = offset;
  bv.byteLength = size;
  bv.target = target;
  model.bufferViews.push_back(std::move(bv));
  return static_cast<int>(model.bufferViews.size() - 1);
}

std::vector<std::string> pack_single_buffer(tinygltf::Model& model) {
  std::vector<std::string> warnings;
  if (model.buffers.size() > 1 || (model.buffers.size() == 1 && !model.buffers[0].uri.empty())) {
    std::vector<std::size_t> offset(model.buffers.size());
    tinygltf::Buffer merged;
    merged.name = model.buffers[0].name;
    for (std::size_t i = 0; i < model.buffers.size(); ++i) {
      merged.data.resize(align4(merged.data.size()), 0);
      offset[i] = merged.data.size();
      merged.data.insert(merged.data.end(), model.buffers[i].data.begin(), model.buffers[i].data.end());
    }
    for (tinygltf::BufferView& bv : model.bufferViews) {
      if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= offset.size()) continue;
      bv.byteOffset += offset[static_cast<std::size_t>(bv.buffer)];
      bv.buffer = 0;
    }
    model.buffers.assign(1, std::move(merged));
  }
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    tinygltf::Image& im = model.images[i];
    // tinygltf clears the uri of a data: URI image it decoded: its bytes are all there is.
    if (im.bufferView >= 0 || (im.uri.empty() && im.image.empty())) continue;
    if (im.image.empty()) {
      warnings.push_back("image " + std::to_string(i) + " ('" + im.uri.substr(0, 80) +
                         "') could not be read; the output keeps the URI as a reference");
      continue;
    }
    if (im.mimeType.empty()) im.mimeType = mime_from_uri(im.uri);
    im.bufferView = append_buffer_view(model, im.image.data(), im.image.size(), 0);
    im.uri.clear();
    im.image.clear();
  }
  return warnings;
}

}  // namespace gazelod::bake
