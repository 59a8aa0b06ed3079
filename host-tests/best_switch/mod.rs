//! Shared by the `best` tests: the jump of a traction across its inside/outside switch; the
//! thin-end ψ × u grid and its error fold.

use contensou::Real;
use contensou::friction::Traction;
use contensou::friction::best::Branch;

/// Bisects the inside/outside switch of `at` along u ∈ [1e-4, 1.5] (inside at 1e-4, outside
/// at 1.5, asserted) down to adjacent floats (`next_up`, asserted), and returns the largest
/// component of |traction(outside) − traction(inside)| there.
pub fn switch_jump<T: Real>(
    at: impl Fn(T) -> (Traction<T>, Branch),
    next_up: impl Fn(T) -> T,
) -> f64 {
    let (mut lo, mut hi) = (T::from_f64(1e-4), T::from_f64(1.5));
    assert_eq!(at(lo).1, Branch::Inside);
    assert_eq!(at(hi).1, Branch::Outside);
    for _ in 0..200 {
        let mid = T::HALF * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if at(mid).1 == Branch::Inside {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    assert!(next_up(lo) >= hi);
    let (a, c) = (at(lo).0, at(hi).0);
    let d = |p: T, q: T| (p.to_f64() - q.to_f64()).abs();
    d(a.fx, c.fx).max(d(a.fy, c.fy)).max(d(a.tz, c.tz))
}

/// The thin-end grid: ψ = 0.001 + 0.0524·i (i < 30) × u = 10^(−3 + 6j/80) (j < 80).
pub fn thin_grid() -> impl Iterator<Item = (f64, f64)> {
    (0..30).flat_map(|i| {
        let psi = 0.001 + i as f64 * 0.0524;
        (0..80).map(move |j| (psi, 10f64.powf(-3.0 + 6.0 * j as f64 / 80.0)))
    })
}

/// Folds the error of `t` against the reference `r` into `e` = (largest |ΔF_x|, |ΔF_y|;
/// largest |ΔT_z|).
pub fn worst<T: Real>(e: &mut (f64, f64), t: &Traction<T>, r: &Traction<f64>) {
    let d = |p: T, q: f64| (p.to_f64() - q).abs();
    e.0 = e.0.max(d(t.fx, r.fx).max(d(t.fy, r.fy)));
    e.1 = e.1.max(d(t.tz, r.tz));
}
