//! Safe Rust wrapper of the cyclide C ABI (exact rational circle-family
//! surfaces): RAII handles, `Result<T, Error>` and slices/`Vec`s instead of
//! raw buffers. The raw declarations are in [`sys`] (the `cyclide-sys`
//! crate); everything the wrapper does not cover is reachable there with
//! [`Context::as_ptr`] and the handles' `as_ptr`.
//!
//! ```no_run
//! use cyclide::{Context, Curve, Surface};
//! let ctx = Context::new()?;
//! let l1 = Curve::line(&ctx, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0])?;
//! let l2 = Curve::line(&ctx, [0.0, 0.0, 1.0], [2.0, 1.0, 0.0])?;
//! let s = Surface::prcs(&ctx, &l1, &l2, None, -0.5, 0.5)?;
//! let p = s.eval(&ctx, 0.25, 1.0)?;
//! println!("{:?} {:?}", p.point, p.normal);
//! # Ok::<(), cyclide::Error>(())
//! ```
//!
//! # Threads
//!
//! The C library (SPEC.md section 2, "C ABI") guarantees: a context is used
//! by one thread at a time (it holds the last status and message), and
//! handles are immutable after creation and may be shared read-only between
//! threads. Hence [`Context`] is `Send` but not `Sync` (give each thread its
//! own context), and [`Curve`], [`Surface`], [`SphereSkin`] and
//! [`BezierExport`] are `Send + Sync`: every method takes the handle by
//! shared reference and the context that receives the errors explicitly.
//!
//! # Ownership
//!
//! Each handle owns its C object and destroys it in `Drop`. Handles carry a
//! copy of their context's allocator, so they may outlive the context that
//! created them. A surface does not borrow the curves it was built from.

use std::ffi::{CStr, CString};
use std::fmt;
use std::os::raw::c_int;
use std::path::Path;
use std::ptr::{self, NonNull};

pub use cyclide_sys as sys;

/// The status codes of `cyclide_errors.h` (numbers frozen by the C ABI).
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Status {
    NullArgument,
    InvalidArgument,
    NotFinite,
    DegreeTooHigh,
    BadDomain,
    DependentPlanes,
    ZeroTangent,
    CollinearPoints,
    DegenerateCircleParameter,
    NotCanal,
    SingularPoint,
    DegenerateRinged,
    ParallelLines,
    NoCommonNormal,
    RankDeficient,
    AtInversionCenter,
    NotParabolic,
    EmptyRealLocus,
    TooFewLines,
    NoNormalForm,
    NotPythagorean,
    IntersectingCircles,
    NestedSpheres,
    CurvatureRadiusTooLarge,
    SpherePencil,
    NoTouchingSphere,
    SingleTouchingSphere,
    DegenerateCyclide,
    NotIsometric,
    NotOnLieQuadric,
    PointAtInfinity,
    TangentGeneratingSpheres,
    BlendFolds,
    Developable,
    PoleInGaussImage,
    Ridge,
    NumericalOverflow,
    BufferTooSmall,
    OutOfMemory,
    Io,
    Unsupported,
    Internal,
    /// A code this version of the crate does not know (a newer library).
    Unknown,
}

impl Status {
    /// The status of a nonzero C code.
    pub fn from_code(code: c_int) -> Status {
        use Status::*;
        match code {
            sys::CYC_E_NULL_ARGUMENT => NullArgument,
            sys::CYC_E_INVALID_ARGUMENT => InvalidArgument,
            sys::CYC_E_NOT_FINITE => NotFinite,
            sys::CYC_E_DEGREE_TOO_HIGH => DegreeTooHigh,
            sys::CYC_E_BAD_DOMAIN => BadDomain,
            sys::CYC_E_DEPENDENT_PLANES => DependentPlanes,
            sys::CYC_E_ZERO_TANGENT => ZeroTangent,
            sys::CYC_E_COLLINEAR_POINTS => CollinearPoints,
            sys::CYC_E_DEGENERATE_CIRCLE_PARAMETER => DegenerateCircleParameter,
            sys::CYC_E_NOT_CANAL => NotCanal,
            sys::CYC_E_SINGULAR_POINT => SingularPoint,
            sys::CYC_E_DEGENERATE_RINGED => DegenerateRinged,
            sys::CYC_E_PARALLEL_LINES => ParallelLines,
            sys::CYC_E_NO_COMMON_NORMAL => NoCommonNormal,
            sys::CYC_E_RANK_DEFICIENT => RankDeficient,
            sys::CYC_E_AT_INVERSION_CENTER => AtInversionCenter,
            sys::CYC_E_NOT_PARABOLIC => NotParabolic,
            sys::CYC_E_EMPTY_REAL_LOCUS => EmptyRealLocus,
            sys::CYC_E_TOO_FEW_LINES => TooFewLines,
            sys::CYC_E_NO_NORMAL_FORM => NoNormalForm,
            sys::CYC_E_NOT_PYTHAGOREAN => NotPythagorean,
            sys::CYC_E_INTERSECTING_CIRCLES => IntersectingCircles,
            sys::CYC_E_NESTED_SPHERES => NestedSpheres,
            sys::CYC_E_CURVATURE_RADIUS_TOO_LARGE => CurvatureRadiusTooLarge,
            sys::CYC_E_SPHERE_PENCIL => SpherePencil,
            sys::CYC_E_NO_TOUCHING_SPHERE => NoTouchingSphere,
            sys::CYC_E_SINGLE_TOUCHING_SPHERE => SingleTouchingSphere,
            sys::CYC_E_DEGENERATE_CYCLIDE => DegenerateCyclide,
            sys::CYC_E_NOT_ISOMETRIC => NotIsometric,
            sys::CYC_E_NOT_ON_LIE_QUADRIC => NotOnLieQuadric,
            sys::CYC_E_POINT_AT_INFINITY => PointAtInfinity,
            sys::CYC_E_TANGENT_GENERATING_SPHERES => TangentGeneratingSpheres,
            sys::CYC_E_BLEND_FOLDS => BlendFolds,
            sys::CYC_E_DEVELOPABLE => Developable,
            sys::CYC_E_POLE_IN_GAUSS_IMAGE => PoleInGaussImage,
            sys::CYC_E_RIDGE => Ridge,
            sys::CYC_E_NUMERICAL_OVERFLOW => NumericalOverflow,
            sys::CYC_E_BUFFER_TOO_SMALL => BufferTooSmall,
            sys::CYC_E_OUT_OF_MEMORY => OutOfMemory,
            sys::CYC_E_IO => Io,
            sys::CYC_E_UNSUPPORTED => Unsupported,
            sys::CYC_E_INTERNAL => Internal,
            _ => Unknown,
        }
    }
}

