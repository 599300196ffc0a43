//! Numbers as text, where a file or a person wants them rounded.

/// A number with 12 significant digits, in scientific notation when very large or small.
pub fn fmt_num(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 || (1e-3..1e6).contains(&a) {
        let digits = 11 - a.log10().floor().max(-3.0) as i32;
        let s = format!("{:.*}", digits.clamp(0, 15) as usize, x);
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let s = format!("{x:.11e}");
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        let mantissa = if mantissa.contains('.') {
            mantissa.trim_end_matches('0').trim_end_matches('.')
        } else {
            mantissa
        };
        format!("{mantissa}e{exp}")
    }
}

/// Floats as their shortest round-trip text (the Żmij algorithm, which serde_json uses too), in ryu's style:
/// fixed notation from 1e-5 up to 1e16, `1e-7` and `1.5e16` outside it, `0.0`, `NaN`, `inf`. Parsing the text
/// gives back the same f64, bit for bit.
#[derive(Default)]
pub struct Shortest {
    buf: zmij::Buffer,
    big: String,
}

impl Shortest {
    /// A formatter (it holds the bytes of the last number).
    pub fn new() -> Self {
        Self::default()
    }

    /// The text of `x`.
    pub fn format(&mut self, x: f64) -> &str {
        if x.abs() < 1e16 || !x.is_finite() {
            return self.buf.format(x);
        }
        // Żmij writes a positive exponent as `e+16`; ryu, csv's serialiser and our earlier files as `e16`.
        let s = self.buf.format(x);
        self.big.clear();
        self.big.push_str(s);
        if let Some(p) = self.big.find("e+") {
            self.big.remove(p + 1);
        }
        &self.big
    }

    /// Appends the text of `x` to `out`.
    pub fn push(&mut self, out: &mut Vec<u8>, x: f64) {
        out.extend_from_slice(self.format(x).as_bytes());
    }
}

/// Powers of ten exactly representable as f64, 10^0 to 10^15.
const POW10: [f64; 16] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
];

/// The decades of the fast path of [`push_time`]: 10^-3 to 10^6 as f64.
const DECADES: [f64; 10] = [1e-3, 1e-2, 1e-1, 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6];

/// `x` rounded to `digits` significant digits, without trailing zeros (for people, not for files).
pub fn fmt_sig(x: f64, digits: i32) -> String {
    if x == 0.0 || !x.is_finite() {
        return fmt_num(x);
    }
    let f = 10f64.powi(digits - 1 - x.abs().log10().floor() as i32);
    fmt_num((x * f).round() / f)
}

/// Appends `fmt_num(t)` to `out`, fast for the output times of a history (about 30 ns where `fmt_num` takes
/// 170): between 1e-3 and 1e6 in magnitude the 12 significant digits are the integer nearest `|t| 10^d`, which
/// f64 arithmetic finds unless that product lies within 1e-3 of a half (its rounding error is below 1e-4,
/// as the product is below 1e12); those cases, magnitudes within 1e-14 of a power of ten (where `fmt_num`'s
/// `log10` decides the decade) and all others are left to `fmt_num`.
pub fn push_time(out: &mut Vec<u8>, t: f64) {
    let a = t.abs();
    if a > DECADES[0] * (1.0 + 1e-14) && a < DECADES[9] * (1.0 - 1e-14) {
        // The decade by comparisons (log10 costs more than the rest together).
        let i = DECADES[1..9].iter().take_while(|&&p| a >= p).count();
        let near_power = |p: f64| (a - p).abs() < 1e-14 * p;
        if !near_power(DECADES[i]) && !near_power(DECADES[i + 1]) {
            let d = 14 - i;
            let p = a * POW10[d];
            // p < 1e13: the truncation is its floor, without a call to libm.
            let whole = p as u64;
            let frac = p - whole as f64;
            if (frac - 0.5).abs() > 1e-3 {
                push_fixed(out, t < 0.0, whole + u64::from(frac > 0.5), d);
                return;
            }
        }
    }
    out.extend_from_slice(fmt_num(t).as_bytes());
}

