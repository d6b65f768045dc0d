// SPDX-License-Identifier: Apache-2.0
/* XR_KHR_locate_spaces (xrLocateSpacesKHR; core xrLocateSpaces from OpenXR 1.1), declared as the
 * OpenXR 1.1 headers declare it, for Debian's OpenXR 1.0.20 headers, which lack it. With headers
 * that have the extension this declares nothing (the guard is the headers' own). The simulated
 * runtime offers the extension; the eye-gaze layer intercepts it. */
#ifndef GAZELOD_KHR_LOCATE_SPACES_H_
#define GAZELOD_KHR_LOCATE_SPACES_H_

#include <openxr/openxr.h>

#ifndef XR_KHR_locate_spaces
#define XR_KHR_locate_spaces 1
#define XR_KHR_locate_spaces_SPEC_VERSION 1
#define XR_KHR_LOCATE_SPACES_EXTENSION_NAME "XR_KHR_locate_spaces"
#define XR_TYPE_SPACES_LOCATE_INFO_KHR ((XrStructureType)1000471000)
#define XR_TYPE_SPACE_LOCATIONS_KHR ((XrStructureType)1000471001)
#define XR_TYPE_SPACE_VELOCITIES_KHR ((XrStructureType)1000471002)

#ifdef __cplusplus
extern "C" {
#endif

typedef struct XrSpacesLocateInfoKHR {
  XrStructureType type;
  const void* XR_MAY_ALIAS next;
  XrSpace baseSpace;
  XrTime time;
  uint32_t spaceCount;
  const XrSpace* spaces;
} XrSpacesLocateInfoKHR;

typedef struct XrSpaceLocationDataKHR {
  XrSpaceLocationFlags locationFlags;
  XrPosef pose;
} XrSpaceLocationDataKHR;

typedef struct XrSpaceLocationsKHR {
  XrStructureType type;
  void* XR_MAY_ALIAS next;
  uint32_t locationCount;
  XrSpaceLocationDataKHR* locations;
} XrSpaceLocationsKHR;

typedef struct XrSpaceVelocityDataKHR {
  XrSpaceVelocityFlags velocityFlags;
  XrVector3f linearVelocity;
  XrVector3f angularVelocity;
} XrSpaceVelocityDataKHR;

/* XrSpaceVelocitiesKHR extends XrSpaceLocationsKHR */
typedef struct XrSpaceVelocitiesKHR {
  XrStructureType type;
  void* XR_MAY_ALIAS next;
  uint32_t velocityCount;
  XrSpaceVelocityDataKHR* velocities;
} XrSpaceVelocitiesKHR;

typedef XrResult(XRAPI_PTR* PFN_xrLocateSpacesKHR)(XrSession session, const XrSpacesLocateInfoKHR* locateInfo,
                                                   XrSpaceLocationsKHR* spaceLocations);

#ifdef __cplusplus
}
#endif

#endif /* XR_KHR_locate_spaces */

#endif /* GAZELOD_KHR_LOCATE_SPACES_H_ */
