//! The catalogue of contact models: names, families, force laws, damping formulas and sources.

use super::damping as dmp;
use super::Tension;

/// The five force-law families; every model is one family plus a damping formula.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize),
    serde(rename_all = "kebab-case")
)]
pub enum Family {
    /// `F = k d^n`, no damping (e = 1).
    Elastic,
    /// `F = k d + c v` with `c = 2 zeta sqrt(k m)`; restitution damped or not.
    LinearViscous,
    /// Hunt–Crossley type: `F = k d^n (1 + chi v / v_i)`.
    HuntCrossley,
    /// Jankowski's nonlinear viscoelastic law: `k d^n + 2 xi sqrt(k m d^(n-1)) v` in approach, `k d^n` after.
    Jankowski,
    /// Muthukumar & DesRoches bilinear loop (OpenSees `ImpactMaterial`).
    Bilinear,
    /// Elastic–perfectly-plastic spheres (Thornton 1997): Hertz, then plastic flow at the yield pressure.
    ElasticPlastic,
}

/// Every contact model of the library (`docs/contact-models.md`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)] // each variant is documented by its row of `Model::info`
pub enum Model {
    Hooke,
    Hertz,
    KelvinVoigt,
    MahmoudJankowski,
    Ye,
    Papi,
    HuntCrossley,
    HerbertMcWhannell,
    LeeWang,
    LankaraniNikravesh,
    Gonthier,
    ZhiyingQishao,
    Flores,
    Hertzdamp,
    Jankowski,
    ImpactMaterial,
    Thornton,
}

/// How a model derives its damping parameter from `e` by its published formula.
#[derive(Clone, Copy, Debug)]
pub enum Formula {
    /// No damping.
    None,
    /// A damping ratio `zeta(e)` of a linear dashpot `c = 2 zeta sqrt(k m)`.
    Zeta(fn(f64) -> f64),
    /// A Hunt–Crossley factor `chi(e)`, the same in both phases.
    Chi(fn(f64) -> f64),
    /// Papi & Toopchi-Nezhad (2022) eq (7): `chi(e, alpha)`, with `alpha` chosen by the user, eq (8) or calibration.
    Papi,
    /// Jankowski's `xi(e)`.
    Xi(fn(f64) -> f64),
    /// The bilinear loop's dissipated energy `k d_m^(n+1) (1 - e^2) / (n + 1)`.
    Bilinear,
    /// None: the loss follows from the yield pressure and the sphere's radius (Thornton 1997).
    Thornton,
}

/// One row of the catalogue.
#[derive(Clone, Copy, Debug)]
pub struct ModelInfo {
    /// The model.
    pub model: Model,
    /// Name on the command line and in scenario files.
    pub name: &'static str,
    /// Force-law family.
    pub family: Family,
    /// Default exponent `n` (stiffness `k` in N/m^n).
    pub default_n: f64,
    /// Whether `n` is fixed at its default (linear models).
    pub n_fixed: bool,
    /// Default tension rule.
    pub tension: Tension,
    /// Whether the restitution phase is damped.
    pub restitution_damped: bool,
    /// The force law, as text.
    pub force_law: &'static str,
    /// The published damping formula, as text.
    pub damping_formula: &'static str,
    /// The published damping formula.
    pub formula: Formula,
    /// Name of the parameter that exact calibration adjusts (`zeta`, `chi`, `xi`, `alpha`, `e_design`).
    pub parameter: Option<&'static str>,
    /// Where the model comes from.
    pub source: &'static str,
}

const HC_LAW: &str = "F = k d^n (1 + chi v / v_i)";

const fn hc(
    model: Model,
    name: &'static str,
    f: fn(f64) -> f64,
    text: &'static str,
    source: &'static str,
    n: f64,
) -> ModelInfo {
    ModelInfo {
        model,
        name,
        family: Family::HuntCrossley,
        default_n: n,
        n_fixed: false,
        tension: Tension::Clamp,
        restitution_damped: true,
        force_law: HC_LAW,
        damping_formula: text,
        formula: Formula::Chi(f),
        parameter: Some("chi"),
        source,
    }
}

