//! Ground-motion records: the built-in El Centro record against its provenance and textbook peaks, the AT2
//! fixture, and malformed files.

use pounding::ground_motion::{parse, Format, Record, Units};

const AT2: &str = include_str!("fixtures/elcentro1940_180_peer2000.AT2");
const G: f64 = 9.80665;

#[test]
fn el_centro_matches_its_provenance() {
    // crates/pounding/data/PROVENANCE.md: 1559 samples at 0.02 s, PGA 0.3188 g (negative) at 2.04 s.
    let r = Record::el_centro_1940();
    assert_eq!(r.npts(), 1559);
    assert_eq!(r.dt(), 0.02);
    assert!((r.duration() - 31.18).abs() < 1e-9);
    let p = r.peaks();
    assert!((p.pga / G - 0.3188).abs() < 5e-5 && p.pga_signed < 0.0);
    assert!((p.pga_time - 2.04).abs() < 1e-9);
    // Chopra, Dynamics of Structures (fig. 6.1.4): peak ground displacement 8.40 in = 0.2134 m; baseline
    // processing differs, so agreement to 2 %.
    assert!((p.pgd / 0.2134 - 1.0).abs() < 0.02, "pgd {}", p.pgd);
    assert!(p.pgv > 0.3 && p.pgv < 0.4, "pgv {}", p.pgv);
}

#[test]
fn acceleration_interpolates_and_starts_from_rest() {
    let r = Record::el_centro_1940();
    assert_eq!(r.at(0.0), 0.0);
    assert!((r.at(0.02) - 0.0063 * G).abs() < 1e-12);
    assert!((r.at(0.03) - 0.5 * (0.0063 + 0.00364) * G).abs() < 1e-12);
    assert!((r.at(0.01) - 0.5 * 0.0063 * G).abs() < 1e-12);
    assert_eq!(r.at(40.0), 0.0);
}

#[test]
fn peer_at2_fixture() {
    // PROVENANCE: NPTS = 4000, DT = 0.01 s, PGA 0.3129 g.
    let r = Record::parse("ielc180", AT2, Format::At2, Units::G).unwrap();
    assert_eq!(r.npts(), 4000);
    assert_eq!(r.dt(), 0.01);
    assert!((r.accelerations()[0] / G + 0.6403182e-2).abs() < 1e-12);
    assert!((r.peaks().pga / G - 0.3129).abs() < 5e-5);
}

#[test]
fn at2_header_variants() {
    let body = "  .1E-01  -.2E-01   .3E-01\n";
    for header in [
        "NPTS=  3, DT=   .0100 SEC,",
        "NPTS=  3, DT=   .0100 SEC",
        "NPTS=  3, DT= .0100",
        "3 0.01000 NPTS, DT",
        "npts=3 dt=0.01",
    ] {
        let text = format!("title\nevent\nunits G\n{header}\n{body}");
        let (dt, v) = parse::at2(&text).unwrap_or_else(|e| panic!("{header}: {e}"));
        assert_eq!((dt, v.len()), (0.01, 3), "{header}");
        // A footer and one value a line are fine too.
        let text = format!("t\n{header}\n.1E-01\n-.2E-01\n.3E-01\n*** End Data ***\n");
        assert_eq!(parse::at2(&text).unwrap().1.len(), 3);
    }
}

#[test]
fn malformed_files_name_the_line() {
    let cases = [
        (
            parse::at2("a\nNPTS=  4, DT= .01\n .1 .2 .3\n").unwrap_err(),
            3,
            "NPTS = 4",
        ),
        (
            parse::at2("a\nNPTS=  2, DT= .01\n .1 x .3\n").unwrap_err(),
            3,
            "'x'",
        ),
        (
            parse::at2("a\nNPTS=  2, DT= .01\n 0,1 0,3\n").unwrap_err(),
            3,
            "decimal comma",
        ),
        (
            parse::time_acc("t,a\n0,0\n0.02,0.1\n0.05,0.2\n").unwrap_err(),
            4,
            "uneven",
        ),
        (
            parse::time_acc("t;a\n0;0\n0,02;0,1\n").unwrap_err(),
            3,
            "decimal comma",
        ),
        (
            parse::time_acc("t a\n0 0\n0.02 0.1\nabc 0.3\n").unwrap_err(),
            4,
            "'abc'",
        ),
        (parse::time_acc("0 0 1\n").unwrap_err(), 1, "2 columns"),
        (parse::values("0.1\n0.2\n0.3x\n").unwrap_err(), 3, "'0.3x'"),
    ];
    for (e, line, text) in cases {
        assert_eq!(e.line, line, "{e}");
        assert!(e.message.contains(text), "{e}");
    }
}

#[test]
fn units_and_scale() {
    let r = Record::parse(
        "v",
        "100\n-50\n",
        Format::Values { dt: 0.01 },
        Units::CmPerS2,
    )
    .unwrap()
    .scaled(2.0)
    .unwrap();
    assert_eq!(r.accelerations(), &[2.0, -1.0]);
    assert!(Record::parse("v", "1\n", Format::Values { dt: 0.0 }, Units::G).is_err());
}

#[test]
fn peaks_between_samples_are_found_exactly() {
    // Samples 1, -1, -1, 1 m/s^2 at t = 0.5, 1, 1.5, 2 s (ramp from rest before): mean and slope are zero,
    // so the baseline correction removes nothing. By hand, with the acceleration linear between samples:
    // v peaks at +0.375 m/s (t = 0.75 s, where a = 0) and -0.375 m/s (t = 1.75 s); d peaks at 23/96 m where
    // v = 0 (t = 1.25 s). Sample values alone would give 0.25 m/s and 0.2083 m.
    let r = Record::new("pulse", 0.5, 0.5, vec![1.0, -1.0, -1.0, 1.0]).unwrap();
    let p = r.peaks();
    assert!((p.pgv - 0.375).abs() < 1e-14, "{}", p.pgv);
    assert!((p.pgd - 23.0 / 96.0).abs() < 1e-14, "{}", p.pgd);
    assert_eq!(p.pga, 1.0);
}
