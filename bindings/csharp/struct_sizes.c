// SPDX-License-Identifier: Apache-2.0
/* struct_sizes.c: the C layout of every struct (and enum) in include/gazelod/gazelod.h, for the C#
 * bindings' layout self-check (tests/GazelodTest.cs compares Marshal.SizeOf / Marshal.OffsetOf
 * with these lines). One line each:
 *   <struct> <sizeof>             a struct
 *   <struct>.<field> <offsetof>   each of its fields
 *   enum <name> <sizeof>          an enum (C# declares them int-sized)
 *   value <enum>.<name> <value>   each of its enumerants
 *   const <name> <value>          a macro the bindings mirror
 * Written to the file named by the first argument, or to stdout. */
#include <gazelod/gazelod.h>

#include <stddef.h>
#include <stdio.h>

#define S(type) fprintf(out, "%s %u\n", #type, (unsigned)sizeof(type))
#define F(type, field) fprintf(out, "%s.%s %u\n", #type, #field, (unsigned)offsetof(type, field))
#define E(type) fprintf(out, "enum %s %u\n", #type, (unsigned)sizeof(type))
#define V(type, value) fprintf(out, "value %s.%s %lld\n", #type, #value, (long long)(value))
#define C(name, value) fprintf(out, "const %s %llu\n", #name, (unsigned long long)(value))

