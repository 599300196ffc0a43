//! A uniformly sampled ground acceleration ([`Record`]) read from text, and its peaks.

use super::{parse, Format, ParseError, Units};
use crate::error::check;
use crate::Error;

/// A uniformly sampled ground acceleration: `acc[k]` (m/s^2) at time `t0 + k dt` (s). The ground is at
/// rest at `t = 0`; before `t0` the acceleration ramps linearly from 0, and after the last sample it is 0.
///
/// A built-in record ([`Record::el_centro_1940`], [`Record::builtin`]), a file's text ([`Record::read`]) or
/// samples ([`Record::new`]):
///
/// ```
/// use pounding::ground_motion::Record;
/// let r = Record::el_centro_1940().scaled(2.0)?; // twice the 1940 El Centro N-S record
/// let p = r.peaks();
/// assert!((p.pga / 9.80665 - 2.0 * 0.3188).abs() < 1e-3); // PGA in g
/// assert_eq!((r.dt(), r.npts()), (0.02, 1559)); // s, samples
/// let pulse = Record::new("pulse", 0.01, 0.01, vec![1.0, -1.0])?; // dt s, t0 s, m/s^2
/// assert!(pulse.at(0.015).abs() < 1e-12); // linear between samples: 0 halfway
/// # Ok::<(), pounding::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    name: String,
    dt: f64,
    t0: f64,
    acc: Vec<f64>,
    /// The record arrives this late, s: everything (its ramp from rest included) happens `delay` later.
    delay: f64,
}

/// Peak values of a record.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Peaks {
    /// Peak ground acceleration (absolute value), m/s^2.
    pub pga: f64,
    /// Signed acceleration at the peak, m/s^2.
    pub pga_signed: f64,
    /// Time of the peak acceleration, s.
    pub pga_time: f64,
    /// Peak ground velocity after linear baseline correction, m/s.
    pub pgv: f64,
    /// Peak ground displacement after linear baseline correction, m.
    pub pgd: f64,
}

/// Accelerations below [`crate::limits::MIN_MAGNITUDE`] in magnitude set to 0: zero for any structure, and
/// they would carry subnormal numbers into the analysis.
fn flush_tiny(acc: &mut [f64]) {
    for a in acc.iter_mut() {
        if !crate::limits::not_tiny(*a) {
            *a = 0.0;
        }
    }
}

impl Record {
    /// A record named `name` with time step `dt` (s, > 0), first sample time `t0` (s, >= 0) and accelerations
    /// in m/s^2 (at least one, all finite).
    ///
    /// Accelerations smaller than [`crate::limits::MIN_MAGNITUDE`] in magnitude are read as 0.
    pub fn new(
        name: impl Into<String>,
        dt: f64,
        t0: f64,
        mut acc: Vec<f64>,
    ) -> Result<Self, Error> {
        check(
            "dt",
            dt,
            (crate::limits::MIN_RECORD_DT..=crate::limits::MAX_RECORD_DT).contains(&dt),
            "1e-5 <= dt <= 10 (s)",
        )?;
        check("t0", t0, (0.0..=1e4).contains(&t0), "0 <= t0 <= 1e4 (s)")?;
        if acc.is_empty() || acc.len() > crate::limits::MAX_RECORD_SAMPLES {
            return Err(Error::Parameter {
                name: "npts",
                value: acc.len() as f64,
                allowed: "1 to 1e7 acceleration values (limits::MAX_RECORD_SAMPLES)",
            });
        }
        if let Some(bad) = acc
            .iter()
            .find(|a| !a.is_finite() || a.abs() > crate::limits::MAX_GROUND_ACCELERATION)
        {
            return Err(Error::Parameter {
                name: "acceleration",
                value: *bad,
                allowed: "finite values of at most 1e5 m/s^2 (about 1e4 g) in magnitude",
            });
        }
        flush_tiny(&mut acc);
        Ok(Self {
            name: name.into(),
            dt,
            t0,
            acc,
            delay: 0.0,
        })
    }

