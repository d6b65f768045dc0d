// SPDX-License-Identifier: Apache-2.0
// GPU-driven cluster LOD: select_clusters' combined rule (lod/cluster/cluster_select.hpp) per
// cluster, a frustum test of each drawn cluster's self sphere, and one
// VkDrawIndexedIndirectCommand per drawn cluster in view, compacted through an atomic counter
// (drawn with vkCmdDrawIndexedIndirectCount). Buffer layouts, bindings and push constants:
// shaders/cluster_select_gpu.h (C mirror; docs/gpu-selection.md). One invocation per cluster,
// 256 per workgroup.
//
// The arithmetic is that of lod/cluster/cluster_select_kernel.cpp (geometry, geometry_loop and
// decision_loop without the per-criterion outputs) and cluster_select_math.hpp, operation for
// operation in the same order, on the frame and mesh constants select_clusters derives
// (make_cluster_frame, make_cluster_mesh_frame; the host passes them bit for bit). Every
// arithmetic result is `precise` (SPIR-V NoContraction: no FMA fusion, no reassociation), so
// + - * round as the CPU's (Vulkan: correctly rounded). Where GLSL may differ from the CPU:
//   - sqrt (Vulkan: from inversesqrt, a few ULP) and division (2.5 ULP), against the CPU's
//     correctly rounded ones: d, h, |k| and |t|, 1 / (d dn) and the atan's ratio;
//   - denormals may be flushed (only products of errors under ~1e-30 m reach them);
//   - infinities: a device may assume none, so +inf (kNoParentError, size off) is tested on
//     the bits, never through arithmetic.
// Those few ULP stay inside the CPU kernel's slacks (kDistanceLow is 16 eps against the ~14
// eps of d here; kEccentricitySlackRad 4e-6 rad against ~3.5e-6; kVelocitySlack 1e-5 against
// ~3e-6), so the GPU too never keeps a coarser cluster than the exact rule in double; it can
// differ from the CPU kernel only on a record whose float margin to a threshold is within a
// few ULP (about 1e-6 relative). Every record is evaluated by one code path (the loop below is
// not unrolled), so the clusters sharing a record decide alike and the cut stays consistent.
#version 450
#extension GL_EXT_control_flow_attributes : require

layout(local_size_x = 256) in;

// Binding 0: the frame (gzl_cluster_select_frame). std140; a float after a vec3 fills its
// fourth slot.
layout(std140, set = 0, binding = 0) uniform Frame {
  vec3 eye_hi_m;          float ecc_offset_rad;     // the eye as a float pair (hi + lo)
  vec3 eye_lo_m;          float scale;              // s, rounded up
  vec3 gaze_unit;         float scale_xi_cpd;       // s xi, rounded up
  vec3 gaze_omega_rad_s;  float static_limit_cpd;   // a0 = s min(60, xi); unused with size off
  float error_factor;     // K (1 + 2^-16), rounded up
  float on_eccentricity;  // 0 or 1
  float on_velocity;      // 0 or 1
  uint use_size;          // 0 or 1 (size off: a0 is +inf on the CPU)
  float lip_w;            // (1 + kVelocitySlack) |w|
  float slack_w;          // kVelocitySlack |w|
  uint cull;              // 1: emit only clusters whose self sphere meets the view
  uint reserved0;
  vec3 view_hi_m;         float near_m;             // the culling view's origin (float pair)
  vec3 view_lo_m;         float far_m;
  vec4 view_row_x;        // world -> view rotation, rows (xyz; w unused); the view looks down -z
  vec4 view_row_y;
  vec4 view_row_z;
  vec4 side_x;            // left (a, b), right (a, b): a x + b depth >= 0 inside, unit length
  vec4 side_y;            // up (a, b), down (a, b)
} frame;

// Binding 1: per mesh, per frame (gzl_cluster_select_mesh).
struct MeshFrame {
  vec3 rel_vel_m_s;       // the mesh's velocity relative to the eye
  float lip_v;            // 2 (1 + kVelocitySlack) |V|
  float slack_v;          // kVelocitySlack |V|
  float cap_combined_m;   // size off: the mesh's distance cap; size on: FLT_MAX (+inf on the CPU)
  float error_factor;     // the frame's over the mesh's detail scale (a frame budget's step)
  float reserved0;
};
layout(std430, set = 0, binding = 1) readonly buffer Meshes { MeshFrame meshes[]; };

