// SPDX-License-Identifier: Apache-2.0
/* XR_GAZELOD_simulator_state: a vendor extension of the gazelod simulated OpenXR runtime that
 * tells tests and the plugin where the simulation stands (frame count, the XrTime of scenario
 * time 0, the scenario's duration and whether it has ended) and what the last frame submitted
 * (the composition layers as the runtime received them, below every API layer). Enable the
 * extension at xrCreateInstance and fetch xrGetSimulatorStateGAZELOD and
 * xrEnumerateSubmittedLayersGAZELOD with xrGetInstanceProcAddr. */
#ifndef GAZELOD_SIMULATOR_STATE_EXT_H_
#define GAZELOD_SIMULATOR_STATE_EXT_H_

#include <openxr/openxr.h>

#ifdef __cplusplus
extern "C" {
#endif

#define XR_GAZELOD_simulator_state 1
#define XR_GAZELOD_simulator_state_SPEC_VERSION 2
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

/* Spec version 2: one composition layer of the session's last successful xrEndFrame, in the
 * order submitted. */
#define XR_GAZELOD_SUBMITTED_LAYER_MAX_POSES 2
typedef struct XrSubmittedLayerGAZELOD {
  XrStructureType layerType; /* the layer's type, XR_TYPE_COMPOSITION_LAYER_... */
  XrSpace space;
  /* Quad, cylinder, equirect(2): its pose; cube: its orientation (position 0); projection: its
   * views' poses (the first XR_GAZELOD_SUBMITTED_LAYER_MAX_POSES); other types: none. */
  uint32_t poseCount;
  XrPosef poses[XR_GAZELOD_SUBMITTED_LAYER_MAX_POSES];
} XrSubmittedLayerGAZELOD;

/* The two-call idiom; none before the session's first xrEndFrame. */
typedef XrResult(XRAPI_PTR* PFN_xrEnumerateSubmittedLayersGAZELOD)(XrSession session, uint32_t capacity,
                                                                   uint32_t* count, XrSubmittedLayerGAZELOD* layers);

#ifdef __cplusplus
}
#endif

#endif /* GAZELOD_SIMULATOR_STATE_EXT_H_ */