/// A failed call: the C status code and the context's last-error message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    code: c_int,
    status: Status,
    message: String,
}

impl Error {
    fn new(code: c_int, message: String) -> Error {
        Error {
            code,
            status: Status::from_code(code),
            message,
        }
    }
    /// The status (`Status::Unknown` for codes newer than this crate).
    pub fn status(&self) -> Status {
        self.status
    }
    /// The raw `CYC_E_*` number.
    pub fn code(&self) -> i32 {
        self.code
    }
    /// The context's message ("cyc_prcs_create: ..."), never empty.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} ({}): {}",
            status_name(self.code),
            self.code,
            self.message
        )
    }
}

impl std::error::Error for Error {}

/// `Result` with [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// The static name of a status code ("CYC_E_DEPENDENT_PLANES").
pub fn status_name(code: i32) -> &'static str {
    // SAFETY: a static, NUL-terminated string, never NULL.
    unsafe { CStr::from_ptr(sys::cyc_status_name(code)) }
        .to_str()
        .unwrap_or("?")
}

/// The version string of the library actually linked ("0.1.0").
pub fn version() -> &'static str {
    // SAFETY: a static string.
    unsafe { CStr::from_ptr(sys::cyc_version_string()) }
        .to_str()
        .unwrap_or("?")
}

/// The ABI version of the library actually linked (must equal
/// [`sys::CYC_ABI_VERSION`], the header this crate was written against).
pub fn abi_version() -> i32 {
    unsafe { sys::cyc_abi_version() }
}

fn c_path(path: &Path) -> Result<CString> {
    let s = path.to_str().ok_or_else(|| {
        Error::new(
            sys::CYC_E_INVALID_ARGUMENT,
            format!("path {:?} is not UTF-8", path),
        )
    })?;
    CString::new(s).map_err(|_| {
        Error::new(
            sys::CYC_E_INVALID_ARGUMENT,
            format!("path {:?} contains a NUL byte", s),
        )
    })
}

fn flat(v: &[[f64; 3]]) -> *const f64 {
    v.as_ptr() as *const f64
}

fn buffer3(v: &mut [[f64; 3]]) -> sys::cyc_buffer3 {
    sys::cyc_buffer3 {
        data: v.as_mut_ptr() as *mut f64,
        capacity: v.len(),
        stride: 3,
    }
}

fn no_buffer() -> sys::cyc_buffer3 {
    sys::cyc_buffer3 {
        data: ptr::null_mut(),
        capacity: 0,
        stride: 3,
    }
}

fn int_len(n: usize, what: &str) -> Result<c_int> {
    if n > c_int::MAX as usize {
        return Err(Error::new(
            sys::CYC_E_INVALID_ARGUMENT,
            format!("too many {}: {}", what, n),
        ));
    }
    Ok(n as c_int)
}

// ---------------------------------------------------------------- context

/// A context: receives the status and message of every call made with it.
/// `Send`, not `Sync`: one thread at a time (SPEC.md, C ABI).
pub struct Context {
    raw: NonNull<sys::cyc_context>,
}

// SAFETY: a context may move between threads; it is not used concurrently
// (Context is not Sync, so &Context cannot be shared across threads).
unsafe impl Send for Context {}

impl Context {
    /// A context with the default allocator (malloc/free).
    pub fn new() -> Result<Context> {
        let mut out = ptr::null_mut();
        let st = unsafe { sys::cyc_context_create(ptr::null(), &mut out) };
        Self::from_create(st, out)
    }

    /// A context with a custom allocator (copied; every handle created
    /// through this context allocates and frees with it).
    ///
    /// # Safety
    /// `alloc` and `free` must behave as documented in cyclide.h (aligned
    /// memory or NULL; free accepts what alloc returned) and stay valid, with
    /// `userdata`, as long as any handle created through this context lives.
    pub unsafe fn with_allocator(allocator: &sys::cyc_allocator) -> Result<Context> {
        let mut out = ptr::null_mut();
        let st = sys::cyc_context_create(allocator, &mut out);
        Self::from_create(st, out)
    }

    fn from_create(st: c_int, out: *mut sys::cyc_context) -> Result<Context> {
        match NonNull::new(out) {
            Some(raw) if st == sys::CYC_OK => Ok(Context { raw }),
            _ => Err(Error::new(
                st,
                format!("cyc_context_create: {}", status_name(st)),
            )),
        }
    }

    /// The raw context, for calls the wrapper does not cover.
    pub fn as_ptr(&self) -> *mut sys::cyc_context {
        self.raw.as_ptr()
    }

    /// The last error message ("" after a success).
    pub fn last_error(&self) -> String {
        // SAFETY: never NULL; copied before the next call can change it.
        unsafe { CStr::from_ptr(sys::cyc_context_last_error(self.raw.as_ptr())) }
            .to_string_lossy()
            .into_owned()
    }