    /// Parses `text` in `format`, with accelerations in `units`: both given, as
    /// [`Record::read`]`(name, text, Some(format), Some(units))`. An AT2 header that states other units
    /// (`UNITS OF G` read as cm/s^2) is an error.
    pub fn parse(
        name: &str,
        text: &str,
        format: Format,
        units: Units,
    ) -> Result<Self, RecordError> {
        Self::read(name, text, Some(format), Some(units))
    }

    /// Reads the record in `text` (a file's contents; the library opens no files), called `name`.
    ///
    /// - `format`: `None` detects it ([`Format::detect`], with `name` as the file name): AT2 if the text has
    ///   the PEER header layout, whatever the file's name, else two columns (time, acceleration).
    /// - `units` of the accelerations: `None` takes the units the text states, and g for a text that states
    ///   none. An AT2 header states them as `... IN UNITS OF G` ([`parse::at2_units`]); a two-column or values
    ///   text in a comment, `# units = "m/s2"` (the tool's own records say `# read with units = "m/s2"`), or
    ///   in the name of its acceleration column, `acceleration_m_per_s2`, `acc (g)` ([`parse::text_units`]).
    ///   Given units must agree with the stated ones: a header that says `UNITS OF G` read as cm/s^2 is an
    ///   error (a [`ParseError`] on the header's line naming both), not a record 981 times too weak. A stated
    ///   word that is not a unit known here needs `units` given.
    ///
    /// A text that is not in the format given but looks like an AT2 gets a hint to read it as one.
    ///
    /// ```
    /// use pounding::ground_motion::{Format, Record, Units};
    /// let text = "PEER NGA STRONG MOTION DATABASE RECORD
    /// Imperial Valley, 1940, El Centro
    /// ACCELERATION TIME SERIES IN UNITS OF G
    /// NPTS=    4, DT=   .0100 SEC
    ///   .10   -.20   .05   .0
    /// ";
    /// // Format and units from the text: an AT2 in g.
    /// let r = Record::read("elcentro.txt", text, None, None)?;
    /// assert_eq!((r.npts(), r.dt()), (4, 0.01));
    /// assert_eq!(r.accelerations()[1], -0.2 * 9.80665); // m/s^2
    /// // Units that contradict the header are refused, with a hint.
    /// let e = Record::read("elcentro", text, None, Some(Units::CmPerS2)).unwrap_err();
    /// assert!(e.to_string().starts_with("line 3: the header states units of G (g), but the units given are cm/s^2"));
    /// # Ok::<(), pounding::ground_motion::RecordError>(())
    /// ```
    pub fn read(
        name: &str,
        text: &str,
        format: Option<Format>,
        units: Option<Units>,
    ) -> Result<Self, RecordError> {
        let format = format.unwrap_or_else(|| Format::detect(text, Some(name)));
        let parsed = match format {
            Format::At2 => parse::at2(text).map(|(dt, v)| (dt, dt, v)),
            Format::TimeAcc => parse::time_acc(text),
            Format::Values { dt } => {
                check("dt", dt, dt > 0.0, "dt > 0 (s)")?;
                parse::values(text).map(|v| (dt, dt, v))
            }
        };
        // AT2 and value files start one step after rest, so t0 = dt; a time column gives its own t0.
        let (t0, dt, values) = parsed.map_err(|mut e| {
            if format != Format::At2 && parse::looks_like_at2(text) {
                e.message.push_str(
                    "; the text looks like a PEER AT2 record (a header line with NPTS and DT): set format = \"at2\" (--format at2)",
                );
            }
            e
        })?;
        let stated = match format {
            Format::At2 => parse::at2_units(text)?,
            _ => parse::text_units(text)?,
        };
        let units = resolve_units(stated, units)?;
        let f = units.to_m_per_s2();
        Ok(Self::new(
            name,
            dt,
            t0,
            values.into_iter().map(|a| a * f).collect(),
        )?)
    }

