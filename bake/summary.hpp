// SPDX-License-Identifier: Apache-2.0
// The bake's summary table: per mesh and level, triangles, vertices, errors, detail, method,
// then totals and throughput.
#pragma once

#include "bake/bake.hpp"

#include <string>

namespace gazelod::bake {

std::string format_summary(const BakeReport& report);

}  // namespace gazelod::bake
