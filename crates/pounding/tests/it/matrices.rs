//! Structures given by their matrices: a shear building's own matrix is the shear building; a dense stiffness
//! and damping matrix against an independent integration of `M x'' + C x' + K x = -M 1 a_g`; a pounding pair's
//! energy; what is refused.

use pounding::analysis::{Building, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::ground_motion::Record;
use pounding::structure::{Matrix, MatrixStructure, ShearBuilding};

fn from(masses: &[f64], k: &[[f64; 3]; 3], c: Option<&[[f64; 3]; 3]>) -> ShearBuilding {
    let rows = |a: &[[f64; 3]; 3]| a.iter().map(|r| r.to_vec()).collect::<Vec<_>>();
    let k = Matrix::from_rows("stiffness_matrix", &rows(k)).unwrap();
    let c = c.map(|c| Matrix::from_rows("damping_matrix", &rows(c)).unwrap());
    let ms = MatrixStructure::new(&Matrix::diagonal(masses), k, c).unwrap();
    ShearBuilding::from_matrices(ms, vec![4.0, 3.0, 3.0], 0.05).unwrap()
}

fn pair(a: ShearBuilding, gap: f64) -> Scenario {
    let b = ShearBuilding::new(
        vec![3e5; 3],
        vec![1.2e8, 1.0e8, 0.8e8],
        vec![4.0, 3.0, 3.0],
        0.05,
    )
    .unwrap();
    Scenario::new(
        vec![
            Building {
                name: "A".into(),
                structure: a,
            },
            Building {
                name: "B".into(),
                structure: b,
            },
        ],
        Record::el_centro_1940(),
    )
    .unwrap()
    .with_duration(8.0)
    .unwrap()
    .with_link(
        "A",
        "B",
        gap,
        &ContactModel::new(Model::KelvinVoigt, 1e9, 0.6).unwrap(),
        None,
    )
    .unwrap()
}

/// Building `a` alone ("A") under El Centro for `t_end` s.
fn alone(a: ShearBuilding, t_end: f64) -> Scenario {
    Scenario::new(
        vec![Building {
            name: "A".into(),
            structure: a,
        }],
        Record::el_centro_1940(),
    )
    .unwrap()
    .with_duration(t_end)
    .unwrap()
}

/// The tridiagonal matrix of a shear building (storeys k1, k2, k3) is that building: the same modes, modal
/// damping and, pounding a neighbour, the same peaks and impacts (to roundoff: the springs sum the same
/// stiffnesses in another order).
#[test]
fn a_shear_buildings_matrix_is_the_shear_building() {
    let (m, k) = ([4e5, 4e5, 3e5], [3e8, 2.5e8, 2e8]);
    let kk = [
        [k[0] + k[1], -k[1], 0.0],
        [-k[1], k[1] + k[2], -k[2]],
        [0.0, -k[2], k[2]],
    ];
    let shear = ShearBuilding::new(m.to_vec(), k.to_vec(), vec![4.0, 3.0, 3.0], 0.05).unwrap();
    let matrix = from(&m, &kk, None);
    assert_eq!(matrix.stiffnesses(), shear.stiffnesses());
    for r in 0..3 {
        let (a, b) = (matrix.modes().omega[r], shear.modes().omega[r]);
        assert!((a / b - 1.0).abs() < 1e-12, "mode {r}: {a} vs {b}");
        let (za, zb) = (matrix.damping_of_mode(r), shear.damping_of_mode(r));
        assert!((za - zb).abs() < 1e-12, "mode {r}: zeta {za} vs {zb}");
    }
    let (ra, rb) = (
        pair(matrix, 0.01).run().unwrap(),
        pair(shear, 0.01).run().unwrap(),
    );
    assert!(ra.impacts.len() > 2);
    assert_eq!(ra.impacts.len(), rb.impacts.len());
    for (x, y) in ra.buildings.iter().zip(&rb.buildings) {
        for (name, p, q) in [
            ("displacement", &x.peak_displacement, &y.peak_displacement),
            ("drift", &x.peak_drift, &y.peak_drift),
            ("shear", &x.peak_storey_shear, &y.peak_storey_shear),
        ] {
            for (a, b) in p.iter().zip(q) {
                assert!((a / b - 1.0).abs() < 1e-9, "{name}: {a} vs {b}");
            }
        }
    }
}

/// Floor peaks of `M x'' + C x' + K x = -M 1 a_g` by classical RK4 at a fixed step of 1e-5 s (a step that
/// divides the record's 0.02 s, so `a_g` is linear within each): the equations written out.
fn reference(m: &[f64; 3], k: &[[f64; 3]; 3], c: &[[f64; 3]; 3], t_end: f64) -> [f64; 3] {
    rk4_peaks(m, k, c, t_end, |y, i| y[i])
}

/// The largest `|q(y, j)|` of three quantities `j` of the state `y = [x, x']`, sampled at every step of
/// [`reference`]'s integration.
fn rk4_peaks(
    m: &[f64; 3],
    k: &[[f64; 3]; 3],
    c: &[[f64; 3]; 3],
    t_end: f64,
    q: impl Fn(&[f64; 6], usize) -> f64,
) -> [f64; 3] {
    let rec = Record::el_centro_1940();
    let rhs = |t: f64, y: &[f64; 6]| -> [f64; 6] {
        let ag = rec.at(t);
        std::array::from_fn(|i| {
            if i < 3 {
                y[i + 3]
            } else {
                let r = i - 3;
                let f: f64 = (0..3).map(|j| k[r][j] * y[j] + c[r][j] * y[j + 3]).sum();
                -ag - f / m[r]
            }
        })
    };
    let h = 1e-5;
    let mut y = [0.0; 6];
    let mut peak = [0.0f64; 3];
    for s in 0..(t_end / h).round() as usize {
        let t = s as f64 * h;
        let add = |y: &[f64; 6], k: &[f64; 6], a: f64| -> [f64; 6] {
            std::array::from_fn(|i| y[i] + a * k[i])
        };
        let k1 = rhs(t, &y);
        let k2 = rhs(t + h / 2.0, &add(&y, &k1, h / 2.0));
        let k3 = rhs(t + h / 2.0, &add(&y, &k2, h / 2.0));
        let k4 = rhs(t + h, &add(&y, &k3, h));
        y = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        for (j, p) in peak.iter_mut().enumerate() {
            *p = p.max(q(&y, j).abs());
        }
    }
    peak
}

/// A frame condensed to its floors: every floor coupled to every other (floor 1 to floor 3 through a positive
/// off-diagonal term, as condensed frames have), with a damping matrix that is not Rayleigh's.
const M3: [f64; 3] = [4e5, 3.5e5, 3e5];
const K3: [[f64; 3]; 3] = [
    [5.2e8, -3.1e8, 0.6e8],
    [-3.1e8, 4.4e8, -1.9e8],
    [0.6e8, -1.9e8, 1.4e8],
];
const C3: [[f64; 3]; 3] = [
    [1.6e6, -0.7e6, 0.1e6],
    [-0.7e6, 1.2e6, -0.4e6],
    [0.1e6, -0.4e6, 0.6e6],
];

#[test]
fn a_dense_matrix_is_its_equations() {
    let t_end = 4.0;
    let peaks = reference(&M3, &K3, &C3, t_end);
    for (tol, within) in [(1e-7, 2e-5), (1e-10, 1e-7)] {
        let s = alone(from(&M3, &K3, Some(&C3)), t_end)
            .with_tolerance(tol)
            .unwrap();
        let r = s.run().unwrap();
        for (i, (&a, b)) in r.buildings[0]
            .peak_displacement
            .iter()
            .zip(peaks)
            .enumerate()
        {
            assert!(
                (a / b - 1.0).abs() < within,
                "tol {tol}, floor {}: {a} vs {b}",
                i + 1
            );
        }
        assert!(
            r.energy.relative_error < 1e-6,
            "{}",
            r.energy.relative_error
        );
    }
}

/// Peak storey shears of a matrix structure under El Centro (Rayleigh damping; the shear as reported is the
/// springs' force, without their dashpots) against classical RK4 at 1e-5 s sampled every step, the shear
/// under floor `j` written out as the springs across the cut below it (`k_ul = -K_ul` joining floor `u >= j`
/// to floor `l < j`, and each floor's row sum to the ground). Stiff enough (40 times `K3`) that its exact
/// steps take whole record intervals (240 steps for 150 intervals): a storey's shear combines every floor's
/// motion and peaks where no drift does (read at its drift's extremum, as it was, storey 1 came out 3.4e-5
/// low; now 5e-9). Within 1e-6: the run's default tolerance (1e-7) and the reference's sampling (a peak
/// between samples 1e-5 s apart is missed by at most `(w h)^2 / 8`, 8e-7 at its highest mode).
#[test]
fn a_matrix_storeys_shear_peaks_where_it_does() {
    let (m, t_end) = (M3, 3.0f64);
    let k: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| 40.0 * K3[i][j]));
    let b = from(&m, &k, None);
    // Rayleigh damping `a0 M + a1 K` on its modes 1 and 2, as the structure holds it.
    let (a0, a1) = b.rayleigh();
    let c: [[f64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| a1 * k[i][j] + if i == j { a0 * m[i] } else { 0.0 })
    });
    let shear = |y: &[f64; 6], j: usize| -> f64 {
        let mut s = 0.0;
        for u in j..3 {
            s += (0..3).map(|v| k[u][v]).sum::<f64>() * y[u];
            for l in 0..j {
                s += -k[u][l] * (y[u] - y[l]);
            }
        }
        s
    };
    let peak = rk4_peaks(&m, &k, &c, t_end, shear);
    let r = alone(b, t_end).run().unwrap();
    for (j, (&a, b)) in r.buildings[0]
        .peak_storey_shear
        .iter()
        .zip(peak)
        .enumerate()
    {
        assert!((a / b - 1.0).abs() < 1e-6, "storey {}: {a} vs {b}", j + 1);
    }
}

