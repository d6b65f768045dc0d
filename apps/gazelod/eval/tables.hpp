// SPDX-License-Identifier: Apache-2.0
// `gazelod eval`'s output: markdown tables and SVG plots of the experiments
// (apps/gazelod/eval/experiments.hpp), written into one folder.
#pragma once

#include "apps/gazelod/eval/experiments.hpp"

#include <filesystem>
#include <ostream>
#include <vector>

namespace gazelod::cli {

void figure5_table(const std::vector<Figure5Row>& rows, std::ostream& md);
void figure6_table(const std::vector<Figure6Row>& rows, std::ostream& md);
void head_turn_table(const std::vector<HeadTurnRow>& rows, std::ostream& md);

// figure5.svg, figure6.svg, head_turns.svg (each only when its rows are non-empty).
// Throws std::runtime_error naming a file that cannot be written.
void write_eval_plots(const std::vector<Figure5Row>& f5, const std::vector<Figure6Row>& f6,
                      const std::vector<HeadTurnRow>& turns, const std::filesystem::path& dir);

}  // namespace gazelod::cli
