//! Fixed-step central-difference peer of the two-SDOF pounding pair (issue 28). The same scheme as
//! `bench/peer/cd_kernel.py` (read its docstring): two single-storey buildings, 5 % damping, a Hooke or a
//! Kelvin-Voigt contact, El Centro linear between samples, `nsub` steps per record interval.
//!
//!     cargo run --release -- run    --model hooke|kelvin-voigt --dt 1e-4 --gap 0.02
//!     cargo run --release -- sweep  --model hooke|kelvin-voigt --dt 1e-4 --runs 10000 --threads 2 [--repeat 5]
//!
//! `run` prints one JSON object (peaks, impacts, seconds); `sweep` runs `runs` gaps evenly spaced over
//! [0, 0.1) m on `threads` threads and prints the wall seconds of each repeat and their median as JSON.

use std::time::Instant;

const G: f64 = 9.80665;

struct Pair {
    m1: f64,
    k1: f64,
    c1: f64,
    m2: f64,
    k2: f64,
    c2: f64,
    kc: f64,
    cc: f64,
}

#[derive(Clone, Copy, Default)]
struct Out {
    pk1: f64,
    pk2: f64,
    fmax: f64,
    impacts: u32,
}

fn run(acc: &[f64], nsub: usize, dt: f64, p: &Pair, gap: f64) -> Out {
    let (m1, k1, c1, m2, k2, c2, kc, cc) = (p.m1, p.k1, p.c1, p.m2, p.k2, p.c2, p.kc, p.cc);
    let idt2 = 1.0 / (dt * dt);
    let i2dt = 0.5 / dt;
    let a1 = m1 * idt2 + c1 * i2dt;
    let a2 = m2 * idt2 + c2 * i2dt;
    let (r1, r2) = (1.0 / a1, 1.0 / a2);
    let q = cc * i2dt;
    let det = (a1 + q) * (a2 + q) - q * q;
    let (j11, j22, j12) = ((a2 + q) / det, (a1 + q) / det, q / det);
    let b1 = m1 * idt2 - c1 * i2dt;
    let b2 = m2 * idt2 - c2 * i2dt;
    let s1 = 2.0 * m1 * idt2 - k1;
    let s2 = 2.0 * m2 * idt2 - k2;
    let (mut u1, mut u2) = (0.0f64, 0.0f64);
    let mut p1 = -0.5 * dt * dt * acc[0];
    let mut p2 = p1;
    let mut o = Out::default();
    let mut closed = false;
    let inv = 1.0 / nsub as f64;
    for w in acc.windows(2) {
        let a0 = w[0];
        let da = (w[1] - a0) * inv;
        for s in 0..nsub {
            let ag = a0 + da * s as f64;
            let d = u1 - u2 - gap;
            let mut g1 = s1 * u1 - b1 * p1 - m1 * ag;
            let mut g2 = s2 * u2 - b2 * p2 - m2 * ag;
            let (n1, n2);
            if d > 0.0 {
                if !closed {
                    o.impacts += 1;
                    closed = true;
                }
                let fs = kc * d;
                let h = q * (p1 - p2);
                g1 += h - fs;
                g2 += fs - h;
                n1 = j11 * g1 + j12 * g2;
                n2 = j12 * g1 + j22 * g2;
                let f = fs + cc * ((n1 - n2) - (p1 - p2)) * i2dt;
                if f > o.fmax {
                    o.fmax = f;
                }
            } else {
                closed = false;
                n1 = g1 * r1;
                n2 = g2 * r2;
            }
            p1 = u1;
            p2 = u2;
            u1 = n1;
            u2 = n2;
            o.pk1 = o.pk1.max(u1.abs());
            o.pk2 = o.pk2.max(u2.abs());
        }
    }
    o
}

