//! Command-line syntax (clap). Values are parsed here; ranges are checked once, by the library.

use clap::builder::{PossibleValue, TypedValueParser};
use clap::{Args, Parser, Subcommand};
use pounding::contact::{AlphaRule, AlphaWord, ContactOptions, Damping, Model, Reading, Tension};
use pounding::ground_motion::coherency::CoherencyKind;
use pounding::ground_motion::synthetic::{FilterKind, SyntheticParams};
use pounding::ground_motion::Units;
use pounding::names::Named;
use pounding::scenario::FormatName;
use pounding::separation::codes::{CodeName, GbSystem, GroundType};
use pounding::separation::random::Clumping;
use std::marker::PhantomData;

/// The value parser of a named choice ([`Named`]): its names are the possible values `--help` lists, and a
/// wrong name gets the library's message, with the name it most likely meant.
#[derive(Clone)]
pub struct NamedParser<T>(PhantomData<T>);

/// The parser of the choices of `T`.
pub fn named<T: Named + Clone + Send + Sync + 'static>() -> NamedParser<T> {
    NamedParser(PhantomData)
}

impl<T: Named + Clone + Send + Sync + 'static> TypedValueParser for NamedParser<T> {
    type Value = T;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<T, clap::Error> {
        let text = value.to_string_lossy();
        T::parse_name(&text).map_err(|m| {
            let flag = arg
                .and_then(|a| a.get_long())
                .map_or(String::new(), |l| format!("--{l}: "));
            clap::Error::raw(clap::error::ErrorKind::InvalidValue, format!("{flag}{m}\n"))
                .with_cmd(cmd)
        })
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        Some(Box::new(T::names().into_iter().map(PossibleValue::new)))
    }
}

/// Contact models, single impacts and structural pounding. SI units: m, s, kg, N (k in N/m^n).
#[derive(Parser, Debug)]
#[command(name = "pounding", version, propagate_version = true)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// List the contact models with force law, damping formula and source.
    Models {
        /// Print one JSON object on stdout.
        #[arg(long)]
        json: bool,
    },
    /// One impact of two bodies (m1 moving at v towards m2 at rest), integrated with located events.
    Impact(ImpactArgs),
    /// The damping parameter that delivers e exactly (alpha for papi; zeta, chi, xi or e_design).
    Calibrate(CalibrateArgs),
    /// A ball dropped from a height onto a rigid slab of the same material (gravity acts during contact).
    Drop(DropArgs),
    /// Several contact models on one impact: a table, and with --plots their force histories overlaid.
    Compare(CompareArgs),
    /// Time-history analysis of pounding between adjacent buildings, as described by a scenario file.
    Run(RunArgs),
    /// Every scenario of a study (a base scenario and axes), in parallel, into a resumable SQLite store and
    /// runs.csv (see docs/studies.md).
    Sweep(SweepArgs),
    /// Required separation of each pair of neighbours at each contact level (from a run without contact),
    /// against the ABS, SRSS and DDC rules; over a suite of records with --records.
    Separation(Box<SeparationArgs>),
    /// Incremental dynamic analysis: records x intensity levels (Sa(T1) or PGA) as a resumable sweep, the
    /// demands of each run, and lognormal fragility curves per limit state (see docs/ida.md).
    Ida(IdaArgs),
    /// A self-contained HTML report (inline figures, no network access) of the output folder of a run.
    Report(ReportArgs),
    /// Ground-motion records.
    Record {
        #[command(subcommand)]
        cmd: RecordCmd,
    },
    /// Contact laws fitted to tests: restitution measured against impact velocity, or the force history of
    /// one impact (see docs/contact-models.md section 2.8).
    Fit {
        #[command(subcommand)]
        cmd: FitCmd,
    },
    /// Reproductions of the tables of Papi & Toopchi-Nezhad (2022).
    Paper {
        #[command(subcommand)]
        table: PaperTable,
    },
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
#[command(
    after_help = "Files in --out: separation.json (what --json prints); with --plots: separation.svg (each rule's estimate against the required gap)."
)]
pub struct SeparationArgs {
    /// Scenario file (TOML); its contacts say which floors face each other (see docs/separation.md).
    pub scenario: std::path::PathBuf,
    /// Records to use in place of the scenario's, comma-separated: built-in names, files, folders or globs
    /// (read in the scenario's units); with more than one, the mean, median and 84th percentile too.
    #[arg(long, value_delimiter = ',')]
    pub records: Vec<String>,
    /// Factor on the rules at levels whose floors are at the same height (Eurocode 8: 0.7), 0 < f <= 1.
    #[arg(long)]
    pub aligned_factor: Option<f64>,
    /// Probability of pounding to find the gap for, 0 < P < 1: within --duration of a random motion, per
    /// record of a suite, or with --hazard over --design-life.
    #[arg(long)]
    pub target_probability: Option<f64>,
    #[command(flatten)]
    pub noise: NoiseArgs,
    #[command(flatten)]
    pub risk: RiskArgs,
    #[command(flatten)]
    pub code: CodeArgs,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub out: OutArgs,
}

