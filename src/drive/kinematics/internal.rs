//! An internal pair on parallel shafts: a pinion inside a ring gear (ISO 21771:2007, an internal
//! pair's transmission ratio u = z_2/z_1 with z_2 < 0). The pinion and the ring turn the same way:
//! ω_ring = ω_pinion z_pinion / z_ring.

use super::stage_kinematics::StageKinematics;

/// The teeth [z_pinion, z_ring] of an internal stage (both counted positive).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Internal {
    pub teeth: [u32; 2],
}

impl StageKinematics for Internal {
    fn speeds(&self, known: usize, omega: f64) -> Vec<f64> {
        super::parallel::pair_speeds(self.teeth, known, omega, 1.0)
    }

    fn torque_ratio(&self, driving: usize) -> f64 {
        super::parallel::pair_torque_ratio(self.teeth, driving)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ring turns the pinion's way at z_p/z_r of its speed; the torque ratio is the teeth's.
    #[test]
    fn the_ring_turns_the_pinions_way() {
        let k = Internal { teeth: [25, 75] };
        assert_eq!(k.speeds(0, 300.0), vec![300.0, 100.0]);
        assert_eq!(k.speeds(1, -100.0), vec![-300.0, -100.0]);
        assert_eq!(k.torque_ratio(0), 3.0);
    }
}
