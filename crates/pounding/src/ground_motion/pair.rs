//! Two records on one time grid, for the ground's two horizontal components.

use super::Record;
use crate::Error;

/// Largest ratio of a record's step to the common one: a finer grid would cost more steps than it is worth
/// (every sample ends a step), and steps that need one are not sampled on a common clock.
const MAX_SUBDIVISION: usize = 100;

/// `x` and `y` on one time grid (the same first sample time and step, lengths their own): a step that
/// divides both steps, starting at the earlier first sample. Each record keeps its piecewise-linear
/// acceleration exactly: its own samples are on the grid, the points between them are read on its lines,
/// and before its first sample it ramps from rest along the same line as before. Records already on one
/// grid are returned as they are (`y` takes `x`'s step and start when they agree to 1e-9 of a step).
/// Refused (naming `dt`, or `t0`) if the steps have no common divisor of at least 1/100 of the smaller one,
/// or the first samples are not a whole number of common steps apart.
pub fn on_one_grid(x: &Record, y: &Record) -> Result<(Record, Record), Error> {
    let (dx, dy) = (x.dt(), y.dt());
    let close = |a: f64, b: f64, scale: f64| (a - b).abs() <= 1e-9 * scale;
    if close(dx, dy, dx) && close(x.t0(), y.t0(), dx) {
        let y = Record::new(y.name(), dx, x.t0(), y.accelerations().to_vec())?;
        return Ok((x.clone(), y));
    }
    // dx / dy = p / q in lowest terms, p and q at most MAX_SUBDIVISION: the common step is dx / p.
    let ratio = dx / dy;
    let (p, q) = (1..=MAX_SUBDIVISION)
        .find_map(|q| {
            let p = (ratio * q as f64).round();
            (p >= 1.0 && p <= MAX_SUBDIVISION as f64 && close(p / q as f64, ratio, ratio))
                .then_some((p as usize, q))
        })
        .ok_or_else(|| Error::Choice {
            name: "dt",
            value: format!(
                "{} s along x and {} s along y",
                crate::words::number(dx),
                crate::words::number(dy)
            ),
            allowed: "time steps with a common divisor of at least 1/100 of the smaller (0.01 and 0.005 s, 0.02 and 0.015 s); resample a record".into(),
        })?;
    let g = dx / p as f64;
    let start = x.t0().min(y.t0());
    let offset = |r: &Record| -> Result<usize, Error> {
        let k = (r.t0() - start) / g;
        if (k - k.round()).abs() > 1e-6 {
            return Err(Error::Choice {
                name: "t0",
                value: format!(
                    "{} s along x and {} s along y",
                    crate::words::number(x.t0()),
                    crate::words::number(y.t0())
                ),
                allowed: format!(
                    "first samples a whole number of common steps ({} s) apart",
                    crate::words::number(g)
                ),
            });
        }
        Ok(k.round() as usize)
    };
    let resample = |r: &Record, every: usize| -> Result<Record, Error> {
        let s = offset(r)?;
        let a = r.accelerations();
        let n = s + (a.len() - 1) * every + 1;
        let acc = (0..n)
            .map(|k| {
                if k < s {
                    // The ramp from rest to the first sample, on the same line through the origin.
                    let t = start + k as f64 * g;
                    return if r.t0() > 0.0 { a[0] * t / r.t0() } else { 0.0 };
                }
                let (j, i) = ((k - s) / every, (k - s) % every);
                if i == 0 {
                    return a[j];
                }
                let f = i as f64 / every as f64;
                a[j] * (1.0 - f) + a[j + 1] * f
            })
            .collect();
        Record::new(r.name(), g, start, acc)
    };
    Ok((resample(x, p)?, resample(y, q)?))
}

/// The ground motion of record `x` (and `y`, along its y axis) turned by `angle` degrees counterclockwise
/// into the site's frame: along x `cos a x - sin a y`, along y `sin a x + cos a y` (one record along an angle
/// is `y = None`). The records are first put on one grid ([`on_one_grid`]); the shorter is followed by zeros
/// (it then ends with a ramp to 0 over one step rather than a jump).
pub fn turned(x: &Record, y: Option<&Record>, angle: f64) -> Result<(Record, Record), Error> {
    let (x, y) = match y {
        Some(y) => on_one_grid(x, y)?,
        None => {
            let zeros = Record::new("", x.dt(), x.t0(), vec![0.0; x.npts()])?;
            (x.clone(), zeros)
        }
    };
    let (c, s) = (angle.to_radians().cos(), angle.to_radians().sin());
    let n = x.npts().max(y.npts());
    let at = |r: &Record, k: usize| r.accelerations().get(k).copied().unwrap_or(0.0);
    let (mut ax, mut ay) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for k in 0..n {
        let (a, b) = (at(&x, k), at(&y, k));
        ax.push(c * a - s * b);
        ay.push(s * a + c * b);
    }
    let name = |r: &Record| format!("{} turned {angle} deg", r.name());
    Ok((
        Record::new(name(&x), x.dt(), x.t0(), ax)?,
        Record::new(name(&y), x.dt(), x.t0(), ay)?,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn records_on_other_steps_keep_their_accelerations() {
        let x = Record::new("x", 0.02, 0.02, vec![1.0, -2.0, 3.0, 0.5]).unwrap();
        let y = Record::new("y", 0.015, 0.015, vec![0.3, 0.7, -1.1, 2.0, 0.0, 1.0]).unwrap();
        let (a, b) = on_one_grid(&x, &y).unwrap();
        assert!((a.dt() - 0.005).abs() < 1e-15 && a.t0() == b.t0() && a.dt() == b.dt());
        for k in 0..=2000 {
            let t = k as f64 * 1e-4;
            assert!((a.at(t) - x.at(t)).abs() < 1e-12, "x at {t}");
            assert!((b.at(t) - y.at(t)).abs() < 1e-12, "y at {t}");
        }
        let z = Record::new("z", 0.0137, 0.0137, vec![1.0, 2.0]).unwrap();
        let e = on_one_grid(&x, &z).unwrap_err().to_string();
        assert!(
            e.starts_with("dt = 0.02 s along x and 0.0137 s along y"),
            "{e}"
        );
    }
}
