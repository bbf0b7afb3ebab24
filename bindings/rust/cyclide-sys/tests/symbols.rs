//! Every declared function resolves in the linked libcyclide.so: taking each
//! address makes the linker resolve every symbol (a declaration the library
//! does not export fails to link), and a few calls check the ABI end to end.

use cyclide_sys::*;
use std::ffi::CStr;

#[test]
fn every_declared_function_is_exported() {
    let fns: &[*const ()] = &[
        cyc_version_number as *const (),
        cyc_version_string as *const (),
        cyc_abi_version as *const (),
        cyc_status_name as *const (),
        cyc_context_create as *const (),
        cyc_context_destroy as *const (),
        cyc_context_last_error as *const (),
        cyc_context_last_status as *const (),
        cyc_context_set_error_handler as *const (),
        cyc_context_static_size as *const (),
        cyc_surface_static_size as *const (),
        cyc_curve_static_size as *const (),
        cyc_context_init_static as *const (),
        cyc_context_static_remaining as *const (),
        cyc_curve_create_polynomial as *const (),
        cyc_curve_create_rational as *const (),
        cyc_curve_create_bezier as *const (),
        cyc_curve_create_line as *const (),
        cyc_curve_create_point as *const (),
        cyc_curve_create_line_element as *const (),
        cyc_curve_create_hermite as *const (),
        cyc_curve_destroy as *const (),
        cyc_curve_degree as *const (),
        cyc_curve_eval as *const (),
        cyc_prcs_create as *const (),
        cyc_prrs_create as *const (),
        cyc_ringed_create as *const (),
        cyc_surface_destroy as *const (),
        cyc_surface_kind as *const (),
        cyc_surface_domain as *const (),
        cyc_surface_eval as *const (),
        cyc_surface_eval_batch as *const (),
        cyc_surface_eval_grid as *const (),
        cyc_surface_circle as *const (),
        cyc_surface_sphere as *const (),
        cyc_surface_ringed_data as *const (),
        cyc_surface_ringed_sphere as *const (),
        cyc_surface_canal_test as *const (),
        cyc_surface_parameter_of as *const (),
        cyc_darboux_eval as *const (),
        cyc_darboux_classify as *const (),
        cyc_invert_point as *const (),
        cyc_invert_sphere as *const (),
        cyc_invert_circle as *const (),
        cyc_invert_darboux as *const (),
        cyc_surface_eval_inverted as *const (),
        cyc_surface_circle_inverted as *const (),
        cyc_surface_eval_grid_inverted as *const (),
        cyc_dcmc as *const (),
        cyc_parabolic_lines as *const (),
        cyc_pencil_circle as *const (),
        cyc_parabolic_parameterize as *const (),
        cyc_prrs_lines_analyze as *const (),
        cyc_prrs_lines_cyclide as *const (),
        cyc_darboux_fit_points as *const (),
        cyc_darboux_fit_surface as *const (),
        cyc_classify_two_lines as *const (),
        cyc_classify_line_element as *const (),
        cyc_classify_line_two_points as *const (),
        cyc_surface_derivatives_u as *const (),
        cyc_blend_canal as *const (),
        cyc_blend_ringed as *const (),
        cyc_blend_ringed_matched as *const (),
        cyc_blend_canal_spline as *const (),
        cyc_blend_ringed_spline as *const (),
        cyc_blend_ringed_spline_matched as *const (),
        cyc_surface_ringed_jet as *const (),
        cyc_pcurve_blend_options_init as *const (),
        cyc_blend_ringed_pcurve as *const (),
        cyc_ringed_field_options_init as *const (),
        cyc_ringed_dnr_create as *const (),
        cyc_ringed_sqrt_create as *const (),
        cyc_ringed_pcurve_create as *const (),
        cyc_blend_ringed_pcurve_bump as *const (),
        cyc_nway_options_init as *const (),
        cyc_blend_ringed_nway as *const (),
        cyc_nway_sphere_create as *const (),
        cyc_surface_sphere_clearance as *const (),
        cyc_surface_normal_deviance as *const (),
        cyc_surface_contour_points as *const (),
        cyc_ringed_contour_curves as *const (),
        cyc_continuity_report as *const (),
        cyc_optimizer_available as *const (),
        cyc_optimize_closest_point as *const (),
        cyc_blend_objective_init as *const (),
        cyc_optimize_options_init as *const (),
        cyc_optimize_blend as *const (),
        cyc_bump_objective_init as *const (),
        cyc_bump_options_init as *const (),
        cyc_optimize_pcurve_bump as *const (),
        cyc_optimize_blend_parameters as *const (),
        cyc_optimize_pcurve_bump_parameters as *const (),
        cyc_implicit_cylinder as *const (),
        cyc_implicit_cone as *const (),
        cyc_implicit_blend_eval as *const (),
        cyc_implicit_contour_points as *const (),
        cyc_implicit_approx_options_init as *const (),
        cyc_optimize_implicit_blend as *const (),
        cyc_skin_end_from_apex as *const (),
        cyc_skin_end_from_sphere as *const (),
        cyc_skin_end_sphere as *const (),
        cyc_skin_options_init as *const (),
        cyc_sphere_skin_create as *const (),
        cyc_sphere_skin_chain_create as *const (),
        cyc_sphere_skin_destroy as *const (),
        cyc_sphere_skin_patch_count as *const (),
        cyc_sphere_skin_eval as *const (),
        cyc_sphere_skin_eval_grid as *const (),
        cyc_sphere_skin_info_get as *const (),
        cyc_sphere_skin_twist as *const (),
        cyc_sphere_skin_lambda as *const (),
        cyc_sphere_skin_tessellation_workspace_size as *const (),
        cyc_sphere_skin_tessellate_plan as *const (),
        cyc_sphere_skin_tessellate_eval as *const (),
        cyc_skin_tangent_options_init as *const (),
        cyc_optimize_skin_tangents as *const (),
        cyc_lie_vector as *const (),
        cyc_lie_sphere_of as *const (),
        cyc_lie_dot as *const (),
        cyc_lie_in_contact as *const (),
        cyc_lie_span as *const (),
        cyc_lie_complement as *const (),
        cyc_lie_complement_signature as *const (),
        cyc_lie_witt_extension as *const (),
        cyc_lie_transform_translation as *const (),
        cyc_lie_transform_rotation as *const (),
        cyc_lie_transform_scaling as *const (),
        cyc_lie_transform_dilatation as *const (),
        cyc_lie_transform_inversion as *const (),
        cyc_lie_transform_orientation_reversal as *const (),
        cyc_lie_transform_compose as *const (),
        cyc_lie_transform_apply as *const (),
        cyc_lie_transform_classify as *const (),
        cyc_dupin_classify_spheres as *const (),
        cyc_dupin_from_spheres as *const (),
        cyc_dupin_from_vectors as *const (),
        cyc_dupin_from_subspace as *const (),
        cyc_dupin_swap_families as *const (),
        cyc_dupin_offset as *const (),
        cyc_dupin_eval as *const (),
        cyc_dupin_eval_homogeneous as *const (),
        cyc_dupin_sphere as *const (),
        cyc_dupin_eval_grid as *const (),
        cyc_dupin_surface_create as *const (),
        cyc_cone_from_spheres as *const (),
        cyc_cone_from_circle as *const (),
        cyc_cone_from_circle_apex as *const (),
        cyc_cone_from_surface as *const (),
        cyc_cone_circle as *const (),
        cyc_cone_surface_create as *const (),
        cyc_cyclide_blend_dimension as *const (),
        cyc_cyclide_blend_beta as *const (),
        cyc_cyclide_blend_build as *const (),
        cyc_cyclide_blend_auto as *const (),
        cyc_cyclide_blend_circle as *const (),
        cyc_cyclide_blend_quality as *const (),
        cyc_cyclide_blend_surface_create as *const (),
        cyc_cyclide_blend_continuity as *const (),
        cyc_cyclide_blend_objective_init as *const (),
        cyc_cyclide_blend_options_init as *const (),
        cyc_optimize_cyclide_blend as *const (),
        cyc_optimize_cyclide_blend_parameters as *const (),
        cyc_tessellation_options_default as *const (),
        cyc_tessellation_workspace_size as *const (),
        cyc_tessellate_plan as *const (),
        cyc_tessellate_eval as *const (),
        cyc_bezier_export_create as *const (),
        cyc_bezier_export_destroy as *const (),
        cyc_bezier_export_count as *const (),
        cyc_bezier_export_patch as *const (),
        cyc_bezier_export_eval as *const (),
        cyc_bezier_export_nurbs as *const (),
        cyc_export_tau_of_v as *const (),
        cyc_export_v_of_tau as *const (),
        cyc_mesh_write as *const (),
        cyc_bezier_export_write_json as *const (),
        cyc_skin_export_options_default as *const (),
        cyc_sphere_skin_export_create as *const (),
        cyc_laguerre_to_isotropic as *const (),
        cyc_isotropic_to_laguerre as *const (),
        cyc_cycle_paraboloid as *const (),
        cyc_paraboloid_contains as *const (),
        cyc_isotropic_translate as *const (),
        cyc_plane_translate as *const (),
        cyc_isotropic_dilatation as *const (),
        cyc_plane_dilatation as *const (),
        cyc_pn_surface_create as *const (),
        cyc_pn_surface_destroy as *const (),
        cyc_pn_surface_eval as *const (),
        cyc_pn_surface_eval_grid as *const (),
        cyc_parabolic_cyclide_from_quadratic as *const (),
        cyc_parabolic_cyclide_quadratic as *const (),
        cyc_parabolic_cyclide_eval as *const (),
        cyc_parabolic_cyclide_implicit as *const (),
        cyc_parabolic_cyclide_type as *const (),
        cyc_parabolic_cyclide_lines as *const (),
        cyc_parabolic_cyclide_u_circle as *const (),
        cyc_parabolic_cyclide_v_circle as *const (),
        cyc_parabolic_cyclide_cone as *const (),
        cyc_parabolic_cyclide_cubic_circle_point as *const (),
        cyc_parabolic_cyclide_net_projection as *const (),
        cyc_parabolic_cyclide_parameter_of as *const (),
        cyc_parabolic_cyclide_surface_create as *const (),
        cyc_cyclide_cubic_triangle as *const (),
        cyc_cyclide_bicubic_patch as *const (),
        cyc_cubic_triangle_eval as *const (),
        cyc_bicubic_patch_eval as *const (),
        cyc_delaunay_workspace_size as *const (),
        cyc_delaunay_max_triangles as *const (),
        cyc_delaunay_triangulate as *const (),
        cyc_powell_sabin_workspace_size as *const (),
        cyc_powell_sabin_interpolate as *const (),
        cyc_isotropic_datum_of as *const (),
        cyc_oriented_point_of as *const (),
        cyc_gauss_image_contains_pole as *const (),
        cyc_design_workspace_size as *const (),
        cyc_design_max_patches as *const (),
        cyc_design_cyclide_surface as *const (),
    ];
    assert_eq!(fns.len(), 218);
    assert!(fns.iter().all(|f| !f.is_null()));
}