    /// The same record with accelerations multiplied by `scale` (finite).
    pub fn scaled(mut self, scale: f64) -> Result<Self, Error> {
        let peak = self.acc.iter().fold(0.0f64, |m, a| m.max(a.abs()));
        check(
            "scale",
            scale,
            (peak * scale).abs() <= crate::limits::MAX_GROUND_ACCELERATION
                && crate::limits::not_tiny(scale),
            "a finite scale, 0 or at least 1e-30 in magnitude, that keeps the peak acceleration at most 1e5 m/s^2",
        )?;
        self.acc.iter_mut().for_each(|a| *a *= scale);
        flush_tiny(&mut self.acc);
        Ok(self)
    }

    /// Name.
    pub fn name(&self) -> &str {
        &self.name
    }
    /// Time step, s.
    pub fn dt(&self) -> f64 {
        self.dt
    }
    /// Time of the first sample, s (with the delay).
    pub fn t0(&self) -> f64 {
        self.t0 + self.delay
    }
    /// How late the record arrives, s ([`Record::delayed`]).
    pub fn delay(&self) -> f64 {
        self.delay
    }

    /// The same record arriving `tau` seconds later (s, finite, >= 0): its acceleration at `t` is the
    /// record's at `t - tau`, at rest before `tau` (wave passage: `tau = distance / apparent velocity`).
    pub fn delayed(mut self, tau: f64) -> Result<Self, Error> {
        check(
            "delay",
            tau,
            (0.0..=1e4).contains(&tau),
            "0 <= delay <= 1e4 (s)",
        )?;
        self.delay += tau;
        Ok(self)
    }
    /// Number of samples.
    pub fn npts(&self) -> usize {
        self.acc.len()
    }
    /// Time of the last sample, s (with the delay).
    pub fn duration(&self) -> f64 {
        self.t0() + (self.acc.len() - 1) as f64 * self.dt
    }
    /// Accelerations, m/s^2.
    pub fn accelerations(&self) -> &[f64] {
        &self.acc
    }

    /// Ground acceleration at time `t` (s), m/s^2: linear between samples, a ramp from rest before `t0`,
    /// zero after the last sample.
    pub fn at(&self, t: f64) -> f64 {
        if t <= self.delay || t > self.duration() {
            return 0.0;
        }
        // The undelayed record's time (exactly t when there is no delay).
        let t = if self.delay == 0.0 { t } else { t - self.delay };
        if t < self.t0 {
            return self.acc[0] * t / self.t0;
        }
        let x = (t - self.t0) / self.dt;
        // x >= 0 here: truncation is its floor (without a call to libm's).
        let k = (x as usize).min(self.acc.len() - 1);
        if k + 1 >= self.acc.len() {
            return self.acc[k];
        }
        let f = x - k as f64;
        self.acc[k] * (1.0 - f) + self.acc[k + 1] * f
    }

    /// Peak ground acceleration (largest absolute sample), m/s^2: [`Record::peaks`]'s `pga` without the
    /// integrations (what a run's summary and its plausibility check read).
    pub fn pga(&self) -> f64 {
        self.acc.iter().fold(0.0, |m, a| m.max(a.abs()))
    }