/// A stationary random ground motion (docs/separation.md, "Probability of pounding").
#[derive(Args, Debug)]
#[command(next_help_heading = "Random vibration")]
pub struct NoiseArgs {
    /// Two-sided spectral density S0 of a white-noise ground acceleration, m^2/s^3 (E[a(t) a(t+tau)] =
    /// 2 pi S0 delta(tau)): the probability of pounding by random vibration, instead of records.
    #[arg(long, value_name = "S0")]
    pub white_noise: Option<f64>,
    /// Duration of the stationary motion, s (with --white-noise).
    #[arg(long, requires = "white_noise")]
    pub duration: Option<f64>,
    /// Filter the white noise into the ground acceleration (record synth's filters) [default: none].
    #[arg(long, value_parser = named::<FilterKind>(), requires = "white_noise")]
    pub filter: Option<FilterKind>,
    /// Soil filter's circular frequency, rad/s.
    #[arg(long, default_value_t = SyntheticParams::default().wg, requires = "filter")]
    pub wg: f64,
    /// Soil filter's damping ratio.
    #[arg(long, default_value_t = SyntheticParams::default().zg, requires = "filter")]
    pub zg: f64,
    /// Clough-Penzien high-pass filter's circular frequency, rad/s.
    #[arg(long, default_value_t = SyntheticParams::default().wf, requires = "filter")]
    pub wf: f64,
    /// Its damping ratio.
    #[arg(long, default_value_t = SyntheticParams::default().zf, requires = "filter")]
    pub zf: f64,
    /// How up-crossings of the gap are counted: poisson, or vanmarcke (clumped crossings of a narrow-band
    /// closing, fewer: a lower probability).
    #[arg(long, value_parser = named::<Clumping>(), default_value = "poisson", requires = "white_noise")]
    pub clumping: Clumping,
}

/// Risk-targeted gaps: records scaled to intensity levels and a hazard curve.
#[derive(Args, Debug)]
#[command(next_help_heading = "Mean annual frequency")]
pub struct RiskArgs {
    /// Hazard curve: two columns, intensity (m/s^2, the --measure) and its annual exceedance rate (1/yr),
    /// intensities increasing; with --records and --levels: the mean annual frequency of pounding.
    #[arg(long, value_name = "FILE", requires = "levels")]
    pub hazard: Option<std::path::PathBuf>,
    /// Intensity levels the records are scaled to, m/s^2, comma-separated (with --hazard).
    #[arg(long, value_delimiter = ',', requires = "hazard")]
    pub levels: Vec<f64>,
    /// Intensity measure of the levels and the hazard: sa (at the first period of --building) or pga.
    #[arg(long, default_value = "sa", value_parser = ["sa", "pga"], requires = "hazard")]
    pub measure: String,
    /// The building whose first period sa is taken at [default: the first].
    #[arg(long, requires = "hazard")]
    pub building: Option<String>,
    /// Damping ratio of sa.
    #[arg(long, default_value_t = 0.05, requires = "hazard")]
    pub im_damping: f64,
    /// Target mean annual frequency of pounding, 1/yr (1/2475 = 4.04e-4): the gap for it.
    #[arg(long, requires = "hazard")]
    pub target_rate: Option<f64>,
    /// Design life, yr: the probability of pounding over it; with --target-probability, the gap for that.
    #[arg(long, requires = "hazard")]
    pub design_life: Option<f64>,
}

