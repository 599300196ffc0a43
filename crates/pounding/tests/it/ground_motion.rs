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

/// A PEER NGA-style AT2 text: line 3 states `units`, line 4 holds NPTS and DT, then `values`.
fn at2_text(units_line: &str, values: &str) -> String {
    let n = values.split_whitespace().count();
    format!(
        "PEER NGA STRONG MOTION DATABASE RECORD\nImperial Valley-02, 5/19/1940, El Centro Array #9, 180\n{units_line}\nNPTS=  {n}, DT=   .0100 SEC\n{values}\n"
    )
}

#[test]
fn an_at2_header_sets_the_units_when_none_are_given() {
    let text = at2_text(
        "ACCELERATION TIME SERIES IN UNITS OF G",
        "  .1000  -.2500   .0500",
    );
    // 1 g = 9.80665 m/s^2 (standard gravity, by definition).
    let want = [0.1 * G, -0.25 * G, 0.05 * G];
    for format in [None, Some(Format::At2)] {
        for units in [None, Some(Units::G)] {
            let r = Record::read("rsn", &text, format, units).unwrap();
            for (a, w) in r.accelerations().iter().zip(want) {
                assert!((a - w).abs() < 1e-15, "{format:?} {units:?}: {a} vs {w}");
            }
        }
    }
    // The other statements PEER and others write, and what they mean in m/s^2 (1 gal = 1 cm/s^2).
    for (statement, factor) in [
        (
            "ACCELERATION TIME HISTORY IN UNITS OF G. FILTER POINTS: HP=0.1 Hz",
            G,
        ),
        ("ACCELERATION IN UNITS OF CM/S/S", 0.01),
        ("Acceleration time series in units of cm/sec^2", 0.01),
        ("ACCELERATION IN UNITS OF GAL", 0.01),
        ("ACCELERATION IN UNITS OF M/S2", 1.0),
        ("ACCELERATION IN UNITS OF MM/SEC/SEC", 0.001),
    ] {
        let r = Record::read("rsn", &at2_text(statement, "2.0 -4.0"), None, None)
            .unwrap_or_else(|e| panic!("{statement}: {e}"));
        assert_eq!(
            r.accelerations(),
            &[2.0 * factor, -4.0 * factor],
            "{statement}"
        );
    }
    // The PEER fixture says "UNITS OF G." on line 3: the same record with or without units = g.
    let unset = Record::read("ielc180", AT2, None, None).unwrap();
    assert_eq!(
        unset,
        Record::parse("ielc180", AT2, Format::At2, Units::G).unwrap()
    );
    // A header that states no units: g, unless told otherwise.
    let silent = at2_text("ACCELERATION TIME SERIES", "1.0");
    assert_eq!(
        Record::read("r", &silent, None, None)
            .unwrap()
            .accelerations(),
        &[G]
    );
    let cm = Record::read("r", &silent, None, Some(Units::CmPerS2)).unwrap();
    assert_eq!(cm.accelerations(), &[0.01]);
}

#[test]
fn units_that_contradict_an_at2_header_are_one_line_naming_both() {
    let text = at2_text("ACCELERATION TIME SERIES IN UNITS OF G", ".1 .2");
    for (given, name) in [(Units::CmPerS2, "cm/s^2"), (Units::MPerS2, "m/s^2")] {
        let e = Record::parse("rsn", &text, Format::At2, given).unwrap_err();
        let msg = e.to_string();
        assert_eq!(msg.lines().count(), 1, "{msg}");
        assert!(
            msg.starts_with("line 3: the header states units of G (g)"),
            "{msg}"
        );
        assert!(
            msg.contains(&format!("the units given are {name}")),
            "{msg}"
        );
        assert!(msg.contains("units = \"g\" (--units g)"), "{msg}");
        assert!(msg.contains("leave the units out"), "{msg}");
    }
    // The same with a header in cm/s/s and units g.
    let cm = at2_text("ACCELERATION IN UNITS OF CM/S/S", ".1 .2");
    let msg = Record::read("r", &cm, None, Some(Units::G))
        .unwrap_err()
        .to_string();
    assert!(
        msg.contains("units of CM/S/S (cm/s^2), but the units given are g"),
        "{msg}"
    );
    assert!(msg.contains("units = \"cm/s2\""), "{msg}");
}

#[test]
fn at2_headers_the_reader_cannot_use_are_errors() {
    // Units it does not know: they must be given (and, given, they are used).
    let inches = at2_text("ACCELERATION IN UNITS OF IN/S/S", "1.0");
    let msg = Record::read("r", &inches, None, None)
        .unwrap_err()
        .to_string();
    assert!(
        msg.starts_with("line 3: the header states units of \"IN/S/S\""),
        "{msg}"
    );
    assert!(msg.contains("give the units (one of g, m/s2"), "{msg}");
    let given = Record::read("r", &inches, None, Some(Units::MPerS2)).unwrap();
    assert_eq!(given.accelerations(), &[1.0]);
    // PEER's velocity and displacement files are not accelerations, whatever the units given.
    let vt2 = at2_text("VELOCITY TIME SERIES IN UNITS OF CM/S", "1.0");
    for units in [None, Some(Units::CmPerS2)] {
        let msg = Record::read("r", &vt2, None, units)
            .unwrap_err()
            .to_string();
        assert!(
            msg.contains("line 3: the header says this is a velocity time series"),
            "{msg}"
        );
    }
}

