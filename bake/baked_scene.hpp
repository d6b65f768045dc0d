// Reads a baked .glb/.gltf back as LOD chains for the selection: one object per scene node
// with a mesh (default scene, or every scene when none is default), its chain from the node's
// MSFT_lod ids and each level's extras.gazelod_lod, and its world-space bounding sphere.
#pragma once

#include "lod/lod_chain.hpp"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace gazelod::bake {

struct BakedObject {
  std::string name;           // node name, or "node N"
  int node = -1;              // glTF node index of the finest level
  glm::dvec3 center_m{0.0};   // world space (node transforms applied)
  double radius_m = 0.0;      // world space, encloses the full-detail mesh
  // lods[0] is the full mesh; detail is removed cycles per diameter (0 at level 0), from the
  // geometric error (detail.hpp); passes lod::validate_chain.
  std::vector<lod::LodLevel> lods;
};

// Throws BakeError "PATH: /nodes/3/extras/gazelod_lod/triangles: ..." for a file that is not a
// gazelod bake output or is inconsistent (bad ids, missing extras, chain that fails validation).
std::vector<BakedObject> load_baked_scene(const std::string& path);

}  // namespace gazelod::bake