/// A design code's separation.
#[derive(Args, Debug)]
#[command(next_help_heading = "Design codes")]
pub struct CodeArgs {
    /// The code's rule beside the analyses: asce7-22 (--cd, --ie), en1998-1 (--q, --qd), is1893-2016 (--r),
    /// gb50011-2010 (--intensity, --system); the first three need a design spectrum.
    #[arg(long, value_parser = named::<CodeName>())]
    pub code: Option<CodeName>,
    /// ASCE 7: deflection amplification factor C_d.
    #[arg(long)]
    pub cd: Option<f64>,
    /// ASCE 7: importance factor I_e.
    #[arg(long, default_value_t = 1.0)]
    pub ie: f64,
    /// EN 1998-1: behaviour factor q (also reduces the en1998-1 spectrum).
    #[arg(long)]
    pub q: Option<f64>,
    /// EN 1998-1: displacement behaviour factor q_d [default: q].
    #[arg(long)]
    pub qd: Option<f64>,
    /// IS 1893: response reduction factor R; ASCE 7: R, to reduce the asce7-22 spectrum by I_e / R.
    #[arg(long)]
    pub r: Option<f64>,
    /// GB 50011: seismic intensity, 6 to 9.
    #[arg(long)]
    pub intensity: Option<u8>,
    /// GB 50011: structural system.
    #[arg(long, value_parser = named::<GbSystem>(), default_value = "frame")]
    pub system: GbSystem,
    /// The design spectrum of the code's elastic analysis: two columns, period (s) and Sa (m/s^2), 5 %
    /// damping (for ASCE 7 and IS 1893 the spectrum already divided by R / I; for EN 1998-1 S_d).
    #[arg(long, value_name = "FILE", conflicts_with = "spectrum")]
    pub design_spectrum: Option<std::path::PathBuf>,
    /// The code's own spectrum shape instead: asce7-22 (--sds, --sd1, --tl, with --r and --ie) or en1998-1
    /// (--ag, --ground-type, --spectrum-type, with --q).
    #[arg(long, value_parser = ["asce7-22", "en1998-1"])]
    pub spectrum: Option<String>,
    /// ASCE 7: S_DS, g.
    #[arg(long)]
    pub sds: Option<f64>,
    /// ASCE 7: S_D1, g.
    #[arg(long)]
    pub sd1: Option<f64>,
    /// ASCE 7: long-period transition T_L, s.
    #[arg(long)]
    pub tl: Option<f64>,
    /// EN 1998-1: design ground acceleration on type A ground a_g, m/s^2.
    #[arg(long)]
    pub ag: Option<f64>,
    /// EN 1998-1: ground type, A to E.
    #[arg(long, value_parser = named::<GroundType>(), default_value = "B")]
    pub ground_type: GroundType,
    /// EN 1998-1: spectrum type, 1 or 2.
    #[arg(long, default_value_t = 1)]
    pub spectrum_type: u8,
}

#[derive(Args, Debug)]
#[command(
    after_help = "Files in --out: study.sqlite, runs.csv, fragility.csv; with --plots: ida-curves.svg (demand against intensity per record and limit state), fragility.svg (the fitted curves with the observed fractions)."
)]
pub struct IdaArgs {
    /// IDA study file (TOML): scenario = "base.toml", records = [...], limit_states = [...] and
    /// [intensity] (measure, levels). See docs/ida.md.
    pub study: std::path::PathBuf,
    /// Folder for study.sqlite (every finished run, committed as it finishes), runs.csv and fragility.csv
    /// (created if missing; an IDA started again resumes from its store).
    #[arg(long, value_name = "DIR")]
    pub out: std::path::PathBuf,
    #[command(flatten)]
    pub runs: StudyRuns,
    #[command(flatten)]
    pub figures: FigureArgs,
}

#[derive(Args, Debug)]
pub struct SweepArgs {
    /// Study file (TOML): scenario = "base.toml" and [axes] (or [[run]] entries). See docs/studies.md.
    pub study: std::path::PathBuf,
    /// Folder for study.sqlite (every finished run, committed as it finishes) and runs.csv (created if
    /// missing; a sweep started again with the same study resumes from its store).
    #[arg(long, value_name = "DIR")]
    pub out: std::path::PathBuf,
    #[command(flatten)]
    pub runs: StudyRuns,
}

/// How a study's runs are run: its threads, its progress bar, and with or without contact.
#[derive(Args, Debug)]
pub struct StudyRuns {
    /// Threads running scenarios [default: the number of cores].
    #[arg(long)]
    pub workers: Option<usize>,
    /// No progress bar.
    #[arg(long, short)]
    pub quiet: bool,
    /// Every run without contact (contacts = "off"): contacts and walls record closings only; devices stay.
    #[arg(long)]
    pub no_contact: bool,
}

#[derive(Args, Debug)]
#[command(
    after_help = "Files in --out: scenario.toml, summary.json, response.csv, impacts.csv, impact-loops.csv, energy.csv. With --plots: record.svg, displacement.svg, energy.svg; envelopes.svg and hysteresis.svg (storeys above any bearings: not for decks alone), hysteresis-storeys.svg (two or more inelastic storeys), isolators.svg (isolated buildings, decks on bearings), contact-force.svg and relative-displacement.svg (contacts or walls), impact-loops.svg (an impact happened), impact-restitution.svg (an impact ended), device-force.svg (devices), plan.svg and corner-orbit.svg (buildings in plan). With --report: report.html. See docs/scenarios.md and docs/figures.md."
)]
pub struct RunArgs {
    /// Scenario file (TOML): ground motion, buildings left to right, contacts. See examples/.
    pub scenario: std::path::PathBuf,
    /// Folder for the run's files, listed below (created if missing; an earlier run's folder is replaced whole).
    #[arg(long, value_name = "DIR")]
    pub out: std::path::PathBuf,
    /// Relative tolerance of the integration, 1e-12 to 1e-3 (overrides [analysis] tolerance).
    #[arg(long)]
    pub tolerance: Option<f64>,
    /// The same structures without contact (contacts = "off"): contacts and walls record closings only;
    /// devices stay. The response that pounding amplifies.
    #[arg(long)]
    pub no_contact: bool,
    /// No progress bar.
    #[arg(long, short)]
    pub quiet: bool,
    /// Print the summary as JSON on stdout.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub figures: FigureArgs,
    /// Also write report.html into the output folder (see `pounding report`).
    #[arg(long)]
    pub report: bool,
}

