//! The safe wrapper end to end: a canal blend of two cones built and
//! evaluated, error paths, sphere skins and exports, meshes, Drop, threads.

use cyclide::{
    sys, BlendEnd, Context, Curve, ExportDomain, MeshFormat, MeshGrid, SphereSkin, Status, Surface,
};
use std::os::raw::c_void;
use std::path::PathBuf;
use std::sync::atomic::{AtomicIsize, AtomicUsize, Ordering};
use std::sync::Arc;

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// The cone of tests/capi_test.c (Fig. 6): PRRS of three lines through the
/// apex along cos t e1 + sin t e2 + e3, u in [0.5, 1].
fn cone(ctx: &Context, apex: [f64; 3], e1: [f64; 3], e2: [f64; 3], e3: [f64; 3]) -> Surface {
    let lines: Vec<Curve> = (0..3)
        .map(|k| {
            let t = 2.0 * std::f64::consts::PI * k as f64 / 3.0 + 0.3;
            let mut d = [0.0; 3];
            for j in 0..3 {
                d[j] = t.cos() * e1[j] + t.sin() * e2[j] + e3[j];
            }
            Curve::line(ctx, apex, d).unwrap()
        })
        .collect();
    Surface::prrs(ctx, &lines[0], &lines[1], &lines[2], None, 0.5, 1.0).unwrap()
}

fn cones(ctx: &Context) -> (Surface, Surface) {
    let (o, a2) = ([0.0, 0.0, 0.0], [4.0, 0.0, 4.0]);
    let (x, y, z, mx) = (
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [-1.0, 0.0, 0.0],
    );
    (cone(ctx, o, x, y, z), cone(ctx, a2, y, z, mx))
}

fn on_circle(c: &cyclide::Circle, p: [f64; 3]) -> f64 {
    let d = sub(p, c.center);
    (dot(d, c.normal))
        .abs()
        .max((norm(d) - c.radius2.sqrt()).abs())
}

fn tmp(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name)
}

#[test]
fn canal_blend_of_two_cones() {
    let ctx = Context::new().unwrap();
    let (a, b) = cones(&ctx);
    assert_eq!(a.kind(&ctx).unwrap(), cyclide::SurfaceKind::Prrs);
    let v = [f64::INFINITY, -0.5, 0.7];
    let start = BlendEnd::new(&a, 1.0, v);
    let end = BlendEnd::new(&b, 1.0, v);
    let blend = Surface::blend_canal(&ctx, &start, &end, 2, 0.0, 1.0).unwrap();
    assert_eq!(blend.kind(&ctx).unwrap(), cyclide::SurfaceKind::Prcs);
    assert_eq!(blend.domain(&ctx).unwrap(), (0.0, 1.0));

    // The blend starts on a's end circle and ends on b's.
    let (ca, cb) = (a.circle(&ctx, 1.0).unwrap(), b.circle(&ctx, 1.0).unwrap());
    let scale = 1.0 + ca.radius2.sqrt() + cb.radius2.sqrt();
    for k in 0..16 {
        let vv = -4.0 + 0.5 * k as f64;
        assert!(on_circle(&ca, blend.point(&ctx, 0.0, vv).unwrap()) < 1e-9 * scale);
        assert!(on_circle(&cb, blend.point(&ctx, 1.0, vv).unwrap()) < 1e-9 * scale);
    }
    // G^1 at the start: the blend's normal there is the cone's (up to sign).
    let p = blend.eval(&ctx, 0.0, 0.3).unwrap();
    let u_a = 1.0;
    let mut best = f64::INFINITY;
    for k in 0..=4000 {
        let vv = -20.0 + 0.01 * k as f64;
        if let Ok(q) = a.eval(&ctx, u_a, vv) {
            if norm(sub(q.point, p.point)) < 1e-2 {
                best = best.min(1.0 - dot(q.normal, p.normal).abs());
            }
        }
    }
    assert!(best < 1e-3, "normal mismatch {}", best);

    // A grid: unit normals orthogonal to both partials; the grid equals
    // pointwise evaluation.
    let us: Vec<f64> = (0..=10).map(|i| i as f64 / 10.0).collect();
    let vs: Vec<f64> = (0..=12).map(|j| -3.0 + 0.5 * j as f64).collect();
    let g = blend.eval_grid(&ctx, &us, &vs).unwrap();
    assert_eq!((g.rows, g.cols, g.points.len()), (11, 13, 143));
    assert_eq!(g.singular, 0);
    for (i, &u) in us.iter().enumerate() {
        for (j, &vv) in vs.iter().enumerate() {
            let n = g.normals[i * vs.len() + j];
            assert!((norm(n) - 1.0).abs() < 1e-12);
            let e = blend.eval(&ctx, u, vv).unwrap();
            assert_eq!(e.point, g.points[i * vs.len() + j]);
            assert!(dot(e.du, n).abs() <= 1e-9 * norm(e.du) + 1e-12);
            assert!(dot(e.dv, n).abs() <= 1e-9 * norm(e.dv) + 1e-12);
        }
    }
    // Slices: a short buffer is an error and nothing is written.
    let mut small = vec![[7.0; 3]; 10];
    let err = blend
        .eval_grid_into(&ctx, &us, &vs, &mut small, None)
        .unwrap_err();
    assert_eq!(err.status(), Status::BufferTooSmall);
    assert!(small.iter().all(|p| *p == [7.0; 3]));
    // The canal blend's spheres: the point lies on the touching sphere.
    let s = blend.sphere(&ctx, 0.5).unwrap();
    let q = blend.point(&ctx, 0.5, 0.1).unwrap();
    assert!((norm(sub(q, s.center)) - s.radius2.sqrt()).abs() < 1e-9 * scale);

    // A ringed blend too, and the cones, blends and a mesh written welded.
    let ringed = Surface::blend_ringed(&ctx, &start, &end, 1, 0.0, 1.0).unwrap();
    assert_eq!(ringed.kind(&ctx).unwrap(), cyclide::SurfaceKind::Prrs);
    let mut o = cyclide::tessellation_options();
    o.chordal_tolerance = 1e-2;
    let meshes: Vec<cyclide::Grid> = [&a, &blend, &b]
        .iter()
        .map(|s| s.tessellate(&ctx, &o).unwrap())
        .collect();
    let grids: Vec<MeshGrid> = meshes
        .iter()
        .map(|m| MeshGrid::from_grid(m, true))
        .collect();
    let path = tmp("blend.obj");
    let stats =
        cyclide::write_mesh(&ctx, &path, MeshFormat::Obj, &grids, Some("blend"), -1.0).unwrap();
    assert!(stats.triangles > 0 && stats.vertices > 0);
    assert!(std::fs::metadata(&path).unwrap().len() > 0);
}

