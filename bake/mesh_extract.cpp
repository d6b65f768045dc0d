// SPDX-License-Identifier: Apache-2.0
// Accessor reading with explicit bounds checks: a malformed file must give a message, not a
// read past the buffer (tinygltf does not check accessor ranges).
#include "bake/mesh_extract.hpp"

#include "bake/bake_error.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <sstream>

namespace gazelod::bake {
namespace {

const char* mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "POINTS";
    case TINYGLTF_MODE_LINE:
      return "LINES";
    case TINYGLTF_MODE_LINE_LOOP:
      return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP:
      return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_STRIP:
      return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN:
      return "TRIANGLE_FAN";
    default:
      return "unknown";
  }
}

// The checked byte range of an accessor: first element and stride.
struct View {
  const unsigned char* first = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
};

View checked_view(const tinygltf::Model& m, int accessor, std::size_t element_size, const std::string& where) {
  const std::string a_where = where + " (accessor " + std::to_string(accessor) + ")";
  if (accessor < 0 || static_cast<std::size_t>(accessor) >= m.accessors.size())
    throw BakeError(a_where + ": no such accessor");
  const tinygltf::Accessor& a = m.accessors[accessor];
  if (a.sparse.isSparse) throw BakeError(a_where + ": sparse accessors are not supported");
  if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= m.bufferViews.size())
    throw BakeError(a_where + ": has no bufferView (all-zero data is not supported)");
  const tinygltf::BufferView& bv = m.bufferViews[a.bufferView];
  if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= m.buffers.size())
    throw BakeError(a_where + ": bufferView " + std::to_string(a.bufferView) + " has no buffer");
  const std::vector<unsigned char>& data = m.buffers[bv.buffer].data;
  const std::size_t stride = bv.byteStride ? bv.byteStride : element_size;
  if (stride < element_size)
    throw BakeError(a_where + ": byteStride " + std::to_string(stride) + " < element size " +
                    std::to_string(element_size));
  // Checked in this order so that no product can overflow.
  const bool past_end =
      bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset ||
      (a.count > 0 && (a.byteOffset > bv.byteLength || (a.count - 1) > (bv.byteLength - a.byteOffset) / stride ||
                       a.byteOffset + stride * (a.count - 1) + element_size > bv.byteLength));
  if (past_end)
    throw BakeError(a_where + ": reads past the end of its bufferView " + std::to_string(a.bufferView) + " / buffer " +
                    std::to_string(bv.buffer) + " (truncated data?)");
  return {data.data() + bv.byteOffset + a.byteOffset, stride, a.count};
}

}  // namespace

std::vector<std::uint32_t> read_index_accessor(const tinygltf::Model& m, int accessor, std::size_t vertex_count,
                                               const std::string& where) {
  if (accessor < 0 || static_cast<std::size_t>(accessor) >= m.accessors.size())
    throw BakeError(where + ": indices accessor " + std::to_string(accessor) + " does not exist");
  const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(accessor));
  std::size_t size = 0;
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      size = 1;
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      size = 2;
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      size = 4;
      break;
    default:
      throw BakeError(where + ": indices accessor " + std::to_string(accessor) + " has component type " +
                      std::to_string(a.componentType) + " (need unsigned byte/short/int)");
  }
  if (a.type != TINYGLTF_TYPE_SCALAR)
    throw BakeError(where + ": indices accessor " + std::to_string(accessor) + " is not SCALAR");
  const View v = checked_view(m, accessor, size, where + " indices");
  std::vector<std::uint32_t> out(v.count);
  for (std::size_t i = 0; i < v.count; ++i) {
    const unsigned char* p = v.first + i * v.stride;
    std::uint32_t x = 0;
    if (size == 1)
      x = p[0];
    else if (size == 2) {
      std::uint16_t s;
      std::memcpy(&s, p, 2);
      x = s;
    } else
      std::memcpy(&x, p, 4);
    if (x >= vertex_count)
      throw BakeError(where + ": index " + std::to_string(i) + " is " + std::to_string(x) + ", but there are only " +
                      std::to_string(vertex_count) + " vertices");
    out[i] = x;
  }
  return out;
}