#[derive(Args, Debug)]
pub struct ReportArgs {
    /// The output folder of `pounding run` (summary.json, response.csv, impacts.csv, energy.csv).
    pub dir: std::path::PathBuf,
    /// Where to write the report [default: DIR/report.html].
    #[arg(long, value_name = "FILE.html")]
    pub out: Option<std::path::PathBuf>,
}

/// Where a command writes its files: a folder, and figures in it on request.
#[derive(Args, Debug, Clone)]
pub struct OutArgs {
    /// Folder for the command's files, created if missing: its result as JSON (what --json prints) and the
    /// files listed below ("Files in --out"), with --plots the figures.
    #[arg(long, value_name = "DIR")]
    pub out: Option<std::path::PathBuf>,
    #[command(flatten)]
    pub figures: FigureArgs,
}

/// Figures on request, into the command's `--out` folder.
#[derive(Args, Debug, Clone, Copy)]
pub struct FigureArgs {
    /// Also write the figures (SVG) into the --out folder (see docs/figures.md).
    #[arg(long, requires = "out")]
    pub plots: bool,
    /// Also write each figure as PNG (with --plots; in a build with `--features png`).
    #[arg(long, requires = "plots")]
    pub png: bool,
}

#[derive(Subcommand, Debug)]
pub enum RecordCmd {
    /// npts, dt, duration, PGA, PGV and PGD (PGV, PGD after a linear baseline correction) of a record.
    Info(RecordArgs),
    /// Elastic response spectrum: SD (m), PSV (m/s) and PSA (m/s^2) of linear oscillators, by the exact
    /// piecewise-linear solution, peaks located between samples too.
    Spectrum(SpectrumArgs),
    /// A synthetic record from a seed: filtered white noise (Kanai-Tajimi or Clough-Penzien) under a time
    /// envelope, scaled to a PGA, written as a two-column file (s, m/s^2). See docs/separation.md.
    Synth(SynthArgs),
    /// Records at supports along a line that lose coherence with distance: the spectrum of `record synth`
    /// and a coherency model (Luco-Wong, Harichandran-Vanmarcke), by the spectral representation (Deodatis
    /// 1996); one file per support, for [[support]] file = ... (add delay for the wave's passage).
    Coherent(CoherentArgs),
}

/// A synthetic ground motion's parameters.
#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct SynthArgs {
    /// Seed of the random numbers: the same seed gives the same record, bit for bit.
    #[arg(long)]
    pub seed: u64,
    /// File to write (time s, acceleration m/s^2; read it with units = "m/s2"), its folder made if missing.
    #[arg(long, value_name = "FILE")]
    pub out: std::path::PathBuf,
    #[command(flatten)]
    pub spectrum: SynthSpectrumArgs,
}

