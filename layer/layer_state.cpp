// SPDX-License-Identifier: Apache-2.0
#include "layer/layer_state.hpp"

#include <cstdio>

namespace gazelod::layer {

LayerState& layer_state() {
  static LayerState
      state;  // lives as long as the library: the loader may unload it at any time after the last instance
  return state;
}

void log_line(const std::string& line) {
  // One write per line, so lines from several threads do not interleave.
  const std::string text = "gazelod layer: " + line + "\n";
  std::fwrite(text.data(), 1, text.size(), stderr);
  std::fflush(stderr);
}

}  // namespace gazelod::layer
