// The rows of the batch benchmarks (benches/batch.rs, examples/batch_scaling.rs; `include!`d):
// the contract's contact columns P = 40, Q in 60…120 1/m, rows in contact (h 1e-7…1e-5 m),
// mixed slips (inside and outside `best`'s ellipse), 20 % without spin.

include!("xorshift.rs");

/// Columns P, Q, h, hdot, vx, vy, omega (a fixed pseudo-random set).
fn columns<T: Real>(rows: usize) -> [Vec<T>; 7] {
    let mut unit = xorshift64(0x2545_f491_4f6c_dd1d);
    let mut cols: [Vec<T>; 7] = Default::default();
    for _ in 0..rows {
        let sign = |u: f64| if u < 0.5 { -1.0 } else { 1.0 };
        let row = [
            40.0,
            60.0 + 60.0 * unit(),
            10f64.powf(-7.0 + 2.0 * unit()),
            1e-3 * (unit() - 0.5),
            sign(unit()) * 10f64.powf(-5.0 + 3.0 * unit()),
            sign(unit()) * 10f64.powf(-5.0 + 3.0 * unit()),
            if unit() < 0.2 {
                0.0
            } else {
                sign(unit()) * 10f64.powf(3.0 * unit())
            },
        ];
        for (c, v) in cols.iter_mut().zip(row) {
            c.push(T::from_f64(v));
        }
    }
    cols
}
