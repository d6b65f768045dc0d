// SPDX-License-Identifier: Apache-2.0
#include "layer/dispatch_table.hpp"

namespace gazelod::layer {

std::string load_next_dispatch(PFN_xrGetInstanceProcAddr next_gipa, XrInstance instance, bool want_timespec,
                               NextDispatch& table) {
  table = NextDispatch{};
  table.GetInstanceProcAddr = next_gipa;
  if (next_gipa == nullptr) return "xrGetInstanceProcAddr";
  auto get = [&](const char* name, PFN_xrVoidFunction& out) {
    out = nullptr;
    return XR_SUCCEEDED(next_gipa(instance, name, &out)) && out != nullptr;
  };
  PFN_xrVoidFunction fn = nullptr;
#define GAZELOD_LAYER_NEXT_LOAD(name)          \
  if (!get("xr" #name, fn)) return "xr" #name; \
  table.name = reinterpret_cast<PFN_xr##name>(fn);
  GAZELOD_LAYER_NEXT_COMMANDS(GAZELOD_LAYER_NEXT_LOAD)
#undef GAZELOD_LAYER_NEXT_LOAD
  if (want_timespec && get("xrConvertTimespecTimeToTimeKHR", fn))
    table.ConvertTimespecTimeToTimeKHR = reinterpret_cast<PFN_xrConvertTimespecTimeToTimeKHR>(fn);
  if (get("xrLocateSpacesKHR", fn)) table.LocateSpacesKHR = reinterpret_cast<PFN_xrLocateSpacesKHR>(fn);
  if (get("xrLocateSpaces", fn)) table.LocateSpaces = reinterpret_cast<PFN_xrLocateSpaces>(fn);
  return "";
}

}  // namespace gazelod::layer
