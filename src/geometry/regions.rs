//! The regions of one mesh cycle of a helical pair (He & Singh §4, Table 1, generalised): the
//! intervals between consecutive break times, and the state of every contact line inside each —
//! which boundary of the path holds each end of the line, and on which side of the pitch line the
//! line lies. He & Singh's zones Z1–Z7 of one line are these states: Z1 = (A, face, approach),
//! Z2/Z3 = (A, face, both sides), Z4 = (face, face, both), Z5/Z6 = (face, E, both), Z7 = (face, E,
//! recess); their 6 regions are the NASA-ART pair's case, any other pair has its own count.

use serde::Serialize;

use super::pair::PairGeometry;

/// Which boundary of the path of contact holds one end of a contact line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LineEnd {
    /// The end lies on the wheel's tip line u = T1A (start of contact).
    StartOfContact,
    /// The end lies on a face edge, z = ±b/2.
    FaceEdge,
    /// The end lies on the pinion's tip line u = T1E (end of contact).
    EndOfContact,
}

/// Where a line lies relative to the pitch line u = T1P.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PitchSide {
    Approach,
    Both,
    Recess,
}

/// The state of line k in a region.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
pub struct LineState {
    pub index: usize,
    /// [end at smaller z, end at larger z].
    pub ends: [LineEnd; 2],
    pub side: PitchSide,
}

/// One region: an interval of the cycle (τ in mesh periods) and the lines in contact.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct Region {
    pub from: f64,
    pub to: f64,
    pub lines: Vec<LineState>,
}

impl PairGeometry {
    /// The regions of one mesh cycle between the break times of [`PairGeometry::cycle_break_times`]
    /// with the pitch line included (as with friction), each with the state of its lines at its
    /// middle.
    pub fn cycle_regions(&self) -> Vec<Region> {
        let breaks = self.cycle_break_times(&[]);
        let tol = 1e-9 * self.base_pitch;
        let (half, p) = (0.5 * self.face_width, self.points);
        breaks
            .windows(2)
            .map(|w| {
                let tau = 0.5 * (w[0] + w[1]);
                let lines = self
                    .contact_lines(tau)
                    .iter()
                    .map(|l| {
                        let end = |z: f64, u: f64| {
                            if (u - p.a).abs() < tol && (z.abs() - half).abs() > tol {
                                LineEnd::StartOfContact
                            } else if (u - p.e).abs() < tol && (z.abs() - half).abs() > tol {
                                LineEnd::EndOfContact
                            } else {
                                LineEnd::FaceEdge
                            }
                        };
                        let (lo, hi) = (l.u[0].min(l.u[1]), l.u[0].max(l.u[1]));
                        let side = if hi <= p.p {
                            PitchSide::Approach
                        } else if lo >= p.p {
                            PitchSide::Recess
                        } else {
                            PitchSide::Both
                        };
                        LineState { index: l.index, ends: [end(l.z[0], l.u[0]), end(l.z[1], l.u[1])], side }
                    })
                    .collect();
                Region { from: w[0], to: w[1], lines }
            })
            .collect()
    }
}