/// Appends `n 10^-d` in fixed notation without trailing zeros (and without a point if it is whole).
fn push_fixed(out: &mut Vec<u8>, negative: bool, n: u64, d: usize) {
    let mut digits = [0u8; 20];
    let mut len = 0;
    let mut m = n;
    loop {
        digits[len] = b'0' + (m % 10) as u8;
        len += 1;
        m /= 10;
        if m == 0 {
            break;
        }
    }
    // digits holds n backwards; pad with zeros so that there is at least one digit before the point.
    while len <= d {
        digits[len] = b'0';
        len += 1;
    }
    let trailing = digits[..d].iter().take_while(|&&c| c == b'0').count();
    if negative {
        out.push(b'-');
    }
    out.extend(digits[d..len].iter().rev());
    if trailing < d {
        out.push(b'.');
        out.extend(digits[trailing..d].iter().rev());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic stream of f64 bit patterns (splitmix64), over every exponent.
    fn bits(n: usize) -> impl Iterator<Item = f64> {
        let mut s = 0x9e37_79b9_7f4a_7c15u64;
        (0..n).map(move |_| {
            s = s.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = s;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            f64::from_bits(z ^ (z >> 31))
        })
    }

    #[test]
    fn shortest_is_ryu_text_and_round_trips() {
        // ryu, an independent implementation, is the reference for the text; parsing for the value.
        let decades = (-330..=310).flat_map(|e| {
            let p = 10f64.powi(e);
            [
                p,
                p * (1.0 - f64::EPSILON),
                p * (1.0 + f64::EPSILON),
                -1.5 * p,
            ]
        });
        let specials = [
            0.0,
            -0.0,
            5e-324,
            f64::MAX,
            f64::MIN_POSITIVE,
            1e-5,
            9.99999e-6,
            1e16,
            9.9e15,
        ];
        let mut f = Shortest::new();
        let mut r = ryu::Buffer::new();
        for x in bits(300_000).chain(decades).chain(specials) {
            if !x.is_finite() {
                continue;
            }
            let s = f.format(x).to_string();
            assert_eq!(s, r.format(x), "{x:e}");
            assert_eq!(s.parse::<f64>().unwrap().to_bits(), x.to_bits(), "{s}");
        }
        assert_eq!(f.format(f64::NAN), "NaN");
        assert_eq!(f.format(f64::NEG_INFINITY), "-inf");
    }

    #[test]
    fn push_time_is_fmt_num() {
        // Output times k dt of many steps, and arbitrary values over the fast range and beyond it.
        let dts = [
            0.005,
            0.01,
            0.001,
            0.02,
            0.0025,
            1e-4,
            0.003,
            0.007,
            1.0 / 3.0,
            0.1,
            2e-5,
        ];
        let times = dts
            .iter()
            .flat_map(|&dt| (0..200_000).map(move |k| k as f64 * dt));
        let others = bits(200_000)
            .map(|x| x.abs() % 2e6 * if x < 0.0 { -1.0 } else { 1.0 })
            .chain(bits(50_000).map(|x| x % 1e-2))
            .chain([
                1e-3,
                1e6,
                999_999.999_999_5,
                0.000_999_999_999_999_5,
                12.345_678_901_25,
            ])
            .chain((-4..=7).flat_map(|e| {
                // Beside each power of ten, where the decade is decided by log10.
                let p = 10f64.powi(e);
                (-40..=40).map(move |k| p * (1.0 + f64::from(k) * f64::EPSILON))
            }));
        let mut out = Vec::new();
        for t in times.chain(others).filter(|t| t.is_finite()) {
            out.clear();
            push_time(&mut out, t);
            assert_eq!(std::str::from_utf8(&out).unwrap(), fmt_num(t), "{t:e}");
        }
    }
}