#[test]
fn curves() {
    let ctx = Context::new().unwrap();
    let c = Curve::polynomial(&ctx, &[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]).unwrap();
    assert_eq!(c.degree(&ctx).unwrap(), 2);
    let d = c.eval(&ctx, 2.0, 2).unwrap();
    assert_eq!(d, vec![[1.0, 2.0, 4.0], [0.0, 1.0, 4.0], [0.0, 0.0, 2.0]]);
    // The unit circle as a rational curve ((1 - u^2), 2u, 0) / (1 + u^2).
    let r = Curve::rational(
        &ctx,
        &[
            [1.0, 0.0, 0.0, 1.0],
            [0.0, 2.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0, 1.0],
        ],
    )
    .unwrap();
    let p = r.eval(&ctx, 0.37, 0).unwrap()[0];
    assert!((norm(p) - 1.0).abs() < 1e-15);
    let bz = Curve::bezier(
        &ctx,
        &[[0.0; 3], [1.0, 1.0, 0.0], [2.0, 0.0, 0.0]],
        Some(&[1.0, 2.0, 1.0]),
        0.0,
        1.0,
    )
    .unwrap();
    assert_eq!(bz.eval(&ctx, 1.0, 0).unwrap()[0], [2.0, 0.0, 0.0]);
    let h = Curve::hermite(
        &ctx,
        0.0,
        1.0,
        &[[0.0; 3], [1.0, 0.0, 0.0]],
        &[[1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
    )
    .unwrap();
    assert_eq!(h.degree(&ctx).unwrap(), 3);
    let le = Curve::line_element(&ctx, [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]).unwrap();
    let l = Curve::line(&ctx, [0.0; 3], [1.0, 0.0, 0.0]).unwrap();
    let s = Surface::prcs(&ctx, &l, &le, None, -0.5, 0.5).unwrap();
    assert!(s.eval(&ctx, 0.2, 0.4).is_ok());
    let pt = Curve::point(&ctx, [0.0, 1.0, 0.0]).unwrap();
    assert!(Surface::prrs(&ctx, &l, &pt, &le, None, 0.0, 1.0).is_err()); // a line element is no PRRS input
}

#[test]
fn errors_carry_status_and_message() {
    let ctx = Context::new().unwrap();
    let l1 = Curve::line(&ctx, [0.0; 3], [1.0, 0.0, 0.0]).unwrap();
    let l2 = Curve::line(&ctx, [0.0, 0.0, 1.0], [2.0, 1.0, 0.0]).unwrap();
    let parallel = Curve::line(&ctx, [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]).unwrap();

    // PRCS of parallel lines: parallel normal planes.
    let e = Surface::prcs(&ctx, &l1, &parallel, None, -0.5, 0.5).unwrap_err();
    assert_eq!(e.status(), Status::DependentPlanes);
    assert_eq!(e.code(), sys::CYC_E_DEPENDENT_PLANES);
    assert!(!e.message().is_empty());
    assert!(
        e.to_string().starts_with("CYC_E_DEPENDENT_PLANES (100): "),
        "{}",
        e
    );
    assert_eq!(ctx.last_status(), sys::CYC_E_DEPENDENT_PLANES);

    // NaN inputs.
    let e = Curve::line(&ctx, [f64::NAN, 0.0, 0.0], [1.0, 0.0, 0.0]).unwrap_err();
    assert_eq!(e.status(), Status::NotFinite);
    assert!(!e.message().is_empty());
    let e = Surface::prcs(&ctx, &l1, &l2, None, f64::NAN, 0.5).unwrap_err();
    assert_eq!(e.status(), Status::NotFinite);
    let s = Surface::prcs(&ctx, &l1, &l2, None, -0.5, 0.5).unwrap();
    let e = s.eval(&ctx, f64::NAN, 0.0).unwrap_err();
    assert_eq!(e.status(), Status::NotFinite);
    assert!(!e.message().is_empty());
    // Success clears the message.
    s.eval(&ctx, 0.25, 1.0).unwrap();
    assert_eq!(ctx.last_error(), "");
    assert_eq!(ctx.last_status(), 0);

    // Domains, orders, files.
    assert_eq!(
        Surface::prcs(&ctx, &l1, &l2, None, 0.5, -0.5)
            .unwrap_err()
            .status(),
        Status::BadDomain
    );
    assert_eq!(s.sphere(&ctx, 0.0).map(|_| ()), Ok(()));
    let (a, b) = cones(&ctx);
    let v = [f64::INFINITY, -0.5, 0.7];
    let e = Surface::blend_canal(
        &ctx,
        &BlendEnd::new(&a, 1.0, v),
        &BlendEnd::new(&b, 1.0, v),
        1,
        0.0,
        1.0,
    )
    .unwrap_err();
    assert_eq!(e.status(), Status::InvalidArgument);
    assert_eq!(a.sphere(&ctx, 0.7).unwrap_err().status(), Status::NotCanal);
    let g = s.eval_grid(&ctx, &[0.0, 0.1], &[0.0, 1.0, 2.0]).unwrap();
    let grids = [MeshGrid::from_grid(&g, false)];
    let e = cyclide::write_mesh(
        &ctx,
        "/nonexistent-dir/x.obj",
        MeshFormat::Obj,
        &grids,
        None,
        0.0,
    )
    .unwrap_err();
    assert_eq!(e.status(), Status::Io);
    assert!(!e.message().is_empty());
    let e = cyclide::write_mesh(&ctx, "bad\0path", MeshFormat::Obj, &grids, None, 0.0).unwrap_err();
    assert_eq!(e.status(), Status::InvalidArgument);
    assert_eq!(cyclide::status_name(sys::CYC_E_RIDGE), "CYC_E_RIDGE");
    assert_eq!(Status::from_code(9999), Status::Unknown);
}

/// The skew spheres of tests/sphere_skin_capi_test.cpp.
fn skin_ends(ctx: &Context) -> (cyclide::SkinEnd, cyclide::SkinEnd) {
    let s = cyclide::skin_end_from_sphere(ctx, [0.0; 3], 1.0, [0.3, 0.0, 0.0], [3.0, 0.0, 0.0])
        .unwrap();
    let l = norm([1.0, 0.6, 0.8]);
    let axis = [1.0 / l, 0.6 / l, 0.8 / l];
    let p = [
        4.0 - 0.4 * axis[0],
        1.0 - 0.4 * axis[1],
        0.5 - 0.4 * axis[2],
    ];
    let t = [3.0 * axis[0], 3.0 * axis[1], 3.0 * axis[2]];
    let e = cyclide::skin_end_from_sphere(ctx, [4.0, 1.0, 0.5], 1.2, p, t).unwrap();
    (s, e)
}

#[test]
fn sphere_skin_and_export() {
    let ctx = Context::new().unwrap();
    let (s, e) = skin_ends(&ctx);
    let skin = SphereSkin::new(&ctx, &s, &e, Some(&cyclide::skin_options())).unwrap();
    assert_eq!(skin.patch_count(&ctx).unwrap(), 1);
    let p = skin.eval(&ctx, 0, 0.4, 0.0).unwrap();
    // t = 0 lies on the start sphere.
    let (mut m, mut r) = ([0.0; 3], 0.0);
    unsafe { sys::cyc_skin_end_sphere(&s, m.as_mut_ptr(), &mut r) };
    assert!((norm(sub(p.point, m)) - r).abs() < 1e-9);
    assert!((norm(p.normal) - 1.0).abs() < 1e-12);
    let thetas: Vec<f64> = (0..8).map(|i| i as f64 * 0.7).collect();
    let ts: Vec<f64> = (0..=4).map(|j| j as f64 / 4.0).collect();
    let g = skin.eval_grid(&ctx, 0, &thetas, &ts).unwrap();
    assert_eq!(g.points.len(), 40);
    assert_eq!(
        g.points[3 * 8 + 5],
        skin.eval(&ctx, 0, thetas[5], ts[3]).unwrap().point
    );
    assert_eq!(
        skin.eval(&ctx, 1, 0.0, 0.0).unwrap_err().status(),
        Status::InvalidArgument
    );
    assert_eq!(
        skin.eval(&ctx, 0, 0.0, 1.5).unwrap_err().status(),
        Status::BadDomain
    );

    let mut o = cyclide::skin_export_options();
    o.tolerance = 1e-6;
    let whole = ExportDomain {
        u0: 0.0,
        u1: 1.0,
        v0: 0.0,
        v1: 0.0,
        whole_circle: 1,
    };
    let (export, rep) = skin.export(&ctx, &whole, Some(&o)).unwrap();
    assert!(!export.is_empty());
    assert!(rep.error_estimate <= 1e-6 && rep.t_intervals >= 1);
    let (info, control) = export.patch(&ctx, 0).unwrap();
    assert_eq!(
        control.len(),
        (info.deg_u as usize + 1) * (info.deg_v as usize + 1)
    );
    assert!(control.iter().all(|c| c[0] > 0.0));
    let (x, uv) = export.eval(&ctx, 0, 0.5, 0.5).unwrap();
    let theta = 2.0 * uv[1].atan();
    let y = skin.eval(&ctx, 0, theta, uv[0]).unwrap().point;
    assert!(norm(sub(x, y)) < 1e-5, "{:?} {:?}", x, y);
    let json = tmp("skin.json");
    export.write_json(&ctx, &json).unwrap();
    assert!(std::fs::read_to_string(&json)
        .unwrap()
        .contains("cyclide-rational-bezier"));
    assert_eq!(
        export.patch(&ctx, export.len()).unwrap_err().status(),
        Status::InvalidArgument
    );

    // A chain of three spheres and a surface export.
    let mid =
        cyclide::skin_end_from_sphere(&ctx, [2.0, 0.0, 0.0], 0.5, [2.0, 0.0, 0.0], [1.0, 0.0, 0.0])
            .unwrap();
    let far =
        cyclide::skin_end_from_sphere(&ctx, [4.0, 0.0, 0.0], 1.0, [3.7, 0.0, 0.0], [3.0, 0.0, 0.0])
            .unwrap();
    let chain = SphereSkin::chain(&ctx, &[s, mid, far], None).unwrap();
    assert_eq!(chain.patch_count(&ctx).unwrap(), 2);
    let l1 = Curve::line(&ctx, [0.0; 3], [1.0, 0.0, 0.0]).unwrap();
    let l2 = Curve::line(&ctx, [0.0, 0.0, 1.0], [2.0, 1.0, 0.0]).unwrap();
    let surf = Surface::prcs(&ctx, &l1, &l2, None, -0.5, 0.5).unwrap();
    let e2 = surf
        .bezier_export(
            &ctx,
            &ExportDomain {
                u0: -0.5,
                u1: 0.5,
                v0: 0.0,
                v1: 0.0,
                whole_circle: 1,
            },
        )
        .unwrap();
    assert!(e2.len() >= 1);
}

// A counting allocator through the C hook: every allocation is freed once
// the handles and the context are dropped.
struct Counts {
    live: AtomicIsize,
    total: AtomicUsize,
}

unsafe extern "C" fn count_alloc(
    userdata: *mut c_void,
    size: usize,
    alignment: usize,
) -> *mut c_void {
    let c = &*(userdata as *const Counts);
    let layout = std::alloc::Layout::from_size_align(size.max(1) + 64, alignment.max(16)).unwrap();
    let base = std::alloc::alloc(layout);
    if base.is_null() {
        return base as *mut c_void;
    }
    // Keep the size in front of the block (64 bytes keep every alignment <= 64).
    let p = base.add(64);
    (p.sub(16) as *mut usize).write(size.max(1));
    (p.sub(8) as *mut usize).write(alignment.max(16));
    c.live.fetch_add(1, Ordering::SeqCst);
    c.total.fetch_add(1, Ordering::SeqCst);
    p as *mut c_void
}

unsafe extern "C" fn count_free(userdata: *mut c_void, ptr: *mut c_void) {
    if ptr.is_null() {
        return;
    }
    let c = &*(userdata as *const Counts);
    let p = ptr as *mut u8;
    let size = (p.sub(16) as *const usize).read();
    let align = (p.sub(8) as *const usize).read();
    std::alloc::dealloc(
        p.sub(64),
        std::alloc::Layout::from_size_align(size + 64, align).unwrap(),
    );
    c.live.fetch_sub(1, Ordering::SeqCst);
}

#[test]
fn drop_frees_every_handle() {
    let counts = Box::new(Counts {
        live: AtomicIsize::new(0),
        total: AtomicUsize::new(0),
    });
    let a = sys::cyc_allocator {
        alloc: Some(count_alloc),
        free: Some(count_free),
        userdata: &*counts as *const Counts as *mut c_void,
    };
    {
        let ctx = unsafe { Context::with_allocator(&a) }.unwrap();
        let (c1, c2) = cones(&ctx);
        let v = [f64::INFINITY, -0.5, 0.7];
        let blend = Surface::blend_canal(
            &ctx,
            &BlendEnd::new(&c1, 1.0, v),
            &BlendEnd::new(&c2, 1.0, v),
            2,
            0.0,
            1.0,
        )
        .unwrap();
        let (s, e) = skin_ends(&ctx);
        let skin = SphereSkin::new(&ctx, &s, &e, None).unwrap();
        let l1 = Curve::line(&ctx, [0.0; 3], [1.0, 0.0, 0.0]).unwrap();
        let l2 = Curve::line(&ctx, [0.0, 0.0, 1.0], [2.0, 1.0, 0.0]).unwrap();
        let prcs = Surface::prcs(&ctx, &l1, &l2, None, -0.5, 0.5).unwrap();
        let export = prcs
            .bezier_export(
                &ctx,
                &ExportDomain {
                    u0: -0.5,
                    u1: 0.5,
                    v0: 0.0,
                    v1: 0.0,
                    whole_circle: 1,
                },
            )
            .unwrap();
        assert!(counts.live.load(Ordering::SeqCst) >= 5);
        drop(export);
        drop(skin);
        // Handles may outlive their context (they carry the allocator).
        drop(ctx);
        assert!(counts.live.load(Ordering::SeqCst) >= 3);
        drop(blend);
        drop(c1);
        drop(c2);
        drop((l1, l2, prcs));
    }
    assert!(counts.total.load(Ordering::SeqCst) >= 6);
    assert_eq!(counts.live.load(Ordering::SeqCst), 0);
}

#[test]
fn handles_are_shared_across_threads() {
    fn send_sync<T: Send + Sync>() {}
    fn send<T: Send>() {}
    send_sync::<Surface>();
    send_sync::<Curve>();
    send_sync::<SphereSkin>();
    send_sync::<cyclide::BezierExport>();
    send::<Context>();

    let ctx = Context::new().unwrap();
    let (a, b) = cones(&ctx);
    let v = [f64::INFINITY, -0.5, 0.7];
    let blend = Arc::new(
        Surface::blend_canal(
            &ctx,
            &BlendEnd::new(&a, 1.0, v),
            &BlendEnd::new(&b, 1.0, v),
            2,
            0.0,
            1.0,
        )
        .unwrap(),
    );
    let expect = blend.point(&ctx, 0.5, 0.25).unwrap();
    let workers: Vec<_> = (0..4)
        .map(|_| {
            let blend = Arc::clone(&blend);
            std::thread::spawn(move || {
                let ctx = Context::new().unwrap(); // one context per thread
                (0..200)
                    .map(|_| blend.point(&ctx, 0.5, 0.25).unwrap())
                    .last()
                    .unwrap()
            })
        })
        .collect();
    for w in workers {
        assert_eq!(w.join().unwrap(), expect);
    }
}

#[test]
fn versions() {
    assert_eq!(cyclide::abi_version(), sys::CYC_ABI_VERSION);
    assert!(!cyclide::version().is_empty());
}
