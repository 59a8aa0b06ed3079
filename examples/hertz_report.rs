//! Regenerates `bench-results/hertz.md`: accuracy of every Hertz method against the mpmath
//! references (`tools/data/hertz_ref.csv`) and host ns per call from criterion.
//!
//! ```text
//! tools/qemu-bench.sh          # optional: refreshes bench-results/qemu.csv (M4F counts)
//! cargo bench --bench hertz
//! cargo run --release --example hertz_report > bench-results/hertz.md
//! ```
use contensou::Real;
use contensou::geometry::Curvatures;
use contensou::normal::{Fitted, Hertz, Modulus, NormalLaw, Patch, Volumetric};
use contensou::shape::{Eccentricity, HamrockDowson, Linear, Newton, Ratio, Shape, Table};

/// Inputs P, Q, E*, h and the reference c, m1, K, E, a, b, N.
struct Reference {
    input: [f64; 4],
    c: f64,
    m1: f64,
    k: f64,
    e: f64,
    abn: [f64; 3],
}

fn references() -> Vec<Reference> {
    let text = include_str!("../tools/data/hertz_ref.csv");
    let mut out = Vec::new();
    for line in text.lines().skip(1) {
        let v: Vec<f64> = line
            .split(',')
            .skip(1)
            .map(|f| f.parse().unwrap_or(f64::NAN))
            .collect();
        if v.len() == 14 {
            out.push(Reference {
                input: [v[0], v[1], v[2], v[3]],
                c: v[4],
                m1: v[5],
                k: v[6],
                e: v[7],
                abn: [v[10], v[11], v[12]],
            });
        }
    }
    out
}

fn rel(got: f64, want: f64) -> f64 {
    if want == 0.0 {
        got.abs()
    } else {
        ((got - want) / want).abs()
    }
}

/// Max errors: c absolute, c relative, m1 relative, K, E, a, b, N relative.
type Errors = [f64; 8];

fn accumulate(worst: &mut Errors, r: &Reference, shape: [f64; 4], patch: [f64; 3]) {
    let [c, m1, k, e] = shape;
    let errs = [
        (c - r.c).abs(),
        rel(c, r.c),
        rel(m1, r.m1),
        rel(k, r.k),
        rel(e, r.e),
        rel(patch[0], r.abn[0]),
        rel(patch[1], r.abn[1]),
        rel(patch[2], r.abn[2]),
    ];
    for (w, x) in worst.iter_mut().zip(errs) {
        *w = w.max(if x.is_nan() { f64::INFINITY } else { x });
    }
}

fn abn<T: Real>(p: &Patch<T>) -> [f64; 3] {
    [p.a.to_f64(), p.b.to_f64(), p.n.to_f64()]
}

fn method_errors<T: Real, M: Eccentricity>(refs: &[Reference]) -> Errors {
    let mut worst = [0.0; 8];
    for r in refs {
        let [p, q, estar, h] = r.input.map(T::from_f64);
        let (Ok(curv), Ok(estar)) = (Curvatures::new(p, q), Modulus::new(estar)) else {
            continue;
        };
        let (Ok(g), Ok(law)) = (Ratio::of(&curv), Hertz::new::<M>(&curv, estar)) else {
            continue;
        };
        let s: Shape<T> = if p == q { Shape::circle() } else { M::shape(g) };
        let i = s.integrals();
        let shape = [s.e2(), s.m1(), i.k, i.e].map(T::to_f64);
        accumulate(&mut worst, r, shape, abn(&law.patch(h)));
    }
    worst
}

fn law_errors<T: Real, L: NormalLaw<T>>(
    refs: &[Reference],
    build: impl Fn(&Curvatures<T>, Modulus<T>) -> Option<L>,
) -> Errors {
    let mut worst = [0.0; 8];
    for r in refs {
        let [p, q, estar, h] = r.input.map(T::from_f64);
        let (Ok(curv), Ok(estar)) = (Curvatures::new(p, q), Modulus::new(estar)) else {
            continue;
        };
        let Some(law) = build(&curv, estar) else {
            continue;
        };
        let patch = law.patch(h);
        let shape = [patch.e2.to_f64(), patch.m1.to_f64(), f64::NAN, f64::NAN];
        accumulate(&mut worst, r, shape, abn(&patch));
    }
    worst
}

fn row(name: &str, precision: &str, w: &Errors) {
    let cell = |x: f64| {
        if x.is_finite() {
            format!("{x:.1e}")
        } else {
            "—".to_string()
        }
    };
    let cells: Vec<String> = w.iter().map(|&x| cell(x)).collect();
    println!("| {name} | {precision} | {} |", cells.join(" | "));
}

