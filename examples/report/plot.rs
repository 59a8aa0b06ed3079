//! Chart renderers (plotters, bitmap backend, the committed DejaVu Sans through ab_glyph).
//!
//! Every chart is drawn on linear f64 axes; a log axis is drawn as log10 of the data with
//! tick labels 10^k at the integers, so one renderer serves every log/linear combination.

use std::error::Error;
use std::path::Path;

use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::{FontStyle, register_font};

pub type Res = Result<(), Box<dyn Error>>;

/// A named series of (x, y) points.
pub type Series = (String, Vec<(f64, f64)>);

/// A series cut into unbroken runs.
type Runs = (String, Vec<Vec<(f64, f64)>>);

const FONT: &str = "sans-serif";

/// Register the committed font (no system font lookup happens afterwards).
pub fn register() {
    static DEJAVU: &[u8] = include_bytes!("../../tools/fonts/DejaVuSans.ttf");
    if register_font(FONT, FontStyle::Normal, DEJAVU).is_err() {
        eprintln!("report: the committed font did not load; charts will lack text");
    }
}

/// The red, green and blue bytes of a `0xRRGGBB` colour.
fn channels(hex: u32) -> [u8; 3] {
    [(hex >> 16) as u8, (hex >> 8) as u8, hex as u8]
}

/// Distinct colours for series (Tableau 10).
pub fn colour(i: usize) -> RGBColor {
    const C: [u32; 10] = [
        0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22,
        0x17becf,
    ];
    let [r, g, b] = channels(C[i % C.len()]);
    RGBColor(r, g, b)
}

/// An axis: its title and whether it is logarithmic.
#[derive(Clone, Copy)]
pub struct Axis<'a> {
    pub title: &'a str,
    pub log: bool,
}

impl Axis<'_> {
    fn map(&self, v: f64) -> Option<f64> {
        if self.log {
            (v > 0.0 && v.is_finite()).then(|| v.log10())
        } else {
            v.is_finite().then_some(v)
        }
    }
}

/// Tick label: 10^k on a log axis (integers only), a short number on a linear one.
fn tick(log: bool, v: f64) -> String {
    if log {
        let k = v.round();
        if (v - k).abs() < 1e-6 {
            format!("1e{k}")
        } else {
            String::new()
        }
    } else if v.abs() < 1e-12 {
        "0".into()
    } else if v.abs() >= 1e4 || v.abs() < 1e-3 {
        format!("{v:.0e}")
    } else {
        format!("{}", (v * 1e6).round() / 1e6)
    }
}

/// Padded range of mapped values; log axes widen to whole decades.
fn range(vals: impl Iterator<Item = f64>, log: bool, pad: f64) -> (f64, f64) {
    let (mut lo, mut hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    if log {
        // whole decades, with room for a point sitting on a decade
        lo = (lo - pad).floor();
        hi = (hi + pad).ceil();
    } else {
        let pad = if hi > lo { 0.05 * (hi - lo) } else { 1.0 };
        lo -= pad;
        hi += pad;
    }
    (lo, hi)
}

/// Number of tick labels so that a log axis gets one per decade (at most ~12).
fn labels(lo: f64, hi: f64, log: bool) -> usize {
    if log {
        let n = (hi - lo).round() as usize + 1;
        if n > 12 { n.div_ceil(2) } else { n }
    } else {
        8
    }
}

type Chart<'a> = ChartContext<'a, BitMapBackend<'a>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Axis titles and tick labels (10^k on log axes), with or without the grid.
fn axes(chart: &mut Chart<'_>, x: Axis<'_>, y: Axis<'_>, r: [f64; 4], grid: bool) -> Res {
    let mut mesh = chart.configure_mesh();
    if !grid {
        mesh.disable_mesh();
    }
    mesh.x_desc(x.title)
        .y_desc(y.title)
        .x_labels(labels(r[0], r[1], x.log))
        .y_labels(labels(r[2], r[3], y.log))
        .x_label_formatter(&|v| tick(x.log, *v))
        .y_label_formatter(&|v| tick(y.log, *v))
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 15))
        .draw()?;
    Ok(())
}