std::vector<unsigned char> read_accessor_bytes(const tinygltf::Model& m, int accessor, std::size_t element_size,
                                               const std::string& where) {
  const View v = checked_view(m, accessor, element_size, where);
  std::vector<unsigned char> out(v.count * element_size);
  for (std::size_t i = 0; i < v.count; ++i)
    std::memcpy(out.data() + i * element_size, v.first + i * v.stride, element_size);
  return out;
}

std::vector<std::uint32_t> strip_to_list(const std::vector<std::uint32_t>& s) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i + 2 < s.size(); ++i)  // every other triangle flips, keeping the winding
    out.insert(out.end(), {s[i], s[i + 1 + i % 2], s[i + 2 - i % 2]});
  return out;
}

std::vector<std::uint32_t> fan_to_list(const std::vector<std::uint32_t>& f) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i + 2 < f.size(); ++i) out.insert(out.end(), {f[i + 1], f[i + 2], f[0]});
  return out;
}

std::string mesh_label(const tinygltf::Model& model, int mesh) {
  std::string s = "mesh " + std::to_string(mesh);
  if (mesh >= 0 && static_cast<std::size_t>(mesh) < model.meshes.size() && !model.meshes[mesh].name.empty())
    s += " '" + model.meshes[mesh].name + "'";
  return s;
}

std::string primitive_label(const tinygltf::Model& model, int mesh, int primitive) {
  return mesh_label(model, mesh) + " primitive " + std::to_string(primitive);
}

std::vector<float> read_positions(const tinygltf::Model& m, int accessor, const std::string& where) {
  if (accessor < 0 || static_cast<std::size_t>(accessor) >= m.accessors.size())
    throw BakeError(where + ": POSITION accessor " + std::to_string(accessor) + " does not exist");
  const tinygltf::Accessor& a = m.accessors[accessor];
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.type != TINYGLTF_TYPE_VEC3)
    throw BakeError(where + ": POSITION accessor " + std::to_string(accessor) +
                    " must be float VEC3 (quantized positions are not supported)");
  const View v = checked_view(m, accessor, 12, where + " POSITION");
  std::vector<float> out(3 * v.count);
  for (std::size_t i = 0; i < v.count; ++i) {
    std::memcpy(&out[3 * i], v.first + i * v.stride, 12);
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(out[3 * i + c])) throw BakeError(where + ": POSITION " + std::to_string(i) + " is not finite");
      if (std::fabs(out[3 * i + c]) > kMaxPositionM) {
        std::ostringstream msg;
        msg << where << ": POSITION " << i << " is out of range: a coordinate of " << out[3 * i + c] << " m (at most "
            << kMaxPositionM << " m)";
        throw BakeError(msg.str());
      }
    }
  }
  return out;
}