/// Records at supports that lose coherence with distance (docs/structures.md, "Ground motion that differs
/// between supports").
#[derive(Args, Debug)]
#[command(
    allow_negative_numbers = true,
    after_help = "Files in --out: support-1.csv, support-2.csv, ... and coherent.json; with --plots: supports.svg (each support's acceleration, and the velocity and displacement a run drives it by)."
)]
pub struct CoherentArgs {
    /// Seed of the random numbers: the same seed gives the same records, bit for bit.
    #[arg(long)]
    pub seed: u64,
    /// The supports' positions along the line, m, comma-separated (e.g. 0,100,250).
    #[arg(
        long,
        value_delimiter = ',',
        required = true,
        allow_hyphen_values = true
    )]
    pub positions: Vec<f64>,
    /// Folder to write: support-1.csv, support-2.csv, ... (time s, acceleration m/s^2) and coherent.json.
    #[arg(long, value_name = "DIR")]
    pub out: std::path::PathBuf,
    /// Coherency model: luco-wong (exp(-(alpha w d)^2)) or harichandran-vanmarcke.
    #[arg(long, value_parser = named::<CoherencyKind>())]
    pub model: CoherencyKind,
    /// Luco-Wong's incoherence alpha, s/m (required with luco-wong).
    #[arg(long)]
    pub alpha: Option<f64>,
    /// Harichandran-Vanmarcke's A (default 0.736: SMART-1 event 20).
    #[arg(long = "hv-A")]
    pub hv_a_big: Option<f64>,
    /// Harichandran-Vanmarcke's a (default 0.147).
    #[arg(long = "hv-a")]
    pub hv_a: Option<f64>,
    /// Harichandran-Vanmarcke's k, m (default 5210).
    #[arg(long = "hv-k")]
    pub hv_k: Option<f64>,
    /// Harichandran-Vanmarcke's f0, Hz (default 1.09).
    #[arg(long = "hv-f0")]
    pub hv_f0: Option<f64>,
    /// Harichandran-Vanmarcke's b (default 2.78).
    #[arg(long = "hv-b")]
    pub hv_b: Option<f64>,
    /// Condition on a recorded motion instead of generating from a spectrum: a record file (AT2 or time-acc,
    /// detected) or a built-in record (el-centro-1940, synthetic-SEED). The record stays at the first
    /// position; the others get its Fourier amplitudes and the model's coherency with it.
    #[arg(
        long,
        value_name = "FILE_OR_NAME",
        conflicts_with_all = ["filter", "wg", "zg", "wf", "zf", "duration", "dt", "t1", "t2", "decay", "pga"]
    )]
    pub record: Option<String>,
    /// Units of the --record file's accelerations: g, m/s2, cm/s2, mm/s2 [default: an AT2 header's, else g].
    #[arg(long, value_parser = units_arg, requires = "record")]
    pub record_units: Option<Units>,
    /// With --record: the window of the record's moving RMS that shapes the simulated parts in time, s
    /// (0: stationary).
    #[arg(long, default_value_t = 2.0, requires = "record")]
    pub window: f64,
    /// With --record: the frequency below which the simulated parts hold nothing, Hz (a half-cosine taper from
    /// half of it; 0 for none): below it the supports differ only by the record's coherent part, so their
    /// displacements do not drift apart.
    #[arg(long, default_value_t = 0.1, requires = "record")]
    pub low_cut: f64,
    #[command(flatten)]
    pub figures: FigureArgs,
    #[command(flatten)]
    pub spectrum: SynthSpectrumArgs,
}

/// The spectrum, envelope and PGA of a synthetic motion.
#[derive(Args, Debug)]
pub struct SynthSpectrumArgs {
    /// Filters of the white noise.
    #[arg(long, value_parser = named::<FilterKind>(), default_value_t = SyntheticParams::default().filter)]
    pub filter: FilterKind,
    /// Circular frequency of the soil filter, rad/s.
    #[arg(long, default_value_t = SyntheticParams::default().wg)]
    pub wg: f64,
    /// Damping ratio of the soil filter.
    #[arg(long, default_value_t = SyntheticParams::default().zg)]
    pub zg: f64,
    /// Circular frequency of the high-pass filter (clough-penzien), rad/s.
    #[arg(long, default_value_t = SyntheticParams::default().wf)]
    pub wf: f64,
    /// Damping ratio of the high-pass filter (clough-penzien).
    #[arg(long, default_value_t = SyntheticParams::default().zf)]
    pub zf: f64,
    /// Duration, s.
    #[arg(long, default_value_t = SyntheticParams::default().duration)]
    pub duration: f64,
    /// Time step, s.
    #[arg(long, default_value_t = SyntheticParams::default().dt)]
    pub dt: f64,
    /// End of the envelope's rise (t/t1)^2, s.
    #[arg(long, default_value_t = SyntheticParams::default().t1)]
    pub t1: f64,
    /// End of the envelope's strong phase, s.
    #[arg(long, default_value_t = SyntheticParams::default().t2)]
    pub t2: f64,
    /// Decay rate of the envelope after t2, 1/s.
    #[arg(long, default_value_t = SyntheticParams::default().decay)]
    pub decay: f64,
    /// Peak ground acceleration of the record, m/s^2.
    #[arg(long, default_value_t = SyntheticParams::default().pga)]
    pub pga: f64,
}

impl SynthSpectrumArgs {
    /// The record's parameters.
    pub fn params(&self) -> SyntheticParams {
        SyntheticParams {
            filter: self.filter,
            wg: self.wg,
            zg: self.zg,
            wf: self.wf,
            zf: self.zf,
            duration: self.duration,
            dt: self.dt,
            t1: self.t1,
            t2: self.t2,
            decay: self.decay,
            pga: self.pga,
        }
    }
}

/// A record and the oscillators of its spectrum.
#[derive(Args, Debug)]
#[command(
    after_help = "Files in --out: spectrum.json (what --json prints); with --plots: record.svg (acceleration, velocity, displacement), spectrum.svg (SD, PSV, PSA)."
)]
#[command(allow_negative_numbers = true)]
pub struct SpectrumArgs {
    #[command(flatten)]
    pub record: RecordArgs,
    /// Damping ratio of the oscillators, 0 <= damping < 1.
    #[arg(long, default_value_t = 0.05)]
    pub damping: f64,
    /// Natural periods, s, comma-separated [default: 100 periods from 0.02 to 10 s, evenly spaced in log].
    #[arg(long, value_delimiter = ',')]
    pub periods: Option<Vec<f64>>,
    #[command(flatten)]
    pub out: OutArgs,
}

