//! Recorded measurements joined by `stage,method,precision` (bench-results/*.csv), the
//! stability charts (docs/report/stability/*.csv) and the scene table (bench-results/scenes.csv).

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use crate::plot::{self, Axis};

pub fn repo(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

/// `stage,method,precision,<value>` rows of a bench-results CSV (None: the file is absent).
pub fn keyed(rel: &str) -> Option<HashMap<(String, String, String), f64>> {
    let text = std::fs::read_to_string(repo(rel)).ok()?;
    let mut out = HashMap::new();
    for line in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        if let [s, m, p, v, ..] = f[..]
            && let Ok(v) = v.parse::<f64>()
        {
            out.insert((s.to_string(), m.to_string(), p.to_string()), v);
        }
    }
    Some(out)
}

/// The MCU clock the "µs at 168 MHz" columns assume (an STM32F405/407 at its maximum).
pub const MCU_HZ: f64 = 168e6;

/// bench-results/cycles.csv (`stage,method,precision,insns,cycles_lo,cycles_mid,cycles_hi`,
/// written by tools/qemu-bench.sh) as key → [lo, mid, hi] cycles per call (None: absent).
pub fn cycles() -> Option<HashMap<(String, String, String), [f64; 3]>> {
    let text = std::fs::read_to_string(repo("bench-results/cycles.csv")).ok()?;
    let mut out = HashMap::new();
    for line in text.lines().skip(1) {
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        if let [s, m, p, _, lo, mid, hi] = f[..]
            && let (Ok(lo), Ok(mid), Ok(hi)) =
                (lo.parse::<f64>(), mid.parse::<f64>(), hi.parse::<f64>())
        {
            out.insert((s.to_string(), m.to_string(), p.to_string()), [lo, mid, hi]);
        }
    }
    Some(out)
}

/// Cycles → "mid (lo–hi)" microseconds at [`MCU_HZ`], three significant digits.
pub fn micros(c: [f64; 3]) -> String {
    let us = |v: f64| {
        let v = v / MCU_HZ * 1e6;
        let d = if v >= 100.0 {
            0
        } else if v >= 10.0 {
            1
        } else if v >= 1.0 {
            2
        } else {
            3
        };
        format!("{v:.d$}")
    };
    format!("{} ({}–{})", us(c[1]), us(c[0]), us(c[2]))
}

/// A `# key: value` header, a CSV header and rows, as written by the stability example.
pub struct Table {
    pub meta: HashMap<String, String>,
    /// The `#` lines as written (without the `#`).
    pub comments: Vec<String>,
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

pub fn read_table(path: &Path) -> Option<Table> {
    let text = std::fs::read_to_string(path).ok()?;
    let mut meta = HashMap::new();
    let mut comments = Vec::new();
    let mut lines = Vec::new();
    for line in text.lines() {
        if let Some(c) = line.strip_prefix('#') {
            comments.push(c.trim().to_string());
            if let Some((k, v)) = c.split_once(':') {
                meta.insert(k.trim().to_lowercase(), v.trim().to_string());
            }
        } else if !line.trim().is_empty() {
            lines.push(
                line.split(',')
                    .map(|s| s.trim().to_string())
                    .collect::<Vec<_>>(),
            );
        }
    }
    let mut it = lines.into_iter();
    let header = it.next()?;
    Some(Table {
        meta,
        comments,
        header,
        rows: it.collect(),
    })
}

/// Render every docs/report/stability/*.csv into `dir` as `stability-<name>.png`; returns
/// (title, file) per chart in name order.
pub fn stability(dir: &Path) -> Vec<(String, String)> {
    let Ok(entries) = std::fs::read_dir(repo("docs/report/stability")) else {
        return Vec::new();
    };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "csv"))
        .collect();
    paths.sort();
    let mut out = Vec::new();
    for path in paths {
        let Some(t) = read_table(&path) else {
            continue;
        };
        let stem = path
            .file_stem()
            .map_or("chart".into(), |s| s.to_string_lossy().to_string());
        let get = |k: &str| t.meta.get(k).cloned().unwrap_or_default();
        let title = t.meta.get("title").cloned().unwrap_or_else(|| stem.clone());
        let num = |s: &str| s.parse::<f64>().ok().filter(|v| v.is_finite());
        let series: Vec<(String, Vec<(f64, f64)>)> = (1..t.header.len())
            .map(|j| {
                let pts = t
                    .rows
                    .iter()
                    // empty cell: not sampled there (skipped, the line goes on);
                    // `nan` (or any non-number): no value there (the line breaks)
                    .filter_map(|r| {
                        let cell = r.get(j).map_or("", String::as_str);
                        if cell.is_empty() {
                            return None;
                        }
                        Some((num(r.first()?)?, num(cell).unwrap_or(f64::NAN)))
                    })
                    .collect();
                (t.header[j].clone(), pts)
            })
            .collect();
        let (xt, yt) = (get("x"), get("y"));
        let name = format!("stability-{stem}.png");
        let r = plot::lines(
            &dir.join(&name),
            &title,
            Axis {
                title: &xt,
                log: get("xscale") == "log",
            },
            Axis {
                title: &yt,
                log: get("yscale") == "log",
            },
            &series,
            false,
        );
        match r {
            Ok(()) => out.push((title, name)),
            Err(e) => eprintln!("report: {}: {e}", path.display()),
        }
    }
    out
}

/// bench-results/scenes.csv as markdown: its `#` lines as text, then the table, with a
/// "µs at 168 MHz" column after `insns` joined from bench-results/cycles.csv (stage `scene`).
pub fn scenes() -> Option<String> {
    let mut t = read_table(&repo("bench-results/scenes.csv"))?;
    if let (Some(cyc), Some(j)) = (cycles(), t.header.iter().position(|h| h == "insns")) {
        t.header.insert(j + 1, "µs at 168 MHz".into());
        for r in &mut t.rows {
            let key = ("scene".to_string(), r[0].clone(), r[1].clone());
            let cell = cyc.get(&key).map_or("—".into(), |&c| micros(c));
            r.insert(j + 1, cell);
        }
    }
    let mut md = String::new();
    if !t.comments.is_empty() {
        md.push_str(&format!("{}\n\n", t.comments.join(" ")));
    }
    md.push_str(&format!("| {} |\n", t.header.join(" | ")));
    md.push_str(&format!("|{}\n", "---|".repeat(t.header.len())));
    for r in &t.rows {
        md.push_str(&format!("| {} |\n", r.join(" | ")));
    }
    Some(md)
}