    /// The status of the last call (0 after a success).
    pub fn last_status(&self) -> i32 {
        unsafe { sys::cyc_context_last_status(self.raw.as_ptr()) }
    }

    /// Turns a C status into a `Result`, taking the context's message.
    pub fn check(&self, status: c_int) -> Result<()> {
        if status == sys::CYC_OK {
            return Ok(());
        }
        let mut message = self.last_error();
        if message.is_empty() {
            message = status_name(status).to_string();
        }
        Err(Error::new(status, message))
    }
}

impl Drop for Context {
    fn drop(&mut self) {
        unsafe { sys::cyc_context_destroy(self.raw.as_ptr()) }
    }
}

impl fmt::Debug for Context {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Context").field("raw", &self.raw).finish()
    }
}

macro_rules! handle {
    ($(#[$doc:meta])* $name:ident, $raw:ty, |$p:ident| $destroy:expr) => {
        $(#[$doc])*
        pub struct $name {
            raw: NonNull<$raw>,
        }
        // SAFETY: the C object is immutable after creation and may be read
        // from several threads at once (SPEC.md, C ABI); it is destroyed
        // only by Drop, which has exclusive access.
        unsafe impl Send for $name {}
        unsafe impl Sync for $name {}
        impl $name {
            /// The raw handle (still owned by `self`).
            pub fn as_ptr(&self) -> *mut $raw {
                self.raw.as_ptr()
            }
            /// Takes ownership of a raw handle (destroyed on drop).
            ///
            /// # Safety
            /// `raw` must be a live handle of this type that nothing else
            /// destroys.
            pub unsafe fn from_raw(raw: NonNull<$raw>) -> $name {
                $name { raw }
            }
            fn created(ctx: &Context, st: c_int, out: *mut $raw) -> Result<$name> {
                ctx.check(st)?;
                match NonNull::new(out) {
                    Some(raw) => Ok($name { raw }),
                    None => Err(Error::new(sys::CYC_E_INTERNAL, "NULL handle on success".into())),
                }
            }
        }
        impl Drop for $name {
            fn drop(&mut self) {
                let $p = self.raw.as_ptr();
                // SAFETY: owned, live, destroyed once; the handle carries
                // its own allocator, so no context is needed.
                unsafe { $destroy }
            }
        }
        impl fmt::Debug for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.debug_struct(stringify!($name)).field("raw", &self.raw).finish()
            }
        }
    };
}

// ---------------------------------------------------------------- curves

handle!(
    /// An input curve (polynomial or rational, a line, a point, a line
    /// element, a Hermite curve).
    Curve, sys::cyc_curve, |p| sys::cyc_curve_destroy(ptr::null_mut(), p)
);

impl Curve {
    /// p(u) = point + u direction.
    pub fn line(ctx: &Context, point: [f64; 3], direction: [f64; 3]) -> Result<Curve> {
        let mut out = ptr::null_mut();
        let st = unsafe {
            sys::cyc_curve_create_line(ctx.as_ptr(), point.as_ptr(), direction.as_ptr(), &mut out)
        };
        Curve::created(ctx, st, out)
    }

    /// A constant point (PRRS and ringed-surface input).
    pub fn point(ctx: &Context, point: [f64; 3]) -> Result<Curve> {
        let mut out = ptr::null_mut();
        let st = unsafe { sys::cyc_curve_create_point(ctx.as_ptr(), point.as_ptr(), &mut out) };
        Curve::created(ctx, st, out)
    }

    /// A line element: a point with a tangent (PRCS input).
    pub fn line_element(ctx: &Context, point: [f64; 3], tangent: [f64; 3]) -> Result<Curve> {
        let mut out = ptr::null_mut();
        let st = unsafe {
            sys::cyc_curve_create_line_element(
                ctx.as_ptr(),
                point.as_ptr(),
                tangent.as_ptr(),
                &mut out,
            )
        };
        Curve::created(ctx, st, out)
    }

    /// p(u) = sum_k coeffs[k] u^k (degree = coeffs.len() - 1).
    pub fn polynomial(ctx: &Context, coeffs: &[[f64; 3]]) -> Result<Curve> {
        let degree = int_len(coeffs.len(), "coefficients")? - 1;
        let mut out = ptr::null_mut();
        let st = unsafe {
            sys::cyc_curve_create_polynomial(ctx.as_ptr(), degree, flat(coeffs), 3, &mut out)
        };
        Curve::created(ctx, st, out)
    }

    /// (x, y, z)(u) / w(u) from rows (x, y, z, w) of power-form coefficients.
    pub fn rational(ctx: &Context, coeffs: &[[f64; 4]]) -> Result<Curve> {
        let degree = int_len(coeffs.len(), "coefficients")? - 1;
        let mut out = ptr::null_mut();
        let st = unsafe {
            sys::cyc_curve_create_rational(
                ctx.as_ptr(),
                degree,
                coeffs.as_ptr() as *const f64,
                4,
                &mut out,
            )
        };
        Curve::created(ctx, st, out)
    }

    /// A rational Bezier curve over [u0, u1] (weights `None`: all 1).
    pub fn bezier(
        ctx: &Context,
        control: &[[f64; 3]],
        weights: Option<&[f64]>,
        u0: f64,
        u1: f64,
    ) -> Result<Curve> {
        let degree = int_len(control.len(), "control points")? - 1;
        if let Some(w) = weights {
            if w.len() != control.len() {
                return Err(Error::new(
                    sys::CYC_E_INVALID_ARGUMENT,
                    format!("{} weights for {} control points", w.len(), control.len()),
                ));
            }
        }
        let mut out = ptr::null_mut();
        let st = unsafe {
            sys::cyc_curve_create_bezier(
                ctx.as_ptr(),
                degree,
                flat(control),
                3,
                weights.map_or(ptr::null(), |w| w.as_ptr()),
                u0,
                u1,
                &mut out,
            )
        };
        Curve::created(ctx, st, out)
    }