/// Where a ground motion comes from and how to read it.
#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct RecordArgs {
    /// A record file, or a built-in record: el-centro-1940, synthetic-SEED (seed 0, 1, 2, ...).
    pub file: String,
    /// File format [default: at2 for a file with the PEER AT2 header (NPTS and DT on line 4) or named
    /// *.at2, time-acc otherwise].
    #[arg(long, value_parser = named::<FormatName>())]
    pub format: Option<FormatName>,
    /// Time step of a `values` file, s.
    #[arg(long)]
    pub dt: Option<f64>,
    /// Units of the accelerations in the file: g, m/s2 (m/s^2), cm/s2 (cm/s^2, gal), mm/s2 (mm/s^2)
    /// [default: the units an AT2 header states, else g; units that contradict the header are refused].
    #[arg(long, value_parser = units_arg)]
    pub units: Option<Units>,
    /// Scale factor applied to the accelerations.
    #[arg(long, default_value_t = 1.0)]
    pub scale: f64,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

/// `--units`: the library's one reading of a units name.
fn units_arg(name: &str) -> Result<Units, String> {
    Units::parse(name).map_err(|e| e.to_string())
}

#[derive(Subcommand, Debug)]
pub enum FitCmd {
    /// From measured (v_i, e) pairs: the material damping constant D/K of the Hunt-Crossley family, Thornton's
    /// yield velocity (and yield pressure), one e for a model whose e does not depend on v_i, or the table
    /// e(v_i) itself, smoothed.
    #[command(
        after_help = "Files in --out: fit.json (what --json prints), fit-curve.csv (the fitted e against v_i); with --plots: fit-restitution.svg (the fit over the points)."
    )]
    Restitution(FitRestitutionArgs),
    /// From the measured force history of one impact (mass and impact velocity known): the stiffness, the
    /// exponent and the damping (e, a damping constant, or Thornton's yield pressure) of a model, by least
    /// squares on the force, with the touch time.
    #[command(
        after_help = "Files in --out: fit.json (what --json prints), fit-curve.csv (the fitted force against time); with --plots: fit-force-history.svg (the fit over the samples, and the residual)."
    )]
    ForceHistory(FitHistoryArgs),
}

/// `pounding fit restitution`.
#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct FitRestitutionArgs {
    /// The measurements: two columns, impact velocity v_i (m/s) and e, separated by a comma or spaces (a
    /// header line and # comments allowed).
    pub data: std::path::PathBuf,
    /// What to fit: a model of the Hunt-Crossley family (its damping_constant), thornton (its yield
    /// velocity), another damped model (one e), or table (e(v_i) itself).
    #[arg(long, value_parser = parse_restitution_law)]
    pub model: pounding_study::fit::RestitutionLaw,
    /// table: at most this many rows, groups of about equal counts by v_i [default: one per velocity].
    #[arg(long)]
    pub rows: Option<usize>,
    /// table: make e non-increasing in v_i (pooling adjacent rows that rise: the least-squares fit).
    #[arg(long)]
    pub monotone: bool,
    /// thornton: the spheres' radius, m (with --k and --m1: the yield pressure).
    #[arg(long)]
    pub radius: Option<f64>,
    /// thornton: the spheres' Hertz stiffness (4/3) E* sqrt(R), N/m^1.5.
    #[arg(long)]
    pub k: Option<f64>,
    /// thornton: mass of the moving body in the tests, kg.
    #[arg(long)]
    pub m1: Option<f64>,
    /// thornton: mass of the body at rest in the tests, kg, or inf for a rigid slab.
    #[arg(long, default_value = "inf")]
    pub m2: f64,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub out: OutArgs,
}

/// `pounding fit force-history`.
#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct FitHistoryArgs {
    /// The measured force history: two columns, time (s, any origin) and force (N), separated by a comma or
    /// spaces (a header line and # comments allowed).
    pub data: std::path::PathBuf,
    /// Contact model (see `pounding models`).
    #[arg(long, value_parser = named::<Model>())]
    pub model: Model,
    /// Mass of the moving body, kg.
    #[arg(long)]
    pub m1: f64,
    /// Mass of the body at rest, kg, or inf for a rigid slab.
    #[arg(long, default_value = "inf")]
    pub m2: f64,
    /// Impact velocity, m/s.
    #[arg(long)]
    pub v: f64,
    /// Hold the exponent n at this value instead of fitting it (a linear model always holds 1).
    #[arg(long)]
    pub n: Option<f64>,
    /// Hunt-Crossley family: fit a material damping constant D/K (s/m) instead of e.
    #[arg(long)]
    pub damping_constant: bool,
    /// thornton: the spheres' radius, m (the yield pressure is fitted).
    #[arg(long)]
    pub radius: Option<f64>,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub out: OutArgs,
}

