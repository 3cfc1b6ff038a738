(** * Assumptions.v — prints the axioms every claimed Theorem depends on.
    Run by [make check-assumptions] (see check_assumptions.sh), which fails
    unless every Theorem in the sources is listed here and each depends only
    on the standard library axioms of the real numbers. *)

From PhongApprox Require Import Span Duff Euler Derivative Symmetry Adaptive Angular Related.
From PhongApprox Require Import ClosedForms Angle.
From PhongApprox Require Import FastSetup.
From PhongApprox Require Import FloatModel Float Fixed.
From PhongApprox Require Import FloatModelK Profiles.

(** Span.v *)
Check eq_2_p_is_linear.
Print Assumptions eq_2_p_is_linear.
Check eq_3_q_is_quadratic.
Print Assumptions eq_3_q_is_quadratic.
Check eq_3_e_is_one.
Print Assumptions eq_3_e_is_one.
Check eq_10_q_is_one_on_edges.
Print Assumptions eq_10_q_is_one_on_edges.
Check eq_4_phong_exact_on_edges.
Print Assumptions eq_4_phong_exact_on_edges.
Check eq_18_na_k_is_minus_nb_k.
Print Assumptions eq_18_na_k_is_minus_nb_k.
Check eq_19_dqb_via_nb.
Print Assumptions eq_19_dqb_via_nb.
Check eq_20_n_k2_is_2k_nb.
Print Assumptions eq_20_n_k2_is_2k_nb.
Check eq_21_dqb_is_2k_nb.
Print Assumptions eq_21_dqb_is_2k_nb.
Check eq_22_dqb_is_minus_dqa.
Print Assumptions eq_22_dqb_is_minus_dqa.
Check eq_11_ds_closed_form.
Print Assumptions eq_11_ds_closed_form.

(** Duff.v *)
Check eq_5_7_duff_recurrence_exact.
Print Assumptions eq_5_7_duff_recurrence_exact.
Check eq_7_duff_dq0_and_d2q.
Print Assumptions eq_7_duff_dq0_and_d2q.
Check eq_5_7_duff_computes_phong.
Print Assumptions eq_5_7_duff_computes_phong.

(** Euler.v *)
Check eq_13_slope_closed_form.
Print Assumptions eq_13_slope_closed_form.
Check eq_14_euler_closed_form.
Print Assumptions eq_14_euler_closed_form.
Check eq_14_arithmetic_series.
Print Assumptions eq_14_arithmetic_series.
Check eq_14_euler_end_value.
Print Assumptions eq_14_euler_end_value.
Check eq_17_corrected_euler_starts_at_pa.
Print Assumptions eq_17_corrected_euler_starts_at_pa.
Check eq_17_corrected_euler_ends_at_pb.
Print Assumptions eq_17_corrected_euler_ends_at_pb.
Check eq_16_17_corrected_is_euler_minus_linear_error.
Print Assumptions eq_16_17_corrected_is_euler_minus_linear_error.
Check eq_15_euler_misses_pb.
Print Assumptions eq_15_euler_misses_pb.

(** Derivative.v *)
Check eq_9_derivative.
Print Assumptions eq_9_derivative.
Check eq_10_11_dp_dq_at_edges.
Print Assumptions eq_10_11_dp_dq_at_edges.
Check eq_10_11_edge_derivatives.
Print Assumptions eq_10_11_edge_derivatives.

(** Symmetry.v *)
Check sec_4_q_is_symmetric.
Print Assumptions sec_4_q_is_symmetric.
Check sec_4_dq_zero_at_middle.
Print Assumptions sec_4_dq_zero_at_middle.
Check sec_4_q_minimum_at_middle.
Print Assumptions sec_4_q_minimum_at_middle.
Check sec_4_symmetric_phong_equals_phong.
Print Assumptions sec_4_symmetric_phong_equals_phong.
Check sec_4_duff_q_is_symmetric.
Print Assumptions sec_4_duff_q_is_symmetric.