    /// The two-point C^K Hermite curve (degree 2K+1) on [u0, u1]: start and
    /// end hold K+1 rows (p, p', ..., p^(K)).
    pub fn hermite(
        ctx: &Context,
        u0: f64,
        u1: f64,
        start: &[[f64; 3]],
        end: &[[f64; 3]],
    ) -> Result<Curve> {
        if start.is_empty() || start.len() != end.len() {
            return Err(Error::new(
                sys::CYC_E_INVALID_ARGUMENT,
                format!("Hermite data of {} and {} rows", start.len(), end.len()),
            ));
        }
        let order = int_len(start.len(), "Hermite rows")? - 1;
        let mut out = ptr::null_mut();
        let st = unsafe {
            sys::cyc_curve_create_hermite(
                ctx.as_ptr(),
                order,
                u0,
                u1,
                flat(start),
                flat(end),
                &mut out,
            )
        };
        Curve::created(ctx, st, out)
    }

    /// The degree (max of numerator and weight degrees).
    pub fn degree(&self, ctx: &Context) -> Result<i32> {
        let mut d = 0;
        ctx.check(unsafe { sys::cyc_curve_degree(ctx.as_ptr(), self.as_ptr(), &mut d) })?;
        Ok(d)
    }

    /// p(u) and its derivatives up to `order` (<= 8): order + 1 rows.
    pub fn eval(&self, ctx: &Context, u: f64, order: usize) -> Result<Vec<[f64; 3]>> {
        let mut out = vec![[0.0; 3]; order + 1];
        let st = unsafe {
            sys::cyc_curve_eval(
                ctx.as_ptr(),
                self.as_ptr(),
                u,
                int_len(order, "derivatives")?,
                out.as_mut_ptr() as *mut f64,
                3 * out.len(),
            )
        };
        ctx.check(st)?;
        Ok(out)
    }
}

// ---------------------------------------------------------------- surfaces

/// The circle parameter f(u, v) (a Moebius function of v with polynomial
/// coefficients in u); `None` where a function takes `Option<&Mobius>` is
/// f = v.
pub type Mobius = sys::cyc_mobius;
/// A circle: center, unit normal of its plane, squared radius.
pub type Circle = sys::cyc_circle;
/// A sphere: center and squared radius.
pub type Sphere = sys::cyc_sphere;
/// One end of a sphere skin (see cyclide.h, `cyc_skin_end`).
pub type SkinEnd = sys::cyc_skin_end;
/// Options of a sphere skin.
pub type SkinOptions = sys::cyc_skin_options;
/// The parameter rectangle of an exact export.
pub type ExportDomain = sys::cyc_export_domain;
/// Options of a sphere skin's export.
pub type SkinExportOptions = sys::cyc_skin_export_options;
/// What a sphere skin's export achieved.
pub type SkinExportReport = sys::cyc_skin_export_report;
/// One patch of an export: degrees and the parameters it covers.
pub type BezierPatchInfo = sys::cyc_bezier_patch_info;
/// What a mesh write produced.
pub type MeshStats = sys::cyc_mesh_stats;
/// Tessellation options (`tessellation_options()` gives the defaults).
pub type TessellationOptions = sys::cyc_tessellation_options;

fn mobius_ptr(f: Option<&Mobius>) -> *const Mobius {
    f.map_or(ptr::null(), |m| m as *const Mobius)
}

/// The kind of a surface (`cyc_surface_kind`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SurfaceKind {
    Prcs,
    Prrs,
    Ringed,
    Dupin,
    Parabolic,
    Other(i32),
}

/// A point of a surface with its partial derivatives and unit normal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfacePoint {
    pub point: [f64; 3],
    pub du: [f64; 3],
    pub dv: [f64; 3],
    pub normal: [f64; 3],
}

/// A grid of points and normals: point (i, j) at index i * cols + j
/// (`Surface::eval_grid`: i along u, j along v).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    pub rows: usize,
    pub cols: usize,
    pub points: Vec<[f64; 3]>,
    pub normals: Vec<[f64; 3]>,
    /// Singular normals, written as (0, 0, 0).
    pub singular: usize,
}

/// One end of a blend (`cyc_blend_end`): the end circle u of `surface`, the
/// circle parameters v of the chosen points (v[0], v[1] for canal blends,
/// all three for ringed ones; `f64::INFINITY` is the generator), the
/// tangent length lambda (0: chosen by the nearer end of the domain) and
/// the higher derivatives phi of the reparameterization (0: none).
#[derive(Debug, Clone, Copy)]
pub struct BlendEnd<'a> {
    pub surface: &'a Surface,
    pub u: f64,
    pub v: [f64; 3],
    pub lambda: f64,
    pub phi: [f64; sys::CYC_MAX_BLEND_ORDER as usize - 1],
}

impl<'a> BlendEnd<'a> {
    /// The end circle u of `surface` through the points v, lambda and phi 0.
    pub fn new(surface: &'a Surface, u: f64, v: [f64; 3]) -> BlendEnd<'a> {
        BlendEnd {
            surface,
            u,
            v,
            lambda: 0.0,
            phi: [0.0; sys::CYC_MAX_BLEND_ORDER as usize - 1],
        }
    }

    fn raw(&self) -> sys::cyc_blend_end {
        sys::cyc_blend_end {
            surface: self.surface.as_ptr(),
            u: self.u,
            v: self.v,
            lambda: self.lambda,
            phi: self.phi,
        }
    }
}

handle!(
    /// A circle-family surface (PRCS, PRRS, ringed, blends, Dupin and
    /// parabolic cyclides). Immutable; `Send + Sync`.
    Surface, sys::cyc_surface, |p| sys::cyc_surface_destroy(ptr::null_mut(), p)
);

impl Surface {
    /// PRCS: the canal surface through p1 and p2 (curves or line elements),
    /// circle parameter f (`None`: f = v), checked on [u0, u1].
    pub fn prcs(
        ctx: &Context,
        p1: &Curve,
        p2: &Curve,
        f: Option<&Mobius>,
        u0: f64,
        u1: f64,
    ) -> Result<Surface> {
        let mut out = ptr::null_mut();
        let st = unsafe {
            sys::cyc_prcs_create(
                ctx.as_ptr(),
                p1.as_ptr(),
                p2.as_ptr(),
                mobius_ptr(f),
                u0,
                u1,
                &mut out,
            )
        };
        Surface::created(ctx, st, out)
    }