int main(int argc, char** argv) {
  FILE* out = stdout;
  if (argc > 1 && (out = fopen(argv[1], "w")) == NULL) {
    perror(argv[1]);
    return 1;
  }

  E(gzl_result);
  E(gzl_structure_type);
  E(gzl_gaze_input);
  E(gzl_level_metric);
  E(gzl_gaze_source);
  E(gzl_eye_motion);
  E(gzl_criterion_bits);
  E(gzl_gaze_sample_flag_bits);
  E(gzl_head_flag_bits);
  /* gzl_result */
  V(gzl_result, GZL_SUCCESS);
  V(gzl_result, GZL_ERROR_NULL_HANDLE);
  V(gzl_result, GZL_ERROR_NULL_POINTER);
  V(gzl_result, GZL_ERROR_STRUCT_TYPE);
  V(gzl_result, GZL_ERROR_INVALID_ARGUMENT);
  V(gzl_result, GZL_ERROR_TIME_OUT_OF_ORDER);
  V(gzl_result, GZL_ERROR_TIME_IN_FUTURE);
  V(gzl_result, GZL_ERROR_OBJECT_INVALID);
  V(gzl_result, GZL_ERROR_WRONG_MODE);
  V(gzl_result, GZL_ERROR_OPENXR_CALL);
  V(gzl_result, GZL_ERROR_OPENXR_FUNCTION);
  V(gzl_result, GZL_ERROR_CAPACITY);
  V(gzl_result, GZL_ERROR_SHUT_DOWN);
  V(gzl_result, GZL_ERROR_OUT_OF_MEMORY);
  V(gzl_result, GZL_ERROR_INTERNAL);
  V(gzl_result, GZL_RESULT_MAX_ENUM);
  /* gzl_structure_type */
  V(gzl_structure_type, GZL_TYPE_UNKNOWN);
  V(gzl_structure_type, GZL_TYPE_CONFIG);
  V(gzl_structure_type, GZL_TYPE_DATA_CREATE_INFO);
  V(gzl_structure_type, GZL_TYPE_OPENXR_CREATE_INFO);
  V(gzl_structure_type, GZL_TYPE_OBJECT_DESC);
  V(gzl_structure_type, GZL_TYPE_GAZE_SAMPLE);
  V(gzl_structure_type, GZL_TYPE_FRAME_INPUT);
  V(gzl_structure_type, GZL_TYPE_FRAME_INFO);
  V(gzl_structure_type, GZL_TYPE_FOVEAL_CONE);
  V(gzl_structure_type, GZL_TYPE_GAZE_BINDING);
  V(gzl_structure_type, GZL_TYPE_FRAME_RECORD);
  V(gzl_structure_type, GZL_STRUCTURE_TYPE_MAX_ENUM);
  /* gzl_criterion_bits */
  V(gzl_criterion_bits, GZL_CRITERION_SIZE);
  V(gzl_criterion_bits, GZL_CRITERION_ECCENTRICITY);
  V(gzl_criterion_bits, GZL_CRITERION_VELOCITY);
  /* gzl_gaze_input */
  V(gzl_gaze_input, GZL_GAZE_INPUT_APP_SPACE);
  V(gzl_gaze_input, GZL_GAZE_INPUT_MERGE_BINDING);
  V(gzl_gaze_input, GZL_GAZE_INPUT_PUSHED);
  V(gzl_gaze_input, GZL_GAZE_INPUT_PLUGIN_ACTIONS);
  V(gzl_gaze_input, GZL_GAZE_INPUT_NONE);
  V(gzl_gaze_input, GZL_GAZE_INPUT_MAX_ENUM);
  /* gzl_level_metric */
  V(gzl_level_metric, GZL_LEVEL_GEOMETRIC_ERROR_M);
  V(gzl_level_metric, GZL_LEVEL_REMOVED_CYCLES_PER_DIAMETER);
  V(gzl_level_metric, GZL_LEVEL_SCREEN_HEIGHT_SHARE);
  V(gzl_level_metric, GZL_LEVEL_PIXELS_AT_FULL_HEIGHT);
  V(gzl_level_metric, GZL_LEVEL_METRIC_MAX_ENUM);
  /* gzl_gaze_sample_flag_bits */
  V(gzl_gaze_sample_flag_bits, GZL_GAZE_SAMPLE_VALID);
  V(gzl_gaze_sample_flag_bits, GZL_GAZE_SAMPLE_IN_WORLD);
  V(gzl_gaze_sample_flag_bits, GZL_GAZE_SAMPLE_HEAD_ORIENTATION);
  /* gzl_head_flag_bits */
  V(gzl_head_flag_bits, GZL_HEAD_POSE_VALID);
  V(gzl_head_flag_bits, GZL_HEAD_ANGULAR_VELOCITY_VALID);
  V(gzl_head_flag_bits, GZL_HEAD_LINEAR_VELOCITY_VALID);
  /* gzl_gaze_source */
  V(gzl_gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  V(gzl_gaze_source, GZL_GAZE_SOURCE_OPENXR);
  V(gzl_gaze_source, GZL_GAZE_SOURCE_PUSHED);
  V(gzl_gaze_source, GZL_GAZE_SOURCE_MAX_ENUM);
  /* gzl_eye_motion */
  V(gzl_eye_motion, GZL_EYE_FIXATION);
  V(gzl_eye_motion, GZL_EYE_SACCADE);
  V(gzl_eye_motion, GZL_EYE_PURSUIT);
  V(gzl_eye_motion, GZL_EYE_LOSS);
  V(gzl_eye_motion, GZL_EYE_MOTION_MAX_ENUM);

  C(GZL_HEADER_VERSION, GZL_HEADER_VERSION);
  C(GZL_MAX_VIEWS, GZL_MAX_VIEWS);
  C(GZL_NULL_OBJECT, GZL_NULL_OBJECT);
  C(GZL_LEVEL_DISABLED, GZL_LEVEL_DISABLED);

  S(gzl_vec3);
  F(gzl_vec3, x);
  F(gzl_vec3, y);
  F(gzl_vec3, z);
  S(gzl_quat);
  F(gzl_quat, x);
  F(gzl_quat, y);
  F(gzl_quat, z);
  F(gzl_quat, w);
  S(gzl_fov);
  F(gzl_fov, angle_left);
  F(gzl_fov, angle_right);
  F(gzl_fov, angle_up);
  F(gzl_fov, angle_down);

  S(gzl_view);
  F(gzl_view, fov);
  F(gzl_view, orientation_in_head);
  F(gzl_view, position_in_head_m);
  F(gzl_view, width_px);
  F(gzl_view, height_px);

  S(gzl_config);
  F(gzl_config, type);
  F(gzl_config, next);
  F(gzl_config, disabled_criteria);
  F(gzl_config, disable_switch_policy);
  F(gzl_config, frame_budget_ms);
  F(gzl_config, gaze_accuracy_deg);
  F(gzl_config, head_fixed_cone_deg);
  F(gzl_config, gaze_silence_timeout_s);
  F(gzl_config, max_gaze_sample_age_s);
  F(gzl_config, hmd_preset);

  S(gzl_data_create_info);
  F(gzl_data_create_info, type);
  F(gzl_data_create_info, next);
  F(gzl_data_create_info, view_count);
  F(gzl_data_create_info, views);
  F(gzl_data_create_info, config);

  S(gzl_openxr_create_info);
  F(gzl_openxr_create_info, type);
  F(gzl_openxr_create_info, next);
  F(gzl_openxr_create_info, get_instance_proc_addr);
  F(gzl_openxr_create_info, instance);
  F(gzl_openxr_create_info, system_id);
  F(gzl_openxr_create_info, session);
  F(gzl_openxr_create_info, base_space);
  F(gzl_openxr_create_info, view_configuration_type);
  F(gzl_openxr_create_info, gaze_input);
  F(gzl_openxr_create_info, gaze_space);
  F(gzl_openxr_create_info, gaze_action);
  F(gzl_openxr_create_info, config);

  S(gzl_gaze_binding);
  F(gzl_gaze_binding, type);
  F(gzl_gaze_binding, next);
  F(gzl_gaze_binding, action_set);
  F(gzl_gaze_binding, action);
  F(gzl_gaze_binding, interaction_profile);
  F(gzl_gaze_binding, binding_path);

  S(gzl_level);
  F(gzl_level, value);
  F(gzl_level, triangles);

  S(gzl_object_desc);
  F(gzl_object_desc, type);
  F(gzl_object_desc, next);
  F(gzl_object_desc, center_m);
  F(gzl_object_desc, radius_m);
  F(gzl_object_desc, velocity_m_s);
  F(gzl_object_desc, importance);
  F(gzl_object_desc, metric);
  F(gzl_object_desc, level_count);
  F(gzl_object_desc, levels);

  S(gzl_gaze_sample);
  F(gzl_gaze_sample, type);
  F(gzl_gaze_sample, next);
  F(gzl_gaze_sample, time_ns);
  F(gzl_gaze_sample, direction);
  F(gzl_gaze_sample, origin_m);
  F(gzl_gaze_sample, flags);
  F(gzl_gaze_sample, head_orientation);

  S(gzl_head_pose);
  F(gzl_head_pose, orientation);
  F(gzl_head_pose, position_m);
  F(gzl_head_pose, angular_velocity_rad_s);
  F(gzl_head_pose, linear_velocity_m_s);
  F(gzl_head_pose, flags);

  S(gzl_frame_input);
  F(gzl_frame_input, type);
  F(gzl_frame_input, next);
  F(gzl_frame_input, display_time_ns);
  F(gzl_frame_input, head);
  F(gzl_frame_input, view_count);
  F(gzl_frame_input, views);

  S(gzl_frame_info);
  F(gzl_frame_info, type);
  F(gzl_frame_info, next);
  F(gzl_frame_info, frame_index);
  F(gzl_frame_info, display_time_ns);
  F(gzl_frame_info, object_count);
  F(gzl_frame_info, gaze_source);
  F(gzl_frame_info, eye_motion);
  F(gzl_frame_info, gaze_suppressed);
  F(gzl_frame_info, head_valid);
  F(gzl_frame_info, gaze_direction_base);
  F(gzl_frame_info, eye_position_base_m);
  F(gzl_frame_info, head_angular_velocity_rad_s);
  F(gzl_frame_info, head_linear_velocity_m_s);
  F(gzl_frame_info, gaze_angular_velocity_in_head_rad_s);
  F(gzl_frame_info, gaze_uncertainty_deg);
  F(gzl_frame_info, xi_cpd);
  F(gzl_frame_info, triangles_drawn);
  F(gzl_frame_info, triangles_full);

  S(gzl_foveal_cone);
  F(gzl_foveal_cone, type);
  F(gzl_foveal_cone, next);
  F(gzl_foveal_cone, direction_in_view);
  F(gzl_foveal_cone, fovea_deg);
  F(gzl_foveal_cone, uncertainty_deg);
  F(gzl_foveal_cone, half_angle_deg);
  F(gzl_foveal_cone, center_u);
  F(gzl_foveal_cone, center_v);
  F(gzl_foveal_cone, radius_u);
  F(gzl_foveal_cone, radius_v);
  F(gzl_foveal_cone, in_view);

  S(gzl_frame_record);
  F(gzl_frame_record, type);
  F(gzl_frame_record, next);
  F(gzl_frame_record, display_time_ns);
  F(gzl_frame_record, head);
  F(gzl_frame_record, view_count);
  F(gzl_frame_record, views);
  F(gzl_frame_record, has_gaze_sample);
  F(gzl_frame_record, gaze_sample);

  if (out != stdout && fclose(out) != 0) {
    perror(argv[1]);
    return 1;
  }
  return 0;
}