bool draws_triangles(const tinygltf::Primitive& p) {
  return p.mode == TINYGLTF_MODE_TRIANGLES || p.mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
         p.mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

std::string mode_label(int mode) {
  return "mode " + std::to_string(mode) + " (" + mode_name(mode) + ")";
}

std::size_t count_area_triangles(const PrimitiveGeometry& g) {
  const auto at = [&](std::uint32_t i) {
    return std::array<float, 3>{g.positions_xyz[3 * i], g.positions_xyz[3 * i + 1], g.positions_xyz[3 * i + 2]};
  };
  std::size_t n = 0;
  for (std::size_t t = 0; t + 2 < g.indices.size(); t += 3) {
    const auto a = at(g.indices[t]), b = at(g.indices[t + 1]), c = at(g.indices[t + 2]);
    n += a != b && b != c && a != c ? 1 : 0;
  }
  return n;
}

PrimitiveGeometry extract_primitive(const tinygltf::Model& m, int mesh, int primitive) {
  const std::string where = primitive_label(m, mesh, primitive);
  const tinygltf::Primitive& p =
      m.meshes.at(static_cast<std::size_t>(mesh)).primitives.at(static_cast<std::size_t>(primitive));
  if (!draws_triangles(p))
    throw BakeError(where + ": " + mode_label(p.mode) +
                    " is not supported; only triangles (TRIANGLES 4, TRIANGLE_STRIP 5, "
                    "TRIANGLE_FAN 6) can be simplified");
  const auto pos = p.attributes.find("POSITION");
  if (pos == p.attributes.end()) throw BakeError(where + ": has no POSITION attribute");
  PrimitiveGeometry g;
  g.positions_xyz = read_positions(m, pos->second, where);
  const std::size_t vcount = g.positions_xyz.size() / 3;
  if (p.indices >= 0) {
    g.indices = read_index_accessor(m, p.indices, vcount, where);
  } else {
    g.indices.resize(vcount);
    for (std::size_t i = 0; i < vcount; ++i) g.indices[i] = static_cast<std::uint32_t>(i);
  }
  if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) g.indices = strip_to_list(g.indices);
  if (p.mode == TINYGLTF_MODE_TRIANGLE_FAN) g.indices = fan_to_list(g.indices);
  if (g.indices.size() % 3 != 0)
    throw BakeError(where + ": " + std::to_string(g.indices.size()) + " indices is not a whole number of triangles");
  check_carried_accessors(m, mesh, primitive);
  return g;
}

void check_carried_accessors(const tinygltf::Model& m, int mesh, int primitive) {
  const std::string where = primitive_label(m, mesh, primitive);
  const tinygltf::Primitive& p =
      m.meshes.at(static_cast<std::size_t>(mesh)).primitives.at(static_cast<std::size_t>(primitive));
  // The vertex count every attribute must have (glTF 2.0 3.7.2.1): POSITION's, else the first's.
  std::size_t vcount = 0;
  bool have_count = false;
  const auto count_of = [&](const std::string& name, int accessor) {
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= m.accessors.size())
      throw BakeError(where + ": " + name + " accessor " + std::to_string(accessor) + " does not exist");
    return m.accessors[static_cast<std::size_t>(accessor)].count;
  };
  if (const auto pos = p.attributes.find("POSITION"); pos != p.attributes.end()) {
    vcount = count_of("POSITION", pos->second);
    have_count = true;
  }
  const auto check = [&](const std::string& name, int accessor) {
    const std::size_t count = count_of(name, accessor);
    const tinygltf::Accessor& a = m.accessors[static_cast<std::size_t>(accessor)];
    const int component_bytes = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (component_bytes <= 0 || components <= 0)
      throw BakeError(where + ": " + name + " accessor " + std::to_string(accessor) + " has component type " +
                      std::to_string(a.componentType) + " and type " + std::to_string(a.type) +
                      ", which glTF 2.0 does not define");
    if (!have_count) {
      vcount = count;
      have_count = true;
    } else if (count != vcount) {
      throw BakeError(where + ": " + name + " accessor " + std::to_string(accessor) + " has " + std::to_string(count) +
                      " elements, but the primitive has " + std::to_string(vcount) +
                      " vertices (all attributes must have the same count)");
    }
    // A sparse accessor without a bufferView is valid glTF and is carried as it is; the
    // simplifier never reads one (POSITION refuses them).
    if (a.sparse.isSparse) return;
    // The unpadded element size: matrices of 1- and 2-byte components are padded per column,
    // so this bound is at most a few bytes lenient there.
    (void)checked_view(m, accessor, static_cast<std::size_t>(component_bytes) * static_cast<std::size_t>(components),
                       where + " " + name);
  };
  for (const auto& [name, accessor] : p.attributes)
    if (name != "POSITION") check(name, accessor);
  for (std::size_t t = 0; t < p.targets.size(); ++t)
    for (const auto& [name, accessor] : p.targets[t]) check("morph target " + std::to_string(t) + " " + name, accessor);
  if (p.indices >= 0 && !draws_triangles(p)) (void)read_index_accessor(m, p.indices, vcount, where);
}

}  // namespace gazelod::bake
