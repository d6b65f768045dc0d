// SPDX-License-Identifier: Apache-2.0
/* XR_GAZELOD_simulator_state: a vendor extension of the gazelod simulated OpenXR runtime that
 * tells tests and the plugin where the simulation stands (frame count, the XrTime of scenario
 * time 0, the scenario's duration and whether it has ended). Enable the extension at
 * xrCreateInstance and fetch xrGetSimulatorStateGAZELOD with xrGetInstanceProcAddr. */
#ifndef GAZELOD_SIMULATOR_STATE_EXT_H_
#define GAZELOD_SIMULATOR_STATE_EXT_H_

#include <openxr/openxr.h>

#ifdef __cplusplus
extern "C" {
#endif

#define XR_GAZELOD_simulator_state 1
#define XR_GAZELOD_simulator_state_SPEC_VERSION 1
#define XR_GAZELOD_SIMULATOR_STATE_EXTENSION_NAME "XR_GAZELOD_simulator_state"

typedef struct XrSimulatorStateGAZELOD {
  uint64_t frameCount;             /* xrWaitFrame calls of this session so far */
  XrTime scenarioTimeBase;         /* XrTime of scenario time 0: scenario ns = XrTime - this */
  XrTime lastPredictedDisplayTime; /* returned by the last xrWaitFrame, 0 before the first */
  XrDuration scenarioDuration;     /* ns, after GAZELOD_SIM_DURATION_S */
  XrBool32 scenarioEnded;          /* the runtime has started the stop at the scenario's end */
  XrBool32 paced;                  /* xrWaitFrame sleeps to the display rate */
} XrSimulatorStateGAZELOD;

typedef XrResult(XRAPI_PTR* PFN_xrGetSimulatorStateGAZELOD)(XrSession session, XrSimulatorStateGAZELOD* state);

#ifdef __cplusplus
}
#endif

#endif /* GAZELOD_SIMULATOR_STATE_EXT_H_ */
