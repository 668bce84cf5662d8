//! The U.S. Standard Atmosphere 1976 up to 86 km geometric altitude (84.852 km geopotential),
//! the model JSBSim's `FGStandardAtmosphere` uses on a standard day: temperature linear in
//! geopotential altitude within each layer, pressure from the hydrostatic equation, density
//! from the ideal gas law, speed of sound sqrt(gamma R T), geometric altitude (above mean sea
//! level) converted to geopotential with the Earth radius 6,356,766 m.

/// Base geopotential altitude (m) and temperature lapse rate (K/m) of each layer.
const LAYERS: [(f64, f64); 7] = [
    (0.0, -0.0065),
    (11_000.0, 0.0),
    (20_000.0, 0.001),
    (32_000.0, 0.0028),
    (47_000.0, 0.0),
    (51_000.0, -0.0028),
    (71_000.0, -0.002),
];
/// The top of the model, geometric m: the standard's 86 km (84,852 m geopotential in its table,
/// 84,852.05 m with this Earth radius), the highest altitude accepted; the top layer extends to
/// it.
pub const TOP_GEOMETRIC_M: f64 = 86_000.0;
/// Sea-level temperature, K.
const T0: f64 = 288.15;
/// Sea-level pressure, Pa: JSBSim's 2116.228 psf, 5e-6 above the standard's 101,325 Pa.
const P0: f64 = 2116.228 * 47.880_258_980_335_84;
/// Gas constant of dry air, J/(kg K): the universal gas constant 8.31432 J/(mol K) over the
/// molar mass 28.9645 g/mol, the values JSBSim uses.
const R: f64 = 8.314_32 / 0.028_964_5;
/// Standard gravity, m/s^2.
const G0: f64 = 9.806_65;
/// Ratio of specific heats.
const GAMMA: f64 = 1.4;
/// Earth radius of the geopotential conversion, m.
const EARTH_RADIUS_M: f64 = 6_356_766.0;

/// The standard day at one altitude, SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Air {
    /// Temperature, K.
    pub temperature: f64,
    /// Pressure, Pa.
    pub pressure: f64,
    /// Density, kg/m^3.
    pub density: f64,
    /// Speed of sound, m/s.
    pub sound_speed: f64,
}

/// The standard atmosphere at geometric altitude `h` m above mean sea level (0 up to the top of
/// the model, [`TOP_GEOMETRIC_M`] included); `None` outside.
pub fn standard(h: f64) -> Option<Air> {
    if !(0.0..=TOP_GEOMETRIC_M).contains(&h) {
        return None;
    }
    let z = h * EARTH_RADIUS_M / (EARTH_RADIUS_M + h);
    let (mut t, mut p) = (T0, P0);
    for (k, &(base, lapse)) in LAYERS.iter().enumerate() {
        let top = LAYERS.get(k + 1).map_or(f64::INFINITY, |l| l.0);
        let dz = z.min(top) - base;
        let t1 = t + lapse * dz;
        p *= if lapse == 0.0 {
            (-G0 * dz / (R * t)).exp()
        } else {
            (t1 / t).powf(-G0 / (R * lapse))
        };
        t = t1;
        if z <= top {
            break;
        }
    }
    Some(Air {
        temperature: t,
        pressure: p,
        density: p / (R * t),
        sound_speed: (GAMMA * R * t).sqrt(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn standard_values_at_sea_level_tropopause_and_20_km() {
        let sl = standard(0.0).unwrap();
        assert!((sl.density - 1.225).abs() < 1e-4 && (sl.sound_speed - 340.294).abs() < 1e-3);
        // Geometric 11,019 m is geopotential 11,000 m: 216.65 K, 22,632 Pa.
        let trop = standard(11_019.1).unwrap();
        assert!((trop.temperature - 216.65).abs() < 1e-2 && (trop.pressure - 22_632.0).abs() < 2.0);
        let h20 = standard(20_063.1).unwrap();
        assert!((h20.pressure - 5_474.9).abs() < 1.0);
        assert!(standard(-1.0).is_none() && standard(90_000.0).is_none());
        // The top, 86 km geometric, is in (the message says "0 to 86,000 m"); above it is not.
        // The 1976 standard's table at 84.852 km geopotential: molecular-scale temperature
        // 186.946 K, pressure 0.37338 Pa.
        let top = standard(86_000.0).unwrap();
        assert!(
            (top.temperature - 186.946).abs() < 1e-2,
            "{}",
            top.temperature
        );
        assert!((top.pressure - 0.3734).abs() < 1e-3, "{}", top.pressure);
        assert!(standard(86_000.001).is_none());
    }
}