#[test]
fn version_and_status_names() {
    unsafe {
        assert_eq!(cyc_abi_version(), CYC_ABI_VERSION);
        let v = CStr::from_ptr(cyc_version_string()).to_str().unwrap();
        assert!(!v.is_empty());
        let name = CStr::from_ptr(cyc_status_name(CYC_E_DEPENDENT_PLANES));
        assert_eq!(name.to_str().unwrap(), "CYC_E_DEPENDENT_PLANES");
    }
}

#[test]
fn raw_context_and_surface() {
    unsafe {
        let mut ctx: *mut cyc_context = std::ptr::null_mut();
        assert_eq!(cyc_context_create(std::ptr::null(), &mut ctx), CYC_OK);
        let (o, x, p, w) = (
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
            [2.0, 1.0, 0.0],
        );
        let mut l1 = std::ptr::null_mut();
        let mut l2 = std::ptr::null_mut();
        assert_eq!(
            cyc_curve_create_line(ctx, o.as_ptr(), x.as_ptr(), &mut l1),
            CYC_OK
        );
        assert_eq!(
            cyc_curve_create_line(ctx, p.as_ptr(), w.as_ptr(), &mut l2),
            CYC_OK
        );
        let mut s = std::ptr::null_mut();
        assert_eq!(
            cyc_prcs_create(ctx, l1, l2, std::ptr::null(), -0.5, 0.5, &mut s),
            CYC_OK
        );
        let mut kind = 0;
        assert_eq!(cyc_surface_kind(ctx, s, &mut kind), CYC_OK);
        assert_eq!(kind, CYC_SURFACE_PRCS);
        let mut pt = [0.0; 3];
        let mut n = [0.0; 3];
        let null = std::ptr::null_mut();
        assert_eq!(
            cyc_surface_eval(
                ctx,
                s,
                0.25,
                1.0,
                pt.as_mut_ptr(),
                null,
                null,
                n.as_mut_ptr()
            ),
            CYC_OK
        );
        assert!(((n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt() - 1.0).abs() < 1e-12);
        // A parallel pair of lines has parallel normal planes.
        let mut bad = std::ptr::null_mut();
        let mut l3 = std::ptr::null_mut();
        assert_eq!(
            cyc_curve_create_line(ctx, p.as_ptr(), x.as_ptr(), &mut l3),
            CYC_OK
        );
        let st = cyc_prcs_create(ctx, l1, l3, std::ptr::null(), -0.5, 0.5, &mut bad);
        assert_ne!(st, CYC_OK);
        assert_eq!(cyc_context_last_status(ctx), st);
        assert!(bad.is_null());
        assert!(!CStr::from_ptr(cyc_context_last_error(ctx))
            .to_bytes()
            .is_empty());
        cyc_surface_destroy(ctx, s);
        cyc_curve_destroy(ctx, l1);
        cyc_curve_destroy(ctx, l2);
        cyc_curve_destroy(ctx, l3);
        cyc_context_destroy(ctx);
    }
}
