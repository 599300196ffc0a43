//! Any bytes through the three record parsers in two units: a record or an error, never a panic or an
//! allocation the input does not justify; a record holds finite, bounded accelerations and a dt in range.
#![no_main]

use libfuzzer_sys::fuzz_target;
use pounding::ground_motion::{Format, Record, Units};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    for format in [Format::At2, Format::TimeAcc, Format::Values { dt: 0.01 }] {
        for units in [Units::G, Units::CmPerS2] {
            if let Ok(r) = Record::parse("fuzz", text, format, units) {
                assert!(r
                    .accelerations()
                    .iter()
                    .all(|a| a.is_finite() && a.abs() <= 1e5));
                assert!(r.dt() >= 1e-5 && r.dt() <= 10.0);
            }
        }
    }
});
