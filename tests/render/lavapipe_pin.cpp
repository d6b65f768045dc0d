// SPDX-License-Identifier: Apache-2.0
// Test-process helper: keeps Mesa's lavapipe ICD loaded for the whole run. Lavapipe keeps a
// few static allocations that become unreachable when the Vulkan loader unloads the ICD at
// vkDestroyInstance, which LeakSanitizer (the unit tests' ASan run) then reports as leaks of
// an "<unknown module>". Holding one extra reference keeps them reachable; our own objects
// are still created and destroyed per test, so real leaks in gazelod's code are still found.
#include <dlfcn.h>

namespace {

const bool kLavapipePinned = [] {
  return dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_GLOBAL) != nullptr;  // absent: nothing to pin
}();

}  // namespace