/// `--model` of `fit restitution`: `table` or a model's name.
fn parse_restitution_law(s: &str) -> Result<pounding_study::fit::RestitutionLaw, String> {
    pounding_study::fit::RestitutionLaw::parse(s)
}

#[derive(Subcommand, Debug)]
pub enum PaperTable {
    /// Table 1: mean |e_pre - e_post| / e_pre * 100 of every model, with the published figures beside.
    #[command(
        after_help = "Files in --out: table1.json (what --json prints); with --plots: table1-e-post.svg (delivered against requested e, with the ideal line), table1-error.svg (the error against e)."
    )]
    Table1 {
        /// Print one JSON object on stdout.
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        out: OutArgs,
    },
    /// Peak force of every model for the documented concrete ball-drop example (the paper's Table 2 needs
    /// experimental inputs it does not give).
    Table2 {
        /// Print one JSON object on stdout.
        #[arg(long)]
        json: bool,
    },
}

/// Options that choose and tune the contact model.
#[derive(Args, Debug, Clone)]
pub struct ModelArgs {
    /// Contact model (see `pounding models`).
    #[arg(long, value_parser = named::<Model>())]
    pub model: Model,
    /// Requested coefficient of restitution e_pre, 0 < e <= 1 (a damped model needs it, or --e-table, or
    /// --damping-constant; the elastic ones, hooke and hertz, deliver 1 and take none).
    #[arg(long)]
    pub e: Option<f64>,
    /// e against the impact velocity: a file of two columns, v_i (m/s) and e, velocities increasing
    /// (read linearly between rows, held beyond the ends; each impact is calibrated to e at its v_i).
    #[arg(long, value_name = "FILE")]
    pub e_table: Option<std::path::PathBuf>,
    /// Hunt-Crossley family: a material damping constant D/K (s/m) instead of e, F = K d^n (1 + (D/K) d').
    #[arg(long)]
    pub damping_constant: Option<f64>,
    /// Exponent n of the force law (default: the model's, 1 or 1.5).
    #[arg(long)]
    pub n: Option<f64>,
    /// Damping: the published formula, or the exact value that delivers e.
    #[arg(long, value_parser = named::<Damping>(), default_value_t = ContactOptions::default().damping)]
    pub damping: Damping,
    /// alpha of papi: a number >= 0, eq8 (eq (8) of Papi & Toopchi-Nezhad (2022), as printed) or calibrate [default: calibrate].
    #[arg(long, value_parser = parse_alpha)]
    pub alpha: Option<AlphaRule>,
    /// Reading of papi's force law.
    #[arg(long, value_parser = named::<Reading>(), default_value_t = ContactOptions::default().reading)]
    pub reading: Reading,
    /// May the force become tensile late in restitution? [default: allow for kelvin-voigt, clamp otherwise]
    #[arg(long, value_parser = named::<Tension>())]
    pub tension: Option<Tension>,
    /// impact-material: expected maximum penetration d_m, m [default: the elastic Hertz penetration].
    #[arg(long)]
    pub max_penetration: Option<f64>,
    /// impact-material: yield ratio a = d_y / d_m, 0 < a < 1.
    #[arg(long, default_value_t = ContactOptions::default().yield_ratio)]
    pub yield_ratio: f64,
    /// thornton: yield pressure p_y, Pa (the largest contact pressure; with the sphere's radius).
    #[arg(long)]
    pub yield_pressure: Option<f64>,
}

impl ModelArgs {
    /// The library's contact options these arguments give.
    /// The options, with what the contact is asked to deliver (`e`, from [`crate::restitution::asked`]).
    /// `radius` (m) is thornton's spheres' radius, where the command has one.
    pub fn options(
        &self,
        e: pounding::contact::Restitution,
        radius: Option<f64>,
    ) -> pounding::contact::ContactOptions {
        pounding::contact::ContactOptions {
            model: self.model,
            e,
            exponent: self.n,
            damping: self.damping,
            alpha: self.alpha,
            reading: self.reading,
            tension: self.tension,
            max_penetration: self.max_penetration,
            yield_ratio: self.yield_ratio,
            radius,
            yield_pressure: self.yield_pressure,
        }
    }
}

/// The two bodies of one impact: m1 moving at v towards m2 at rest.
#[derive(Args, Debug, Clone, Copy)]
pub struct BodiesArgs {
    /// Mass of the moving body, kg.
    #[arg(long, default_value_t = 1.0e5)]
    pub m1: f64,
    /// Mass of the body at rest, kg, or inf for a rigid wall.
    #[arg(long, default_value = "inf")]
    pub m2: f64,
    /// Approach velocity at first touch, m/s.
    #[arg(long, default_value_t = 1.0)]
    pub v: f64,
}