    /// PRRS: the ringed surface through p1, p2, p3 (one or two may be points).
    pub fn prrs(
        ctx: &Context,
        p1: &Curve,
        p2: &Curve,
        p3: &Curve,
        f: Option<&Mobius>,
        u0: f64,
        u1: f64,
    ) -> Result<Surface> {
        let mut out = ptr::null_mut();
        let st = unsafe {
            sys::cyc_prrs_create(
                ctx.as_ptr(),
                p1.as_ptr(),
                p2.as_ptr(),
                p3.as_ptr(),
                mobius_ptr(f),
                u0,
                u1,
                &mut out,
            )
        };
        Surface::created(ctx, st, out)
    }

    /// The ringed surface (d, n, rho) through the curve c (seed 001 eq. 3).
    pub fn ringed(
        ctx: &Context,
        d: &Curve,
        n: &Curve,
        c: &Curve,
        f: Option<&Mobius>,
        u0: f64,
        u1: f64,
    ) -> Result<Surface> {
        let mut out = ptr::null_mut();
        let st = unsafe {
            sys::cyc_ringed_create(
                ctx.as_ptr(),
                d.as_ptr(),
                n.as_ptr(),
                c.as_ptr(),
                mobius_ptr(f),
                u0,
                u1,
                &mut out,
            )
        };
        Surface::created(ctx, st, out)
    }

    /// The canal blend (G^(K-1), K in 2..=7) from `start` to `end` on [t0, t1].
    pub fn blend_canal(
        ctx: &Context,
        start: &BlendEnd,
        end: &BlendEnd,
        k: i32,
        t0: f64,
        t1: f64,
    ) -> Result<Surface> {
        let (s, e) = (start.raw(), end.raw());
        let mut out = ptr::null_mut();
        let st = unsafe { sys::cyc_blend_canal(ctx.as_ptr(), &s, &e, k, t0, t1, &mut out) };
        Surface::created(ctx, st, out)
    }

    /// The ringed blend (C^K, K in 1..=7) from `start` to `end` on [t0, t1].
    pub fn blend_ringed(
        ctx: &Context,
        start: &BlendEnd,
        end: &BlendEnd,
        k: i32,
        t0: f64,
        t1: f64,
    ) -> Result<Surface> {
        let (s, e) = (start.raw(), end.raw());
        let mut out = ptr::null_mut();
        let st = unsafe { sys::cyc_blend_ringed(ctx.as_ptr(), &s, &e, k, t0, t1, &mut out) };
        Surface::created(ctx, st, out)
    }

    /// The kind of the surface.
    pub fn kind(&self, ctx: &Context) -> Result<SurfaceKind> {
        let mut k = 0;
        ctx.check(unsafe { sys::cyc_surface_kind(ctx.as_ptr(), self.as_ptr(), &mut k) })?;
        Ok(match k {
            sys::CYC_SURFACE_PRCS => SurfaceKind::Prcs,
            sys::CYC_SURFACE_PRRS => SurfaceKind::Prrs,
            sys::CYC_SURFACE_RINGED => SurfaceKind::Ringed,
            sys::CYC_SURFACE_DUPIN => SurfaceKind::Dupin,
            sys::CYC_SURFACE_PARABOLIC => SurfaceKind::Parabolic,
            other => SurfaceKind::Other(other),
        })
    }

    /// The domain [u0, u1] the surface was checked on.
    pub fn domain(&self, ctx: &Context) -> Result<(f64, f64)> {
        let (mut u0, mut u1) = (0.0, 0.0);
        ctx.check(unsafe {
            sys::cyc_surface_domain(ctx.as_ptr(), self.as_ptr(), &mut u0, &mut u1)
        })?;
        Ok((u0, u1))
    }

    /// x(u, v), x_u, x_v and the unit normal (`SingularPoint` where the
    /// normal of a ringed surface is undefined; use [`Surface::point`]).
    pub fn eval(&self, ctx: &Context, u: f64, v: f64) -> Result<SurfacePoint> {
        let mut p = SurfacePoint {
            point: [0.0; 3],
            du: [0.0; 3],
            dv: [0.0; 3],
            normal: [0.0; 3],
        };
        let st = unsafe {
            sys::cyc_surface_eval(
                ctx.as_ptr(),
                self.as_ptr(),
                u,
                v,
                p.point.as_mut_ptr(),
                p.du.as_mut_ptr(),
                p.dv.as_mut_ptr(),
                p.normal.as_mut_ptr(),
            )
        };
        ctx.check(st)?;
        Ok(p)
    }

    /// x(u, v) only.
    pub fn point(&self, ctx: &Context, u: f64, v: f64) -> Result<[f64; 3]> {
        let mut x = [0.0; 3];
        let n = ptr::null_mut();
        let st = unsafe {
            sys::cyc_surface_eval(ctx.as_ptr(), self.as_ptr(), u, v, x.as_mut_ptr(), n, n, n)
        };
        ctx.check(st)?;
        Ok(x)
    }

