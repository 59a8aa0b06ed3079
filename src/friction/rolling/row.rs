//! `row`: the rolling contract row by row — the columns `a,b,G,nu,f,N,V,xi,eta,phi` to
//! `Fx,Fy,Mz` with the law chosen at run time, the one evaluator that `contact_eval rolling`,
//! the C API (`contensou_rolling_*`) and the Python package (`contensou.rolling`,
//! `contensou.RollingContact`) call, so that they validate alike and give the same bits.
//!
//! The contract:
//! - **Columns**: semi-axes a (along the rolling direction +x) and b (m), the elasticity G (Pa)
//!   and ν, the friction coefficient f, the normal force N (N), the rolling velocity V (m/s)
//!   and the creepages ξ, η (dimensionless) and φ (1/m) of body B relative to A ([`COLUMNS`]);
//!   out F_x, F_y (N) and M_z (N·m, about the patch centre) on body B ([`OUTPUTS`]).
//! - **The V = 0 rule**: the wrench depends on V only through its sign (the creepages are
//!   given): V < 0 is the mirror image (rolling towards −x), V = 0 is read as the limit
//!   V → 0⁺ at the given creepages.
//! - **The column named in an error** ([`Rejected`]): a NaN or ±∞ is named by its own column,
//!   the first in column order (the constructors see some columns only through others: a/b,
//!   the products of the creepages and V); then, in this order, G or ν
//!   ([`Elasticity::new`]), the first of a, b (≤ 0) or f (< 0) ([`Patch::new`]), the shape
//!   a/b ([`RollingContact::new`], [`Column::AOverB`]) and the creepage whose product with V
//!   overflows ([`RollingSlip::from_creepages`]).
//!
//! Two ways in: [`Rows`], a whole row at a time (the contact rebuilt only when a/b, G or ν
//! change), and [`RowContact`], the contact built once from (a/b, G, ν) and the per-call
//! columns ([`RowState`]) — the same validation, split where the columns are given.
//!
//! ```
//! use contensou::friction::rolling::row::{Column, RowLaw, Rows};
//!
//! let mut rows = Rows::<f64>::new(RowLaw::Table);
//! //        a     b     G     nu   f    N     V     xi    eta  phi
//! let w = rows.eval(&[6e-3, 4e-3, 80e9, 0.28, 0.3, 80e3, 30.0, 1e-3, 0.0, 0.0])?;
//! assert!(w.fx < 0.0 && w.fx.abs() <= 0.3 * 80e3);
//! let bad = rows.eval(&[6e-3, 4e-3, 80e9, 0.28, -0.3, 80e3, 30.0, 1e-3, 0.0, 0.0]);
//! assert_eq!(bad.unwrap_err().column, Column::F);
//! # Ok::<(), contensou::friction::rolling::row::Rejected<f64>>(())
//! ```

use core::fmt;

use super::{
    Blend, Elasticity, Fastsim, FastsimGrid, FullSlip, Linear, Patch, RollingContact, RollingLaw,
    RollingSlip, Table, Wrench,
};
use crate::{Error, Real};

/// The input columns, in order.
pub const COLUMNS: [&str; 10] = ["a", "b", "G", "nu", "f", "N", "V", "xi", "eta", "phi"];
/// The output columns.
pub const OUTPUTS: [&str; 3] = ["Fx", "Fy", "Mz"];

/// An input column ([`COLUMNS`], in order) or the shape a/b: where an error came from. The
/// discriminants are the C API's `contensou_rolling_column` values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u32)]
pub enum Column {
    /// `a`.
    A = 0,
    /// `b`.
    B,
    /// `G`.
    G,
    /// `nu`.
    Nu,
    /// `f`.
    F,
    /// `N`.
    N,
    /// `V`.
    V,
    /// `xi`.
    Xi,
    /// `eta`.
    Eta,
    /// `phi`.
    Phi,
    /// `a/b`: the shape (a column of neither the row nor the state, a ratio of two).
    AOverB,
}