// Bindings 2-6: per cluster, structure of arrays, world space (ClusterSet's fields).
layout(std430, set = 0, binding = 2) readonly buffer SelfSpheres { vec4 self_sphere_m[]; };      // centre, radius
layout(std430, set = 0, binding = 3) readonly buffer ParentSpheres { vec4 parent_sphere_m[]; };
layout(std430, set = 0, binding = 4) readonly buffer Errors { vec2 error_m[]; };                // self, parent
layout(std430, set = 0, binding = 5) readonly buffer ClusterMesh { uint cluster_mesh[]; };
struct DrawRange {
  uint first_index;
  uint index_count;
  int vertex_offset;
};
layout(std430, set = 0, binding = 6) readonly buffer DrawRanges { DrawRange draw_range[]; };

// Bindings 7-9: outputs. drawn_bits: bit (i % 32) of word i / 32 is cluster i's decision (in
// the cut, in view or not); every word of the dispatch is written.
layout(std430, set = 0, binding = 7) writeonly buffer DrawnBits { uint drawn_bits[]; };
layout(std430, set = 0, binding = 8) buffer DrawCount { uint draw_count; };  // zeroed before
struct DrawCommand {  // VkDrawIndexedIndirectCommand
  uint index_count;
  uint instance_count;
  uint first_index;
  int vertex_offset;
  uint first_instance;  // the cluster's id (cluster_base + index)
};
layout(std430, set = 0, binding = 9) writeonly buffer DrawCommands { DrawCommand commands[]; };

layout(push_constant) uniform Dispatch {
  uint cluster_base;      // id of this dispatch's cluster 0 (its buffers are bound from it)
  uint cluster_count;     // clusters in this dispatch
  uint command_capacity;  // commands[] holds this many; draw_count may exceed it (overflow)
  uint reserved0;
} pc;

// lod/cluster/cluster_select_kernel.hpp, cluster_select_kernel.cpp, lod/acuity.hpp: the float
// constants bit for bit (17 digits: exact; tests/render/cluster_select_pass_test.cpp checks).
const float kNearFloorM = 9.9999999747524271e-07;
const float kDistanceLow = 0.99999904632568359;  // 1 - 2^-20
const float kD2Low = 0.99999809265136719;        // 1 - 2^-19
const float kNormLow = 0.99999904632568359;      // 1 - 2^-20
const float kDegPerRad = 57.295780181884766;
const float kSeamDps = 0.82499998807907104;
const float kCapDps = 200.0;
const float kGIntercept = 57.690097808837891;  // 57.69 + kGSlackCpd
const float kGSlope = 27.780000686645508;
const float kMaxCpd = 60.0;
const float kEccSeamDeg = 5.7899999618530273;
const float kMSlope = 0.30000001192092896;
const float kMNumerator = 7.4899997711181641;
// cluster_select_math.hpp's polynomials.
const float kAtanC0 = -0.33333286643028259;
const float kAtanC1 = 0.19991238415241241;
const float kAtanC2 = -0.14024142920970917;
const float kAtanC3 = 0.085204921662807465;
const float kTanPi8 = 0.41421356797218323;
const float kPi = 3.1415927410125732;
const float kQuarterPi = 0.78539818525314331;
const float kInvSqrt2 = 0.70710676908493042;
const float kLog2C0 = 1.4426965713500977;
const float kLog2C1 = -0.72136020660400391;
const float kLog2C2 = 0.480613112449646;
const float kLog2C3 = -0.35952445864677429;
const float kLog2C4 = 0.2961195707321167;
const float kLog2C5 = -0.26796385645866394;
const float kLog2C6 = 0.16818659007549286;
const float kLog10Of2 = 0.30102998018264771;  // ln 2 / ln 10
// The frustum test's slack (relative to |r| + radius): float rounding of the rotation, so that
// a sphere partly inside is never culled (render/camera.hpp's ViewCuller in float).
const float kCullSlack = 3.814697265625e-06;  // 2^-18

// x >= 0 (NaN false, -0 and +inf true), x finite, x == +inf: on the bits.
bool non_negative(float x) {
  const uint b = floatBitsToUint(x);
  return b <= 0x7f800000u || b == 0x80000000u;
}
bool finite(float x) {
  return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u;
}
bool positive_inf(float x) {
  return floatBitsToUint(x) == 0x7f800000u;
}

// fastf::atan_small: atan(u), 0 <= u <= tan(pi/8).
float atan_small(float u) {
  precise float x = u * u;
  precise float q01 = kAtanC0 + x * kAtanC1;
  precise float q23 = kAtanC2 + x * kAtanC3;
  precise float q = q01 + (x * x) * q23;
  precise float r = u + u * x * q;
  return r;
}

// fastf::atan_unit_ratio: atan(num / den), 0 <= num <= den.
float atan_unit_ratio(float num, float den) {
  precise float big = num > kTanPi8 * den ? 1.0 : 0.0;
  precise float top = num - big * den;
  precise float bottom = den + big * num;
  precise float r = big * kQuarterPi + atan_small(top / bottom);
  return r;
}