/// The catalogue, in the order of docs/contact-models.md.
pub const MODELS: [ModelInfo; 17] = [
    ModelInfo {
        model: Model::Hooke,
        name: "hooke",
        family: Family::Elastic,
        default_n: 1.0,
        n_fixed: true,
        tension: Tension::Clamp,
        restitution_damped: false,
        force_law: "F = k d",
        damping_formula: "none (e = 1)",
        formula: Formula::None,
        parameter: None,
        source: "linear spring; OpenSees ElasticPPGap",
    },
    ModelInfo {
        model: Model::Hertz,
        name: "hertz",
        family: Family::Elastic,
        default_n: 1.5,
        n_fixed: false,
        tension: Tension::Clamp,
        restitution_damped: false,
        force_law: "F = k d^n",
        damping_formula: "none (e = 1)",
        formula: Formula::None,
        parameter: None,
        source: "Hertz (1882); Papi & Toopchi-Nezhad (2022) eq (1)",
    },
    ModelInfo {
        model: Model::KelvinVoigt,
        name: "kelvin-voigt",
        family: Family::LinearViscous,
        default_n: 1.0,
        n_fixed: true,
        tension: Tension::Allow,
        restitution_damped: true,
        force_law: "F = k d + c v, c = 2 zeta sqrt(k m)",
        damping_formula: "zeta = -ln e / sqrt(pi^2 + ln^2 e)",
        formula: Formula::Zeta(dmp::zeta_anagnostopoulos),
        parameter: Some("zeta"),
        source: "Anagnostopoulos (1988, 2004); Papi & Toopchi-Nezhad (2022) eqs (2)-(4)",
    },
    ModelInfo {
        model: Model::MahmoudJankowski,
        name: "mahmoud-jankowski",
        family: Family::LinearViscous,
        default_n: 1.0,
        n_fixed: true,
        tension: Tension::Clamp,
        restitution_damped: false,
        force_law: "F = k d + c v (approach), k d (restitution), c = 2 zeta sqrt(k m)",
        damping_formula: "zeta = (1 - e^2) / (e (e (pi - 2) + 2))",
        formula: Formula::Zeta(dmp::zeta_mahmoud_jankowski),
        parameter: Some("zeta"),
        source: "Mahmoud & Jankowski (2011); Papi & Toopchi-Nezhad (2022) eq (5)",
    },
    hc(
        Model::Ye,
        "ye",
        dmp::chi_ye,
        "chi = 3 (1 - e) / (2 e)",
        "Ye, Li & Zhu (2009); Papi & Toopchi-Nezhad (2022) eq (6)",
        1.0,
    ),
    ModelInfo {
        model: Model::Papi,
        name: "papi",
        family: Family::HuntCrossley,
        default_n: 1.0,
        n_fixed: false,
        tension: Tension::Clamp,
        restitution_damped: true,
        force_law:
            "F = k d^n (1 + chi v / v_i) (approach), chi_r = (alpha / e) chi in restitution \
                    (energy-split) or chi (same-damping); clamped at 0",
        damping_formula: "chi = (3/2) (1 - e^2) / (alpha + e^2); alpha given, eq (8) or calibrated",
        formula: Formula::Papi,
        parameter: Some("alpha"),
        source: "Papi & Toopchi-Nezhad (2022), eqs (7)-(8); readings are our reconstruction",
    },
    hc(
        Model::HuntCrossley,
        "hunt-crossley",
        dmp::chi_hunt_crossley,
        "chi = 3 (1 - e) / 2",
        "Hunt & Crossley (1975)",
        1.5,
    ),
    hc(
        Model::HerbertMcWhannell,
        "herbert-mcwhannell",
        dmp::chi_herbert_mcwhannell,
        "chi = 6 (1 - e) / ((2e - 1)^2 + 3)",
        "Herbert & McWhannell (1977)",
        1.5,
    ),
    hc(
        Model::LeeWang,
        "lee-wang",
        dmp::chi_lee_wang,
        "chi = 3 (1 - e) / 4",
        "Lee & Wang (1983)",
        1.5,
    ),
    hc(
        Model::LankaraniNikravesh,
        "lankarani-nikravesh",
        dmp::chi_lankarani_nikravesh,
        "chi = 3 (1 - e^2) / 4",
        "Lankarani & Nikravesh (1990)",
        1.5,
    ),
    hc(
        Model::Gonthier,
        "gonthier",
        dmp::chi_gonthier,
        "chi = (1 - e^2) / e",
        "Gonthier, McPhee, Lange & Piedboeuf (2004)",
        1.5,
    ),
    hc(
        Model::ZhiyingQishao,
        "zhiying-qishao",
        dmp::chi_zhiying_qishao,
        "chi = 3 (1 - e^2) exp(2 (1 - e)) / 4",
        "Zhiying & Qishao (2006)",
        1.5,
    ),
    hc(
        Model::Flores,
        "flores",
        dmp::chi_flores,
        "chi = 8 (1 - e) / (5 e)",
        "Flores, Machado, Silva & Martins (2011)",
        1.5,
    ),
    hc(
        Model::Hertzdamp,
        "hertzdamp",
        dmp::chi_flores,
        "chi = 8 (1 - e) / (5 e)",
        "Muthukumar & DesRoches (2006) form with Ye, Li & Zhu (2009) damping; OpenSees Hertzdamp",
        1.5,
    ),
    ModelInfo {
        model: Model::Jankowski,
        name: "jankowski",
        family: Family::Jankowski,
        default_n: 1.5,
        n_fixed: false,
        tension: Tension::Clamp,
        restitution_damped: false,
        force_law:
            "F = k d^n + c(d) v (approach), k d^n (restitution), c(d) = 2 xi sqrt(k d^(n-1) m)",
        damping_formula: "xi = (9 sqrt 5 / 2) (1 - e^2) / (e (e (9 pi - 16) + 16))",
        formula: Formula::Xi(dmp::xi_jankowski),
        parameter: Some("xi"),
        source: "Jankowski (2005, 2006); OpenSees JankowskiImpact",
    },
    ModelInfo {
        model: Model::ImpactMaterial,
        name: "impact-material",
        family: Family::Bilinear,
        default_n: 1.5,
        n_fixed: false,
        tension: Tension::Clamp,
        restitution_damped: true,
        force_law: "bilinear loading K1 to d_y = a d_m then K2; unloading K1 down to F = K2 d",
        damping_formula: "dE = k d_m^(n+1) (1 - e^2) / (n + 1), K_eff = k d_m^(n-1), \
                          K1 = K_eff + dE / (a d_m^2), K2 = K_eff - dE / ((1 - a) d_m^2)",
        formula: Formula::Bilinear,
        parameter: Some("e_design"),
        source: "Muthukumar & DesRoches (2006); OpenSees ImpactMaterial",
    },
    ModelInfo {
        model: Model::Thornton,
        name: "thornton",
        family: Family::ElasticPlastic,
        default_n: 1.5,
        n_fixed: true,
        tension: Tension::Clamp,
        restitution_damped: false,
        force_law: "Hertz k d^1.5 up to d_y = R (pi p_y / (2 E*))^2, then F_y + pi p_y R (d - d_y); \
                    unloading Hertzian with radius R_p = 4 E* a_p^3 / (3 F_p), a_p^2 = (2 F_p + F_y) / (2 pi p_y)",
        damping_formula: "none: e follows from the yield pressure, e = 1 below the yield velocity v_y",
        formula: Formula::Thornton,
        parameter: None,
        source: "Thornton (1997), J. Appl. Mech. 64:383-386",
    },
];