(** Adaptive.v *)
Check eq_23_m_is_half_n_minus_1.
Print Assumptions eq_23_m_is_half_n_minus_1.
Check eq_23_truncated_step_is_ceil_half.
Print Assumptions eq_23_truncated_step_is_ceil_half.
Check eq_24_gouraud_minus_corrected_euler.
Print Assumptions eq_24_gouraud_minus_corrected_euler.
Check eq_24_delta_closed_form.
Print Assumptions eq_24_delta_closed_form.
Check eq_24_delta_is_max_difference.
Print Assumptions eq_24_delta_is_max_difference.
Check eq_24_delta_test_does_not_imply_same_levels.
Print Assumptions eq_24_delta_test_does_not_imply_same_levels.
Check eq_24_delta_test_fails_on_concrete_span.
Print Assumptions eq_24_delta_test_fails_on_concrete_span.
Check eq_24_large_delta_implies_different_levels.
Print Assumptions eq_24_large_delta_implies_different_levels.

(** Angular.v *)
Check mortensen_equal_angles_counterexample.
Print Assumptions mortensen_equal_angles_counterexample.
Check mortensen_angle_not_linear.
Print Assumptions mortensen_angle_not_linear.
Check mortensen_unequal_angles_counterexample.
Print Assumptions mortensen_unequal_angles_counterexample.

(** Related.v *)
Check bishop_weimer_forward_differences_are_exact.
Print Assumptions bishop_weimer_forward_differences_are_exact.
Check seiler_forward_differences_are_exact.
Print Assumptions seiler_forward_differences_are_exact.
Check bishop_weimer_scanline_special_case.
Print Assumptions bishop_weimer_scanline_special_case.
Check seiler_is_exact_at_the_six_points.
Print Assumptions seiler_is_exact_at_the_six_points.
Check seiler_reproduces_quadratics.
Print Assumptions seiler_reproduces_quadratics.
Check spherical_recurrence_matches_closed_form.
Print Assumptions spherical_recurrence_matches_closed_form.
Check spherical_equals_phong_at_the_middle.
Print Assumptions spherical_equals_phong_at_the_middle.
Check vertex_angle_equal_angles_give_a_flat_polygon.
Print Assumptions vertex_angle_equal_angles_give_a_flat_polygon.

(** ClosedForms.v *)
Check eq_11_ds_unit_closed_form.
Print Assumptions eq_11_ds_unit_closed_form.
Check eq_15_eps_closed_form.
Print Assumptions eq_15_eps_closed_form.
Check eq_15_eps_limit.
Print Assumptions eq_15_eps_limit.
Check eq_15_euler_misses_pb_general.
Print Assumptions eq_15_euler_misses_pb_general.
Check eq_24_delta_unit_closed_form.
Print Assumptions eq_24_delta_unit_closed_form.
Check eq_23_24_paper_step_gives_delta.
Print Assumptions eq_23_24_paper_step_gives_delta.
Check eq_24_delta_test_does_not_imply_same_clamped_levels.
Print Assumptions eq_24_delta_test_does_not_imply_same_clamped_levels.
Check eq_24_delta_test_fails_on_concrete_span_clamped.
Print Assumptions eq_24_delta_test_fails_on_concrete_span_clamped.
Check eq_24_large_delta_implies_different_clamped_levels.
Print Assumptions eq_24_large_delta_implies_different_clamped_levels.
Check sec_4_symmetric_phong_algorithm.
Print Assumptions sec_4_symmetric_phong_algorithm.
Check eq_14_euler_sum_of_slopes.
Print Assumptions eq_14_euler_sum_of_slopes.