// fastf::atan2_with_norm: atan2(y, x) for y >= 0 given n = |(x, y)|.
float atan2_with_norm(float y, float x, float n) {
  precise float half_angle = atan_unit_ratio(y, n + abs(x));
  precise float r = x < 0.0 ? kPi - 2.0 * half_angle : 2.0 * half_angle;
  return r;
}

// fastf::log10_normal: x positive, normal, finite.
float log10_normal(float x) {
  const uint bits = floatBitsToUint(x);
  precise float e = float(int(bits >> 23) - 127) + 0.5;
  const float m_raw = uintBitsToFloat((bits & 0x007fffffu) | 0x3f800000u);
  precise float t = m_raw * kInvSqrt2 - 1.0;
  precise float t2 = t * t;
  precise float t4 = t2 * t2;
  precise float p01 = kLog2C0 + t * kLog2C1;
  precise float p23 = kLog2C2 + t * kLog2C3;
  precise float p45 = kLog2C4 + t * kLog2C5;
  precise float p = (p01 + t2 * p23) + t4 * (p45 + t2 * kLog2C6);
  precise float r = (e + t * p) * kLog10Of2;
  return r;
}

// One record (sphere, error) of mesh m: ok = valid data; returns whether the error is
// invisible under the combined rule (cluster_select_kernel.cpp: geometry, geometry_loop,
// decision_loop, the latter two fused).
bool record_invisible(vec4 sphere, float e, uint m, out bool ok) {
  const float cx = sphere.x, cy = sphere.y, cz = sphere.z, rho = sphere.w;
  // geometry(): the eye-relative centre, validity, the nearest-point distance rounded down.
  precise float rx = (cx - frame.eye_hi_m.x) - frame.eye_lo_m.x;
  precise float ry = (cy - frame.eye_hi_m.y) - frame.eye_lo_m.y;
  precise float rz = (cz - frame.eye_hi_m.z) - frame.eye_lo_m.z;
  precise float sum = cx + cy + cz + rho;  // not finite exactly when (sum * 0 == 0) fails
  ok = finite(sum) && non_negative(rho) && non_negative(e);
  precise float d2 = rx * rx + ry * ry + rz * rz;
  precise float d = sqrt(d2);
  precise float dn_raw = d * kDistanceLow - rho;
  const bool is_near = !(dn_raw > kNearFloorM);
  precise float dn = is_near ? kNearFloorM : dn_raw;

  // geometry_loop: the nearest point's eccentricity.
  const vec3 g = frame.gaze_unit;
  precise float d2_low = d2 * kD2Low;
  precise float rho2 = rho * rho;
  const bool inside = !(d2_low > rho2);
  precise float h = sqrt(inside ? 0.0 : d2_low - rho2);
  precise float kx = g.y * rz - g.z * ry;
  precise float ky = g.z * rx - g.x * rz;
  precise float kz = g.x * ry - g.y * rx;
  precise float sp = sqrt(kx * kx + ky * ky + kz * kz);
  precise float cp = g.x * rx + g.y * ry + g.z * rz;
  precise float sin_e = sp * h - cp * rho;
  precise float cos_e = cp * h + sp * rho;
  precise float ecc_rad = atan2_with_norm(sin_e, cos_e, d2 * kNormLow) - frame.ecc_offset_rad;
  const bool eccentric = !inside && (sin_e >= 0.0) && (ecc_rad > 0.0);

  // The retinal velocity at the centre, lowered to the sphere's slowest point and the slack.
  const MeshFrame mf = meshes[m];
  const vec3 v = mf.rel_vel_m_s, o = frame.gaze_omega_rad_s;
  precise float d_safe = d > kNearFloorM ? d : kNearFloorM;
  precise float inv_ddn = 1.0 / (d_safe * dn);
  precise float inv_d = dn * inv_ddn;
  precise float inv_dn = d_safe * inv_ddn;
  precise float inv_d2 = inv_d * inv_d;
  precise float wx = (ry * v.z - rz * v.y) * inv_d2 - o.x;
  precise float wy = (rz * v.x - rx * v.z) * inv_d2 - o.y;
  precise float wz = (rx * v.y - ry * v.x) * inv_d2 - o.z;
  precise float tx = wy * rz - wz * ry;
  precise float ty = wz * rx - wx * rz;
  precise float tz = wx * ry - wy * rx;
  precise float v_c = sqrt(tx * tx + ty * ty + tz * tz) * inv_d;
  precise float v_slack = (mf.slack_v * inv_dn + frame.slack_w) + rho * inv_dn * (mf.lip_v * inv_dn + frame.lip_w);
  precise float v_lo = v_c - v_slack;
  precise float ecc_deg = eccentric ? ecc_rad * kDegPerRad : 0.0;
  precise float v_deg = (!is_near && (v_lo > 0.0)) ? v_lo * kDegPerRad : 0.0;

  // decision_loop: G(v) raised by its slack (switched off: 60), M(E) as a comparison.
  precise float v_clamped = min(max(v_deg, kSeamDps), kCapDps);
  precise float g_log = kGIntercept - kGSlope * log10_normal(v_clamped);
  precise float g_clamped = min(max(g_log, 0.0), kMaxCpd);
  precise float gv = v_deg * frame.on_velocity > kSeamDps ? g_clamped : kMaxCpd;
  precise float ecc_on = ecc_deg * frame.on_eccentricity;
  const bool beyond = ecc_on > kEccSeamDeg;
  precise float mq = kMSlope * ecc_on + 1.0;
  precise float mq2 = mq * mq;
  // Invisible when A e K < dist (f > A), each min() of A an "or". e = +inf never goes (the
  // CPU gets there through inf and NaN, which a device may assume away).
  precise float b = e * mf.error_factor;
  precise float x_xi = frame.scale_xi_cpd * b;
  precise float x_g = (frame.scale * gv) * b;
  precise float dist_c = dn < mf.cap_combined_m ? dn : mf.cap_combined_m;
  precise float size_lhs = frame.static_limit_cpd * b;  // by_size: a0 (e K) < dn
  const bool size_ok = frame.use_size != 0u && size_lhs < dn;
  const bool zero = e == 0.0;
  precise float m_lhs = kMNumerator * x_g;
  precise float m_rhs = dist_c * mq2;
  const bool comb = size_ok || zero || (x_xi < dist_c) || (x_g < dist_c) || (beyond && (m_lhs < m_rhs));
  return ok && comb && !positive_inf(e);
}