/// The series legend, in the corner (a third of each axis) holding the fewest of `pts`.
fn legend(chart: &mut Chart<'_>, r: [f64; 4], pts: &[(f64, f64)]) -> Res {
    let (w, h) = ((r[1] - r[0]) / 3.0, (r[3] - r[2]) / 3.0);
    let count = |right: bool, top: bool| {
        pts.iter()
            .filter(|p| {
                (if right {
                    p.0 > r[1] - w
                } else {
                    p.0 < r[0] + w
                }) && (if top { p.1 > r[3] - h } else { p.1 < r[2] + h })
            })
            .count()
    };
    let corners = [
        (true, true, SeriesLabelPosition::UpperRight),
        (false, true, SeriesLabelPosition::UpperLeft),
        (true, false, SeriesLabelPosition::LowerRight),
        (false, false, SeriesLabelPosition::LowerLeft),
    ];
    let position = corners
        .into_iter()
        .min_by_key(|c| count(c.0, c.1))
        .map_or(SeriesLabelPosition::UpperRight, |c| c.2);
    chart
        .configure_series_labels()
        .position(position)
        .label_font((FONT, 14))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

/// A scatter of labelled points with the Pareto front (non-dominated points: no other point
/// has both fewer instructions and a smaller error) joined by a line.
pub fn pareto(
    path: &Path,
    title: &str,
    x: Axis<'_>,
    y: Axis<'_>,
    pts: &[(String, f64, f64)],
) -> Res {
    let mapped: Vec<(String, f64, f64)> = pts
        .iter()
        .filter_map(|(l, a, b)| Some((l.clone(), x.map(*a)?, y.map(*b)?)))
        .collect();
    let (x0, x1) = range(mapped.iter().map(|p| p.1), x.log, 0.1);
    let (y0, y1) = range(mapped.iter().map(|p| p.2), y.log, 0.1);
    let mut front: Vec<(f64, f64)> = Vec::new();
    let mut sorted: Vec<(f64, f64)> = mapped.iter().map(|p| (p.1, p.2)).collect();
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    for (a, b) in sorted {
        if front.last().is_none_or(|&(_, best)| b < best) {
            front.push((a, b));
        }
    }
    let root = BitMapBackend::new(path, (1000, 680)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, (FONT, 22))
        .margin(15)
        .x_label_area_size(50)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1 + 0.6 * (x1 - x0) / 4.0, y0..y1)?;
    axes(&mut chart, x, y, [x0, x1, y0, y1], true)?;
    chart
        .draw_series(LineSeries::new(front.clone(), RED.stroke_width(2)))?
        .label("Pareto front")
        .legend(|(a, b)| PathElement::new(vec![(a, b), (a + 20, b)], RED.stroke_width(2)));
    // label placement: the first candidate offset whose box (≈7 px per character, 14 px high)
    // overlaps no label placed so far and no point
    let pixel: Vec<(i32, i32)> = mapped
        .iter()
        .map(|p| chart.backend_coord(&(p.1, p.2)))
        .collect();
    let mut boxes: Vec<(i32, i32, i32, i32)> = pixel
        .iter()
        .map(|&(px, py)| (px - 6, py - 6, px + 6, py + 6))
        .collect();
    let overlaps = |b: &(i32, i32, i32, i32), o: &(i32, i32, i32, i32)| {
        b.0 < o.2 && o.0 < b.2 && b.1 < o.3 && o.1 < b.3
    };
    for ((label, a, b), &(px, py)) in mapped.iter().zip(&pixel) {
        let on_front = front.iter().any(|&(fa, fb)| fa == *a && fb == *b);
        let c = if label.contains("micromath") {
            colour(2)
        } else if label.ends_with("f32") {
            colour(0)
        } else {
            colour(1)
        };
        let size = if on_front { 6 } else { 4 };
        let w = 7 * label.chars().count() as i32;
        let candidates = [
            (8, -16),
            (8, 3),
            (-w - 8, -16),
            (-w - 8, 3),
            (8, -30),
            (8, 17),
            (-w / 2, -32),
            (-w / 2, 12),
        ];
        let (dx, dy) = candidates
            .iter()
            .copied()
            .find(|&(dx, dy)| {
                let bx = (px + dx, py + dy, px + dx + w, py + dy + 14);
                !boxes.iter().any(|o| overlaps(&bx, o))
            })
            .unwrap_or(candidates[0]);
        boxes.push((px + dx, py + dy, px + dx + w, py + dy + 14));
        chart.draw_series(std::iter::once(
            EmptyElement::at((*a, *b))
                + Circle::new((0, 0), size, c.filled())
                + Text::new(label.clone(), (dx, dy), (FONT, 13)),
        ))?;
    }
    let micromath = mapped.iter().any(|p| p.0.contains("micromath"));
    let kinds = [
        ("f32", colour(0)),
        ("f64", colour(1)),
        ("f32, micromath backend", colour(2)),
    ];
    for &(name, c) in kinds.iter().take(if micromath { 3 } else { 2 }) {
        chart
            .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?
            .label(name)
            .legend(move |(a, b)| Circle::new((a + 10, b), 5, c.filled()));
    }
    let pts: Vec<(f64, f64)> = mapped.iter().map(|p| (p.1, p.2)).collect();
    legend(&mut chart, [x0, x1, y0, y1], &pts)?;
    root.present()?;
    Ok(())
}