fn arg(args: &[String], key: &str, default: Option<&str>) -> String {
    match args.iter().position(|a| a == key) {
        Some(i) => args.get(i + 1).cloned().unwrap_or_else(|| panic!("{key} needs a value")),
        None => default.unwrap_or_else(|| panic!("{key} is required")).to_string(),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let cmd = args.get(1).map(String::as_str).unwrap_or("");
    let default_record = concat!(env!("CARGO_MANIFEST_DIR"), "/../../../crates/pounding/data/elcentro1940_ns.csv");
    let path = arg(&args, "--record", Some(default_record));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut t = Vec::new();
    let mut acc = Vec::new();
    for line in text.lines().skip(1).filter(|l| !l.trim().is_empty()) {
        let mut it = line.split(',');
        t.push(it.next().unwrap().trim().parse::<f64>().unwrap());
        acc.push(it.next().unwrap().trim().parse::<f64>().unwrap() * G);
    }
    let rec_dt = t[1] - t[0];
    let dt: f64 = arg(&args, "--dt", Some("1e-4")).parse().unwrap();
    let nsub = (rec_dt / dt).round() as usize;
    assert!(((nsub as f64) * dt - rec_dt).abs() < 1e-9 * rec_dt, "dt must divide the record's dt");
    let dt = rec_dt / nsub as f64;
    let model = arg(&args, "--model", Some("hooke"));
    let e: f64 = arg(&args, "--e", Some("0.65")).parse().unwrap();
    let kc: f64 = arg(&args, "--stiffness", Some("2e9")).parse().unwrap();
    let (m1, m2, k1, k2, zeta) = (5.0e5, 5.0e5, 7.8957e7, 1.9739e7, 0.05);
    let meff = m1 * m2 / (m1 + m2);
    let cc = match model.as_str() {
        "hooke" => 0.0,
        "kelvin-voigt" => {
            let le = e.ln();
            let zc = -le / (std::f64::consts::PI.powi(2) + le * le).sqrt();
            2.0 * zc * (kc * meff).sqrt()
        }
        m => panic!("unknown model {m}"),
    };
    let p = Pair {
        m1,
        k1,
        c1: 2.0 * zeta * (k1 * m1).sqrt(),
        m2,
        k2,
        c2: 2.0 * zeta * (k2 * m2).sqrt(),
        kc,
        cc,
    };
    let steps = (acc.len() - 1) * nsub;
    match cmd {
        "run" => {
            let gap: f64 = arg(&args, "--gap", Some("0.02")).parse().unwrap();
            let repeat: usize = arg(&args, "--repeat", Some("1")).parse().unwrap();
            let mut times = Vec::new();
            let mut o = Out::default();
            for _ in 0..repeat {
                let t0 = Instant::now();
                o = std::hint::black_box(run(&acc, nsub, dt, &p, std::hint::black_box(gap)));
                times.push(t0.elapsed().as_secs_f64());
            }
            times.sort_by(f64::total_cmp);
            println!(
                "{{\"model\":\"{model}\",\"dt\":{dt:e},\"gap\":{gap},\"steps\":{steps},\"peak_u1\":{:e},\"peak_u2\":{:e},\"peak_force\":{:e},\"impacts\":{},\"median_s\":{:e}}}",
                o.pk1, o.pk2, o.fmax, o.impacts, times[times.len() / 2]
            );
        }
        "sweep" => {
            let runs: usize = arg(&args, "--runs", Some("10000")).parse().unwrap();
            let threads: usize = arg(&args, "--threads", Some("2")).parse().unwrap();
            let repeat: usize = arg(&args, "--repeat", Some("1")).parse().unwrap();
            let gaps: Vec<f64> = (0..runs).map(|i| 0.1 * i as f64 / runs as f64).collect();
            let mut times = Vec::new();
            let mut impacts = 0u64;
            for _ in 0..repeat {
                let t0 = Instant::now();
                let next = std::sync::atomic::AtomicUsize::new(0);
                impacts = std::thread::scope(|sc| {
                    let hs: Vec<_> = (0..threads)
                        .map(|_| {
                            sc.spawn(|| {
                                let mut sum = 0u64;
                                loop {
                                    let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                                    if i >= runs {
                                        break sum;
                                    }
                                    sum += run(&acc, nsub, dt, &p, gaps[i]).impacts as u64;
                                }
                            })
                        })
                        .collect();
                    hs.into_iter().map(|h| h.join().unwrap()).sum()
                });
                times.push(t0.elapsed().as_secs_f64());
            }
            let mut sorted = times.clone();
            sorted.sort_by(f64::total_cmp);
            println!(
                "{{\"model\":\"{model}\",\"dt\":{dt:e},\"runs\":{runs},\"threads\":{threads},\"steps\":{steps},\"impacts_total\":{impacts},\"times_s\":{times:?},\"median_s\":{:e}}}",
                sorted[sorted.len() / 2]
            );
        }
        _ => eprintln!("usage: cd-peer run|sweep --model hooke|kelvin-voigt --dt DT [--gap G | --runs N --threads T] [--repeat R]"),
    }
}