// Conservative sphere-against-frustum (ViewCuller's planes, near and far), in view space.
bool in_view(vec4 sphere) {
  precise vec3 r = (sphere.xyz - frame.view_hi_m) - frame.view_lo_m;
  precise float x = dot(frame.view_row_x.xyz, r);
  precise float y = dot(frame.view_row_y.xyz, r);
  precise float depth = -dot(frame.view_row_z.xyz, r);
  precise float reach = sphere.w + kCullSlack * (abs(r.x) + abs(r.y) + abs(r.z) + sphere.w);
  precise float lo = frame.near_m - reach, hi = frame.far_m + reach;
  if (depth < lo || depth > hi) return false;
  precise float l = frame.side_x.x * x + frame.side_x.y * depth, rt = frame.side_x.z * x + frame.side_x.w * depth;
  precise float u = frame.side_y.x * y + frame.side_y.y * depth, dn = frame.side_y.z * y + frame.side_y.w * depth;
  return l >= -reach && rt >= -reach && u >= -reach && dn >= -reach;
}

shared uint s_bits[8];  // the workgroup's 256 decisions
shared uint s_count;    // its commands
shared uint s_first;    // where they start in commands[]

void main() {
  const uint local = gl_LocalInvocationID.x;
  const uint i = gl_GlobalInvocationID.x;
  if (local < 8u) s_bits[local] = 0u;
  if (local == 0u) s_count = 0u;
  barrier();

  bool drawn = false;
  if (i < pc.cluster_count) {
    // Parent record first (k = 0): where it is invisible the cluster is not drawn and its self
    // record (invisible too, by the nesting) is not evaluated. One code path for both.
    const uint m = cluster_mesh[i];
    const vec2 errors = error_m[i];
    [[dont_unroll]] for (int k = 0; k < 2; ++k) {
      const vec4 sphere = k == 0 ? parent_sphere_m[i] : self_sphere_m[i];
      bool ok;
      const bool invisible = record_invisible(sphere, k == 0 ? errors.y : errors.x, m, ok);
      if (k == 0 && (!ok || invisible)) break;
      drawn = k == 1 && ok && invisible;
    }
  }
  const bool emit = drawn && (frame.cull == 0u || in_view(self_sphere_m[i]));
  uint slot = 0u;
  if (drawn) atomicOr(s_bits[local >> 5], 1u << (local & 31u));
  if (emit) slot = atomicAdd(s_count, 1u);
  barrier();
  // One global atomic per workgroup, not per cluster.
  if (local == 0u) s_first = s_count > 0u ? atomicAdd(draw_count, s_count) : 0u;
  if (local < 8u) drawn_bits[gl_WorkGroupID.x * 8u + local] = s_bits[local];
  barrier();
  if (emit) {
    const uint at = s_first + slot;
    if (at < pc.command_capacity) {
      const DrawRange range = draw_range[i];
      commands[at] = DrawCommand(range.index_count, 1u, range.first_index, range.vertex_offset, pc.cluster_base + i);
    }
  }
}