(** Angle.v *)
Check sec_7_phong_in_t.
Print Assumptions sec_7_phong_in_t.
Check sec_7_gouraud_in_t.
Print Assumptions sec_7_gouraud_in_t.
Check sec_7_corrected_euler_in_t.
Print Assumptions sec_7_corrected_euler_in_t.
Check sec_7_euler_in_t.
Print Assumptions sec_7_euler_in_t.
Check sec_7_error_sup_over_lights.
Print Assumptions sec_7_error_sup_over_lights.
Check sec_7_gouraud_angle_bound.
Print Assumptions sec_7_gouraud_angle_bound.
Check sec_7_corrected_euler_angle_table.
Print Assumptions sec_7_corrected_euler_angle_table.
Check sec_7_corrected_euler_one_level.
Print Assumptions sec_7_corrected_euler_one_level.
Check sec_7_euler_angle_bound.
Print Assumptions sec_7_euler_angle_bound.

(** FastSetup.v *)
Check fast_rows_ce_from_span_invariants.
Print Assumptions fast_rows_ce_from_span_invariants.
Check fast_rows_phong_from_span_invariants.
Print Assumptions fast_rows_phong_from_span_invariants.
Check fast_rows_field_span_identities.
Print Assumptions fast_rows_field_span_identities.
Check edge_stepped_setup_exact.
Print Assumptions edge_stepped_setup_exact.
Check rsqrt_newton_step_error.
Print Assumptions rsqrt_newton_step_error.

(** Float.v *)
Check float_gouraud_binary32.
Print Assumptions float_gouraud_binary32.
Check float_gouraud_binary64.
Print Assumptions float_gouraud_binary64.
Check float_corrected_euler_binary32.
Print Assumptions float_corrected_euler_binary32.
Check float_corrected_euler_binary64.
Print Assumptions float_corrected_euler_binary64.

(** Fixed.v *)
Check fixed_point_corrected_euler_error.
Print Assumptions fixed_point_corrected_euler_error.
Check fixed_point_gouraud_error.
Print Assumptions fixed_point_gouraud_error.
Check fixed_point_half_level_bits.
Print Assumptions fixed_point_half_level_bits.

(** Profiles.v *)
Check profile_ieee_gouraud_binary32.
Print Assumptions profile_ieee_gouraud_binary32.
Check profile_ieee_gouraud_binary64.
Print Assumptions profile_ieee_gouraud_binary64.
Check profile_ieee_gouraud_binary64_large.
Print Assumptions profile_ieee_gouraud_binary64_large.
Check profile_shader_gouraud_binary32.
Print Assumptions profile_shader_gouraud_binary32.
Check profile_ieee_corrected_euler_binary32.
Print Assumptions profile_ieee_corrected_euler_binary32.
Check profile_ieee_corrected_euler_binary64.
Print Assumptions profile_ieee_corrected_euler_binary64.
Check profile_shader_corrected_euler_binary32.
Print Assumptions profile_shader_corrected_euler_binary32.
Check profile_ieee_corrected_euler_closed_binary32.
Print Assumptions profile_ieee_corrected_euler_closed_binary32.
Check profile_ieee_corrected_euler_closed_binary64.
Print Assumptions profile_ieee_corrected_euler_closed_binary64.
Check profile_ieee_corrected_euler_binary64_large.
Print Assumptions profile_ieee_corrected_euler_binary64_large.
Check profile_ieee_corrected_euler_closed_binary64_large.
Print Assumptions profile_ieee_corrected_euler_closed_binary64_large.
Check profile_ieee_euler_binary32.
Print Assumptions profile_ieee_euler_binary32.
Check profile_ieee_euler_binary64.
Print Assumptions profile_ieee_euler_binary64.
Check profile_ieee_euler_binary64_large.
Print Assumptions profile_ieee_euler_binary64_large.
Check profile_shader_euler_binary32.
Print Assumptions profile_shader_euler_binary32.
Check profile_ieee_euler_closed_binary32.
Print Assumptions profile_ieee_euler_closed_binary32.
Check profile_ieee_euler_closed_binary64.
Print Assumptions profile_ieee_euler_closed_binary64.
Check profile_ieee_euler_closed_binary64_large.
Print Assumptions profile_ieee_euler_closed_binary64_large.