    /// The grid (us[i], vs[j]) into caller slices at index i * vs.len() + j
    /// (normals may be `None`); returns the number of singular normals.
    /// All or nothing: on error nothing is written.
    pub fn eval_grid_into(
        &self,
        ctx: &Context,
        us: &[f64],
        vs: &[f64],
        points: &mut [[f64; 3]],
        normals: Option<&mut [[f64; 3]]>,
    ) -> Result<usize> {
        let mut singular = 0usize;
        let nb = normals.map_or_else(no_buffer, buffer3);
        let st = unsafe {
            sys::cyc_surface_eval_grid(
                ctx.as_ptr(),
                self.as_ptr(),
                us.as_ptr(),
                us.len(),
                vs.as_ptr(),
                vs.len(),
                buffer3(points),
                no_buffer(),
                no_buffer(),
                nb,
                &mut singular,
            )
        };
        ctx.check(st)?;
        Ok(singular)
    }

    /// The grid (us[i], vs[j]) with normals, as a [`Grid`].
    pub fn eval_grid(&self, ctx: &Context, us: &[f64], vs: &[f64]) -> Result<Grid> {
        let n = us
            .len()
            .checked_mul(vs.len())
            .ok_or_else(|| Error::new(sys::CYC_E_INVALID_ARGUMENT, "grid size overflows".into()))?;
        let mut points = vec![[0.0; 3]; n];
        let mut normals = vec![[0.0; 3]; n];
        let singular = self.eval_grid_into(ctx, us, vs, &mut points, Some(&mut normals))?;
        Ok(Grid {
            rows: us.len(),
            cols: vs.len(),
            points,
            normals,
            singular,
        })
    }

    /// The circle v -> x(u, v).
    pub fn circle(&self, ctx: &Context, u: f64) -> Result<Circle> {
        let mut c = Circle {
            center: [0.0; 3],
            normal: [0.0; 3],
            radius2: 0.0,
        };
        ctx.check(unsafe { sys::cyc_surface_circle(ctx.as_ptr(), self.as_ptr(), u, &mut c) })?;
        Ok(c)
    }

    /// The sphere touching a canal surface along its circle at u
    /// (`NotCanal` for ringed surfaces).
    pub fn sphere(&self, ctx: &Context, u: f64) -> Result<Sphere> {
        let mut s = Sphere {
            center: [0.0; 3],
            radius2: 0.0,
        };
        ctx.check(unsafe { sys::cyc_surface_sphere(ctx.as_ptr(), self.as_ptr(), u, &mut s) })?;
        Ok(s)
    }

    /// The adaptive mesh of the surface (SPEC.md 8j.2): `rows` circles of
    /// `cols` points each, closed along the circles (the grid for
    /// [`write_mesh`] with `closed = true`).
    pub fn tessellate(&self, ctx: &Context, options: &TessellationOptions) -> Result<Grid> {
        let segs = if options.fixed_segments > 0 {
            options.fixed_segments
        } else {
            options.max_segments
        };
        let work_bytes = unsafe { sys::cyc_tessellation_workspace_size(segs) };
        let mut work = vec![0u64; (work_bytes + 7) / 8];
        let row_cap: c_int = 1 << 14;
        let mut us = vec![0.0; row_cap as usize];
        let mut plan = sys::cyc_tessellation_plan {
            rows: 0,
            segments: 0,
            phase0: 0.0,
            phase1: 0.0,
            max_radius: 0.0,
            depth_limited: 0,
        };
        let st = unsafe {
            sys::cyc_tessellate_plan(
                ctx.as_ptr(),
                self.as_ptr(),
                options,
                us.as_mut_ptr(),
                row_cap,
                work.as_mut_ptr() as *mut std::os::raw::c_void,
                work.len() * 8,
                &mut plan,
            )
        };
        ctx.check(st)?;
        let (rows, cols) = (plan.rows as usize, plan.segments as usize);
        let mut points = vec![[0.0; 3]; rows * cols];
        let mut normals = vec![[0.0; 3]; rows * cols];
        let mut singular = 0usize;
        let st = unsafe {
            sys::cyc_tessellate_eval(
                ctx.as_ptr(),
                self.as_ptr(),
                &plan,
                us.as_ptr(),
                buffer3(&mut points),
                buffer3(&mut normals),
                &mut singular,
            )
        };
        ctx.check(st)?;
        Ok(Grid {
            rows,
            cols,
            points,
            normals,
            singular,
        })
    }

    /// The exact rational Bezier patches of the surface over `domain`.
    pub fn bezier_export(&self, ctx: &Context, domain: &ExportDomain) -> Result<BezierExport> {
        let mut out = ptr::null_mut();
        let st =
            unsafe { sys::cyc_bezier_export_create(ctx.as_ptr(), self.as_ptr(), domain, &mut out) };
        BezierExport::created(ctx, st, out)
    }
}

/// The default tessellation options (chordal tolerance 1e-3, 8..1024 arcs).
pub fn tessellation_options() -> TessellationOptions {
    // SAFETY: all-zero is a valid value (numbers and NULL pointers); the
    // C function then fills every field.
    let mut o: TessellationOptions = unsafe { std::mem::zeroed() };
    unsafe { sys::cyc_tessellation_options_default(&mut o) };
    o
}

// ---------------------------------------------------------------- sphere skins

handle!(
    /// A sphere skin (seed 002): one patch, or a chain of patches.
    SphereSkin, sys::cyc_sphere_skin, |p| sys::cyc_sphere_skin_destroy(ptr::null_mut(), p)
);

/// The default skin options (the RMF pairing).
pub fn skin_options() -> SkinOptions {
    let mut o: SkinOptions = unsafe { std::mem::zeroed() };
    unsafe { sys::cyc_skin_options_init(&mut o) };
    o
}

/// The default skin export options (tolerance 1e-9, degree 7).
pub fn skin_export_options() -> SkinExportOptions {
    let mut o = SkinExportOptions {
        tolerance: 0.0,
        degree: 0,
    };
    unsafe { sys::cyc_skin_export_options_default(&mut o) };
    o
}

/// The end on the sphere (sphere_center, sphere_radius) at the circle with
/// the given center, the spine leaving along `tangent`.
pub fn skin_end_from_sphere(
    ctx: &Context,
    sphere_center: [f64; 3],
    sphere_radius: f64,
    center: [f64; 3],
    tangent: [f64; 3],
) -> Result<SkinEnd> {
    let mut e = SkinEnd {
        center: [0.0; 3],
        radius: 0.0,
        tangent: [0.0; 3],
        inv_c: 0.0,
    };
    let st = unsafe {
        sys::cyc_skin_end_from_sphere(
            ctx.as_ptr(),
            sphere_center.as_ptr(),
            sphere_radius,
            center.as_ptr(),
            tangent.as_ptr(),
            &mut e,
        )
    };
    ctx.check(st)?;
    Ok(e)
}

impl SphereSkin {
    /// The skin from `start` to `end` (options `None`: the defaults).
    pub fn new(
        ctx: &Context,
        start: &SkinEnd,
        end: &SkinEnd,
        options: Option<&SkinOptions>,
    ) -> Result<SphereSkin> {
        let mut out = ptr::null_mut();
        let o = options.map_or(ptr::null(), |o| o as *const SkinOptions);
        let st = unsafe { sys::cyc_sphere_skin_create(ctx.as_ptr(), start, end, o, &mut out) };
        SphereSkin::created(ctx, st, out)
    }

