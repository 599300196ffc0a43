//! Scalar root finding and maximisation used for event location and calibration.

/// The real roots of `a x^2 + b x + c`, `NaN` for each one missing: the linear root when `a` is negligible
/// against `b` and `c` (1e-14), else the root of larger magnitude and the other from their product (no
/// cancellation).
pub fn quadratic_roots(a: f64, b: f64, c: f64) -> [f64; 2] {
    if a.abs() <= 1e-14 * (b.abs() + c.abs()) {
        return [if b != 0.0 { -c / b } else { f64::NAN }, f64::NAN];
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return [f64::NAN; 2];
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    [q / a, if q != 0.0 { c / q } else { f64::NAN }]
}

/// Brent's method (Brent 1973, *Algorithms for Minimization without Derivatives*, ch. 4): a root of `f`
/// in `[a, b]` given `f(a)` and `f(b)` of opposite signs (or one of them zero), to an absolute tolerance
/// `xtol` on the argument. Returns `None` if the bracket does not change sign.
pub fn brent_root<F: FnMut(f64) -> f64>(
    mut f: F,
    mut a: f64,
    mut b: f64,
    mut fa: f64,
    mut fb: f64,
    xtol: f64,
) -> Option<f64> {
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    if fa.signum() == fb.signum() || !(fa.is_finite() && fb.is_finite()) {
        return None;
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * xtol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Some(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            // Inverse quadratic (or secant) interpolation.
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = d;
            }
        } else {
            d = m;
            e = d;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
    }
    Some(b)
}

/// Golden-section search for the maximum of a unimodal `f` on `[a, b]` to an absolute tolerance `xtol`;
/// returns `(x, f(x))`, including the end points as candidates.
pub fn golden_max<F: FnMut(f64) -> f64>(mut f: F, a: f64, b: f64, xtol: f64) -> (f64, f64) {
    const R: f64 = 0.618_033_988_749_894_8;
    let (fa0, fb0) = (f(a), f(b));
    let (mut lo, mut hi) = (a, b);
    let mut x1 = hi - R * (hi - lo);
    let mut x2 = lo + R * (hi - lo);
    let (mut f1, mut f2) = (f(x1), f(x2));
    // The interval shrinks by 0.618 per iteration; stop at the tolerance or at the resolution of f64.
    for _ in 0..200 {
        if hi - lo <= xtol + 4.0 * f64::EPSILON * hi.abs().max(lo.abs()) {
            break;
        }
        if f1 < f2 {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + R * (hi - lo);
            f2 = f(x2);
        } else {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - R * (hi - lo);
            f1 = f(x1);
        }
    }
    let mut best = if f1 > f2 { (x1, f1) } else { (x2, f2) };
    if fa0 > best.1 {
        best = (a, fa0);
    }
    if fb0 > best.1 {
        best = (b, fb0);
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_finds_known_roots() {
        let r = brent_root(|x| x * x - 2.0, 0.0, 2.0, -2.0, 2.0, 1e-15).unwrap();
        assert!((r - 2f64.sqrt()).abs() < 1e-14);
        let r = brent_root(|x: f64| x.cos() - x, 0.0, 1.0, 1.0, 1f64.cos() - 1.0, 1e-15).unwrap();
        assert!((r.cos() - r).abs() < 1e-15);
        assert!(brent_root(|x| x * x + 1.0, -1.0, 1.0, 2.0, 2.0, 1e-12).is_none());
    }

    #[test]
    fn golden_section_finds_interior_and_end_maxima() {
        let (x, fx) = golden_max(|x: f64| x.sin(), 0.0, 3.0, 1e-12);
        assert!((x - std::f64::consts::FRAC_PI_2).abs() < 1e-6 && (fx - 1.0).abs() < 1e-12);
        let (x, _) = golden_max(|x| -x, 0.0, 1.0, 1e-12);
        assert_eq!(x, 0.0);
    }
}
