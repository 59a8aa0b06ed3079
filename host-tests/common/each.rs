//! `each!(f, [T…], [L…])`: calls `f::<T, L>()` for every precision `T` and law `L` listed;
//! `each!(f, [T…])`: `f::<T>()` for every precision listed
//! (a test crate includes it with `#[macro_use] #[path = "common/each.rs"] mod each;`).

/// `f::<T, L>()` for each `T` in the first list and, within it, each `L` in the second; without
/// a second list, `f::<T>()`.
macro_rules! each {
    ($f:ident, [$($t:ty),*], $laws:tt) => {
        $(each!(@laws $f, $t, $laws);)*
    };
    ($f:ident, [$($t:ty),*]) => {
        $($f::<$t>();)*
    };
    (@laws $f:ident, $t:ty, [$($l:ty),*]) => {
        $($f::<$t, $l>();)*
    };
}
