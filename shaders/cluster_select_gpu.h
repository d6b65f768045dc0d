// SPDX-License-Identifier: Apache-2.0
/* The interface of shaders/cluster_select.comp (GPU-driven cluster LOD) for a host that runs it
 * on its own buffers: descriptor bindings, buffer element layouts and the push constants, as C99
 * structs (also valid C++). Installed next to the shader in <prefix>/share/gazelod/shaders/;
 * docs/gpu-selection.md describes how to fill them. render/cluster_select_pass.hpp is gazelod's
 * own host for it.
 *
 * One dispatch of ceil(cluster_count / GZL_CLUSTER_SELECT_WORKGROUP) workgroups evaluates
 * clusters [0, cluster_count) of the bound per-cluster buffers (bindings 2-7, bound from the
 * dispatch's first cluster, whose id is cluster_base). Per cluster i it writes bit i % 32 of
 * drawn_bits[i / 32] (1: in the cut) and, when the cluster is in the cut and (with cull) its
 * self sphere meets the view, one VkDrawIndexedIndirectCommand at an index taken from the
 * draw count (binding 8, which the host zeroes before the first dispatch of a frame). Commands
 * past command_capacity are counted, not written: draw with
 * maxDrawCount = command_capacity.
 *
 * All lengths in metres, world space (the same space for every mesh). Layouts: std140 for the
 * frame (binding 0, a uniform buffer), std430 for the storage buffers; every struct here has
 * the size and field offsets the shader's blocks have (tests/render/cluster_select_pass_test.cpp
 * checks them against the SPIR-V). */
#ifndef GAZELOD_CLUSTER_SELECT_GPU_H_
#define GAZELOD_CLUSTER_SELECT_GPU_H_ 1

#include <stdint.h>

#define GZL_CLUSTER_SELECT_WORKGROUP 256u

/* Descriptor set 0. */
enum gzl_cluster_select_binding {
  GZL_CLUSTER_SELECT_BINDING_FRAME = 0,          /* uniform: gzl_cluster_select_frame */
  GZL_CLUSTER_SELECT_BINDING_MESHES = 1,         /* gzl_cluster_select_mesh[mesh count] */
  GZL_CLUSTER_SELECT_BINDING_SELF_SPHERES = 2,   /* float[4] per cluster: centre x y z, radius */
  GZL_CLUSTER_SELECT_BINDING_PARENT_SPHERES = 3, /* float[4] per cluster */
  GZL_CLUSTER_SELECT_BINDING_ERRORS = 4,         /* float[2] per cluster: self, parent error */
  GZL_CLUSTER_SELECT_BINDING_CLUSTER_MESH = 5,   /* uint32_t per cluster: its mesh (< mesh count) */
  GZL_CLUSTER_SELECT_BINDING_DRAW_RANGES = 6,    /* gzl_cluster_select_draw_range per cluster */
  GZL_CLUSTER_SELECT_BINDING_DRAWN_BITS = 7,     /* uint32_t per 32 clusters (a whole workgroup's 8) */
  GZL_CLUSTER_SELECT_BINDING_DRAW_COUNT = 8,     /* uint32_t: the count; also the indirect count */
  GZL_CLUSTER_SELECT_BINDING_COMMANDS = 9,       /* VkDrawIndexedIndirectCommand[command_capacity] */
  GZL_CLUSTER_SELECT_BINDING_COUNT = 10
};

/* Binding 0, per frame (std140, 208 bytes). Fill the selection part from
 * lod::detail::make_cluster_frame (lod/cluster/cluster_select_kernel.hpp), bit for bit: the
 * shader then decides as select_clusters does (docs/gpu-selection.md, "Precision"). */
typedef struct gzl_cluster_select_frame {
  float eye_hi_m[3];         /* the eye as a float pair: eye = hi + lo */
  float ecc_offset_rad;      /* tracker error + kEccentricitySlackRad, rounded up */
  float eye_lo_m[3];
  float scale;               /* Reddy's s, rounded up */
  float gaze_unit[3];
  float scale_xi_cpd;        /* s xi, rounded up */
  float gaze_omega_rad_s[3]; /* head + eye-in-head rotation, world axes */
  float static_limit_cpd;    /* s min(60, xi), rounded up; any value with use_size 0 */
  float error_factor;        /* 360 / pi (1 + 2^-16), rounded up */
  float on_eccentricity;     /* 1 or 0 */
  float on_velocity;         /* 1 or 0 */
  uint32_t use_size;         /* 1 or 0 */
  float lip_w;               /* (1.0f + kVelocitySlack) * gaze_omega_norm_rad_s, in float */
  float slack_w;             /* kVelocitySlack * |w| */
  uint32_t cull;             /* 1: commands only for clusters whose self sphere meets the view */
  uint32_t reserved0;
  /* The culling view (with cull 1): render/camera.hpp's EyeView as ViewCuller sees it. */
  float view_hi_m[3];        /* its origin as a float pair */
  float near_m;
  float view_lo_m[3];
  float far_m;
  float view_row_x[4];       /* world -> view rotation, row by row (w unused); looks down -z */
  float view_row_y[4];
  float view_row_z[4];
  float side_x[4];           /* left (a, b), right (a, b): a x + b depth >= 0 inside, unit length */
  float side_y[4];           /* up (a, b), down (a, b), on y */
} gzl_cluster_select_frame;

/* Binding 1, per mesh and frame (std430, 32 bytes); from lod::detail::make_cluster_mesh_frame. */
typedef struct gzl_cluster_select_mesh {
  float rel_vel_m_s[3];      /* the mesh's velocity minus the eye's */
  float lip_v;               /* 2.0f * (1.0f + kVelocitySlack) * rel_speed_m_s */
  float slack_v;             /* kVelocitySlack * rel_speed_m_s */
  float cap_combined_m;      /* size off: cap_m; size on (+inf): FLT_MAX */
  float error_factor;        /* the frame's error_factor over the mesh's detail scale, rounded up:
                              * ClusterMeshFrame::error_factor (a frame budget's coarsening step;
                              * at scale 1 the frame block's error_factor, bit for bit). The
                              * shader reads this one, not the frame block's. */
  float reserved;
} gzl_cluster_select_mesh;

/* Binding 6, per cluster (std430, 12 bytes): its triangles in the index buffer the commands
 * draw from (VkDrawIndexedIndirectCommand's fields). */
typedef struct gzl_cluster_select_draw_range {
  uint32_t first_index;
  uint32_t index_count;
  int32_t vertex_offset;
} gzl_cluster_select_draw_range;

/* Push constants (16 bytes, compute stage). */
typedef struct gzl_cluster_select_dispatch {
  uint32_t cluster_base;     /* id of the dispatch's cluster 0: first_instance = cluster_base + i */
  uint32_t cluster_count;
  uint32_t command_capacity;
  uint32_t reserved0;
} gzl_cluster_select_dispatch;

#ifdef __cplusplus
static_assert(sizeof(gzl_cluster_select_frame) == 208, "std140 block size");
static_assert(sizeof(gzl_cluster_select_mesh) == 32, "std430 array stride");
static_assert(sizeof(gzl_cluster_select_draw_range) == 12, "std430 array stride");
static_assert(sizeof(gzl_cluster_select_dispatch) == 16, "push constant size");
#endif

#endif /* GAZELOD_CLUSTER_SELECT_GPU_H_ */