impl Column {
    /// The input columns in [`COLUMNS`] order.
    pub const INPUTS: [Column; 10] = [
        Column::A,
        Column::B,
        Column::G,
        Column::Nu,
        Column::F,
        Column::N,
        Column::V,
        Column::Xi,
        Column::Eta,
        Column::Phi,
    ];

    /// The column's name (`"a/b"` for the shape).
    pub const fn name(self) -> &'static str {
        match self {
            Column::AOverB => "a/b",
            c => COLUMNS[c as usize],
        }
    }
}

/// A refused row: the column to blame, its value (a/b for the shape) and the reason.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rejected<T> {
    /// The column.
    pub column: Column,
    /// Its value in the row.
    pub value: T,
    /// Why.
    pub error: Error,
}

impl<T: fmt::Display> fmt::Display for Rejected<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} = {}: {}",
            self.column.name(),
            self.value,
            self.error.as_str()
        )
    }
}

impl<T: fmt::Debug + fmt::Display> core::error::Error for Rejected<T> {}

/// The rolling laws by name at run time, the default first (the names of
/// `contact_eval rolling --law`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RowLaw {
    /// [`Table`] (the default, [`RowLaw::DEFAULT`]).
    Table,
    /// [`Blend`].
    Blend,
    /// [`Fastsim`] (32 × 32).
    Fastsim,
    /// [`FastsimGrid<16, 16>`].
    Fastsim16,
    /// [`FullSlip`].
    FullSlip,
    /// [`Linear`].
    Linear,
}

impl Default for RowLaw {
    /// [`RowLaw::DEFAULT`].
    fn default() -> Self {
        Self::DEFAULT
    }
}

impl RowLaw {
    /// Every law, the default first.
    pub const ALL: [RowLaw; 6] = [
        RowLaw::Table,
        RowLaw::Blend,
        RowLaw::Fastsim,
        RowLaw::Fastsim16,
        RowLaw::FullSlip,
        RowLaw::Linear,
    ];

    /// The law's name.
    pub const fn name(self) -> &'static str {
        match self {
            RowLaw::Table => Table::NAME,
            RowLaw::Blend => Blend::NAME,
            RowLaw::Fastsim => Fastsim::NAME,
            RowLaw::Fastsim16 => "fastsim-16",
            RowLaw::FullSlip => FullSlip::NAME,
            RowLaw::Linear => Linear::NAME,
        }
    }

    /// The default rolling law: what [`RowLaw::ALIAS`] (`"rolling"`) names in every shell
    /// (`contact_eval wrench`/`rolling --law rolling`, the C API's `contensou_law_from_name`,
    /// Python's `law="rolling"`). The one place where the default is chosen.
    pub const DEFAULT: RowLaw = RowLaw::Table;

    /// The name that stands for [`RowLaw::DEFAULT`], whatever its method is called.
    pub const ALIAS: &'static str = "rolling";

    /// `name` with the alias [`RowLaw::ALIAS`] replaced by the default law's own name
    /// ([`RowLaw::DEFAULT`]); any other string unchanged. Every shell's law lookup
    /// ([`RowLaw::from_name`], [`crate::dynamic::Law::from_name`]) goes through it.
    pub fn resolve(name: &str) -> &str {
        if name == Self::ALIAS {
            Self::DEFAULT.name()
        } else {
            name
        }
    }

    /// The law called `name` (or [`RowLaw::DEFAULT`] for [`RowLaw::ALIAS`]), if any.
    pub fn from_name(name: &str) -> Option<Self> {
        let name = Self::resolve(name);
        Self::ALL.into_iter().find(|l| l.name() == name)
    }

    /// One line on the law (`contact_eval rolling --help`).
    pub const fn about(self) -> &'static str {
        match self {
            RowLaw::Table => {
                "blend plus per-shape residual tables fitted to the exact steady-rolling reference"
            }
            RowLaw::Blend => {
                "Kalker's linear theory and the exact full slip (best) joined by a cubic saturation"
            }
            RowLaw::Fastsim => "FASTSIM (Kalker 1982), elliptic traction bound, 32 x 32 grid",
            RowLaw::Fastsim16 => "FASTSIM on a 16 x 16 grid",
            RowLaw::FullSlip => {
                "full slip whatever the creepage (best: the Contensou-Erismann integrals)"
            }
            RowLaw::Linear => {
                "Kalker's linear theory, unsaturated (a reference, not a friction law)"
            }
        }
    }

    /// `contact.wrench::<L>(patch, slip)` for this law.
    pub fn wrench<T: Real>(
        self,
        contact: &RollingContact<T>,
        patch: &Patch<T>,
        slip: &RollingSlip<T>,
    ) -> Wrench<T> {
        fn by<T: Real, L: RollingLaw>(
            c: &RollingContact<T>,
            p: &Patch<T>,
            s: &RollingSlip<T>,
        ) -> Wrench<T> {
            c.wrench::<L>(p, s)
        }
        match self {
            RowLaw::Table => by::<T, Table>(contact, patch, slip),
            RowLaw::Blend => by::<T, Blend>(contact, patch, slip),
            RowLaw::Fastsim => by::<T, Fastsim>(contact, patch, slip),
            RowLaw::Fastsim16 => by::<T, FastsimGrid<16, 16>>(contact, patch, slip),
            RowLaw::FullSlip => by::<T, FullSlip>(contact, patch, slip),
            RowLaw::Linear => by::<T, Linear>(contact, patch, slip),
        }
    }
}