#[test]
fn an_at2_is_found_by_its_header_whatever_its_name() {
    let text = at2_text("ACCELERATION TIME SERIES IN UNITS OF G", ".1 .2 .3");
    for name in [None, Some("RSN6_IMPVALL.I_I-ELC180.txt"), Some("record")] {
        assert_eq!(Format::detect(&text, name), Format::At2, "{name:?}");
    }
    // The old PEER layout (values before the labels on line 4).
    let old = "PEER STRONG MOTION DATABASE RECORD\nIMPERIAL VALLEY 5/19/40 0439, EL CENTRO ARRAY #9, 180\nACCELERATION TIME HISTORY IN UNITS OF G\n 3    0.01000    NPTS, DT\n.1 .2 .3\n";
    assert_eq!(Format::detect(old, Some("x.dat")), Format::At2);
    let r = Record::read("x", old, None, None).unwrap();
    assert_eq!((r.npts(), r.dt(), r.t0()), (3, 0.01, 0.01));
    // Two columns are two columns, even with comments that mention NPTS and DT; the name is only a hint.
    let csv = "# NPTS = 3, DT = 0.01 s\ntime_s,acc\n0.0,0.1\n0.01,0.2\n0.02,0.3\n";
    assert_eq!(Format::detect(csv, Some("r.csv")), Format::TimeAcc);
    assert_eq!(Format::detect(csv, None), Format::TimeAcc);
    assert_eq!(Record::read("r", csv, None, None).unwrap().npts(), 3);
    // Numbers first, then a line that mentions NPTS and DT: not an AT2 header.
    assert_eq!(
        Format::detect("0 0.1\n0.01 0.2\nNPTS DT\n", None),
        Format::TimeAcc
    );
    // A damaged file named *.at2 is read as AT2, to get the AT2 reader's message.
    assert_eq!(
        Format::detect("0.1\n0.2\n", Some("broken.AT2")),
        Format::At2
    );
    let msg = Record::read("broken.AT2", "0.1\n0.2\n", None, None)
        .unwrap_err()
        .to_string();
    assert!(msg.contains("no header line with NPTS and DT"), "{msg}");
}

#[test]
fn an_at2_read_in_another_format_gets_a_hint() {
    let text = at2_text("ACCELERATION TIME SERIES IN UNITS OF G", ".1 .2 .3");
    for format in [Format::TimeAcc, Format::Values { dt: 0.01 }] {
        let msg = Record::read("r", &text, Some(format), None)
            .unwrap_err()
            .to_string();
        assert_eq!(msg.lines().count(), 1, "{msg}");
        assert!(msg.contains("is not a number"), "{msg}");
        assert!(
            msg.contains("looks like a PEER AT2 record")
                && msg.contains("set format = \"at2\" (--format at2)"),
            "{msg}"
        );
    }
    // No hint for a text that is not an AT2.
    let msg = parse::time_acc("t a\n0 0\nabc 0.3\n")
        .unwrap_err()
        .to_string();
    let via = Record::read("r", "t a\n0 0\nabc 0.3\n", Some(Format::TimeAcc), None)
        .unwrap_err()
        .to_string();
    assert_eq!(via, msg);
}