#[derive(Args, Debug)]
#[command(
    after_help = "Files in --out: impact.json (what --json prints), history.csv (t, penetration, rate, force at every step); with --plots: impact-force-time.svg, impact-force-penetration.svg."
)]
#[command(allow_negative_numbers = true)]
pub struct ImpactArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    /// Contact stiffness k, N/m^n (thornton: the Hertz stiffness (4/3) E* sqrt(R), N/m^1.5).
    #[arg(long, default_value_t = 1.0e9)]
    pub k: f64,
    /// thornton: radius R of the spheres, m.
    #[arg(long)]
    pub radius: Option<f64>,
    #[command(flatten)]
    pub bodies: BodiesArgs,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub out: OutArgs,
}

#[derive(Args, Debug)]
#[command(
    after_help = "Files in --out: compare.json (what --json prints); with --plots: compare-force-time.svg, compare-force-penetration.svg (one curve per model)."
)]
#[command(allow_negative_numbers = true)]
pub struct CompareArgs {
    /// Contact models, comma-separated (see `pounding models`).
    #[arg(long, value_delimiter = ',', value_parser = named::<Model>(), required = true)]
    pub models: Vec<Model>,
    /// Requested coefficient of restitution e_pre, 0 < e <= 1 (or --e-table).
    #[arg(long, required_unless_present = "e_table")]
    pub e: Option<f64>,
    /// e against the impact velocity: a file of two columns, v_i (m/s) and e; read at --v (the damped models
    /// are asked that e).
    #[arg(long, value_name = "FILE", conflicts_with = "e")]
    pub e_table: Option<std::path::PathBuf>,
    /// Damping: the published formula, or the exact value that delivers e.
    #[arg(long, value_parser = named::<Damping>(), default_value_t = ContactOptions::default().damping)]
    pub damping: Damping,
    /// Hertz stiffness k_h, N/m^1.5, of the models with n = 1.5. A model with another n gets the
    /// equivalent k_h d_h^(1.5 - n), d_h the elastic Hertz penetration, so all reach about the same
    /// penetration.
    #[arg(long, default_value_t = 1.0e10)]
    pub k: f64,
    /// thornton: radius R of the spheres, m (k_h is their Hertz stiffness (4/3) E* sqrt(R)).
    #[arg(long)]
    pub radius: Option<f64>,
    /// thornton: yield pressure p_y, Pa.
    #[arg(long)]
    pub yield_pressure: Option<f64>,
    #[command(flatten)]
    pub bodies: BodiesArgs,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub out: OutArgs,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct CalibrateArgs {
    /// Contact model (see `pounding models`).
    #[arg(long, value_parser = named::<Model>())]
    pub model: Model,
    /// Requested coefficient of restitution e_pre, 0 < e <= 1.
    #[arg(long)]
    pub e: f64,
    /// Reading of papi's force law.
    #[arg(long, value_parser = named::<Reading>(), default_value_t = ContactOptions::default().reading)]
    pub reading: Reading,
    /// Tension rule (changes the exact zeta of kelvin-voigt).
    #[arg(long, value_parser = named::<Tension>())]
    pub tension: Option<Tension>,
    /// Exponent n (changes the exact xi of jankowski and e_design of impact-material).
    #[arg(long)]
    pub n: Option<f64>,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args, Debug)]
#[command(
    after_help = "Files in --out: drop.json (what --json prints), history.csv (t, penetration, rate, force at every step); with --plots: drop-force-time.svg, drop-force-penetration.svg."
)]
#[command(allow_negative_numbers = true)]
pub struct DropArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    /// Ball radius, m.
    #[arg(long)]
    pub radius: f64,
    /// Young's modulus of ball and slab, Pa.
    #[arg(long)]
    pub youngs_modulus: f64,
    /// Poisson's ratio of ball and slab.
    #[arg(long)]
    pub poisson: f64,
    /// Drop height, m.
    #[arg(long)]
    pub height: f64,
    /// Density of the ball, kg/m^3 (concrete).
    #[arg(long, default_value_t = 2400.0)]
    pub density: f64,
    /// Print one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub out: OutArgs,
}

/// `--alpha`: a number, or a word of [`AlphaWord`].
pub fn parse_alpha(s: &str) -> Result<AlphaRule, String> {
    match AlphaWord::from_name(s) {
        Some(AlphaWord::Eq8) => Ok(AlphaRule::Eq8),
        Some(AlphaWord::Calibrate) => Ok(AlphaRule::Calibrate),
        None => s.parse::<f64>().map(AlphaRule::Given).map_err(|_| {
            format!(
                "allowed: a number >= 0, {}",
                AlphaWord::names().join(" or ")
            )
        }),
    }
}