/// Modes of the dense matrix against the characteristic polynomial `det(K - w^2 M) = 0`, and the pounding pair's
/// energy balance with Rayleigh damping on them.
#[test]
fn a_dense_matrix_pounds_in_balance() {
    let b = from(&M3, &K3, None);
    for &w in &b.modes().omega {
        let l = w * w;
        let a = |i: usize, j: usize| K3[i][j] - if i == j { l * M3[i] } else { 0.0 };
        let det = a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1))
            - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0))
            + a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
        // Relative to the product of the diagonal's magnitudes.
        assert!(
            det.abs() < 1e-10 * K3[0][0] * K3[1][1] * K3[2][2],
            "w {w}: det {det}"
        );
    }
    for r in 0..2 {
        let z = b.damping_of_mode(r);
        assert!((z - 0.05).abs() < 1e-12, "mode {r}: zeta {z}");
    }
    let r = pair(b, 0.005).run().unwrap();
    assert!(r.impacts.len() > 2);
    assert!(
        r.energy.relative_error < 1e-6,
        "{}",
        r.energy.relative_error
    );
}

#[test]
fn what_a_matrix_structure_refuses() {
    let m = Matrix::diagonal(&[1e5, 1e5]);
    let k = |rows: &[[f64; 2]; 2]| {
        Matrix::from_rows(
            "stiffness_matrix",
            &rows.iter().map(|r| r.to_vec()).collect::<Vec<_>>(),
        )
        .unwrap()
    };
    let e = |r: Result<MatrixStructure, pounding::Error>| r.unwrap_err().to_string();
    assert!(e(MatrixStructure::new(
        &m,
        k(&[[2.0, -1.0], [-0.5, 1.0]]),
        None
    ))
    .contains("symmetric"));
    let full = Matrix::from_rows("mass_matrix", &[vec![1e5, 1.0], vec![1.0, 1e5]]).unwrap();
    assert!(e(MatrixStructure::new(
        &full,
        k(&[[2.0, -1.0], [-1.0, 1.0]]),
        None
    ))
    .contains("diagonal"));
    // Not held: a rigid-body mode.
    let loose = MatrixStructure::new(&m, k(&[[1e8, -1e8], [-1e8, 1e8]]), None).unwrap();
    let msg = ShearBuilding::from_matrices(loose, vec![3.0, 3.0], 0.05)
        .unwrap_err()
        .to_string();
    assert!(msg.starts_with("stiffness_matrix = "), "{msg}");
}

