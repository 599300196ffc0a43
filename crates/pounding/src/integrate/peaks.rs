//! Peaks of a quantity between integration nodes: the cubic Hermite interpolant of a step, and the largest
//! value of a history given piece by piece, located by golden-section search on its interpolant.

use super::roots::{golden_max, quadratic_roots};

/// The cubic Hermite interpolant on a step of length `h` of a quantity with values `pa`, `pb` and slopes
/// `va`, `vb` at its ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hermite {
    pa: f64,
    /// `h va`.
    d: f64,
    b: f64,
    c: f64,
    h: f64,
    va: f64,
    vb: f64,
}

impl Hermite {
    /// The interpolant of values `pa`, `pb` and slopes `va`, `vb` on a step of length `h`.
    pub fn new(pa: f64, pb: f64, va: f64, vb: f64, h: f64) -> Self {
        let dlt = pb - pa;
        Self {
            pa,
            d: h * va,
            b: 3.0 * dlt - h * (2.0 * va + vb),
            c: -2.0 * dlt + h * (va + vb),
            h,
            va,
            vb,
        }
    }

    /// The value at the fraction `s` of the step.
    #[inline]
    pub fn at(&self, s: f64) -> f64 {
        self.pa + s * (self.d + s * (self.b + s * self.c))
    }

    /// The fractions of the step (in [0, 1]) where the slope vanishes, when the slopes at the ends differ in
    /// sign (the case of one interior extremum; `NaN` for none).
    pub fn extrema(&self) -> [f64; 2] {
        if self.va * self.vb > 0.0 || self.h <= 0.0 {
            return [f64::NAN; 2];
        }
        // p'(s) = h va + 2 b s + 3 c s^2.
        quadratic_roots(3.0 * self.c, 2.0 * self.b, self.d).map(|s| {
            if (0.0..=1.0).contains(&s) {
                s
            } else {
                f64::NAN
            }
        })
    }
}

impl Hermite {
    /// Whether an interior extremum reaches `fraction` of the largest value `hi` so far, or of the largest
    /// `-value` `lo` (the screen before an extremum is located on an exact motion the curve stays close to).
    pub fn extremum_near(&self, (hi, lo): (f64, f64), fraction: f64) -> bool {
        self.extrema()
            .into_iter()
            .any(|s| !s.is_nan() && (self.at(s) >= fraction * hi || -self.at(s) >= fraction * lo))
    }

    /// The slopes at the step's two ends.
    pub fn end_slopes(&self) -> (f64, f64) {
        (self.va, self.vb)
    }

    /// The fraction of the step where the slope vanishes, when the slopes at the ends differ in sign (one
    /// such point); `None` otherwise.
    pub fn root_of_slope(&self) -> Option<f64> {
        self.extrema().into_iter().find(|s| !s.is_nan())
    }

    /// The slope (rate per unit time) at the fraction `s` of the step.
    pub fn slope(&self, s: f64) -> f64 {
        (self.d + s * (2.0 * self.b + 3.0 * s * self.c)) / self.h
    }

    /// The fraction of the step (in (0, 1)) where the slope is extreme (the curvature vanishes), or `NaN`:
    /// where a rate, such as a dashpot's force, peaks.
    pub fn inflection(&self) -> f64 {
        // p''(s) = 2 b + 6 c s.
        let s = -self.b / (3.0 * self.c);
        if s > 0.0 && s < 1.0 {
            s
        } else {
            f64::NAN
        }
    }
}

/// Largest `|p|` of the cubic Hermite interpolant of `p` (values `pa`, `pb`, slopes `va`, `vb`) on a step of
/// length `h`, over its interior extremum (if any) and its end: `(fraction of the step, |p|)`.
pub fn hermite_peak(pa: f64, pb: f64, va: f64, vb: f64, h: f64) -> (f64, f64) {
    let mut best = (1.0, pb.abs());
    let p = Hermite::new(pa, pb, va, vb, h);
    for s in p.extrema() {
        if !s.is_nan() && p.at(s).abs() > best.1 {
            best = (s, p.at(s).abs());
        }
    }
    best
}