    /// A chain through `ends` (at least 2): patch k from ends[k] to ends[k+1].
    pub fn chain(
        ctx: &Context,
        ends: &[SkinEnd],
        options: Option<&SkinOptions>,
    ) -> Result<SphereSkin> {
        let mut out = ptr::null_mut();
        let o = options.map_or(ptr::null(), |o| o as *const SkinOptions);
        let n = int_len(ends.len(), "ends")?;
        let st = unsafe {
            sys::cyc_sphere_skin_chain_create(
                ctx.as_ptr(),
                ends.as_ptr(),
                n,
                o,
                &mut out,
                ptr::null_mut(),
            )
        };
        SphereSkin::created(ctx, st, out)
    }

    /// The number of patches.
    pub fn patch_count(&self, ctx: &Context) -> Result<usize> {
        let mut n = 0;
        ctx.check(unsafe {
            sys::cyc_sphere_skin_patch_count(ctx.as_ptr(), self.as_ptr(), &mut n)
        })?;
        Ok(n as usize)
    }

    /// s(theta, t) of a patch, its partials and the unit normal, as a
    /// [`SurfacePoint`] (du = ds/dtheta, dv = ds/dt).
    pub fn eval(&self, ctx: &Context, patch: usize, theta: f64, t: f64) -> Result<SurfacePoint> {
        let mut p = SurfacePoint {
            point: [0.0; 3],
            du: [0.0; 3],
            dv: [0.0; 3],
            normal: [0.0; 3],
        };
        let st = unsafe {
            sys::cyc_sphere_skin_eval(
                ctx.as_ptr(),
                self.as_ptr(),
                int_len(patch, "patches")?,
                theta,
                t,
                p.point.as_mut_ptr(),
                p.du.as_mut_ptr(),
                p.dv.as_mut_ptr(),
                p.normal.as_mut_ptr(),
            )
        };
        ctx.check(st)?;
        Ok(p)
    }

    /// The grid of a patch: rows along t, columns along theta (point
    /// (j, i) = s(thetas[i], ts[j]) at index j * thetas.len() + i).
    pub fn eval_grid(
        &self,
        ctx: &Context,
        patch: usize,
        thetas: &[f64],
        ts: &[f64],
    ) -> Result<Grid> {
        let n = thetas.len() * ts.len();
        let mut points = vec![[0.0; 3]; n];
        let mut normals = vec![[0.0; 3]; n];
        let mut singular = 0usize;
        let st = unsafe {
            sys::cyc_sphere_skin_eval_grid(
                ctx.as_ptr(),
                self.as_ptr(),
                int_len(patch, "patches")?,
                thetas.as_ptr(),
                int_len(thetas.len(), "thetas")?,
                ts.as_ptr(),
                int_len(ts.len(), "ts")?,
                points.as_mut_ptr() as *mut f64,
                normals.as_mut_ptr() as *mut f64,
                &mut singular,
            )
        };
        ctx.check(st)?;
        Ok(Grid {
            rows: ts.len(),
            cols: thetas.len(),
            points,
            normals,
            singular,
        })
    }

    /// The rational Bezier patches of the skin (exact in theta, the RMF
    /// interpolated within options.tolerance), u = patch + t.
    pub fn export(
        &self,
        ctx: &Context,
        domain: &ExportDomain,
        options: Option<&SkinExportOptions>,
    ) -> Result<(BezierExport, SkinExportReport)> {
        let mut out = ptr::null_mut();
        let mut rep = SkinExportReport {
            error_estimate: 0.0,
            rmf_error: 0.0,
            exact: 0,
            t_intervals: 0,
        };
        let o = options.map_or(ptr::null(), |o| o as *const SkinExportOptions);
        let st = unsafe {
            sys::cyc_sphere_skin_export_create(
                ctx.as_ptr(),
                self.as_ptr(),
                domain,
                o,
                &mut out,
                &mut rep,
            )
        };
        Ok((BezierExport::created(ctx, st, out)?, rep))
    }
}

// ---------------------------------------------------------------- exports

handle!(
    /// Exact rational tensor-product Bezier patches of a surface or skin.
    BezierExport, sys::cyc_bezier_export, |p| sys::cyc_bezier_export_destroy(p)
);

impl BezierExport {
    /// The number of patches.
    pub fn len(&self) -> usize {
        unsafe { sys::cyc_bezier_export_count(self.as_ptr()) as usize }
    }

