// SPDX-License-Identifier: Apache-2.0
// gazelod eval clusters: cluster LOD against per-object LOD on one large mesh. Generates the
// terrain (`gazelod scene generate terrain`, or takes --scene-source F), bakes it three times
// in a work folder: `gazelod bake` (an MSFT_lod chain per mesh node, the baseline), the same
// chains as one cluster per level (clusters/eval_baseline.hpp: per-object LOD under the
// cluster rule), and `gazelod bake --clusters`; runs `gazelod run --no-render --scene ...
// --scene-placement file --scenario terrain-walk` on each in this process and reads their
// summaries side by side: triangles drawn per frame, against full detail and the oracle at the
// true gaze, visible degradations (per object-frame, per leaf-frame), switches. The target:
// cluster LOD draws at most a third of per-object LOD's triangles at <= 0.5 % degradations.
// Then each is rendered for a few frames (lavapipe without a GPU) for its measured frame time.
// Writes clusters.md, clusters.json and clusters.svg into --out (docs/evaluation.md, "Cluster
// LOD").
#pragma once

#include "apps/gazelod/commands/command.hpp"

namespace gazelod::cli {

struct EvalSubcommand {
  CLI::App* app = nullptr;  // parsed() when it was selected
  Action action;
};

// Adds `clusters` to the `eval` command.
EvalSubcommand add_eval_clusters(CLI::App& eval);

}  // namespace gazelod::cli
