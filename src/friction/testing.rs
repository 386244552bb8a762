//! A contact state for examples and tests: FZG type C near the start of contact at 1000 rpm, 302 N·m.

use crate::geometry::ContactPoint;

pub fn contact() -> ContactPoint {
    ContactPoint {
        u: 6.0e-3,
        s: -7.97e-3,
        radius_of_curvature: [6.0e-3, 28.9e-3],
        reduced_radius: 4.97e-3,
        rolling_velocity: [0.628, 2.02],
        sliding_velocity: 1.39,
        sum_velocity: 2.65,
        entrainment_velocity: 1.325,
        slide_to_roll: 1.05,
        pairs_in_contact: 2,
        load_share: 0.5,
        force_share: 0.5,
        load_per_width: 3.19e5,
        hertz_pressure: 1.52e9,
        hertz_half_width: 1.34e-4,
    }
}