    /// True when there is no patch.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Patch `index`: its info and homogeneous control points (w, wx, wy, wz),
    /// control point (i, j) at index i * (deg_v + 1) + j.
    pub fn patch(&self, ctx: &Context, index: usize) -> Result<(BezierPatchInfo, Vec<[f64; 4]>)> {
        let mut info: BezierPatchInfo = unsafe { std::mem::zeroed() };
        let i = int_len(index, "patches")?;
        let st = unsafe {
            sys::cyc_bezier_export_patch(
                ctx.as_ptr(),
                self.as_ptr(),
                i,
                &mut info,
                ptr::null_mut(),
                0,
            )
        };
        ctx.check(st)?;
        let n = (info.deg_u as usize + 1) * (info.deg_v as usize + 1);
        let mut control = vec![[0.0; 4]; n];
        let st = unsafe {
            sys::cyc_bezier_export_patch(
                ctx.as_ptr(),
                self.as_ptr(),
                i,
                &mut info,
                control.as_mut_ptr() as *mut f64,
                4 * n,
            )
        };
        ctx.check(st)?;
        Ok((info, control))
    }

    /// The point of patch `index` at local (s, t) in [0, 1]^2 and its
    /// surface parameters (u, v).
    pub fn eval(
        &self,
        ctx: &Context,
        index: usize,
        s: f64,
        t: f64,
    ) -> Result<([f64; 3], [f64; 2])> {
        let (mut x, mut uv) = ([0.0; 3], [0.0; 2]);
        let st = unsafe {
            sys::cyc_bezier_export_eval(
                ctx.as_ptr(),
                self.as_ptr(),
                int_len(index, "patches")?,
                s,
                t,
                x.as_mut_ptr(),
                uv.as_mut_ptr(),
            )
        };
        ctx.check(st)?;
        Ok((x, uv))
    }

    /// The patches as JSON (schema "cyclide-rational-bezier").
    pub fn write_json(&self, ctx: &Context, path: impl AsRef<Path>) -> Result<()> {
        let p = c_path(path.as_ref())?;
        ctx.check(unsafe {
            sys::cyc_bezier_export_write_json(ctx.as_ptr(), self.as_ptr(), p.as_ptr())
        })
    }
}

// ---------------------------------------------------------------- meshes

/// File formats of [`write_mesh`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshFormat {
    Obj,
    Ply,
    Stl,
    Glb,
}

impl MeshFormat {
    fn code(self) -> c_int {
        match self {
            MeshFormat::Obj => sys::CYC_MESH_OBJ,
            MeshFormat::Ply => sys::CYC_MESH_PLY,
            MeshFormat::Stl => sys::CYC_MESH_STL,
            MeshFormat::Glb => sys::CYC_MESH_GLB,
        }
    }
}

/// A grid to write: rows x cols points (normals optional, same indexing),
/// `closed`: the cols direction wraps; rgba all 0: a palette colour.
#[derive(Debug, Clone, Copy)]
pub struct MeshGrid<'a> {
    pub points: &'a [[f64; 3]],
    pub normals: Option<&'a [[f64; 3]]>,
    pub rows: usize,
    pub cols: usize,
    pub closed: bool,
    pub rgba: [f32; 4],
}

impl<'a> MeshGrid<'a> {
    /// A grid of a [`Grid`] (normals included), closed or not.
    pub fn from_grid(grid: &'a Grid, closed: bool) -> MeshGrid<'a> {
        MeshGrid {
            points: &grid.points,
            normals: if grid.normals.len() == grid.points.len() {
                Some(&grid.normals)
            } else {
                None
            },
            rows: grid.rows,
            cols: grid.cols,
            closed,
            rgba: [0.0; 4],
        }
    }
}

/// Writes the grids as one welded triangle mesh (SPEC.md 8j.3); the file
/// is written to path + ".part" and renamed on success. `weld_tolerance`
/// < 0: 1e-9 x the model size. `name`: the OBJ object / glb node name.
pub fn write_mesh(
    ctx: &Context,
    path: impl AsRef<Path>,
    format: MeshFormat,
    grids: &[MeshGrid],
    name: Option<&str>,
    weld_tolerance: f64,
) -> Result<MeshStats> {
    let p = c_path(path.as_ref())?;
    let mut raw = Vec::with_capacity(grids.len());
    for g in grids {
        let n = g.rows.checked_mul(g.cols).unwrap_or(usize::MAX);
        if g.points.len() < n || g.normals.map_or(false, |nr| nr.len() < n) {
            return Err(Error::new(
                sys::CYC_E_BUFFER_TOO_SMALL,
                format!("a {} x {} grid needs {} points", g.rows, g.cols, n),
            ));
        }
        raw.push(sys::cyc_grid_mesh {
            points: flat(g.points),
            normals: g.normals.map_or(ptr::null(), flat),
            stride: 3,
            rows: int_len(g.rows, "rows")?,
            cols: int_len(g.cols, "cols")?,
            closed: g.closed as c_int,
            rgba: g.rgba,
        });
    }
    let cname = match name {
        Some(n) => Some(CString::new(n).map_err(|_| {
            Error::new(
                sys::CYC_E_INVALID_ARGUMENT,
                "mesh name contains a NUL byte".into(),
            )
        })?),
        None => None,
    };
    let options = sys::cyc_mesh_write_options {
        weld_tolerance,
        name: cname.as_ref().map_or(ptr::null(), |c| c.as_ptr()),
    };
    let mut stats: MeshStats = unsafe { std::mem::zeroed() };
    let st = unsafe {
        sys::cyc_mesh_write(
            ctx.as_ptr(),
            p.as_ptr(),
            format.code(),
            raw.as_ptr(),
            int_len(raw.len(), "grids")?,
            &options,
            &mut stats,
        )
    };
    ctx.check(st)?;
    Ok(stats)
}
