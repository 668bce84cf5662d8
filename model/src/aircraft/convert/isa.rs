//! The International Standard Atmosphere in the troposphere: the density at an altitude, for a
//! body-axis file that gives `flight.altitude` instead of a density.

/// ISA sea-level temperature T0, K.
pub const ISA_T0_K: f64 = 288.15;
/// ISA sea-level pressure p0, Pa.
pub const ISA_P0_PA: f64 = 101_325.0;
/// ISA troposphere temperature lapse rate, K/m (T = T0 - 0.0065 h).
pub const ISA_LAPSE_K_M: f64 = 0.0065;
/// Specific gas constant of dry air R, J/(kg K) (ISA value).
pub const ISA_R_J_KG_K: f64 = 287.052_87;
/// Standard gravity g0, m/s^2.
pub const ISA_G0_M_S2: f64 = 9.806_65;

/// ISA troposphere density at geometric altitude `h` m (0 to 11 km): T = T0 - 0.0065 h,
/// p = p0 (T/T0)^(g0/(0.0065 R)), rho = p/(R T), kg/m^3.
pub fn isa_density(h: f64) -> f64 {
    let t = ISA_T0_K - ISA_LAPSE_K_M * h;
    let p = ISA_P0_PA * (t / ISA_T0_K).powf(ISA_G0_M_S2 / (ISA_LAPSE_K_M * ISA_R_J_KG_K));
    p / (ISA_R_J_KG_K * t)
}
