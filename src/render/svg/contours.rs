//! The efficiency map's contours: iso-levels on a 1-2-5 step, marching squares for the iso-lines
//! (joined into one path each), bilinear values for the filled bands.

/// One contour panel: values[t][s] over speeds (x) and torques (y).
pub(crate) struct Field<'a> {
    pub(crate) title: String,
    pub(crate) speeds: &'a [f64],
    pub(crate) torques: &'a [f64],
    pub(crate) values: Vec<Vec<f64>>,
    pub(crate) unit: &'a str,
}

/// "Nice" iso-levels spanning [lo, hi]: about `n` of them on a 1-2-5 step.
pub(super) fn levels(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
        return vec![lo];
    }
    let raw = (hi - lo) / n as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0].iter().map(|m| m * mag).find(|s| *s >= raw).unwrap_or(10.0 * mag);
    let first = (lo / step).ceil() * step;
    (0..).map(|i| first + i as f64 * step).take_while(|v| *v <= hi + 1e-12 * step).collect()
}

/// Marching squares: the segments of the iso-line `level` on the grid, in (speed, torque).
pub(super) fn iso_segments(f: &Field, level: f64) -> Vec<[(f64, f64); 2]> {
    let mut out = Vec::new();
    let (xs, ys, v) = (f.speeds, f.torques, &f.values);
    for t in 0..ys.len() - 1 {
        for s in 0..xs.len() - 1 {
            let corners = [(s, t), (s + 1, t), (s + 1, t + 1), (s, t + 1)];
            let mut cuts = Vec::new();
            for k in 0..4 {
                // Each edge read in one direction whichever cell reads it, so that the neighbours'
                // cuts are the same numbers and the segments join ([`iso_lines`]).
                let (a, b) = (corners[k], corners[(k + 1) % 4]);
                let (a, b) = if (a.1, a.0) <= (b.1, b.0) { (a, b) } else { (b, a) };
                let (va, vb) = (v[a.1][a.0], v[b.1][b.0]);
                if !(va.is_finite() && vb.is_finite()) || (va - level) * (vb - level) > 0.0 || va == vb {
                    continue;
                }
                let w = (level - va) / (vb - va);
                cuts.push((xs[a.0] + w * (xs[b.0] - xs[a.0]), ys[a.1] + w * (ys[b.1] - ys[a.1])));
            }
            if cuts.len() >= 2 {
                out.push([cuts[0], cuts[1]]);
            }
            if cuts.len() == 4 {
                out.push([cuts[2], cuts[3]]);
            }
        }
    }
    out
}

/// The iso-line of `level` as polylines: [`iso_segments`] joined end to end where they meet (one
/// path per line instead of one per cell: the map's file a fraction of the size).
pub(super) fn iso_lines(f: &Field, level: f64) -> Vec<Vec<(f64, f64)>> {
    let segs = iso_segments(f, level);
    let key = |p: (f64, f64)| (p.0.to_bits(), p.1.to_bits());
    let mut at: std::collections::HashMap<(u64, u64), Vec<usize>> = std::collections::HashMap::new();
    for (i, s) in segs.iter().enumerate() {
        for p in s {
            at.entry(key(*p)).or_default().push(i);
        }
    }
    let mut used = vec![false; segs.len()];
    let mut lines = Vec::new();
    for start in 0..segs.len() {
        if used[start] {
            continue;
        }
        used[start] = true;
        let mut line = std::collections::VecDeque::from(segs[start].to_vec());
        for forward in [true, false] {
            loop {
                let end = if forward { line[line.len() - 1] } else { line[0] };
                let next = at.get(&key(end)).and_then(|v| v.iter().copied().find(|i| !used[*i]));
                let Some(i) = next else { break };
                used[i] = true;
                let other = if key(segs[i][0]) == key(end) { segs[i][1] } else { segs[i][0] };
                if forward {
                    line.push_back(other);
                } else {
                    line.push_front(other);
                }
            }
        }
        lines.push(line.into_iter().collect());
    }
    lines
}

/// Bilinear value at fractional grid position (s, t).
pub(super) fn bilinear(v: &[Vec<f64>], s: f64, t: f64) -> f64 {
    let (s0, t0) = ((s.floor() as usize).min(v[0].len() - 2), (t.floor() as usize).min(v.len() - 2));
    let (fs, ft) = (s - s0 as f64, t - t0 as f64);
    let a = v[t0][s0] * (1.0 - fs) + v[t0][s0 + 1] * fs;
    let b = v[t0 + 1][s0] * (1.0 - fs) + v[t0 + 1][s0 + 1] * fs;
    a * (1.0 - ft) + b * ft
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The iso-line of a plane v = x + y at level 1 on the unit square crosses at (1, 0) and (0, 1).
    #[test]
    fn marching_squares_on_a_plane() {
        let f = Field {
            title: String::new(),
            speeds: &[0.0, 1.0],
            torques: &[0.0, 1.0],
            values: vec![vec![0.0, 1.0], vec![1.0, 2.0]],
            unit: "",
        };
        let s = iso_segments(&f, 0.5);
        assert_eq!(s.len(), 1);
        let mut ends = s[0].to_vec();
        ends.sort_by(|a, b| a.0.total_cmp(&b.0));
        assert!((ends[0].0 - 0.0).abs() < 1e-12 && (ends[0].1 - 0.5).abs() < 1e-12);
        assert!((ends[1].0 - 0.5).abs() < 1e-12 && (ends[1].1 - 0.0).abs() < 1e-12);
        assert_eq!(levels(0.0, 1.0, 5), vec![0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0]);
    }
}
