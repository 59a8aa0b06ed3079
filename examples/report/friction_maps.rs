//! Friction error maps over (u, ψ) and the model curves against the exact integrals.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};
use std::path::Path;

use contensou::elliptic::Parameter;
use contensou::friction::{
    Best, Constants, Coulomb, Ellipsoid, Exact, FrictionLaw, Pade, Simplified, SlipState, Traction,
};

use crate::measure::traction_error;
use crate::plot::{self, Axis, Panel};

/// e² of the map panels.
pub const MAP_E2: [f64; 6] = [0.0, 0.5, 0.9, 0.99, 0.999, 0.9999];
/// Grid: u log-spaced over [1e-2, 1e2] (cells), ψ over [0, π/2] (cells).
const NU: usize = 128;
const NPSI: usize = 64;

fn constants(e2: f64) -> Constants<f64> {
    Constants::from_parameter(Parameter::new(e2).expect("e² of the maps is inside [0, 1)"))
}

fn state(psi: f64, u: f64) -> Option<SlipState<f64>> {
    SlipState::from_polar(psi, u).ok()
}

/// Cell centres of the grid (log10 u, ψ) with the cell edges.
fn cells() -> Vec<(f64, f64, f64, f64)> {
    let mut v = Vec::new();
    for i in 0..NU {
        for j in 0..NPSI {
            let x0 = -2.0 + 4.0 * i as f64 / NU as f64;
            let x1 = -2.0 + 4.0 * (i + 1) as f64 / NU as f64;
            let y0 = FRAC_PI_2 * j as f64 / NPSI as f64;
            let y1 = FRAC_PI_2 * (j + 1) as f64 / NPSI as f64;
            v.push((x0, x1, y0, y1));
        }
    }
    v
}

/// The exact traction at every cell centre, per e² of [`MAP_E2`].
pub fn exact_grid() -> Vec<Vec<Option<Traction<f64>>>> {
    MAP_E2
        .iter()
        .map(|&e2| {
            let k = constants(e2);
            cells()
                .into_iter()
                .map(|(x0, x1, y0, y1)| {
                    let s = state(0.5 * (y0 + y1), 10f64.powf(0.5 * (x0 + x1)))?;
                    Some(Exact::traction(&k, &s).0)
                })
                .collect()
        })
        .collect()
}

/// Force and torque error maps of law `L` (f64, per-contact form): two PNGs.
pub fn maps<L: FrictionLaw>(
    dir: &Path,
    exact: &[Vec<Option<Traction<f64>>>],
) -> Result<Maps, Box<dyn std::error::Error>>
where
    L::Prepared<f64>: 'static,
{
    maps_of(dir, exact, L::NAME, |k| {
        let p = L::prepare(k);
        Box::new(move |s| L::traction_prepared(&p, s).0)
    })
}

/// The maps of `best`'s per-step form (`Best::traction`, the flash table with e² interpolated:
/// what `VaryingContact` calls), named `best-varying`.
pub fn maps_per_step(
    dir: &Path,
    exact: &[Vec<Option<Traction<f64>>>],
) -> Result<Maps, Box<dyn std::error::Error>> {
    maps_of(dir, exact, "best-varying", |k| {
        let k = *k;
        Box::new(move |s| Best::traction(&k, s).0)
    })
}

type Law = Box<dyn Fn(&SlipState<f64>) -> Traction<f64>>;