/// The per-call columns of a [`RowContact`]: `a,b,f,N,V,xi,eta,phi` (its G, ν and the shape
/// a/b are the contact's; a and b set the patch size c = √(ab)).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RowState<T> {
    /// a (m), > 0: sets c = √(ab) with b.
    pub a: T,
    /// b (m), > 0.
    pub b: T,
    /// f ≥ 0.
    pub f: T,
    /// N (N); N ≤ 0 gives a zero wrench.
    pub n: T,
    /// V (m/s), by its sign only.
    pub v: T,
    /// ξ.
    pub xi: T,
    /// η.
    pub eta: T,
    /// φ (1/m).
    pub phi: T,
}

impl<T: Real> RowState<T> {
    /// The per-call columns of a whole row ([`COLUMNS`] order).
    pub fn of_row(r: &[T; 10]) -> Self {
        let [a, b, _, _, f, n, v, xi, eta, phi] = *r;
        Self {
            a,
            b,
            f,
            n,
            v,
            xi,
            eta,
            phi,
        }
    }

    /// The columns with their [`Column`]s, in column order.
    fn columns(&self) -> [(Column, T); 8] {
        [
            (Column::A, self.a),
            (Column::B, self.b),
            (Column::F, self.f),
            (Column::N, self.n),
            (Column::V, self.v),
            (Column::Xi, self.xi),
            (Column::Eta, self.eta),
            (Column::Phi, self.phi),
        ]
    }

    /// The patch (a, b, N, f), the first of a, b (≤ 0) or f (< 0) blamed.
    fn patch(&self) -> Result<Patch<T>, Rejected<T>> {
        Patch::new(self.a, self.b, self.n, self.f).map_err(|error| {
            let (column, value) = if self.a <= T::ZERO {
                (Column::A, self.a)
            } else if self.b <= T::ZERO {
                (Column::B, self.b)
            } else {
                (Column::F, self.f)
            };
            Rejected {
                column,
                value,
                error,
            }
        })
    }

    /// The slip at the creepages, V = 0 read as the limit V → 0⁺; a product with V that
    /// overflows blames its creepage.
    fn slip(&self) -> Result<RollingSlip<T>, Rejected<T>> {
        let v = if self.v == T::ZERO { T::ONE } else { self.v };
        RollingSlip::from_creepages(self.xi, self.eta, self.phi, v).map_err(|error| {
            let (column, value) = match error {
                Error::NonFinite("v_y") => (Column::Eta, self.eta),
                Error::NonFinite("omega") => (Column::Phi, self.phi),
                _ => (Column::Xi, self.xi),
            };
            Rejected {
                column,
                value,
                error,
            }
        })
    }
}