#[test]
fn every_units_spelling_and_its_factor() {
    // Factors to m/s^2 by definition: g = 9.80665, 1 gal = 1 cm/s^2 = 0.01, 1 mm/s^2 = 0.001.
    for (name, units, factor) in [
        ("g", Units::G, G),
        ("G", Units::G, G),
        ("m/s2", Units::MPerS2, 1.0),
        ("m/s^2", Units::MPerS2, 1.0),
        ("cm/s2", Units::CmPerS2, 0.01),
        ("cm/s^2", Units::CmPerS2, 0.01),
        ("gal", Units::CmPerS2, 0.01),
        (" Gal ", Units::CmPerS2, 0.01),
        ("mm/s2", Units::MmPerS2, 0.001),
        ("mm/s^2", Units::MmPerS2, 0.001),
    ] {
        let u = Units::parse(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(u, units, "{name}");
        assert_eq!(u.to_m_per_s2(), factor, "{name}");
        // Read back from the name the tool prints.
        assert_eq!(Units::parse(u.name()).unwrap(), u);
        let r = Record::read("v", "100\n", Some(Format::Values { dt: 0.01 }), Some(u)).unwrap();
        assert!(
            (r.accelerations()[0] - 100.0 * factor).abs() < 1e-12,
            "{name}"
        );
    }
    for bad in ["m/s", "cm", "", "g's", "ft/s2"] {
        match Units::parse(bad) {
            Err(pounding::Error::Choice {
                name: "units",
                value,
                allowed,
            }) => {
                assert_eq!(value, format!("{bad:?}"));
                assert!(
                    allowed.contains("gal") && allowed.contains("m/s^2"),
                    "{allowed}"
                );
            }
            other => panic!("{bad}: {other:?}"),
        }
    }
}

#[cfg(feature = "serde")]
#[test]
fn scenario_units_and_format_keys() {
    use pounding::scenario::GroundMotionDoc;
    let doc = |extra: &str| -> GroundMotionDoc {
        serde_json::from_str(&format!(r#"{{"file": "r.txt"{extra}}}"#)).unwrap()
    };
    // Not given: None, so that an AT2 header's units are used.
    let spec = doc("").spec().unwrap();
    assert_eq!((spec.units, spec.format), (None, None));
    for (name, units) in [
        ("gal", Units::CmPerS2),
        ("m/s^2", Units::MPerS2),
        ("g", Units::G),
    ] {
        let spec = doc(&format!(r#", "units": "{name}""#)).spec().unwrap();
        assert_eq!(spec.units, Some(units), "{name}");
    }
    // Units are read by the one reading of a units name, as the document is read.
    let e = serde_json::from_str::<GroundMotionDoc>(r#"{"file": "r.txt", "units": "m/s"}"#)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("units = \"m/s\" is not allowed: one of g, m/s2"),
        "{e}"
    );
    // A scenario that does not say its units serialises without them.
    let text = serde_json::to_string(&doc("")).unwrap();
    assert!(!text.contains("units"), "{text}");
}

#[test]
fn a_two_column_text_states_its_units_in_a_comment_or_its_column_name() {
    // The tool's own synthetic records: a comment and a column name, both m/s^2. Read without units they
    // are m/s^2 (they used to be read as g: a PGA 9.8 times too large).
    let ours = "# synthetic ground motion, pounding record synth --seed 1\n# read with units = \"m/s2\" (format time-acc)\ntime_s,acceleration_m_per_s2\n0.01,1.5\n0.02,-3\n";
    let r = Record::read("s1", ours, None, None).unwrap();
    assert_eq!(r.accelerations(), &[1.5, -3.0]);
    // Column names and comments of other tools, each alone.
    let cases = [
        ("time,acc_g\n0,0.1\n0.01,0.2\n", G),
        ("Time (s), Acceleration (g)\n0 0.1\n0.01 0.2\n", G),
        ("t[s] a[cm/s2]\n0 0.1\n0.01 0.2\n", 0.01),
        ("% units: gal\n0 0.1\n0.01 0.2\n", 0.01),
        ("time_s,acceleration_mm_per_s2\n0,0.1\n0.01,0.2\n", 0.001),
        // Nothing stated: g, as before.
        ("time,acc\n0,0.1\n0.01,0.2\n", G),
        ("0 0.1\n0.01 0.2\n", G),
    ];
    for (text, factor) in cases {
        let r = Record::read("r", text, None, None).unwrap();
        assert_eq!(r.accelerations()[1], 0.2 * factor, "{text}");
    }
    // A values file with a units comment.
    let values = "# units = \"m/s2\"\n0.1\n0.2\n";
    let r = Record::read("v", values, Some(Format::Values { dt: 0.01 }), None).unwrap();
    assert_eq!(r.accelerations(), &[0.1, 0.2]);
    // Units given that agree are used; units that contradict the text are one line naming both.
    let agree = Record::read("s1", ours, None, Some(Units::MPerS2)).unwrap();
    assert_eq!(agree.accelerations(), r_accs(ours));
    let msg = Record::read("s1", ours, None, Some(Units::G))
        .unwrap_err()
        .to_string();
    assert_eq!(msg.lines().count(), 1, "{msg}");
    assert!(
        msg.starts_with(
            "line 2: the header states units of m/s2 (m/s^2), but the units given are g"
        ),
        "{msg}"
    );
    // Two statements that disagree.
    let both = "# units = g\ntime_s,acceleration_m_per_s2\n0,1\n0.01,2\n";
    let msg = Record::read("b", both, None, None).unwrap_err().to_string();
    assert!(msg.contains("states its units twice, differently"), "{msg}");
    // A comment after the data begin says nothing about the units (it is not a header).
    let late = "0 0.1\n0.01 0.2\n# units = m/s2\n";
    assert_eq!(
        Record::read("l", late, None, None).unwrap().accelerations()[1],
        0.2 * G
    );
}

fn r_accs(text: &str) -> Vec<f64> {
    Record::read("x", text, None, None)
        .unwrap()
        .accelerations()
        .to_vec()
}