/// Line chart of named series: a series breaks at a non-finite point or one outside a log
/// axis's domain; with at most 60 points per series every point is also marked.
pub fn lines(
    path: &Path,
    title: &str,
    x: Axis<'_>,
    y: Axis<'_>,
    series: &[Series],
    first_black: bool,
) -> Res {
    let mapped: Vec<Runs> = series
        .iter()
        .map(|(name, pts)| {
            let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
            for &(a, b) in pts {
                match (x.map(a), y.map(b)) {
                    (Some(a), Some(b)) => runs.last_mut().map_or((), |r| r.push((a, b))),
                    _ => runs.push(Vec::new()),
                }
            }
            runs.retain(|r| !r.is_empty());
            (name.clone(), runs)
        })
        .collect();
    let all = || mapped.iter().flat_map(|s| s.1.iter().flatten());
    // few points: mark each one
    let sparse = mapped
        .iter()
        .all(|s| s.1.iter().map(Vec::len).sum::<usize>() <= 60);
    let (x0, x1) = range(all().map(|p| p.0), x.log, 0.0);
    let (y0, y1) = range(all().map(|p| p.1), y.log, 0.0);
    let root = BitMapBackend::new(path, (1000, 620)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, (FONT, 20))
        .margin(15)
        .x_label_area_size(50)
        .y_label_area_size(75)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    axes(&mut chart, x, y, [x0, x1, y0, y1], true)?;
    for (i, (name, runs)) in mapped.iter().enumerate() {
        // the first series (the reference, where there is one) black and wide, under the rest
        let (c, width) = if i == 0 && first_black {
            (BLACK, 5)
        } else {
            (colour(i), 2)
        };
        for (j, run) in runs.iter().enumerate() {
            let s = chart.draw_series(LineSeries::new(run.clone(), c.stroke_width(width)))?;
            if j == 0 {
                s.label(name.as_str()).legend(move |(a, b)| {
                    PathElement::new(vec![(a, b), (a + 20, b)], c.stroke_width(3))
                });
            }
            if run.len() == 1 || sparse {
                chart.draw_series(run.iter().map(|&p| Circle::new(p, 3, c.filled())))?;
            }
        }
    }
    let pts: Vec<(f64, f64)> = all().copied().collect();
    legend(&mut chart, [x0, x1, y0, y1], &pts)?;
    root.present()?;
    Ok(())
}

