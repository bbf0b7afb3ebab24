//! The layout of every #[repr(C)] struct against the C compiler's.
//!
//! tests/layout.c prints `size T SIZE ALIGN`, `offset T FIELD OFFSET SIZE` and
//! `const NAME VALUE` for every struct, field and constant of the header.
//! Its output is read from the file `CYCLIDE_LAYOUT_FILE` when that is set
//! (e.g. produced by a CTest step); otherwise this test compiles
//! tests/layout.c itself with `$CC` (default `cc`) against the header in
//! `CYCLIDE_INCLUDE_DIR` (or the include directory build.rs found) and runs
//! it. Every struct and constant printed must be checked here, and every
//! struct checked here must have been printed.

use cyclide_sys::*;
use std::collections::{HashMap, HashSet};
use std::mem::{align_of, size_of, MaybeUninit};
use std::path::PathBuf;
use std::process::Command;

fn layout_text() -> String {
    if let Some(file) = std::env::var_os("CYCLIDE_LAYOUT_FILE") {
        return std::fs::read_to_string(&file)
            .unwrap_or_else(|e| panic!("reading CYCLIDE_LAYOUT_FILE {:?}: {}", file, e));
    }
    let include = std::env::var("CYCLIDE_INCLUDE_DIR")
        .ok()
        .filter(|s| !s.is_empty())
        .or_else(|| option_env!("CYCLIDE_SYS_INCLUDE_DIR").map(String::from))
        .expect(
            "no header: set CYCLIDE_INCLUDE_DIR (the directory holding cyclide/cyclide.h) \
             or CYCLIDE_LAYOUT_FILE",
        );
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_string());
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("layout.c");
    let exe = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cyclide_layout");
    let st = Command::new(&cc)
        .arg("-std=c11")
        .arg("-I")
        .arg(&include)
        .arg(&src)
        .arg("-o")
        .arg(&exe)
        .status()
        .unwrap_or_else(|e| panic!("running the C compiler {:?}: {}", cc, e));
    assert!(st.success(), "{} failed to compile {:?}", cc, src);
    let out = Command::new(&exe)
        .output()
        .expect("running the layout program");
    assert!(out.status.success(), "the layout program failed");
    String::from_utf8(out.stdout).unwrap()
}

fn size_of_pointee<F>(_: *const F) -> usize {
    size_of::<F>()
}

fn offset_of_field<T, F>(base: &MaybeUninit<T>, field: *const F) -> usize {
    field as usize - base.as_ptr() as usize
}

