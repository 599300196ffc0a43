//! The row of buildings as a system of the engine: one degree of freedom per floor, one storey element per
//! storey (and, for an isolated building, one dashpot per floor above the base slab for the
//! mass-proportional damping of its superstructure), one contact element per level of each contact site
//! (two with a bumper), and one device element per floor pair of each device.

use super::{ContactSite, DeviceEnds, Layer, Level, Scenario, SiteKind, NO_CONTACT_GAP};
use crate::element::device::Dashpot;
use crate::element::{Contact, Element, ElementLaw, End, Scales};
use crate::engine::{Dof, Ground, System};

/// A contact element and where it stands.
#[derive(Clone, Copy, Debug)]
pub(super) struct ContactRef {
    /// Index of the element in the system.
    pub element: usize,
    /// Its site (index in [`Scenario::sites`]).
    pub site: usize,
    /// Its level (index in the site's levels).
    pub level: usize,
    /// Which law of the site.
    pub layer: Layer,
}

/// A device element and where it stands.
#[derive(Clone, Copy, Debug)]
pub(super) struct DeviceRef {
    /// Index of the element in the system.
    pub element: usize,
    /// Index in [`Scenario::devices`].
    pub device: usize,
}

/// The system and the map from buildings, storeys and contacts to its degrees of freedom and elements.
pub(super) struct Model<'a> {
    pub system: System<'a>,
    /// First degree of freedom of each building (floor 1).
    pub offsets: Vec<usize>,
    /// Element index of storey 1 of each building (its storeys follow in order).
    pub first_storey: Vec<usize>,
    /// Element index of the storey under each floor (degree of freedom).
    pub storey_under: Vec<usize>,
    /// The contact elements, site by site, level by level; a bumper's layer comes before the hard law
    /// behind it.
    pub contacts: Vec<ContactRef>,
    /// The elements of the devices, device by device, floor pair by floor pair.
    pub devices: Vec<DeviceRef>,
}

impl<'a> Model<'a> {
    pub fn new(s: &'a Scenario) -> Self {
        let mut dofs = Vec::new();
        let mut elements = Vec::new();
        let mut offsets = Vec::new();
        let mut first_storey = Vec::new();
        let mut storey_under = Vec::new();
        // Dashpots of the mass-proportional damping of isolated superstructures, relative to the base slab.
        let mut base_dashpots = Vec::new();
        for b in s.buildings() {
            let st = &b.structure;
            let (c, a0, base) = st.damping_layout();
            let offset = dofs.len();
            offsets.push(offset);
            first_storey.push(elements.len());
            for (j, (&k, law)) in st.stiffnesses().iter().zip(st.storey_laws()).enumerate() {
                let bottom = if j == 0 {
                    End::Ground
                } else {
                    End::Dof(offset + j - 1)
                };
                storey_under.push(elements.len());
                // Rayleigh damping on the initial stiffness (OpenSees' betaKinit); an isolator's own.
                elements.push(
                    Element::new(End::Dof(offset + j), bottom, law.law(k)).with_dashpot(c[j]),
                );
            }
            let a0_dof = if base.is_some() { 0.0 } else { a0 };
            dofs.extend(st.masses().iter().map(|&mass| Dof::x(mass, a0_dof)));
            if let (Some(base), true) = (base, a0 > 0.0) {
                for (i, &m) in st.masses().iter().enumerate().filter(|(i, _)| *i != base) {
                    base_dashpots.push((offset + i, offset + base, a0 * m));
                }
            }
        }
        for (i, b, c) in base_dashpots {
            elements.push(Element::new(End::Dof(i), End::Dof(b), Dashpot::new(c)));
        }
        let mut contacts = Vec::new();
        for (si, site) in s.sites().iter().enumerate() {
            for (li, level) in site.levels.iter().enumerate() {
                let ends = site_ends(site, level, &offsets);
                let m_eff = s.effective_mass(site, level);
                let mut push = |layer, gap, contact: &crate::contact::PreparedContact| {
                    contacts.push(ContactRef {
                        element: elements.len(),
                        site: si,
                        level: li,
                        layer,
                    });
                    let law = Contact::new(contact.clone(), gap, m_eff, s.min_impact_velocity());
                    elements.push(Element::new(ends.0, ends.1, law));
                };
                match &site.bumper {
                    _ if !site.active => push(Layer::Direct, NO_CONTACT_GAP, &site.contact),
                    None => push(Layer::Direct, site.gap, &site.contact),
                    Some(bm) => {
                        let (touch, consumed) = bm.gaps(site.gap);
                        push(Layer::Bumper, touch, &bm.contact);
                        push(Layer::Consumed, consumed, &site.contact);
                    }
                }
            }
        }
        let mut devices = Vec::new();
        for (di, d) in s.devices().iter().enumerate() {
            for &(fa, fb) in &d.floors {
                let ends = match d.ends {
                    DeviceEnds::Buildings { left, right } => (
                        End::Dof(offsets[left] + fa - 1),
                        End::Dof(offsets[right] + fb - 1),
                    ),
                    DeviceEnds::Wall { site } => {
                        let level = Level {
                            left: Some(fa),
                            right: Some(fa),
                        };
                        site_ends(&s.sites()[site], &level, &offsets)
                    }
                };
                devices.push(DeviceRef {
                    element: elements.len(),
                    device: di,
                });
                // Checked when the device was added.
                let law = d
                    .law
                    .law()
                    .expect("a device law checked by Scenario::with_device");
                elements.push(Element::new(ends.0, ends.1, law));
            }
        }
        Self {
            system: System::new(&dofs, elements, Ground::Record(s.record())),
            offsets,
            first_storey,
            storey_under,
            contacts,
            devices,
        }
    }

