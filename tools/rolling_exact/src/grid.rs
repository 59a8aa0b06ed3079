//! The discretised Hertz ellipse: `m` strips along y, each cut into `n` equal elements that
//! exactly cover the strip's chord, plus one "ghost" point per strip just upstream of its
//! leading edge (where the displacement is needed by the upwind derivative, traction zero).
//!
//! **Skewed patch.** An ellipse with semi-axes (a₀, b₀) whose a₀ axis is turned by θ from the
//! rolling direction x is the set A x² + 2B xy + C y² ≤ 1, A = cos²θ/a₀² + sin²θ/b₀²,
//! B = sinθ cosθ (1/a₀² − 1/b₀²), C = sin²θ/a₀² + cos²θ/b₀², and since AC − B² = 1/(a₀b₀)²,
//! A x² + 2B xy + C y² = (x − s y)²/a² + y²/b² with a = 1/√A, b = a₀b₀√A, s = −B/A: the
//! aligned ellipse (a, b) (a along x: the patch's extent along the rolling direction) sheared
//! along x by x → x + s y. The strips along x stay strips; each is shifted by s·y_j, and the
//! Hertz pressure p₀√(1 − (x − s y)²/a² − y²/b²) is the aligned one carried along, so the
//! grid is the aligned grid with every element and ghost moved by s·y_j ([`Grid::sheared`];
//! s = 0 is [`Grid::new`] exactly).

/// One rectangular element with piecewise-constant traction.
#[derive(Clone, Copy, Debug)]
pub struct Element {
    /// Centre.
    pub x: f64,
    pub y: f64,
    /// Half widths.
    pub hx: f64,
    pub hy: f64,
    /// Traction bound f·p averaged over the element (exact in x at the strip's centre line).
    pub bound: f64,
}

/// The element grid of one (a, b) ellipse (sheared by s: see the module docs).
#[derive(Clone, Debug)]
pub struct Grid {
    /// Strips (along y) and elements per strip (along x).
    pub m: usize,
    pub n: usize,
    pub a: f64,
    pub b: f64,
    /// `m·n` elements, strip-major: element (j, i) at `j·n + i`, i = 0 at the trailing edge −a_j.
    pub elements: Vec<Element>,
    /// Per strip: the ghost point upstream of the leading edge, x = a_j + dx_j/2.
    pub ghosts: Vec<(f64, f64)>,
}

impl Grid {
    /// `m` strips of width 2b/m, `n` elements per strip; the traction bound is f·p with the
    /// Hertz pressure p = p0 √(1 − x²/a² − y²/b²) whose p0 is set so that the discrete total
    /// Σ bound·area equals f·N exactly (`f_n` = f·N).
    pub fn new(a: f64, b: f64, m: usize, n: usize, f_n: f64) -> Self {
        Self::sheared(a, b, 0.0, m, n, f_n)
    }

    /// The ellipse (x − s·y)²/a² + y²/b² ≤ 1 (see the module docs): [`Grid::new`]'s grid with
    /// strip j moved along x by s·y_j.
    pub fn sheared(a: f64, b: f64, s: f64, m: usize, n: usize, f_n: f64) -> Self {
        let dy = 2.0 * b / m as f64;
        let mut elements = Vec::with_capacity(m * n);
        let mut ghosts = Vec::with_capacity(m);
        // ∫ √(A² − x²) dx, clamped to the chord.
        let h = |x: f64, big_a: f64| {
            let x = x.clamp(-big_a, big_a);
            0.5 * (x * (big_a * big_a - x * x).max(0.0).sqrt() + big_a * big_a * (x / big_a).asin())
        };
        let mut total = 0.0;
        for j in 0..m {
            let y = -b + (j as f64 + 0.5) * dy;
            let aj = a * (1.0 - (y / b).powi(2)).sqrt();
            let dx = 2.0 * aj / n as f64;
            for i in 0..n {
                let x0 = -aj + i as f64 * dx;
                // mean of √(a_j² − x²)/a over the element; p0 applied below
                let mean = (h(x0 + dx, aj) - h(x0, aj)) / (dx * a);
                elements.push(Element {
                    x: x0 + 0.5 * dx + s * y,
                    y,
                    hx: 0.5 * dx,
                    hy: 0.5 * dy,
                    bound: mean,
                });
                total += mean * dx * dy;
            }
            ghosts.push((aj + 0.5 * dx + s * y, y));
        }
        let p0 = f_n / total;
        for e in &mut elements {
            e.bound *= p0;
        }
        Grid {
            m,
            n,
            a,
            b,
            elements,
            ghosts,
        }
    }

    pub fn len(&self) -> usize {
        self.elements.len()
    }

    pub fn is_empty(&self) -> bool {
        self.elements.is_empty()
    }

    /// Index of the point upstream (+x) of element `k`: an element, or `len() + j` for strip j's ghost.
    pub fn upstream(&self, k: usize) -> usize {
        let (j, i) = (k / self.n, k % self.n);
        if i + 1 < self.n {
            k + 1
        } else {
            self.len() + j
        }
    }

    /// Coordinates of point `p` (element centre or ghost).
    pub fn point(&self, p: usize) -> (f64, f64) {
        if p < self.len() {
            (self.elements[p].x, self.elements[p].y)
        } else {
            self.ghosts[p - self.len()]
        }
    }
}