/// The white-noise separation's linear system of a shear building's matrix is the shear building's (its state
/// matrix to roundoff), and its stationary covariance the same.
#[test]
fn a_shear_buildings_matrix_has_its_random_vibration() {
    use pounding::separation::linear::{state_space, stationary_covariance};
    let (m, k) = ([4e5, 4e5, 3e5], [3e8, 2.5e8, 2e8]);
    let kk = [
        [k[0] + k[1], -k[1], 0.0],
        [-k[1], k[1] + k[2], -k[2]],
        [0.0, -k[2], k[2]],
    ];
    let shear = ShearBuilding::new(m.to_vec(), k.to_vec(), vec![4.0, 3.0, 3.0], 0.05).unwrap();
    let (a, b) = (pair(from(&m, &kk, None), 0.01), pair(shear, 0.01));
    let (sa, sb) = (state_space(&a, None), state_space(&b, None));
    let big = sb.a.iter().fold(0.0f64, |x, y| x.max(y.abs()));
    for (x, y) in sa.a.iter().zip(&sb.a) {
        assert!((x - y).abs() <= 1e-12 * big, "{x} vs {y}");
    }
    let (pa, pb) = (
        stationary_covariance(&sa, 0.01).unwrap(),
        stationary_covariance(&sb, 0.01).unwrap(),
    );
    for (x, y) in pa.iter().zip(&pb) {
        assert!((x - y).abs() <= 1e-9 * y.abs().max(1e-12), "{x} vs {y}");
    }
}