    /// Peak acceleration, and peak velocity and displacement after a linear baseline correction: a straight
    /// line `c0 + c1 t`, fitted by least squares to the acceleration samples, is subtracted before integrating
    /// from rest. Integration is exact for the piecewise-linear acceleration between samples. The correction
    /// is for reporting only; analyses use the record as given.
    pub fn peaks(&self) -> Peaks {
        let n = self.acc.len();
        let times = |k: usize| self.t0 + k as f64 * self.dt;
        let (k_max, a_max) = self
            .acc
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
            .map(|(k, a)| (k, *a))
            .expect("a record has samples");
        // Least-squares line through (t_k, a_k).
        let nf = n as f64;
        let (st, sa) = (0..n).fold((0.0, 0.0), |(st, sa), k| (st + times(k), sa + self.acc[k]));
        let (mt, ma) = (st / nf, sa / nf);
        let (sxx, sxy) = (0..n).fold((0.0, 0.0), |(sxx, sxy), k| {
            let dt = times(k) - mt;
            (sxx + dt * dt, sxy + dt * (self.acc[k] - ma))
        });
        let c1 = if sxx > 0.0 { sxy / sxx } else { 0.0 };
        let c0 = ma - c1 * mt;
        let corr = |k: usize| self.acc[k] - (c0 + c1 * times(k));
        // From rest at t = 0: the ramp to the first sample, then the samples.
        let (mut v, mut d, mut pgv, mut pgd) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        // Over a step of length h the acceleration is linear, the velocity quadratic and the displacement
        // cubic: their extrema inside the step are where a = 0 and where v = 0.
        let mut step = |a0: f64, a1: f64, h: f64| {
            let j = (a1 - a0) / h;
            let vel = |s: f64| v + a0 * s + j * s * s / 2.0;
            let disp = |s: f64| d + v * s + a0 * s * s / 2.0 + j * s * s * s / 6.0;
            if a0 * a1 < 0.0 {
                pgv = pgv.max(vel(a0 / (a0 - a1) * h).abs());
            }
            // Roots of v + a0 s + j s^2 / 2 = 0 in (0, h).
            let roots: [f64; 2] = if j == 0.0 {
                [if a0 != 0.0 { -v / a0 } else { -1.0 }, -1.0]
            } else {
                let disc = a0 * a0 - 2.0 * j * v;
                if disc < 0.0 {
                    [-1.0, -1.0]
                } else {
                    let r = disc.sqrt();
                    [(-a0 + r) / j, (-a0 - r) / j]
                }
            };
            for s in roots {
                if s > 0.0 && s < h {
                    pgd = pgd.max(disp(s).abs());
                }
            }
            let (v1, d1) = (vel(h), disp(h));
            v = v1;
            d = d1;
            pgv = pgv.max(v.abs());
            pgd = pgd.max(d.abs());
        };
        if self.t0 > 0.0 {
            step(0.0, corr(0), self.t0);
        }
        for k in 1..n {
            step(corr(k - 1), corr(k), self.dt);
        }
        Peaks {
            pga: a_max.abs(),
            pga_signed: a_max,
            pga_time: times(k_max) + self.delay,
            pgv,
            pgd,
        }
    }
}

/// The units of a text's accelerations: those `given`, which must agree with those its header states, else
/// the header's, else g.
fn resolve_units(
    stated: Option<parse::StatedUnits>,
    given: Option<Units>,
) -> Result<Units, ParseError> {
    match (stated, given) {
        (None, given) => Ok(given.unwrap_or(Units::G)),
        (Some(s), None) => s.units.ok_or_else(|| ParseError {
            line: s.line,
            message: format!(
                "the header states units of {:?}, which are not units of acceleration known here: give the units ({})",
                s.stated,
                Units::ALLOWED
            ),
        }),
        (Some(s), Some(given)) => match s.units {
            Some(h) if h != given => Err(ParseError {
                line: s.line,
                message: format!(
                    "the header states units of {} ({h}), but the units given are {given}: set units = \"{}\" (--units {}), or leave the units out to use the header's",
                    s.stated,
                    h.name().replace('^', ""),
                    h.name().replace('^', "")
                ),
            }),
            _ => Ok(given),
        },
    }
}

/// Why a record could not be built from text.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RecordError {
    /// The text is malformed.
    #[error(transparent)]
    Parse(#[from] ParseError),
    /// A value is out of range.
    #[error(transparent)]
    Value(#[from] Error),
}