/// Viridis-like colour map, t in [0, 1]: six stops of viridis, interpolated per channel.
fn viridis(t: f64) -> RGBColor {
    const P: [u32; 6] = [0x440154, 0x414487, 0x2a788e, 0x22a884, 0x7ad151, 0xfde725];
    let t = t.clamp(0.0, 1.0) * (P.len() - 1) as f64;
    let i = (t.floor() as usize).min(P.len() - 2);
    let f = t - i as f64;
    let (a, b) = (channels(P[i]), channels(P[i + 1]));
    let lerp = |k: usize| (a[k] as f64 + (b[k] as f64 - a[k] as f64) * f).round() as u8;
    RGBColor(lerp(0), lerp(1), lerp(2))
}

/// One heat-map panel: title and cells (x0, x1, y0, y1, value) in axis units (x already
/// mapped if its axis is log).
pub struct Panel {
    pub title: String,
    pub cells: Vec<(f64, f64, f64, f64, f64)>,
}

/// Heat maps side by side sharing one logarithmic colour scale (values ≤ 0 take its floor),
/// with a colour bar.
pub fn heatmaps(
    path: &Path,
    title: &str,
    x: Axis<'_>,
    y: Axis<'_>,
    value: &str,
    panels: &[Panel],
) -> Res {
    let logs = || {
        panels
            .iter()
            .flat_map(|p| p.cells.iter())
            .filter(|c| c.4 > 0.0 && c.4.is_finite())
            .map(|c| c.4.log10())
    };
    let hi = logs().fold(f64::NEG_INFINITY, f64::max).ceil();
    let lo = logs().fold(f64::INFINITY, f64::min).floor().max(hi - 12.0);
    let (lo, hi) = if lo < hi { (lo, hi) } else { (hi - 1.0, hi) };
    let t = |v: f64| {
        let l = if v > 0.0 { v.log10() } else { lo };
        (l - lo) / (hi - lo)
    };
    let (x0, x1) = panels
        .iter()
        .flat_map(|p| p.cells.iter())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
            (a.min(c.0), b.max(c.1))
        });
    let (y0, y1) = panels
        .iter()
        .flat_map(|p| p.cells.iter())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
            (a.min(c.2), b.max(c.3))
        });
    let width = 330 * panels.len() as u32 + 130;
    let root = BitMapBackend::new(path, (width, 420)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(title, (FONT, 20))?;
    let (maps, bar) = root.split_horizontally(width - 130);
    for (area, p) in maps.split_evenly((1, panels.len())).iter().zip(panels) {
        let mut chart = ChartBuilder::on(area)
            .caption(&p.title, (FONT, 16))
            .margin(8)
            .x_label_area_size(45)
            .y_label_area_size(55)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart.draw_series(
            p.cells
                .iter()
                .map(|&(a, b, c, d, v)| Rectangle::new([(a, c), (b, d)], viridis(t(v)).filled())),
        )?;
        axes(&mut chart, x, y, [x0, x1, y0, y1], false)?;
    }
    let mut cb = ChartBuilder::on(&bar)
        .caption(value, (FONT, 14))
        .margin_top(42)
        .margin_bottom(55)
        .margin_right(10)
        .y_label_area_size(55)
        .build_cartesian_2d(0.0..1.0, lo..hi)?;
    let steps = 200;
    cb.draw_series((0..steps).map(|i| {
        let a = lo + (hi - lo) * i as f64 / steps as f64;
        let b = lo + (hi - lo) * (i + 1) as f64 / steps as f64;
        Rectangle::new([(0.0, a), (1.0, b)], viridis((a - lo) / (hi - lo)).filled())
    }))?;
    cb.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_labels(labels(lo, hi, true))
        .y_label_formatter(&|v| tick(true, *v))
        .label_style((FONT, 13))
        .draw()?;
    root.present()?;
    Ok(())
}