    /// Absolute tolerances of every state component for the relative tolerance `rtol`, and a first trial
    /// step; sets each element's rate resolution from them ([`crate::element::RateGate`]). Scales per
    /// building: the static displacement of its fundamental mode under the peak ground acceleration within
    /// the analysis (or, for a building so flexible that it barely responds within the analysis, of a mode
    /// with the analysis duration as period), and the velocity that goes with it; energies from the modal
    /// effective masses and velocities. Gaps play no part: a floor reaches what its building can reach.
    pub fn tolerances(&mut self, s: &Scenario, rtol: f64) -> (Vec<f64>, f64) {
        let sys = &self.system;
        let l = sys.layout();
        let n = l.dofs();
        // The peak ground acceleration within the analysis (a short analysis of a long record sees only its
        // start).
        let r = s.record();
        let within = ((s.duration() - r.t0()) / r.dt()).floor().max(0.0) as usize + 1;
        let pga = r.accelerations()[..within.min(r.npts())]
            .iter()
            .fold(0.0f64, |a, x| a.max(x.abs()));
        let w_floor = 2.0 * std::f64::consts::PI / s.duration();
        let mut atol = vec![0.0; l.dim()];
        let mut u_scale = vec![0.0; n];
        let mut v_scale = vec![0.0; n];
        let mut w_max: f64 = 0.0;
        let mut resolutions = Vec::new();
        // Energy a building can take in: each mode's effective mass times its velocity under the peak ground
        // acceleration (the modal masses sum to the building's mass; a stiff, heavy floor whose mode barely
        // responds used to count with the fundamental mode's velocity, which loosened the control of the
        // energy terms a hundredfold).
        let mut e_scale = 0.0;
        for b in s.buildings() {
            let modes = b.structure.modes();
            let m = b.structure.masses();
            for (w, phi) in modes.omega.iter().zip(&modes.shapes) {
                let gamma: f64 = phi.iter().zip(m).map(|(p, m)| p * m).sum();
                let w = w.max(w_floor);
                let v = (pga / (w * w)).max(1e-30) * w;
                e_scale += gamma * gamma * v * v;
            }
        }
        for (b, &offset) in s.buildings().iter().zip(&self.offsets) {
            let omega = &b.structure.modes().omega;
            w_max = omega.iter().copied().fold(w_max, f64::max);
            let w = omega[0].max(w_floor);
            // What the building can reach, not a gap it may never close (a huge gap used to loosen the error
            // control of every floor); no floor of a nanometre either (a stiff floor that moves 1e-10 m had its
            // energies controlled to 1e-3 only).
            let u = (pga / (w * w)).max(1e-30);
            for i in offset..offset + omega.len() {
                (u_scale[i], v_scale[i]) = (u, u * w);
                atol[l.u(i)] = rtol * u;
                atol[l.v(i)] = rtol * u * w;
            }
        }
        atol[l.input()] = rtol * e_scale;
        atol[l.damping()] = rtol * e_scale;
        for (e, el) in sys.elements().iter().enumerate() {
            let r = l.block(e);
            // Each end's terms (a point of a floor in plan weighs its degrees of freedom; a plain degree of
            // freedom is one term of weight 1).
            let (ta, tb) = (el.a.terms(), el.b.terms());
            let terms = || {
                ta.terms()
                    .iter()
                    .chain(tb.terms())
                    .map(|&(i, c)| (i, c.abs()))
            };
            let v = terms().map(|(i, c)| c * v_scale[i]).fold(0.0, f64::max);
            // Ten times the local error allowed in each end's rate (atol + rtol |v|, up to 2 atol).
            let v_res: f64 = terms().map(|(i, c)| 20.0 * c * atol[l.v(i)]).sum();
            resolutions.push((e, v_res));
            let u = terms().map(|(i, c)| c * u_scale[i]).fold(0.0, f64::max);
            let scales = Scales {
                rtol,
                displacement: u,
                velocity: v,
                energy: e_scale,
            };
            el.law.state_tolerances(&scales, &mut atol[r]);
        }
        for (e, v_res) in resolutions {
            self.system.elements_mut()[e].set_rate_resolution(v_res);
        }
        (atol, 1e-3 * 2.0 * std::f64::consts::PI / w_max)
    }
}

/// The ends of a site's contact element at `level`: the left floor and the right floor, or a floor and the
/// ground (a wall on its right is end `b`; on its left, end `a`). For a device to a wall, `level` gives the
/// building's floor on both sides.
fn site_ends(site: &ContactSite, level: &Level, offsets: &[usize]) -> (End, End) {
    let floor = |b: usize, f: Option<usize>| End::Dof(offsets[b] + f.unwrap_or(1) - 1);
    match site.kind {
        SiteKind::Between { left, right } => (floor(left, level.left), floor(right, level.right)),
        SiteKind::Wall {
            building,
            side: super::Side::Right,
        } => (floor(building, level.left), End::Ground),
        SiteKind::Wall {
            building,
            side: super::Side::Left,
        } => (End::Ground, floor(building, level.right)),
    }
}
