// SPDX-License-Identifier: Apache-2.0
// gazelod eval gltfpack MODEL: gazelod bake's LOD chain beside meshoptimizer's own gltfpack
// (Debian package gltfpack, the same meshopt 0.18) on one model, measured the same way. For
// each triangle ratio R of the chain: the chain's level (one `gazelod bake` run makes them all)
// and `gltfpack -si R -noq` (its default error cap) and `gltfpack -si R -sa -noq` (aggressive:
// the ratio regardless of quality); each result as one world-space triangle soup, against the
// source's: triangles, the distance from every source vertex to the result's surface (largest,
// 99th percentile, mean; bake/surface_deviation.hpp, the measure behind the bake's own errors)
// and back, and the tool's wall time. Writes gltfpack.md and gltfpack.json into --out
// (docs/bake.md, "Against gltfpack").
#pragma once

#include "apps/gazelod/clusters/eval.hpp"  // EvalSubcommand

namespace gazelod::cli {

// Adds `gltfpack` to the `eval` command.
EvalSubcommand add_eval_gltfpack(CLI::App& eval);

}  // namespace gazelod::cli
