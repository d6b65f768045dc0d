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

GazeActionState* gaze_action(EmulatedInstance& e, XrSession session, XrAction action, SessionRecord** record) {
  auto s = e.sessions.find(session);
  if (s == e.sessions.end()) return nullptr;
  if (record != nullptr) *record = &s->second;
  auto a = s->second.gaze_actions.find(action);
  if (a == s->second.gaze_actions.end() || a->second.destroyed) return nullptr;
  return &a->second;
}

const ActionRecord* live_action(const EmulatedInstance& e, XrAction action) {
  auto it = e.actions.find(action);
  return it == e.actions.end() || it->second.handle_destroyed ? nullptr : &it->second;
}

}  // namespace gazelod::layer