/// The first non-finite of `columns`, as a [`Rejected`] naming it.
fn first_non_finite<T: Real>(columns: &[(Column, T)]) -> Result<(), Rejected<T>> {
    match columns.iter().find(|(_, x)| !x.is_finite()) {
        Some(&(column, value)) => Err(Rejected {
            column,
            value,
            error: Error::NonFinite(column.name()),
        }),
        None => Ok(()),
    }
}

/// The elasticity (G, ν): ν blamed when G is positive, else G.
fn elasticity<T: Real>(g: T, nu: T) -> Result<Elasticity<T>, Rejected<T>> {
    Elasticity::new(g, nu).map_err(|error| {
        let (column, value) = match error {
            Error::NonFinite("G") => (Column::G, g),
            Error::NonFinite(_) => (Column::Nu, nu),
            _ if g > T::ZERO => (Column::Nu, nu),
            _ => (Column::G, g),
        };
        Rejected {
            column,
            value,
            error,
        }
    })
}

/// The contact of shape `a_over_b`.
fn contact<T: Real>(a_over_b: T, el: Elasticity<T>) -> Result<RollingContact<T>, Rejected<T>> {
    RollingContact::new(a_over_b, el).map_err(|error| Rejected {
        column: Column::AOverB,
        value: a_over_b,
        error,
    })
}

/// A rolling contact built once from the shape a/b, G, ν and the law; the per-call columns
/// in a [`RowState`]. What `contensou_rolling_new_*` / `contensou_rolling_wrench_*` in C and
/// `contensou.RollingContact` in Python hold.
#[derive(Clone, Debug)]
pub struct RowContact<T: Real> {
    contact: RollingContact<T>,
    law: RowLaw,
}

impl<T: Real> RowContact<T> {
    /// Validates G, ν (a NaN or ±∞ first, G before ν), then a/b ∈ [0.01, 100].
    pub fn new(a_over_b: T, g: T, nu: T, law: RowLaw) -> Result<Self, Rejected<T>> {
        let el = elasticity(g, nu)?;
        Ok(Self {
            contact: contact(a_over_b, el)?,
            law,
        })
    }

    /// The wrench for the per-call columns, validated in column order (see the
    /// [module docs](self)); bit for bit [`Rows::eval`] on the same row with a/b = a / b.
    pub fn wrench(&self, s: &RowState<T>) -> Result<Wrench<T>, Rejected<T>> {
        first_non_finite(&s.columns())?;
        let patch = s.patch()?;
        let slip = s.slip()?;
        Ok(self.law.wrench(&self.contact, &patch, &slip))
    }

    /// The law.
    pub fn law(&self) -> RowLaw {
        self.law
    }

    /// The contact.
    pub fn contact(&self) -> &RollingContact<T> {
        &self.contact
    }
}

/// Whole rows ([`COLUMNS`]) by one law: a contact per row, the last one reused while a/b, G
/// and ν repeat bit for bit (building one costs the shape's tables).
#[derive(Clone, Debug)]
pub struct Rows<T: Real> {
    law: RowLaw,
    /// The last contact and the bits of its (a/b, G, ν).
    last: Option<([u64; 3], RowContact<T>)>,
}

impl<T: Real> Rows<T> {
    /// No contact yet.
    pub fn new(law: RowLaw) -> Self {
        Self { law, last: None }
    }

    /// The wrench of row `r`, or the column to blame (see the [module docs](self)).
    pub fn eval(&mut self, r: &[T; 10]) -> Result<Wrench<T>, Rejected<T>> {
        let columns: [(Column, T); 10] = core::array::from_fn(|k| (Column::INPUTS[k], r[k]));
        first_non_finite(&columns)?;
        let [a, b, g, nu, ..] = *r;
        let el = elasticity(g, nu)?;
        let state = RowState::of_row(r);
        state.patch()?;
        let ratio = a / b;
        let key = [ratio, g, nu].map(|x| x.to_f64().to_bits());
        let built = match &mut self.last {
            Some((k, c)) if *k == key => c,
            last => {
                let c = RowContact {
                    contact: contact(ratio, el)?,
                    law: self.law,
                };
                &mut last.insert((key, c)).1
            }
        };
        built.wrench(&state)
    }
}
