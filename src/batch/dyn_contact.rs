//! The batch path of [`DynContact`]: [`DynContact::wrench_many`] (the law's column kernels)
//! and [`DynContact::wrench_many_rolling`] (a scalar loop), here so that the batch module
//! depends on [`crate::dynamic`] and not the other way round.

use super::{BatchReal, RowError, Steps, Wrenches, put};
use crate::Error;
use crate::dynamic::{ByLaw, DynContact, Formed, RollingStep, RollingSteps, Step};

impl<T: BatchReal> DynContact<T> {
    /// [`DynContact::wrench`] over columns ([`crate::batch`]): row i of `out` is bit for bit
    /// `self.wrench(&Step { h: h[i], … })`, several rows per instruction. A varying contact
    /// evaluates every row at its current curvatures (as [`DynContact::wrench`] does).
    /// Errors: the first rejected row, its column and the error as [`DynContact::wrench`]
    /// reports them (rows before it written), or [`Error::ColumnLengthMismatch`].
    pub fn wrench_many(
        &self,
        steps: &Steps<'_, T>,
        out: &mut Wrenches<'_, T>,
    ) -> Result<(), RowError> {
        macro_rules! many {
            ($formed:expr) => {
                match $formed {
                    Formed::Fixed(c) => c.wrench_many(steps, out),
                    Formed::Varying(c) => c.wrench_many_at(&self.curvatures, steps, out),
                }
            };
        }
        match &self.contact {
            ByLaw::Best(x) => many!(x),
            ByLaw::Simplified(x) => many!(x),
            ByLaw::Pade(x) => many!(x),
            ByLaw::Ellipsoid(x) => many!(x),
            ByLaw::Coulomb(x) => many!(x),
            ByLaw::Table(_) | ByLaw::Blend(_) | ByLaw::Fastsim(_) | ByLaw::Fastsim16(_) => {
                self.rows(steps, None, out)
            }
        }
    }

    /// [`DynContact::wrench_many`] with the rolling columns `vrx, vry` ([`RollingSteps`]):
    /// row i is bit for bit `self.wrench_rolling(&Step { h: h[i], … }, &RollingStep { vrx:
    /// vrx[i], vry: vry[i] })`. A scalar loop over the rows for every law (the sliding laws
    /// ignore the rolling columns but their lengths are checked). Errors as
    /// [`DynContact::wrench_many`] (`vrx`, `vry` named too).
    pub fn wrench_many_rolling(
        &self,
        steps: &Steps<'_, T>,
        rolling: &RollingSteps<'_, T>,
        out: &mut Wrenches<'_, T>,
    ) -> Result<(), RowError> {
        self.rows(steps, Some(rolling), out)
    }

    /// The scalar loop: one [`DynContact::wrench_rolling`] per row.
    fn rows(
        &self,
        steps: &Steps<'_, T>,
        rolling: Option<&RollingSteps<'_, T>>,
        out: &mut Wrenches<'_, T>,
    ) -> Result<(), RowError> {
        let n = steps.h.len();
        let empty: &[T] = &[];
        let (vrx, vry) = rolling.map_or((empty, empty), |r| (r.vrx, r.vry));
        let lengths = [
            ("hdot", steps.hdot.len()),
            ("vx", steps.vx.len()),
            ("vy", steps.vy.len()),
            ("omega", steps.omega.len()),
            ("vrx", if rolling.is_some() { vrx.len() } else { n }),
            ("vry", if rolling.is_some() { vry.len() } else { n }),
            ("N", out.n.len()),
            ("Fx", out.fx.len()),
            ("Fy", out.fy.len()),
            ("Tz", out.tz.len()),
            ("a", out.a.len()),
            ("b", out.b.len()),
            ("e2", out.e2.len()),
        ];
        for (column, len) in lengths {
            if len != n {
                return Err(RowError {
                    row: len.min(n),
                    column,
                    error: Error::ColumnLengthMismatch,
                });
            }
        }
        let get = |c: &[T], i: usize| c.get(i).copied().unwrap_or(T::ZERO);
        for i in 0..n {
            let step = Step {
                h: get(steps.h, i),
                hdot: get(steps.hdot, i),
                vx: get(steps.vx, i),
                vy: get(steps.vy, i),
                omega: get(steps.omega, i),
            };
            let roll = rolling.map_or(RollingStep::default(), |r| RollingStep {
                vrx: get(r.vrx, i),
                vry: get(r.vry, i),
            });
            let o = self.wrench_rolling(&step, &roll).map_err(|e| RowError {
                row: i,
                column: e.column,
                error: e.error,
            })?;
            put(out, i, o);
        }
        Ok(())
    }
}
