//! criterion: the exact friction integrals (reference path) per precision; ψ = 0.7, so u = 0.3
//! is inside the ellipse at e² = 0.687 and outside at e² = 0.99.
use contensou::elliptic::Parameter;
use contensou::friction::exact::traction;
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("friction_exact");
    let p64 = Parameter::new(0.687f64).unwrap();
    let p32 = Parameter::new(0.687f32).unwrap();
    let thin = Parameter::new(0.99f64).unwrap();
    let psi = 0.7f64;
    for (name, u) in [("u0.3", 0.3), ("u1.5", 1.5), ("u30", 30.0)] {
        let (vx, vy) = (u * psi.cos(), u * psi.sin());
        g.bench_function(format!("f64/{name}"), |b| {
            b.iter(|| traction(black_box(p64), black_box(vx), black_box(vy), black_box(1.0)))
        });
        g.bench_function(format!("f64_e2_0.99/{name}"), |b| {
            b.iter(|| {
                traction(
                    black_box(thin),
                    black_box(vx),
                    black_box(vy),
                    black_box(1.0),
                )
            })
        });
        let (vx, vy) = (vx as f32, vy as f32);
        g.bench_function(format!("f32/{name}"), |b| {
            b.iter(|| traction(black_box(p32), black_box(vx), black_box(vy), black_box(1.0)))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
