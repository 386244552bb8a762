//! The undercut of a rack-cut gear below its undercut limit (`geometry::undercut_radius`) against
//! an independent brute-force cut: the gear's material at a radius is what no position of the
//! generating rack's tooth (its flank's half-plane above its tip line) covers, the rack placed at
//! every roll angle and the deepest covering found by a grid and a ternary search. Where the cut
//! boundary falls inside the involute, the gear is undercut; the radius where it stops is located
//! by bisection and must equal the closed construction's to 1e-7 of the undercut's radial reach.

use gearloss::geometry::undercut_radius;

struct Rack {
    r: f64,
    h: f64,
    alpha: f64,
}

impl Rack {
    /// How deep the gear-frame point (ρ, θ) lies inside the rack's tooth at roll angle φ (> 0: inside).
    fn depth(&self, rho: f64, theta: f64, phi: f64) -> f64 {
        let (x, y) = (rho * (theta + phi).cos(), rho * (theta + phi).sin());
        let n = (self.alpha.cos(), -self.alpha.sin());
        let behind_flank = -((x + self.r * phi) * n.0 + (y - self.r) * n.1);
        behind_flank.min(y - (self.r - self.h))
    }

    /// Whether some roll angle puts the point inside the tooth: the depth's largest value is at a
    /// grid point's neighbourhood (ternary search) or where the flank's and the tip line's depths
    /// cross (the tooth's corner passing; bisection on their difference), which a narrow passage
    /// of the corner would hide from the grid.
    fn removed(&self, rho: f64, theta: f64) -> bool {
        let (lo, hi, n) = (-1.2, 0.3, 3000);
        let at = |k: usize| lo + (hi - lo) * k as f64 / n as f64;
        let parts = |phi: f64| {
            let (x, y) = (rho * (theta + phi).cos(), rho * (theta + phi).sin());
            let n = (self.alpha.cos(), -self.alpha.sin());
            (-((x + self.r * phi) * n.0 + (y - self.r) * n.1), y - (self.r - self.h))
        };
        let gap = |phi: f64| {
            let (f, t) = parts(phi);
            f - t
        };
        let mut best = f64::NEG_INFINITY;
        for k in 0..n {
            let (mut a, mut b) = (at(k), at(k + 1));
            best = best.max(self.depth(rho, theta, a));
            if gap(a).signum() != gap(b).signum() {
                for _ in 0..200 {
                    let m = 0.5 * (a + b);
                    if gap(m).signum() == gap(a).signum() {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                best = best.max(self.depth(rho, theta, a)).max(self.depth(rho, theta, b));
            }
        }
        best > 0.0
    }

    /// The involute's polar angle at ρ (the rack's flank through the pitch point at φ = 0).
    fn involute(&self, rho: f64) -> f64 {
        let (s_a, c_a) = self.alpha.sin_cos();
        let s = self.r * s_a - (rho * rho - (self.r * c_a).powi(2)).sqrt();
        let phi = -s / (self.r * c_a);
        (self.r - s * s_a).atan2(s * c_a) - phi
    }

    /// Whether the brute-force cut at ρ reaches inside the involute.
    fn undercut_at(&self, rho: f64) -> bool {
        let theta = self.involute(rho);
        let (mut a, mut b) = (theta - 0.05, theta + 0.05);
        for _ in 0..60 {
            let m = 0.5 * (a + b);
            if self.removed(rho, m) {
                b = m;
            } else {
                a = m;
            }
        }
        0.5 * (a + b) < theta - 1e-12
    }
}

#[test]
fn the_undercut_radius_is_where_a_brute_force_cut_stops() {
    let alpha = 20f64.to_radians();
    for (z, x) in [(10.0, 0.0), (16.0, -0.2), (12.0, -0.1), (8.0, 0.2)] {
        let rack = Rack { r: z / 2.0, h: 1.0 - x, alpha };
        let rb = rack.r * alpha.cos();
        let ru = undercut_radius(rack.r, alpha, rack.h).expect("below x_min");
        let reach = ru - rb;
        assert!(reach > 0.0, "z {z}, x {x}");
        assert!(rack.undercut_at(rb + 0.5 * reach), "z {z}, x {x}: cut below r_u");
        assert!(!rack.undercut_at(ru + 0.5 * reach), "z {z}, x {x}: whole above r_u");
        let (mut lo, mut hi) = (rb + 0.5 * reach, ru + 0.5 * reach);
        while hi - lo > 1e-9 * reach {
            let m = 0.5 * (lo + hi);
            if rack.undercut_at(m) {
                lo = m;
            } else {
                hi = m;
            }
        }
        let brute = 0.5 * (lo + hi);
        assert!((brute - ru).abs() < 1e-7 * reach, "z {z}, x {x}: brute force {brute}, closed {ru}, reach {reach}");
    }
}

/// At and above the undercut limit x_min = 1 − z sin²α/2 nothing is cut; just below it the cut
/// starts at the base circle; further below it reaches higher.
#[test]
fn the_undercut_grows_from_the_base_circle_below_the_limit() {
    let alpha = 20f64.to_radians();
    let z = 14.0;
    let (r, rb) = (z / 2.0, z / 2.0 * alpha.cos());
    let x_min = 1.0 - z * alpha.sin().powi(2) / 2.0;
    assert!(undercut_radius(r, alpha, 1.0 - x_min).is_none());
    assert!(undercut_radius(r, alpha, 1.0 - (x_min + 0.01)).is_none());
    let just_below = undercut_radius(r, alpha, 1.0 - (x_min - 1e-6)).unwrap();
    assert!(just_below - rb < 1e-6 * rb, "{}", just_below - rb);
    let mut last = rb;
    for deficit in [0.01, 0.05, 0.1, 0.2, 0.4] {
        let ru = undercut_radius(r, alpha, 1.0 - (x_min - deficit)).unwrap();
        assert!(ru > last && ru < r, "deficit {deficit}: {ru}");
        last = ru;
    }
}

/// A pair whose undercut stays below its path of contact runs and its report says so (the FZG
/// type C pinion at x = −0.2); one whose undercut reaches the path is refused
/// (`tests/specs/err/undercut.gear`).
#[test]
fn a_harmless_undercut_is_reported_and_a_harmful_one_refused() {
    let root = crate::root();
    let fzg = std::fs::read_to_string(root.join("specs/fzg_type_c.gear")).unwrap();
    let shifted = fzg.replacen("profile_shift = 0.1817", "profile_shift = -0.2", 1);
    assert_ne!(fzg, shifted, "the FZG C pinion's profile shift is written as 0.1817");
    let scene = gearloss::check("fzg_undercut.gear", &shifted).unwrap_or_else(|e| panic!("{e}"));
    let g = scene.gears.geometry().unwrap();
    let ru = g.undercut_radius[0].expect("the pinion is undercut");
    assert!(ru > g.base_radius[0] && ru < g.base_radius[0].hypot(g.points.a), "{ru}");
    let bad = std::fs::read_to_string(root.join("tests/specs/err/undercut.gear")).unwrap();
    let e = gearloss::check("undercut.gear", &bad).expect_err("the undercut reaches the path");
    assert!(e.diagnostics[0].reason.contains("into its path of contact"), "{}", e.diagnostics[0].reason);
}
