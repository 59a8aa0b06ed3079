//! `rolling`: a,b,G,nu,f,N,V,xi,eta,phi → Fx,Fy,Mz: Kalker's rolling contact
//! (`contensou::friction::rolling`). a along the rolling direction +x, b across (m), G (Pa),
//! ν, f, N (N), V (m/s), creepages ξ, η (dimensionless) and φ (1/m) of body B relative to A;
//! output F_x, F_y (N) and M_z (N·m, about the patch centre) on body B. The wrench depends on
//! V only through its sign (the creepages are given): V < 0 is the mirror image (rolling
//! towards −x), V = 0 is read as the limit V → 0⁺ at these creepages.
use std::fmt::LowerExp;
use std::process::ExitCode;

use contensou::Real;
use contensou::friction::rolling::{
    Blend, Elasticity, Fastsim, FastsimGrid, FullSlip, Linear, Patch, RollingContact, RollingLaw,
    RollingSlip, Table,
};

use crate::csv::{message, run_csv, shortest};
use crate::{Args, Model, Precision, list_models, run_model};

/// The laws, the default rolling law first.
pub const MODELS: &[Model] = &[
    Model {
        name: Table::NAME,
        about: "blend plus per-shape residual tables fitted to the exact steady-rolling reference",
        run: rows::<Table>,
    },
    Model {
        name: Blend::NAME,
        about: "Kalker's linear theory and the exact full slip (best) joined by a cubic saturation",
        run: rows::<Blend>,
    },
    Model {
        name: Fastsim::NAME,
        about: "FASTSIM (Kalker 1982), elliptic traction bound, 32 x 32 grid",
        run: rows::<Fastsim>,
    },
    Model {
        name: "fastsim-16",
        about: "FASTSIM on a 16 x 16 grid",
        run: rows::<FastsimGrid<16, 16>>,
    },
    Model {
        name: FullSlip::NAME,
        about: "full slip whatever the creepage (best: the Contensou-Erismann integrals)",
        run: rows::<FullSlip>,
    },
    Model {
        name: Linear::NAME,
        about: "Kalker's linear theory, unsaturated (a reference, not a friction law)",
        run: rows::<Linear>,
    },
];

/// The help text.
pub fn help() -> String {
    format!(
        "{}  a along the rolling direction (+x), creepages of body B relative to A, Fx,Fy,Mz on B;\n  V < 0 mirrors (rolling towards -x); V = 0 is the limit V -> 0+ at the given creepages\n",
        list_models("--law", MODELS)
    )
}

/// Run the subcommand, or say why the options are wrong.
pub fn run(args: Args) -> Result<ExitCode, String> {
    run_model(MODELS, &["--law"], args)
}

fn rows<L: RollingLaw>(precision: Precision) -> ExitCode {
    match precision {
        Precision::F32 => eval::<f32, L>(),
        Precision::F64 => eval::<f64, L>(),
    }
}

fn eval<T: Real + LowerExp, L: RollingLaw>() -> ExitCode {
    let inputs = ["a", "b", "G", "nu", "f", "N", "V", "xi", "eta", "phi"];
    run_csv::<T>(&inputs, &["Fx", "Fy", "Mz"], &mut |r| {
        let named = |i: usize, e| message(inputs[i], shortest(r[i]), e);
        // a NaN or ±∞ is named by its own column (the constructors below see some columns
        // only through others: a/b, the products of the creepages and V)
        if let Some(k) = r.iter().position(|x| !x.is_finite()) {
            return Err(named(k, contensou::Error::NonFinite(inputs[k])));
        }
        let el = Elasticity::new(r[2], r[3])
            .map_err(|e| named(if r[2] > T::ZERO { 3 } else { 2 }, e))?;
        let patch = Patch::new(r[0], r[1], r[5], r[4]).map_err(|e| named(patch_culprit(r), e))?;
        let contact = RollingContact::new(r[0] / r[1], el)
            .map_err(|e| message("a/b", shortest(r[0] / r[1]), e))?;
        let v = if r[6] == T::ZERO { T::ONE } else { r[6] };
        let slip = RollingSlip::from_creepages(r[7], r[8], r[9], v).map_err(|e| named(7, e))?;
        let w = contact.wrench::<L>(&patch, &slip);
        Ok(vec![w.fx, w.fy, w.mz])
    })
}

/// The first of a, b (≤ 0) or f (< 0) that `Patch::new` refuses.
fn patch_culprit<T: Real>(r: &[T]) -> usize {
    if r[0] <= T::ZERO {
        0
    } else if r[1] <= T::ZERO {
        1
    } else {
        4
    }
}