fn errors_for<T: Real>(refs: &[Reference]) {
    let p = T::NAME;
    row("newton", p, &method_errors::<T, Newton>(refs));
    row("table", p, &method_errors::<T, Table>(refs));
    row("linear (paper G*)", p, &method_errors::<T, Linear>(refs));
    row(
        "hamrock-dowson",
        p,
        &method_errors::<T, HamrockDowson>(refs),
    );
    let fitted = law_errors::<T, _>(refs, |c, e| Fitted::new(c, e).ok());
    row("fitted (eccentricity-free)", p, &fitted);
    let vol = law_errors::<T, _>(refs, |c, e| Some(Volumetric::new(c, e)));
    row("volumetric (R_e)", p, &vol);
}

fn criterion_ns(id: &str) -> String {
    let path = format!(
        "target/criterion/{}/new/estimates.json",
        id.replace('/', "_")
    );
    let Ok(text) = std::fs::read_to_string(&path) else {
        return "not run".to_string();
    };
    // {"mean":{"confidence_interval":{...},"point_estimate":X,...
    let estimate = text
        .split_once("\"mean\"")
        .and_then(|(_, rest)| rest.split_once("\"point_estimate\":"))
        .and_then(|(_, rest)| rest.split([',', '}']).next())
        .and_then(|x| x.parse::<f64>().ok());
    estimate.map_or("unreadable".to_string(), |ns| format!("{ns:.1}"))
}

fn main() {
    let refs = references();
    println!("# Hertz normal contact: accuracy and host cost\n");
    println!(
        "Regenerate: `cargo bench --bench hertz && cargo run --release --example hertz_report > bench-results/hertz.md` \
         (the M4F table reads `bench-results/qemu.csv`, written by `tools/qemu-bench.sh`).\n"
    );
    println!(
        "## Accuracy\n\nMax error over the {} reference rows of `tools/data/hertz_ref.csv` (mpmath, dps 40; \
         g = P/Q ∈ [1e-4, 1]: sphere–plane, 209 bearing inner/outer, log grid, 150 random cases). \
         c abs = absolute error on c = e²; every other column relative. a, b, N at equal approach h. \
         K, E: not produced by the fitted and volumetric laws.\n",
        refs.len()
    );
    println!("| method | precision | c abs | c rel | m₁ rel | K | E | a | b | N |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    errors_for::<f64>(&refs);
    errors_for::<f32>(&refs);

    println!("\n## Volumetric law: force error vs exact Hertz at equal h\n");
    println!("N_vol/N_Hertz − 1 with the Gaussian radius R_e = 1/(2√(PQ)) (f64):\n");
    println!("| g = P/Q | Q/P | error |");
    println!("|---|---|---|");
    for r in refs.iter().filter(|r| r.input[1] == 1.0) {
        let [p, q, estar, h] = r.input;
        let g = p / q;
        if !(0.999e-3..=0.995).contains(&g) {
            continue;
        }
        let (Ok(curv), Ok(estar)) = (Curvatures::new(p, q), Modulus::new(estar)) else {
            continue;
        };
        let n = Volumetric::new(&curv, estar).patch(h).n;
        println!(
            "| {g:.4} | {:.1} | {:+.2}% |",
            1.0 / g,
            100.0 * (n / r.abn[2] - 1.0)
        );
    }

    println!("\n## Table size\n");
    println!(
        "`shape::Table`: 32 cells × 3 quantities × degree 5: {} bytes (f32), {} bytes (f64).\n",
        Table::bytes::<f32>(),
        Table::bytes::<f64>()
    );

    println!("## Host cost (criterion, mean ns per call; loaded shared 2-core machine, ±30%)\n");
    println!("| benchmark | what | f32 | f64 |");
    println!("|---|---|---|---|");
    for (id, what) in [
        ("hertz/per_step", "a, b, N, p0 from h, geometry precomputed"),
        (
            "hertz/table_each_step",
            "c, K, E by table from g, then a, b, N, p0",
        ),
        (
            "hertz/fitted_each_step",
            "fitted law from g, then a, b, N, p0",
        ),
        ("hertz/shape_newton", "construction: exact c, K, E, B, D"),
        ("hertz/shape_table", "c, K, E, B, D by table"),
        ("hertz/shape_linear", "construction: paper G* + AGM"),
        ("hertz/shape_hamrock-dowson", "construction: g^{4/π} + AGM"),
    ] {
        println!(
            "| `{id}` | {what} | {} | {} |",
            criterion_ns(&format!("{id}/f32")),
            criterion_ns(&format!("{id}/f64"))
        );
    }

    println!("\n## M4F instructions per call (QEMU, `tools/qemu-bench.sh`)\n");
    println!(
        "Stage `hertz` of `bench-results/qemu.csv` (includes the rig's 8-instruction call floor):\n"
    );
    println!("| method | precision | instructions |");
    println!("|---|---|---|");
    let csv = std::fs::read_to_string("bench-results/qemu.csv").unwrap_or_default();
    for line in csv.lines().filter(|l| l.starts_with("hertz,")) {
        let f: Vec<&str> = line.split(',').collect();
        if let [_, method, precision, insns] = f[..] {
            println!("| `{method}` | {precision} | {insns} |");
        }
    }
}