#[test]
fn struct_layouts_and_constants_match_the_c_header() {
    let text = layout_text();
    let mut sizes: HashMap<String, (usize, usize)> = HashMap::new();
    let mut offsets: HashMap<(String, String), (usize, usize)> = HashMap::new();
    let mut consts: HashMap<String, i64> = HashMap::new();
    for line in text.lines() {
        let w: Vec<&str> = line.split_whitespace().collect();
        match w.as_slice() {
            ["size", t, s, a] => {
                sizes.insert(t.to_string(), (s.parse().unwrap(), a.parse().unwrap()));
            }
            ["offset", t, f, o, s] => {
                offsets.insert(
                    (t.to_string(), f.to_string()),
                    (o.parse().unwrap(), s.parse().unwrap()),
                );
            }
            ["const", k, v] => {
                consts.insert(k.to_string(), v.parse().unwrap());
            }
            _ => panic!("bad layout line {:?}", line),
        }
    }
    assert!(sizes.len() >= 75, "only {} structs printed", sizes.len());

    let mut failures: Vec<String> = Vec::new();
    let mut checked: HashSet<String> = HashSet::new();
    let mut fields_checked = 0usize;
    macro_rules! check {
        ($t:ident { $($f:ident),* $(,)? }) => {{
            let name = stringify!($t).to_string();
            match sizes.get(&name) {
                None => failures.push(format!("{}: not printed by layout.c", name)),
                Some(&(s, a)) => {
                    if size_of::<$t>() != s || align_of::<$t>() != a {
                        failures.push(format!(
                            "{}: Rust size/align {}/{}, C {}/{}",
                            name, size_of::<$t>(), align_of::<$t>(), s, a
                        ));
                    }
                }
            }
            let base = MaybeUninit::<$t>::uninit();
            let p = base.as_ptr();
            let mut nfields = 0usize;
            $(
                nfields += 1;
                // SAFETY: only the field's address is taken, nothing is read.
                let fp = unsafe { std::ptr::addr_of!((*p).$f) };
                let got = (offset_of_field(&base, fp), size_of_pointee(fp));
                let field = stringify!($f).trim_start_matches("r#").to_string();
                match offsets.get(&(name.clone(), field.clone())) {
                    None => failures.push(format!("{}.{}: not printed by layout.c", name, field)),
                    Some(&o) if o != got => failures.push(format!(
                        "{}.{}: Rust offset/size {:?}, C {:?}", name, field, got, o
                    )),
                    _ => {}
                }
            )*
            let c_fields = offsets.keys().filter(|(t, _)| *t == name).count();
            if c_fields != nfields {
                failures.push(format!("{}: {} fields in C, {} in Rust", name, c_fields, nfields));
            }
            fields_checked += nfields;
            checked.insert(name);
        }};
    }
    check!(cyc_sphere { center, radius2 });
    check!(cyc_circle {
        center,
        normal,
        radius2
    });
    check!(cyc_mobius {
        degree,
        alpha,
        beta,
        gamma,
        delta
    });
    check!(cyc_buffer3 {
        data,
        capacity,
        stride
    });
    check!(cyc_allocator {
        alloc,
        free,
        userdata
    });
    check!(cyc_darboux { k });
    check!(cyc_inversion { center, radius });
    check!(cyc_general_sphere { a, b, c });
    check!(cyc_circle_or_line {
        is_line,
        point,
        axis,
        radius
    });
    check!(cyc_line { point, direction });
    check!(cyc_cyclide_line {
        point,
        direction,
        t,
        multiplicity
    });
    check!(cyc_cyclide_lines {
        normal,
        plane_count,
        plane_t,
        plane_kind,
        line_count,
        lines,
        l0_circles,
        circle_families,
        double_families
    });
    check!(cyc_prrs_lines_analysis {
        coplanar_pair,
        common_parameter,
        a2,
        b2,
        a3,
        b3,
        x3,
        y3,
        cond55,
        cond56,
        pencil,
        cyclide,
        mu,
        l4
    });
    check!(cyc_darboux_fit {
        d,
        residual,
        sigma_ratio,
        nullity,
        points,
        is_darboux
    });
    check!(cyc_lines_classification {
        kind,
        paper_case,
        circle_families,
        double_families,
        pn,
        swapped,
        a,
        b,
        c,
        rotation,
        scale,
        origin,
        alpha,
        beta
    });
    check!(cyc_blend_end {
        surface,
        u,
        v,
        lambda,
        phi
    });
    check!(cyc_ringed_jet {
        d,
        dd,
        n,
        dn,
        rho,
        drho
    });
    check!(cyc_pcurve_blend_options { sign, tau, v });
    check!(cyc_ringed_field_options { method, v, which });
    check!(cyc_ringed_field_report {
        method,
        v,
        directions,
        sos_residual,
        sos_margin
    });
    check!(cyc_ringed_sqrt_report {
        field,
        exact_square,
        conic_residual,
        conic_degree
    });
    check!(cyc_directrix_bump { w, tau, kind });
    check!(cyc_nway_options {
        center,
        alpha,
        s,
        r,
        r_fraction,
        lambda,
        side,
        require_disjoint,
        auto_v,
        blend,
        auto_lambda
    });
    check!(cyc_nway_report {
        y,
        normal,
        alpha,
        s,
        r,
        bound,
        clear_bound,
        n_star,
        distance,
        theta,
        gap,
        nested,
        min_gap,
        worst_i,
        worst_j,
        end_jet,
        sphere_jet,
        v,
        failed_end,
        lambda
    });
    check!(cyc_continuity {
        K,
        samples,
        singular_samples,
        max_gap,
        point_scale,
        max_normal_angle,
        point_jump,
        point_scale_l,
        circle_jump
    });
    check!(cyc_blend_target { point, t });
    check!(cyc_blend_obstacle { center, radius });
    check!(cyc_blend_objective {
        fairness,
        regularity,
        min_determinant,
        min_speed,
        targets,
        target_count,
        target_weight,
        obstacles,
        obstacle_count,
        clearance,
        obstacle_weight,
        quadrature_t,
        quadrature_v
    });
    check!(cyc_optimize_options {
        free_orders,
        lambda_min_ratio,
        lambda_max_ratio,
        higher_bound,
        circle_parameter_range,
        max_iterations,
        function_tolerance,
        gradient_tolerance,
        parameter_tolerance
    });
    check!(cyc_optimize_summary {
        initial_cost,
        final_cost,
        iterations,
        seconds,
        termination,
        fairness,
        regularity,
        targets,
        obstacles,
        length_scale,
        fairness_scale
    });
    check!(cyc_bump_objective {
        deviance,
        obstacles,
        obstacle_count,
        clearance,
        obstacle_weight,
        nodes
    });
    check!(cyc_bump_options {
        w_bound,
        tau_min,
        tau_max,
        free_tau,
        max_iterations,
        function_tolerance,
        gradient_tolerance,
        parameter_tolerance
    });
    check!(cyc_free_parameter {
        role,
        index,
        order,
        lower,
        upper,
        start
    });
    check!(cyc_implicit_blend {
        f1,
        f2,
        f10,
        f20,
        lambda,
        n
    });
    check!(cyc_implicit_approx_options {
        pieces,
        psi_weight,
        nodes,
        length_min_ratio,
        length_max_ratio,
        max_iterations,
        function_tolerance,
        gradient_tolerance,
        parameter_tolerance,
        error_nodes_t,
        error_nodes_u,
        two_curves
    });
    check!(cyc_implicit_approx_report {
        pieces,
        omega,
        error87,
        seconds,
        omega_initial,
        omega_piece,
        error87_piece,
        alpha,
        beta,
        reverted
    });
    check!(cyc_skin_end {
        center,
        radius,
        tangent,
        inv_c
    });
    check!(cyc_skin_options {
        pairing,
        method,
        tolerance,
        reference,
        e
    });
    check!(cyc_sphere_skin_info {
        kappa,
        delta,
        rmf_substeps,
        rmf_error_estimate,
        spine,
        pairing,
        method
    });
    check!(cyc_skin_tangent_options {
        target,
        min_ratio,
        max_ratio,
        max_iterations
    });
    check!(cyc_skin_tangent_summary {
        scale,
        kappa_r_initial,
        kappa_r,
        iterations
    });
    check!(cyc_lie_sphere {
        kind,
        m,
        rho,
        n,
        lambda
    });
    check!(cyc_lie_transform { m });
    check!(cyc_dupin {
        theta,
        r#type,
        origin,
        unit
    });
    check!(cyc_dupin_point {
        point,
        normal,
        lambda,
        d_xi,
        d_zeta
    });
    check!(cyc_lie_cone { r0, r_plus });
    check!(cyc_cyclide_blend {
        pieces,
        branch,
        alpha,
        beta,
        joint,
        piece
    });
    check!(cyc_cyclide_blend_report { gap, angle, scale });
    check!(cyc_cyclide_blend_objective {
        fairness,
        joint_points,
        joint_point_count,
        joint_point_weight,
        joint_radius,
        joint_radius_weight,
        obstacles,
        obstacle_count,
        clearance,
        obstacle_weight,
        regularity,
        min_extent,
        circles
    });
    check!(cyc_cyclide_blend_options {
        samples,
        branch,
        max_iterations,
        function_tolerance,
        gradient_tolerance,
        parameter_tolerance
    });
    check!(cyc_tessellation_options {
        chordal_tolerance,
        min_segments,
        max_segments,
        fixed_segments,
        initial_rows,
        reference_u0,
        reference_u1
    });
    check!(cyc_tessellation_plan {
        rows,
        segments,
        phase0,
        phase1,
        max_radius,
        depth_limited
    });
    check!(cyc_export_domain {
        u0,
        u1,
        v0,
        v1,
        whole_circle
    });
    check!(cyc_bezier_patch_info {
        deg_u,
        deg_v,
        u0,
        u1,
        v0,
        v1,
        reciprocal_v
    });
    check!(cyc_nurbs_size {
        deg_u,
        deg_v,
        cp_u,
        cp_v,
        knots_u,
        knots_v
    });
    check!(cyc_grid_mesh {
        points,
        normals,
        stride,
        rows,
        cols,
        closed,
        rgba
    });
    check!(cyc_mesh_write_options {
        weld_tolerance,
        name
    });
    check!(cyc_mesh_stats {
        vertices,
        triangles,
        welded_rows,
        collapsed_rows,
        coordinate_sum,
        tolerance
    });
    check!(cyc_skin_export_options { tolerance, degree });
    check!(cyc_skin_export_report {
        error_estimate,
        rmf_error,
        exact,
        t_intervals
    });
    check!(cyc_oriented_plane { e0, e });
    check!(cyc_cycle { m, r });
    check!(cyc_isotropic_point { exceptional, y, c });
    check!(cyc_isotropic_paraboloid { k, l1, l2, c0 });
    check!(cyc_oriented_point { point, normal });
    check!(cyc_isotropic_datum { b, z, g });
    check!(cyc_graph_quadratic { q });
    check!(cyc_quadratic_graph_triangle { vertex, ordinate });
    check!(cyc_rational_cubic_triangle { control });
    check!(cyc_rational_bicubic_patch { control });
    check!(cyc_parabolic_cyclide {
        a,
        b,
        frame,
        origin
    });
    check!(cyc_revolution_cone {
        apex,
        axis,
        half_angle,
        cylinder,
        circle_and_line
    });
    check!(cyc_design_options { allow_ridges });
    check!(cyc_design_report {
        triangles,
        patches,
        orientation,
        ridge_patches,
        first_ridge_patch,
        first_bad_datum,
        patches_needed,
        work_needed
    });
    check!(cyc_pn_point {
        point,
        x_u,
        x_v,
        normal,
        plane,
        y
    });

    for t in sizes.keys() {
        if !checked.contains(t) {
            failures.push(format!(
                "{}: printed by layout.c but not checked in Rust",
                t
            ));
        }
    }
    for (k, v) in CONSTANTS {
        match consts.get(*k) {
            None => failures.push(format!("{}: not printed by layout.c", k)),
            Some(c) if c != v => failures.push(format!("{}: Rust {}, C {}", k, v, c)),
            _ => {}
        }
    }
    for k in consts.keys() {
        if !CONSTANTS.iter().any(|(n, _)| n == k) {
            failures.push(format!(
                "{}: printed by layout.c but not checked in Rust",
                k
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "layout mismatches:\n{}",
        failures.join("\n")
    );
    eprintln!(
        "checked {} structs, {} fields, {} constants",
        checked.len(),
        fields_checked,
        CONSTANTS.len()
    );
}

const CONSTANTS: &[(&str, i64)] = &[
    ("CYC_MAX_CURVE_DEGREE", CYC_MAX_CURVE_DEGREE as i64),
    ("CYC_MAX_HERMITE_ORDER", CYC_MAX_HERMITE_ORDER as i64),
    ("CYC_MAX_MOBIUS_DEGREE", CYC_MAX_MOBIUS_DEGREE as i64),
    ("CYC_ERROR_MESSAGE_SIZE", CYC_ERROR_MESSAGE_SIZE as i64),
    ("CYC_SURFACE_PRCS", CYC_SURFACE_PRCS as i64),
    ("CYC_SURFACE_PRRS", CYC_SURFACE_PRRS as i64),
    ("CYC_SURFACE_RINGED", CYC_SURFACE_RINGED as i64),
    ("CYC_SURFACE_DUPIN", CYC_SURFACE_DUPIN as i64),
    ("CYC_SURFACE_PARABOLIC", CYC_SURFACE_PARABOLIC as i64),
    ("CYC_DARBOUX_COEFFS", CYC_DARBOUX_COEFFS as i64),
    ("CYC_MAX_CYCLIDE_LINES", CYC_MAX_CYCLIDE_LINES as i64),
    ("CYC_MAX_SECTION_PLANES", CYC_MAX_SECTION_PLANES as i64),
    ("CYC_MIN_FIT_POINTS", CYC_MIN_FIT_POINTS as i64),
    ("CYC_MAX_FIT_POINTS", CYC_MAX_FIT_POINTS as i64),
    ("CYC_MAX_BLEND_ORDER", CYC_MAX_BLEND_ORDER as i64),
    ("CYC_MAX_SPLINE_KNOTS", CYC_MAX_SPLINE_KNOTS as i64),
    ("CYC_RINGED_FIELD_AUTO", CYC_RINGED_FIELD_AUTO as i64),
    (
        "CYC_RINGED_FIELD_PROJECTION",
        CYC_RINGED_FIELD_PROJECTION as i64,
    ),
    (
        "CYC_RINGED_FIELD_QUADRATIC",
        CYC_RINGED_FIELD_QUADRATIC as i64,
    ),
    ("CYC_RINGED_FIELD_SOS", CYC_RINGED_FIELD_SOS as i64),
    ("CYC_BUMP_SINGLE", CYC_BUMP_SINGLE as i64),
    ("CYC_BUMP_TWO_PIECE", CYC_BUMP_TWO_PIECE as i64),
    ("CYC_NWAY_MAX_ENDS", CYC_NWAY_MAX_ENDS as i64),
    ("CYC_NWAY_CENTER_AUTO", CYC_NWAY_CENTER_AUTO as i64),
    ("CYC_NWAY_CENTER_ALPHA", CYC_NWAY_CENTER_ALPHA as i64),
    ("CYC_NWAY_CENTER_GIVEN", CYC_NWAY_CENTER_GIVEN as i64),
    ("CYC_NWAY_SIDE_FACING", CYC_NWAY_SIDE_FACING as i64),
    ("CYC_NWAY_SIDE_PRINTED", CYC_NWAY_SIDE_PRINTED as i64),
    ("CYC_BLEND_CANAL", CYC_BLEND_CANAL as i64),
    ("CYC_BLEND_RINGED", CYC_BLEND_RINGED as i64),
    ("CYC_MAX_QUADRATURE", CYC_MAX_QUADRATURE as i64),
    ("CYC_OPTIMIZE_CONVERGED", CYC_OPTIMIZE_CONVERGED as i64),
    (
        "CYC_OPTIMIZE_ITERATION_LIMIT",
        CYC_OPTIMIZE_ITERATION_LIMIT as i64,
    ),
    ("CYC_OPTIMIZE_REVERTED", CYC_OPTIMIZE_REVERTED as i64),
    ("CYC_PARAMETER_JET", CYC_PARAMETER_JET as i64),
    (
        "CYC_PARAMETER_BUMP_DISPLACEMENT",
        CYC_PARAMETER_BUMP_DISPLACEMENT as i64,
    ),
    (
        "CYC_PARAMETER_BUMP_POSITION",
        CYC_PARAMETER_BUMP_POSITION as i64,
    ),
    (
        "CYC_PARAMETER_CIRCLE_POINT",
        CYC_PARAMETER_CIRCLE_POINT as i64,
    ),
    ("CYC_PARAMETER_FAMILY", CYC_PARAMETER_FAMILY as i64),
    (
        "CYC_MAX_IMPLICIT_EXPONENT",
        CYC_MAX_IMPLICIT_EXPONENT as i64,
    ),
    ("CYC_MAX_IMPLICIT_PIECES", CYC_MAX_IMPLICIT_PIECES as i64),
    ("CYC_SKIN_RMF", CYC_SKIN_RMF as i64),
    ("CYC_SKIN_KUNKLI_HOFFMANN", CYC_SKIN_KUNKLI_HOFFMANN as i64),
    ("CYC_SKIN_CROSS_TANGENTS", CYC_SKIN_CROSS_TANGENTS as i64),
    ("CYC_RMF_REFERENCE", CYC_RMF_REFERENCE as i64),
    (
        "CYC_RMF_DOUBLE_REFLECTION",
        CYC_RMF_DOUBLE_REFLECTION as i64,
    ),
    ("CYC_LIE_SPHERE", CYC_LIE_SPHERE as i64),
    ("CYC_LIE_POINT", CYC_LIE_POINT as i64),
    ("CYC_LIE_PLANE", CYC_LIE_PLANE as i64),
    (
        "CYC_LIE_POINT_AT_INFINITY",
        CYC_LIE_POINT_AT_INFINITY as i64,
    ),
    ("CYC_DUPIN_DEGENERATE", CYC_DUPIN_DEGENERATE as i64),
    ("CYC_DUPIN_PARABOLIC", CYC_DUPIN_PARABOLIC as i64),
    ("CYC_DUPIN_QUARTIC", CYC_DUPIN_QUARTIC as i64),
    ("CYC_MAX_CIRCLE_SEGMENTS", CYC_MAX_CIRCLE_SEGMENTS as i64),
    ("CYC_MAX_EXPORT_PATCHES", CYC_MAX_EXPORT_PATCHES as i64),
    ("CYC_MAX_PN_DEGREE", CYC_MAX_PN_DEGREE as i64),
    ("CYC_OK", CYC_OK as i64),
    ("CYC_E_NULL_ARGUMENT", CYC_E_NULL_ARGUMENT as i64),
    ("CYC_E_INVALID_ARGUMENT", CYC_E_INVALID_ARGUMENT as i64),
    ("CYC_E_NOT_FINITE", CYC_E_NOT_FINITE as i64),
    ("CYC_E_DEGREE_TOO_HIGH", CYC_E_DEGREE_TOO_HIGH as i64),
    ("CYC_E_BAD_DOMAIN", CYC_E_BAD_DOMAIN as i64),
    ("CYC_E_DEPENDENT_PLANES", CYC_E_DEPENDENT_PLANES as i64),
    ("CYC_E_ZERO_TANGENT", CYC_E_ZERO_TANGENT as i64),
    ("CYC_E_COLLINEAR_POINTS", CYC_E_COLLINEAR_POINTS as i64),
    (
        "CYC_E_DEGENERATE_CIRCLE_PARAMETER",
        CYC_E_DEGENERATE_CIRCLE_PARAMETER as i64,
    ),
    ("CYC_E_NOT_CANAL", CYC_E_NOT_CANAL as i64),
    ("CYC_E_SINGULAR_POINT", CYC_E_SINGULAR_POINT as i64),
    ("CYC_E_DEGENERATE_RINGED", CYC_E_DEGENERATE_RINGED as i64),
    ("CYC_E_PARALLEL_LINES", CYC_E_PARALLEL_LINES as i64),
    ("CYC_E_NO_COMMON_NORMAL", CYC_E_NO_COMMON_NORMAL as i64),
    ("CYC_E_RANK_DEFICIENT", CYC_E_RANK_DEFICIENT as i64),
    (
        "CYC_E_AT_INVERSION_CENTER",
        CYC_E_AT_INVERSION_CENTER as i64,
    ),
    ("CYC_E_NOT_PARABOLIC", CYC_E_NOT_PARABOLIC as i64),
    ("CYC_E_EMPTY_REAL_LOCUS", CYC_E_EMPTY_REAL_LOCUS as i64),
    ("CYC_E_TOO_FEW_LINES", CYC_E_TOO_FEW_LINES as i64),
    ("CYC_E_NO_NORMAL_FORM", CYC_E_NO_NORMAL_FORM as i64),
    ("CYC_E_NOT_PYTHAGOREAN", CYC_E_NOT_PYTHAGOREAN as i64),
    (
        "CYC_E_INTERSECTING_CIRCLES",
        CYC_E_INTERSECTING_CIRCLES as i64,
    ),
    ("CYC_E_NESTED_SPHERES", CYC_E_NESTED_SPHERES as i64),
    (
        "CYC_E_CURVATURE_RADIUS_TOO_LARGE",
        CYC_E_CURVATURE_RADIUS_TOO_LARGE as i64,
    ),
    ("CYC_E_SPHERE_PENCIL", CYC_E_SPHERE_PENCIL as i64),
    ("CYC_E_NO_TOUCHING_SPHERE", CYC_E_NO_TOUCHING_SPHERE as i64),
    (
        "CYC_E_SINGLE_TOUCHING_SPHERE",
        CYC_E_SINGLE_TOUCHING_SPHERE as i64,
    ),
    ("CYC_E_DEGENERATE_CYCLIDE", CYC_E_DEGENERATE_CYCLIDE as i64),
    ("CYC_E_NOT_ISOMETRIC", CYC_E_NOT_ISOMETRIC as i64),
    ("CYC_E_NOT_ON_LIE_QUADRIC", CYC_E_NOT_ON_LIE_QUADRIC as i64),
    ("CYC_E_POINT_AT_INFINITY", CYC_E_POINT_AT_INFINITY as i64),
    (
        "CYC_E_TANGENT_GENERATING_SPHERES",
        CYC_E_TANGENT_GENERATING_SPHERES as i64,
    ),
    ("CYC_E_BLEND_FOLDS", CYC_E_BLEND_FOLDS as i64),
    ("CYC_E_DEVELOPABLE", CYC_E_DEVELOPABLE as i64),
    (
        "CYC_E_POLE_IN_GAUSS_IMAGE",
        CYC_E_POLE_IN_GAUSS_IMAGE as i64,
    ),
    ("CYC_E_RIDGE", CYC_E_RIDGE as i64),
    ("CYC_E_NUMERICAL_OVERFLOW", CYC_E_NUMERICAL_OVERFLOW as i64),
    ("CYC_E_BUFFER_TOO_SMALL", CYC_E_BUFFER_TOO_SMALL as i64),
    ("CYC_E_OUT_OF_MEMORY", CYC_E_OUT_OF_MEMORY as i64),
    ("CYC_E_IO", CYC_E_IO as i64),
    ("CYC_E_UNSUPPORTED", CYC_E_UNSUPPORTED as i64),
    ("CYC_E_INTERNAL", CYC_E_INTERNAL as i64),
    ("CYC_DARBOUX_ZERO", CYC_DARBOUX_ZERO as i64),
    ("CYC_DARBOUX_QUARTIC", CYC_DARBOUX_QUARTIC as i64),
    ("CYC_DARBOUX_PARABOLIC", CYC_DARBOUX_PARABOLIC as i64),
    ("CYC_DARBOUX_QUADRIC", CYC_DARBOUX_QUADRIC as i64),
    ("CYC_DARBOUX_PLANE", CYC_DARBOUX_PLANE as i64),
    ("CYC_DARBOUX_CONSTANT", CYC_DARBOUX_CONSTANT as i64),
    ("CYC_DARBOUX_REDUCIBLE", CYC_DARBOUX_REDUCIBLE as i64),
    ("CYC_SECTION_LINE_PAIR", CYC_SECTION_LINE_PAIR as i64),
    ("CYC_SECTION_DOUBLE_LINE", CYC_SECTION_DOUBLE_LINE as i64),
    (
        "CYC_SECTION_IMAGINARY_PAIR",
        CYC_SECTION_IMAGINARY_PAIR as i64,
    ),
    ("CYC_SECTION_LINE_AND_L0", CYC_SECTION_LINE_AND_L0 as i64),
    ("CYC_CYCLIDE_HYPERBOLOID", CYC_CYCLIDE_HYPERBOLOID as i64),
    (
        "CYC_CYCLIDE_PARABOLIC_DARBOUX",
        CYC_CYCLIDE_PARABOLIC_DARBOUX as i64,
    ),
    (
        "CYC_CYCLIDE_PARABOLIC_DUPIN",
        CYC_CYCLIDE_PARABOLIC_DUPIN as i64,
    ),
    ("CYC_MESH_OBJ", CYC_MESH_OBJ as i64),
    ("CYC_MESH_PLY", CYC_MESH_PLY as i64),
    ("CYC_MESH_STL", CYC_MESH_STL as i64),
    ("CYC_MESH_GLB", CYC_MESH_GLB as i64),
    ("CYC_PARABOLIC_HORN", CYC_PARABOLIC_HORN as i64),
    ("CYC_PARABOLIC_RING", CYC_PARABOLIC_RING as i64),
    ("CYC_PARABOLIC_THORN", CYC_PARABOLIC_THORN as i64),
    ("CYC_PARABOLIC_SPHERE", CYC_PARABOLIC_SPHERE as i64),
    ("CYC_PARABOLIC_POINT", CYC_PARABOLIC_POINT as i64),
    ("CYC_ABI_VERSION", CYC_ABI_VERSION as i64),
];