/// A piece of a scalar history that can be evaluated anywhere on its span.
pub trait Piece: Copy {
    /// Start and end, s.
    fn span(&self) -> (f64, f64);
    /// The value at `t`.
    fn value(&self, t: f64) -> f64;
    /// The largest value on the span and its time `(t, value)`, where the piece can find it exactly (a
    /// polynomial's extremum); `None` (the default): searched by golden section on [`Self::value`].
    fn peak(&self) -> Option<(f64, f64)> {
        None
    }
}

/// The largest value of a scalar history given piece by piece, with its time. Only the pieces around a node
/// higher than both of its neighbours are searched (golden section), so two pieces are kept and nothing is
/// allocated per step.
#[derive(Clone, Debug)]
pub struct PeakTracker<S: Piece> {
    segs: [Option<S>; 2],
    cur: usize,
    f_prev: f64,
    f_node: f64,
    best: (f64, f64),
    best_seg: Option<S>,
}

impl<S: Piece> PeakTracker<S> {
    /// A history that starts with value `f0` at `t0`.
    pub fn new(t0: f64, f0: f64) -> Self {
        Self {
            segs: [None, None],
            cur: 0,
            f_prev: f64::NEG_INFINITY,
            f_node: f0,
            best: (t0, f0),
            best_seg: None,
        }
    }

    fn refine(&mut self, seg: S) {
        let p = seg.peak().unwrap_or_else(|| {
            let (ta, tb) = seg.span();
            let tol = 1e-12 * (tb - ta).max(f64::MIN_POSITIVE);
            golden_max(|t| seg.value(t), ta, tb, tol)
        });
        self.consider(p, seg);
    }

    fn consider(&mut self, p: (f64, f64), seg: S) {
        if p.1 > self.best.1 {
            self.best = p;
            self.best_seg = Some(seg);
        }
    }

    /// The next piece, whose value at its end is `f_end`.
    pub fn push(&mut self, seg: S, f_end: f64) {
        self.segs[self.cur] = Some(seg);
        if self.f_node >= f_end && self.f_node >= self.f_prev {
            self.refine(seg);
            if let Some(prev) = self.segs[1 - self.cur] {
                self.refine(prev);
            }
        }
        self.consider((seg.span().1, f_end), seg);
        self.f_prev = self.f_node;
        self.f_node = f_end;
        self.cur = 1 - self.cur;
    }

    /// The largest value and its time `(t, value)`, once the history has ended.
    pub fn finish(&mut self) -> (f64, f64) {
        if self.f_node >= self.f_prev {
            if let Some(last) = self.segs[1 - self.cur] {
                self.refine(last);
            }
        }
        self.best
    }

    /// The largest value so far `(t, value)` (the last node not yet refined).
    pub fn best(&self) -> (f64, f64) {
        self.best
    }

    /// The piece that holds the largest value (`None` if it is the first node).
    pub fn best_piece(&self) -> Option<&S> {
        self.best_seg.as_ref()
    }
}

#[cfg(test)]
mod tests {
    use super::hermite_peak;

    #[test]
    fn hermite_peak_of_a_cubic_is_exact() {
        // p(t) = t (2 - t)^2 on [0, 1.5] has its maximum 32/27 at t = 2/3.
        let p = |t: f64| t * (2.0 - t) * (2.0 - t);
        let dp = |t: f64| (2.0 - t) * (2.0 - t) - 2.0 * t * (2.0 - t);
        let (s, v) = hermite_peak(p(0.0), p(1.5), dp(0.0), dp(1.5), 1.5);
        assert!((v - 32.0 / 27.0).abs() < 1e-14);
        assert!((s * 1.5 - 2.0 / 3.0).abs() < 1e-12);
    }
}