impl Model {
    /// The model's row of the catalogue.
    pub fn info(self) -> &'static ModelInfo {
        // The catalogue lists the variants in declaration order.
        &MODELS[self as usize]
    }

    /// The model's command-line name.
    pub fn name(self) -> &'static str {
        self.info().name
    }

    /// The model called `name`, if any.
    pub fn from_name(name: &str) -> Option<Model> {
        MODELS.iter().find(|i| i.name == name).map(|i| i.model)
    }

    /// Every model, in catalogue order.
    pub fn all() -> impl Iterator<Item = Model> {
        MODELS.iter().map(|i| i.model)
    }

    /// Whether the model dissipates energy (has a damping parameter).
    pub fn is_damped(self) -> bool {
        self.info().parameter.is_some()
    }

    /// Why the model is asked no `e`, in a few words for messages; `None` for a damped model, which is.
    pub fn asks_no_e(self) -> Option<&'static str> {
        match (self.is_damped(), self.info().formula) {
            (true, _) => None,
            (false, Formula::Thornton) => {
                Some("its loss is plastic flow, set by its yield pressure (e = 1 below the yield velocity)")
            }
            (false, _) => Some("it is elastic and delivers e = 1"),
        }
    }
}

/// Every model, in catalogue order.
const ALL_MODELS: [Model; MODELS.len()] = {
    let mut out = [Model::Hooke; MODELS.len()];
    let mut i = 0;
    while i < MODELS.len() {
        out[i] = MODELS[i].model;
        i += 1;
    }
    out
};

impl crate::names::Named for Model {
    const WHAT: &'static str = "model";
    const ALL: &'static [Self] = &ALL_MODELS;
    fn name(self) -> &'static str {
        self.info().name
    }
}

crate::named_impls!(Model);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn catalogue_is_in_declaration_order_and_names_round_trip() {
        for (i, info) in MODELS.iter().enumerate() {
            assert_eq!(info.model as usize, i);
            assert_eq!(Model::from_name(info.name), Some(info.model));
        }
    }
}