/// Force and torque error maps of the law `build` makes per e² (f64): two PNGs.
fn maps_of(
    dir: &Path,
    exact: &[Vec<Option<Traction<f64>>>],
    name: &'static str,
    build: impl Fn(&Constants<f64>) -> Law,
) -> Result<Maps, Box<dyn std::error::Error>> {
    let mut force = Vec::new();
    let mut torque = Vec::new();
    let (mut fmax, mut tmax) = (0.0f64, 0.0f64);
    for (&e2, want) in MAP_E2.iter().zip(exact) {
        let law = build(&constants(e2));
        let mut fc = Vec::new();
        let mut tc = Vec::new();
        for ((x0, x1, y0, y1), want) in cells().into_iter().zip(want) {
            let (Some(s), Some(w)) = (state(0.5 * (y0 + y1), 10f64.powf(0.5 * (x0 + x1))), want)
            else {
                continue;
            };
            let (ef, et) = traction_error(&law(&s), w);
            fmax = fmax.max(ef);
            tmax = tmax.max(et);
            fc.push((x0, x1, y0, y1, ef));
            tc.push((x0, x1, y0, y1, et));
        }
        let title = format!("e² = {e2}");
        force.push(Panel {
            title: title.clone(),
            cells: fc,
        });
        torque.push(Panel { title, cells: tc });
    }
    let x = Axis {
        title: "u = v/(aω)",
        log: true,
    };
    let y = Axis {
        title: "ψ (rad)",
        log: false,
    };
    let mut files = Vec::new();
    for (what, unit, panels) in [
        ("force", "|ΔF|/(fN)", &force),
        ("torque", "|ΔT_z|/(fNa)", &torque),
    ] {
        let file = format!("friction-map-{name}-{what}.png");
        let title = format!("{name}: {what} error against the exact integrals (f64)");
        plot::heatmaps(&dir.join(&file), &title, x, y, unit, panels)?;
        files.push(file);
    }
    Ok(Maps {
        law: name,
        files,
        max_force: fmax,
        max_torque: tmax,
    })
}

/// e = 0.81 (e² = 0.6561), ψ = π/4: F_x, F_y, T_z against u for the exact integrals and
/// every law (f64, per-contact form), one PNG per component (the paper's Figs. 3.4–3.6).
pub fn curves(dir: &Path) -> Result<Vec<String>, Box<dyn std::error::Error>> {
    let k = constants(0.6561);
    let us: Vec<f64> = (0..=240)
        .map(|i| 10f64.powf(-2.0 + 4.0 * i as f64 / 240.0))
        .collect();
    fn law<L: FrictionLaw>(k: &Constants<f64>, us: &[f64]) -> (String, Vec<Traction<f64>>) {
        let p = L::prepare(k);
        let v = us
            .iter()
            .map(|&u| {
                state(FRAC_PI_4, u).map_or(Traction::default(), |s| L::traction_prepared(&p, &s).0)
            })
            .collect();
        (L::NAME.to_string(), v)
    }
    let all = [
        law::<Exact>(&k, &us),
        law::<Simplified>(&k, &us),
        law::<Pade>(&k, &us),
        law::<Ellipsoid>(&k, &us),
        law::<Coulomb>(&k, &us),
        law::<Best>(&k, &us),
    ];
    let mut files = Vec::new();
    type Component = (&'static str, &'static str, fn(&Traction<f64>) -> f64);
    let comps: [Component; 3] = [
        ("fx", "F_x/(fN)", |t| t.fx),
        ("fy", "F_y/(fN)", |t| t.fy),
        ("tz", "T_z/(fNa)", |t| t.tz),
    ];
    for (id, label, get) in comps {
        let series: Vec<plot::Series> = all
            .iter()
            .map(|(n, ts)| {
                (
                    n.clone(),
                    us.iter().zip(ts).map(|(&u, t)| (u, get(t))).collect(),
                )
            })
            .collect();
        let name = format!("friction-curve-{id}.png");
        plot::lines(
            &dir.join(&name),
            &format!("{label} at e = 0.81, ψ = π/4: exact integrals and every law (f64)"),
            Axis {
                title: "u = v/(aω)",
                log: true,
            },
            Axis {
                title: label,
                log: false,
            },
            &series,
            true,
        )?;
        files.push(name);
    }
    Ok(files)
}

/// The error maps of one law.
pub struct Maps {
    pub law: &'static str,
    pub files: Vec<String>,
    pub max_force: f64,
    pub max_torque: f64,
}

/// Error maps of the laws shown (one line each).
pub fn all_maps(dir: &Path) -> Result<Vec<Maps>, Box<dyn std::error::Error>> {
    let exact = exact_grid();
    Ok(vec![
        maps::<Best>(dir, &exact)?,
        maps_per_step(dir, &exact)?,
        maps::<Simplified>(dir, &exact)?,
        maps::<Pade>(dir, &exact)?,
        maps::<Ellipsoid>(dir, &exact)?,
        maps::<Coulomb>(dir, &exact)?,
    ])
}
