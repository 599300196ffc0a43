//! The separation report as tables on the terminal: lengths in mm (separation.json holds m).

use crate::output::{fmt_num, fmt_sig};
use pounding_study::separation::codes::CodeInfo;
use pounding_study::separation::{PairReport, SeparationReport, Stats};

/// Millimetres per metre, for the terminal.
const MM: f64 = 1e3;

/// A length in mm, or `-`.
fn mm(x: Option<f64>) -> String {
    x.map_or("-".into(), |x| format!("{:.2}", MM * x))
}

/// A probability, or `-`.
fn prob(x: Option<f64>) -> String {
    x.map_or("-".into(), |p| format!("{p:.4}"))
}

/// Prints `v`.
pub fn report(v: &SeparationReport) {
    match v {
        SeparationReport::One { pairs, code, .. } => {
            header();
            table(pairs);
            codes(code.as_ref());
        }
        SeparationReport::Suite {
            records,
            statistics,
            target_probability,
            code,
            ..
        } => {
            header();
            for r in records {
                println!("\nrecord {}", r.record);
                table(&r.pairs);
            }
            type Pick = fn(&Stats) -> f64;
            let stats: [(&str, Pick); 3] = [
                ("mean", |s| s.mean),
                ("median", |s| s.median),
                ("p84", |s| s.p84),
            ];
            for (stat, pick) in stats {
                println!("\n{stat} over {} records", records.len());
                for p in &statistics.pairs {
                    for l in &p.levels {
                        println!(
                            "{:<20} {:>3}-{:<3} {:>12.2}  {:>13.2}  {:>15.2}  {:>8.2}  {:>8.2}  {:>8.2}",
                            at(&p.between, l.point),
                            l.floors.0,
                            l.floors.1,
                            MM * pick(&l.peak_left),
                            MM * pick(&l.peak_right),
                            MM * pick(&l.required_gap),
                            MM * pick(&l.abs),
                            MM * pick(&l.srss),
                            MM * pick(&l.ddc)
                        );
                    }
                }
            }
            let target = target_probability.map_or(String::new(), |p| format!(" (target P = {p})"));
            println!(
                "\nprobability that a record pounds, over {} records: a lognormal fitted to the required gaps, and the records' fraction{target}",
                records.len()
            );
            println!("pair                 floors  gap_mm  median_mm  dispersion  P_fit   P_records  gap_for_target_mm  (records)  code_gap_mm  P_fit_at_code");
            for p in &statistics.pairs {
                for l in &p.levels {
                    println!(
                        "{:<20} {:>3}-{:<3} {:>6.1}  {:>9}  {:>10}  {:>6}  {:>9.4}  {:>17}  {:>9}  {:>11}  {:>13}",
                        p.between.join("|"),
                        l.floors.0,
                        l.floors.1,
                        MM * l.gap,
                        mm(l.fit.map(|f| f.median)),
                        l.fit.map_or("-".into(), |f| format!("{:.4}", f.dispersion)),
                        prob(l.probability),
                        l.probability_empirical,
                        mm(l.gap_for_target),
                        mm(l.gap_for_target_empirical),
                        mm(l.code_required_gap),
                        prob(l.probability_at_code_gap)
                    );
                }
            }
            codes(code.as_ref());
        }
        SeparationReport::WhiteNoise(n) => {
            let w = &n.white_noise;
            println!(
                "random vibration: white noise S0 = {} m^2/s^3{}, {} s, {} crossings; structures {}",
                w["s0"],
                match &w["filter"] {
                    serde_json::Value::Object(f) => format!(" through a {} filter", f["kind"].as_str().unwrap_or("")),
                    _ => String::new(),
                },
                w["duration"],
                w["clumping"].as_str().unwrap_or(""),
                w["structures"].as_str().unwrap_or("")
            );
            println!("pair                 floors  gap_mm  sigma_mm  sigma_rate_mm_per_s  nu0_per_s  P_pounding  gap_for_target_mm  code_gap_mm  P_at_code_gap");
            for p in &n.pairs {
                for l in &p.levels {
                    println!(
                        "{:<20} {:>3}-{:<3} {:>6.1}  {:>8.2}  {:>19.2}  {:>9.4}  {:>10.6}  {:>17}  {:>11}  {:>13}",
                        p.between.join("|"),
                        l.floors.0,
                        l.floors.1,
                        MM * l.gap,
                        MM * l.crossing.sigma,
                        MM * l.crossing.sigma_rate,
                        l.crossing.nu0,
                        l.probability,
                        mm(l.gap_for_target),
                        mm(l.code_required_gap),
                        prob(l.probability_at_code_gap)
                    );
                }
            }
            codes(n.code.as_ref());
        }
        SeparationReport::Risk(r) => {
            println!(
                "mean annual frequency of pounding: {} records x {} levels of {}",
                r.risk["records"].as_array().map_or(0, Vec::len),
                r.risk["levels"].as_array().map_or(0, Vec::len),
                r.risk["measure"].as_str().unwrap_or("")
            );
            println!("pair                 floors  gap_mm  annual_frequency_per_yr  P_in_life  gap_for_target_mm  code_gap_mm  rate_at_code_gap");
            for p in &r.pairs {
                for l in &p.levels {
                    println!(
                        "{:<20} {:>3}-{:<3} {:>6.1}  {:>23}  {:>9}  {:>17}  {:>11}  {:>16}",
                        p.between.join("|"),
                        l.floors.0,
                        l.floors.1,
                        MM * l.gap,
                        fmt_sig(l.annual_frequency, 4),
                        prob(l.probability_in_life),
                        mm(l.gap_for_target),
                        mm(l.code_required_gap),
                        l.annual_frequency_at_code_gap
                            .map_or("-".into(), |x| fmt_sig(x, 4))
                    );
                }
            }
            codes(r.code.as_ref());
        }
    }
}

fn header() {
    println!("required separation (a run without contact) and the rules' estimates, mm (separation.json holds m)");
    println!("pair                 floors  peak_left_mm  peak_right_mm  required_gap_mm    abs_mm   srss_mm    ddc_mm  rho     code_gap_mm");
}

fn table(pairs: &[PairReport]) {
    for p in pairs {
        for l in &p.levels {
            let x = &l.level;
            println!(
                "{:<20} {:>3}-{:<3} {:>12.2}  {:>13.2}  {:>15.2}  {:>8.2}  {:>8.2}  {:>8.2}  {:.4}  {:>11}",
                at(&p.between, x.point),
                x.floors.0,
                x.floors.1,
                MM * x.peak_left,
                MM * x.peak_right,
                MM * x.required_gap,
                MM * x.abs,
                MM * x.srss,
                MM * x.ddc,
                x.rho,
                mm(l.code_required_gap)
            );
        }
    }
}

/// The code's line: its clause, parameters and spectrum.
fn codes(c: Option<&CodeInfo>) {
    let Some(c) = c else { return };
    let params: Vec<String> = c
        .parameters
        .iter()
        .map(|(k, v)| format!("{k} = {v}"))
        .collect();
    println!(
        "\ncode {} ({}){}: {}",
        c.name,
        params.join(", "),
        c.spectrum
            .as_ref()
            .map_or(String::new(), |s| format!(" under {s}")),
        c.clause
    );
}

/// A pair's name, with the point of a level between buildings in plan: `a|b (20, 6)`.
fn at(between: &[String], point: Option<(f64, f64)>) -> String {
    let name = between.join("|");
    match point {
        Some((x, y)) => format!("{name} ({}, {})", fmt_num(x), fmt_num(y)),
        None => name,
    }
}
