// SPDX-License-Identifier: Apache-2.0
// Publishing a decided frame for readers on other threads (plugin/capi/capi_outputs.cpp).
#pragma once

#include "plugin/capi/capi_plugin.hpp"

#include <cstdint>

namespace gazelod::capi {

// Copies the frame's levels (by handle), its summary, the foveal cone per view and the frame's
// record into p->pub under p->out_mu. Called with p->mu held; allocates nothing.
void publish(gzl_plugin p, const FrameDecisions& d, std::int64_t t_ns);

// The foveal cone seen from one view (u, v from the view's top-left corner).
gzl_foveal_cone cone_in_view(const glm::dvec3& gaze_dir_base, const glm::dquat& head_orientation,
                             const plugin::ViewInput& view, double fovea_deg, double uncertainty_deg);

}  // namespace gazelod::capi
